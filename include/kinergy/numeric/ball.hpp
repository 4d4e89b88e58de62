/// @file ball.hpp  Ball arithmetic (Arb): a closed form's tape evaluated on balls [m ± r] that are
/// proven to hold the exact value, from the exact inputs; the precision raised until the ball
/// fixes the digits asked. What `--digits N` prints.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/numeric/tape.hpp"

namespace kinergy::numerics {

/// The exact value x lies in [lo, hi] (both exact binary fractions).
struct Enclosure {
  GiNaC::numeric lo, hi;
  GiNaC::numeric mid() const { return (lo + hi) / 2; }
  GiNaC::numeric radius() const { return (hi - lo) / 2; }
  bool has_zero() const { return !lo.is_positive() && !hi.is_negative(); }
};

/// A value with N digits fixed by its enclosure, or the enclosure that could not fix them.
struct Proven {
  enum class Kind {
    Exact,     ///< exact rational (GiNaC's exact arithmetic): `value` is it
    Digits,    ///< every value in `at` rounds to the same N significant digits: `value` is that rounding
    Unsigned,  ///< the enclosure keeps holding 0 as the precision rises: |value| ≤ max(|lo|, |hi|), sign not fixed
  } kind = Kind::Exact;
  GiNaC::numeric value;  ///< Exact: the value; Digits: the ball's midpoint (it rounds to the N digits)
  Enclosure at;          ///< Digits, Unsigned: the last enclosure
  long bits = 0;         ///< the precision (bits) of the last evaluation
};

/// A tape bound to exact input values, evaluated on balls. The arithmetic itself is Arb's, in a
/// module of its own (kinergy_arb.so) loaded when the first BallEvaluator is made: @throws
/// InputError naming where it was looked for, and what to do, when it cannot be loaded.
class BallEvaluator {
public:
  /// `inputs`: one exact value per tape input (a rational, or an exact form such as π/6 or √2,
  /// which is evaluated on balls itself). A float among them (a number found numerically) is
  /// taken as the exact binary fraction it is: `from_float()` then says the proof is of that
  /// float's consequences, not of the scene's value.
  BallEvaluator(const Tape& t, const std::vector<GiNaC::ex>& inputs);
  ~BallEvaluator();
  BallEvaluator(BallEvaluator&&) noexcept;
  BallEvaluator& operator=(BallEvaluator&&) noexcept;

  /// N significant digits proven: the precision starts near what N needs and doubles until the
  /// enclosure's ends round alike, or until `max_bits`. @returns nothing when the form is proven
  /// undefined there. @throws std::domain_error when no precision up to max_bits decides
  /// (an indeterminate step all the way, or digits that never settle and a ball that does not
  /// hold zero).
  std::optional<Proven> digits(int n, long max_bits) const;

  bool from_float() const { return from_float_; }

  struct Impl;

private:
  std::unique_ptr<Impl> impl_;
  bool from_float_ = false;
};

/// A root of r(u) = 0 (the other symbols of r at their exact `values`) to n proven digits,
/// started from x0 (a number near it): Newton's method on the balls' midpoints, then a ball I
/// around the result on which r is defined and whose ends give r proven opposite signs, so that
/// I holds a root; the precision doubles until every value of I rounds to the same n digits. When
/// lo < hi, I must lie in [lo, hi] (the bracket the root was found in). @returns nothing when r
/// does not compile to a tape (a function it has no instruction for), holds a float, or no precision up to
/// max_bits proves the digits.
std::optional<Proven> root_digits(const GiNaC::ex& r, const GiNaC::symbol& u, const GiNaC::numeric& x0, const GiNaC::numeric& lo,
                                  const GiNaC::numeric& hi, const GiNaC::exmap& values, int n, long max_bits);

/// A number found as a root that a value depends on: u with residual(u) = 0 (the other symbols of
/// the residual at their values), found as `at` inside the bracket [lo, hi].
struct RootOf {
  GiNaC::ex u;  ///< a symbol (held as an ex: a realsymbol copied into a symbol would be another symbol)
  GiNaC::ex residual;
  GiNaC::numeric at, lo, hi;
};

/// g at the roots u₁…u_k (and the other symbols of g at their exact `values`) to n proven digits:
/// each root is enclosed on balls at the precision of m ≥ n + 10 digits (as root_digits proves
/// one, in order: a root whose residual holds an earlier root takes that root's enclosure as an
/// input), and g runs on balls whose inputs are those enclosures; m doubles until g's digits are
/// fixed. A value solved from a numeric root, or an extreme at a stationary point found
/// numerically, is proven so. @returns
/// nothing when a root is not proven, g holds a float or a function the tape has no instruction
/// for, or no m up to max_bits fixes the digits.
std::optional<Proven> digits_at_roots(const GiNaC::ex& g, const std::vector<RootOf>& roots, const GiNaC::exmap& values, int n,
                                      long max_bits);

/// Bits for n decimal digits (n·log₂10), rounded up.
long bits_for(int n);
/// The decimal digits `bits` bits hold (bits·log₁₀2), rounded down: a working precision as text says it.
long digits_in(long bits);

/// The smallest number of at most 2 significant digits ≥ x ≥ 0 (a radius printed so that it still
/// bounds): 1.234e-20 → 1.3e-20.
GiNaC::numeric round_up2(const GiNaC::numeric& x);

}  // namespace kinergy::numerics
