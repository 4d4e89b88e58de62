/// @file solver.hpp  Solve the equations of a scene for its unknowns: linear ones by
/// elimination, then single-unknown quadratics and trigonometric equations in closed form,
/// a numeric root where no closed form exists. Two roots make two branches.
#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/principles/principles.hpp"

namespace kinergy::solve {

using GiNaC::ex;

/// A failure to solve: what and where (the equation's place in the scene).
class SolveError : public std::runtime_error {
public:
  SolveError(std::string what, std::string fix, SourcePos pos)
      : std::runtime_error(std::move(what)), fix_(std::move(fix)), pos_(std::move(pos)) {}
  const std::string& fix() const { return fix_; }
  const SourcePos& pos() const { return pos_; }
private:
  std::string fix_;
  SourcePos pos_;
};

struct Problem {
  std::vector<principles::Equation> equations;
  std::vector<ex> unknowns;  ///< symbols to solve for, in a stable order
  GiNaC::exmap given;        ///< known state values (expressions of parameters)
  GiNaC::exmap env;          ///< numeric values of parameters, for decisions
  /// Reference values for a numeric root search (same coordinate at another state).
  GiNaC::exmap reference;
  /// Ranges to search for a numeric root, from results' `root: {in: [lo, hi]}` (SI values).
  std::map<ex, std::pair<ex, ex>, GiNaC::ex_is_less> ranges;
  /// Unknowns that are impulses (contact impulses, support reactions): an equation linear in
  /// one of them is solved for it first, so that what remains is in the states' values (a state
  /// that cannot be reached is then told by its velocity, not by an impulse).
  std::set<ex, GiNaC::ex_is_less> impulses;
  /// Parameters without a value: env holds a stand-in for them, good for choosing a branch but
  /// not for refusing one (a state unreachable at the stand-in may be reachable at the value the
  /// result asks for, as in "the least speed for which the state is reached").
  std::set<ex, GiNaC::ex_is_less> stand_ins;
};

/// A numeric root: the equation residual(u) = 0 it solves, and the bracket it was found in
/// (the residual changes sign between lo and hi, SI values).
struct NumericRoot {
  ex residual;  ///< in u and the parameters (their values in Problem::env)
  GiNaC::numeric lo, hi;
};

/// One consistent solution.
struct Branch {
  GiNaC::exmap sol;                 ///< unknown → closed form (or number when no closed form)
  std::set<ex, GiNaC::ex_is_less> numeric_only;  ///< unknowns found by a numeric root
  std::map<ex, NumericRoot, GiNaC::ex_is_less> roots;  ///< how each of them was found
  std::vector<std::string> steps;   ///< how each unknown was found
};

/// All solution branches (at most a few). @throws SolveError when no branch survives.
std::vector<Branch> solve(const Problem& p);

}  // namespace kinergy::solve
