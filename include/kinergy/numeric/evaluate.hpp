/// @file evaluate.hpp  Numbers from closed forms: exact values in, decimal text out.
#pragma once
#include <optional>
#include <string>

#include <ginac/ginac.h>

namespace kinergy::numerics {

/// The significant digits a value may be asked for, in a batch request's "digits" and the Python
/// module's value() and ball(): 1 to kMaxDigits (more would run for minutes and take gigabytes).
inline constexpr int kMaxDigits = 1000;
/// Is `digits` a number of significant digits one may ask for?
inline bool valid_digits(long long digits) { return digits >= 1 && digits <= kMaxDigits; }
/// What to say of digits that are not: the problem, and its fix.
inline std::pair<std::string, std::string> digits_fault(const std::string& what) {
  return {what + " is not a whole number from 1 to " + std::to_string(kMaxDigits), "ask for 15 digits (a double's), or up to " + std::to_string(kMaxDigits)};
}

/// Evaluate e with `values` substituted, using `digits` decimal working digits.
/// @returns nothing when e is not a real number (symbols left, complex, undefined).
/// Nothing too when a sin, cos or tan in it has an argument too large for any working precision
/// up to 20000 digits (see beyond_precision).
std::optional<GiNaC::numeric> evaluate(const GiNaC::ex& e, const GiNaC::exmap& values, int digits);

/// Whether a sin, cos or tan in e (values substituted) has an argument so large that no working
/// precision up to 20000 digits leaves `digits` digits after reducing it by whole turns.
bool beyond_precision(const GiNaC::ex& e, const GiNaC::exmap& values, int digits);

/// Is e zero at `values`, judged against the size of its terms: |e| ≤ 10^(12−digits) · max |term|
/// of its expansion (a lone term: only an exact zero). A small value is not a zero: a couple
/// of 1e-12 N·m is a couple. @returns nothing when e has no value there.
std::optional<bool> negligible(const GiNaC::ex& e, const GiNaC::exmap& values, int digits = 40);

/// ∫_a^b f ds numerically to `digits` significant digits (double-exponential tanh–sinh
/// quadrature, its step halved until two levels agree; `values` give f's other symbols). For an
/// integrand with no elementary antiderivative. @returns nothing when f has no real value at a
/// node, or the levels do not settle.
std::optional<GiNaC::numeric> integrate(const GiNaC::ex& f, const GiNaC::symbol& s, const GiNaC::numeric& a,
                                        const GiNaC::numeric& b, const GiNaC::exmap& values, int digits);

/// ∫_a^b f ds held as an expression (a work integral with no elementary antiderivative whose end
/// is unknown): it takes its value by `integrate` at the working precision once f's other symbols
/// and both ends are numbers (evalf), and differentiates by its ends (d/db = f(b), d/da = −f(a)),
/// so that a numeric root search can solve for an end. Printed as integral(f, s, a, b).
GiNaC::ex integral_of(const GiNaC::ex& f, const GiNaC::symbol& s, const GiNaC::ex& a, const GiNaC::ex& b);
/// Is e such an integral?
bool is_integral(const GiNaC::ex& e);

/// v rounded to n significant digits, as text: "3.50178525897863", "-0.00125", "1.5e-12".
std::string format(const GiNaC::numeric& v, int n);
/// The same text as format(exact(d), n) for a finite double d (1 ≤ n ≤ 17), without CLN: its
/// digits correctly rounded by the C++ library, a tie rounded away from zero as format does.
std::string format_double(double d, int n);
/// d to n significant digits as printf's "%.*g" writes it: "0.125", "1e-07", "inf" (short
/// numbers in messages and notes, where format's exact rounding is not asked for).
std::string g_text(double d, int n);

/// v rounded to n significant digits (exact decimal).
GiNaC::numeric round_sig(const GiNaC::numeric& v, int n);

}  // namespace kinergy::numerics
