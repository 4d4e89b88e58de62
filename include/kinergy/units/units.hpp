/// @file units.hpp  Dimensions, units (SI and US customary) and exact quantities "NUMBER UNIT".
#pragma once
#include <array>
#include <string>

#include <ginac/ginac.h>

namespace kinergy::units {

/// A physical dimension M^a L^b T^c with rational exponents. Angles are dimensionless.
struct Dimension {
  std::array<GiNaC::numeric, 3> e{0, 0, 0};  ///< exponents of mass, length, time

  static Dimension none() { return {}; }
  static Dimension mass() { return {{1, 0, 0}}; }
  static Dimension length() { return {{0, 1, 0}}; }
  static Dimension time() { return {{0, 0, 1}}; }

  bool dimensionless() const { return e[0].is_zero() && e[1].is_zero() && e[2].is_zero(); }
  Dimension operator*(const Dimension& o) const;
  Dimension operator/(const Dimension& o) const;
  Dimension pow(const GiNaC::numeric& p) const;
  bool operator==(const Dimension& o) const;
  bool operator!=(const Dimension& o) const { return !(*this == o); }
  /// "kg·m^2/s^2"-style SI text; "1" when dimensionless.
  std::string str() const;
};

/// A unit: an SI value is (number × factor); factor is exact (may contain π).
struct Unit {
  GiNaC::ex factor = 1;
  Dimension dim;
  std::string text;  ///< as written
};

/// Parse a unit such as "m/s^2", "N·m", "lb*ft", "kg*m^2", "rpm", "1/s".
/// @throws InputError naming the unknown unit and its column.
Unit parse_unit(const std::string& text);

/// Parse an exact decimal ("9.81", "-2", "1e-6", "2.5E3") starting at `pos`; advances `pos`.
/// @returns false (pos unchanged) when no number starts there.
bool parse_decimal(const std::string& s, std::size_t& pos, GiNaC::numeric& out, int* sig_figs = nullptr);

/// A written quantity: "5 kg", "30 deg", "unknown m/s", "kg" (symbolic), "3.50 rad/s".
struct Quantity {
  bool has_number = false;
  bool unknown = false;
  GiNaC::numeric number;   ///< as written, in `unit`
  GiNaC::ex si;            ///< number × unit.factor (exact), when has_number
  Unit unit;
  int sig_figs = 0;        ///< significant figures of the written number
};

/// @throws InputError (column inside text) when the text is not a quantity.
Quantity parse_quantity(const std::string& text);

/// A readable SI unit name for a dimension: "m/s", "rad/s" (for 1/s), "J", "N", "W", …
std::string si_name(const Dimension& d);

}  // namespace kinergy::units
