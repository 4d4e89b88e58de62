/// @file work.hpp  What the principles say of an effect's work between two states, and what is
/// known at the states before solving: the model's vocabulary for both, so that an effect kind
/// whose work follows a rule of its own (model::Effect::work) answers in it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/common/error.hpp"

namespace kinergy::model {

using GiNaC::ex;
class Model;

/// What an equation took for granted about the solution: `e` (state-bound) ≥ 0 there, or the
/// branch is no solution (a force that switches, taken as switched at a state whose position is
/// unknown).
struct Condition {
  ex e;
  std::string what, fix;  ///< the error when it fails ("{}" in `what` is e's value)
  SourcePos pos;
  /// What e ≥ 0 says, stated with a closed form where it cannot be checked (it holds a parameter
  /// without a value): "the sliding under 'table' keeps its sense at state '2'".
  std::string assumed;
  /// A value `what` shows in place of "{v}" (the ratio a friction needs), where it has one.
  ex shown = 0;
};

/// The work of one non-conservative effect between two states, in state symbols.
struct Work {
  std::string effect;
  ex U;
  std::string how;  ///< "U = M (φ₂ − φ₁)", …
  std::vector<Condition> holds;
  int switch_cases = 1;  ///< how many ways a switching force's unknown end may lie (see Knowledge)
  /// U is right at the two states' positions only, not as a function of the end along the way (a
  /// force split where it switches, a one-sided spring): no kinetic energy along the path from it
  bool ends_only = false;
};

/// What is known numerically at each state before solving: given values and what the
/// constraints give from them (for directions of motion). Parameters at their values.
class Knowledge {
public:
  explicit Knowledge(const Model& m);
  /// Numeric value of a state-bound expression, if everything in it is known.
  std::optional<GiNaC::numeric> value(const ex& e) const;
  const GiNaC::exmap& values() const { return known_; }
  /// Record a value found by an earlier analysis, and its form in the parameters.
  void set(const ex& sym, const GiNaC::numeric& v, const ex& form) {
    known_[sym] = v;
    forms_[sym] = form;
  }
  /// A value that is the same for any parameter values (its form is the number).
  void set(const ex& sym, const GiNaC::numeric& v) { set(sym, v, v); }
  /// A force that switches (abs, max, min) on the way to a state whose position is unknown is
  /// taken past every switching point on that side but this many of the farthest (the scene
  /// is solved again with one more while the taken case has no solution).
  int fewer_switches = 0;
private:
  GiNaC::exmap known_;
  GiNaC::exmap forms_;  ///< what is known as forms in the parameters (noted by a sweep's trace)
  GiNaC::exmap env_;  ///< parameter values
};

}  // namespace kinergy::model
