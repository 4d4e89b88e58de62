/// @file evaluator.hpp  The value of one closed form at one set of exact inputs, three ways:
/// compiled double with an error bound, CLN at a given precision, and N guaranteed digits.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/numeric/tape.hpp"

namespace kinergy::numerics {

class BallEvaluator;

/// A value with N correct significant digits, and how it was obtained.
struct Precise {
  GiNaC::numeric value;      ///< exact rational; or the ball's midpoint (proven: it rounds to the N digits); or a float of `working` digits
  long working = 0;          ///< working precision (decimal digits) of the last evaluation; 0 when exact
  bool exact = false;        ///< the value is exact (a rational)
  bool zero_bound = false;   ///< not settled, but shrinking with precision: zero, |value| < bound
  double bound = 0;          ///< |value| bound when zero_bound
  /// The digits (or the zero bound) are proven by ball arithmetic: the exact value lies in
  /// [lo, hi]. Otherwise they settled between two CLN precisions (a form with a number found
  /// numerically in it, or a function the tape does not evaluate).
  bool proven = false;
  GiNaC::numeric lo, hi;
};

class Evaluator {
public:
  /// e: the closed form; values: an exact value (rational, or an exact form such as π/6) for
  /// every free symbol of e.
  Evaluator(const GiNaC::ex& e, const GiNaC::exmap& values);

  /// Compiled double. Candidates: e itself and its stable form; in each, the subexpressions
  /// that are rational in the inputs (no function, no fractional power: 2L − 3d, 1 − e, m₂ − m₁)
  /// are computed exactly once and rounded once. The candidate with the smaller running error
  /// bound is kept. @returns nothing when no candidate compiles (an unsupported function), or
  /// when a double overflowed, underflowed or was invalid anywhere on the way.
  std::optional<Bounded> fast() const;

  /// CLN directly: the tape in floats of `working` decimal digits (inputs rounded to that precision).
  /// @throws NeedsPrecision when `working` cannot cover an argument (a trigonometric function of a large angle).
  std::optional<GiNaC::numeric> at(long working) const;

  /// `digits` correct significant digits: exact when the value is rational; else proven by ball
  /// arithmetic (Arb) from the exact inputs, the precision raised until the ball fixes them.
  /// Where balls cannot be used (a float in the form or its inputs: a number found numerically;
  /// a function the tape has no instruction for) the working precision of CLN grows until the
  /// rounding to `digits` stops changing, and the result says it is not proven.
  /// @returns nothing when the form is undefined at the values.
  /// @throws std::domain_error when no working precision up to the limit decides.
  std::optional<Precise> digits(int digits) const;
  /// The same by CLN alone (two precisions that round alike): not a proof.
  std::optional<Precise> settled(int digits) const;

  /// The form fast() evaluates, with its exactly computed parts written out (for reports).
  GiNaC::ex fast_form() const { return fast_form_; }
  /// The running error bound of e itself in double (no rewrite, no exact parts): what naive
  /// evaluation would give. @returns nothing when it does not compile.
  std::optional<Bounded> naive() const;

private:
  GiNaC::ex e_, stable_;
  std::vector<GiNaC::ex> syms_;   ///< free symbols of e, in a fixed order
  std::vector<GiNaC::ex> exact_;  ///< their exact values
  GiNaC::exmap values_;           ///< symbol → exact value, for GiNaC
  std::vector<double> x_, dx_;    ///< the exact values as doubles, and their rounding errors
  std::optional<Tape> precise_tape_;
  std::optional<Tape> fast_tape_;
  std::vector<double> fast_x_, fast_dx_;
  GiNaC::ex fast_form_;
  mutable std::map<long, std::vector<cln::cl_R>> inputs_;  ///< the inputs converted, per precision
  mutable std::shared_ptr<BallEvaluator> balls_;  ///< the precise tape on balls (made when first asked)
  std::vector<cln::cl_R> rational_inputs_;  ///< the exact values as CLN rationals (empty unless every one is rational)
  /// e's exact value when it is rational at the values; `undefined` when e is not defined there.
  std::optional<GiNaC::numeric> exact_value(bool& undefined) const;
  mutable bool irrational_ = false;  ///< e at the values is not rational in GiNaC's exact arithmetic
};

}  // namespace kinergy::numerics
