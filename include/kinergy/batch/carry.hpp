/// @file carry.hpp  A solution carried to other parameter values: the signs its choices read
/// (numeric/trace.hpp) and its results' closed forms, compiled in the values that vary. Where
/// interval arithmetic shows every sign the same, every choice falls the same way, and the same
/// closed forms hold: what a sweep and a batch of variants evaluate instead of solving again.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/numeric/tape.hpp"
#include "kinergy/numeric/trace.hpp"
#include "kinergy/problem.hpp"

namespace kinergy::batch {

/// A value from a closed form is taken when its double's error bound is within this of it (a
/// solve rounds to 15 digits: the two then agree to 1e-12).
constexpr double kRelBound = 1e-13;

/// The varying values' symbols (one input of every compiled form each), and how a form recorded
/// by a solve becomes a form in them: each symbol by its name, a varying parameter as its factor
/// to SI times its input, another parameter as its value.
struct Inputs {
  std::vector<GiNaC::symbol> x;
  std::map<std::string, GiNaC::ex> by_name;
  /// e in the inputs, or nothing when it holds a symbol that is neither (a state's place whose
  /// form was not followed).
  std::optional<GiNaC::ex> map(const GiNaC::ex& e) const;
  /// The inputs of model m's parameters `varying`: input i is parameter varying[i] in the unit
  /// whose factor to SI is factor[i]; every other parameter with a value is that value.
  static Inputs of(const model::Model& m, const std::vector<std::string>& varying, const std::vector<GiNaC::ex>& factor);
};

/// What one solve (at one set of values) found, and what makes it hold at others.
struct Region {
  std::vector<double> at;
  bool ok = false;
  std::string error;     ///< !ok: why the scene has no solution there
  std::string unusable;  ///< why it holds only at `at` ("": it is carried to any box its choices hold in)
  /// `unusable` for a reason that holds at every point (a numeric root, a scan, a form without a
  /// closed form): no solve's solution is carried anywhere, and every point is solved
  bool nowhere = false;
  std::optional<numerics::Tape> notes;  ///< every sign its choices read, in the inputs
  std::vector<int> signs;
  struct Path {
    numerics::Tape K;     ///< K(q, inputs) ≥ 0 along the way
    numerics::Tape ends;  ///< q1, q2 (inputs)
  };
  std::vector<Path> paths;
  std::vector<numerics::Tape> results;  ///< each result in its display unit (ok and usable)
};

/// Compile what a traced solve read, and its results (`s`: nothing when it failed), in the inputs.
void carry(Region& r, const numerics::Trace& t, const Solution* s, const Inputs& in);

/// Do region r's choices fall the same way at every point whose inputs lie within rad of mid?
bool holds(const Region& r, const std::vector<double>& mid, const std::vector<double>& rad);

/// Region r's results at inputs x (r ok and usable), each with its double's error bound (dx[i]
/// bounds the error of input i); nothing when a bound is not within kRelBound of its value.
std::optional<std::vector<numerics::Bounded>> values_at(const Region& r, const double* x, const double* dx);

/// The shortest decimal that reads back as d, exactly (the value a grid point's text gives).
GiNaC::numeric decimal_of(double d);

/// The same in CLN, where a double's bound is too wide (a result that cancels there): each result
/// at 30 and at 45 digits from the inputs' shortest decimals (decimal_of: as a solve at that point
/// reads them), the two agreeing to 1e-20 relative; the double nearest. Nothing when they do not
/// agree, or a result is undefined there.
std::optional<std::vector<double>> precise_values_at(const Region& r, const std::vector<double>& x);

}  // namespace kinergy::batch
