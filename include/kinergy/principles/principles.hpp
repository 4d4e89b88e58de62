/// @file principles.hpp  Principles of the chapter turned into scalar equations between states.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/model/model.hpp"
#include "kinergy/model/work.hpp"

namespace kinergy::principles {

using GiNaC::ex;

/// One scalar equation `lhs = rhs`, with the principle it comes from.
struct Equation {
  ex lhs, rhs;
  std::string principle;  ///< "work-energy", "constraint", "condition", …
  std::string label;      ///< readable: "work–energy, states 1 → 2"
  SourcePos pos;
  ex residual() const { return lhs - rhs; }
};

using model::Condition;
using model::Knowledge;
using model::Work;

/// What a principle gives for one analysis: its equations, and what their terms took for
/// granted. Each analysis kind's balance derives from it (its section of the derivation reads the
/// rest).
struct Balance {
  virtual ~Balance() = default;
  /// Its equations, in the order they join the system.
  virtual std::vector<Equation> equations() const = 0;
  /// What its terms took for granted (a switching force passed, a declared direction of
  /// sliding), each e ≥ 0, checked on the solution.
  virtual std::vector<Condition> conditions() const = 0;
  /// Equations it holds in reserve: solved only when a result is not determined without them
  /// (the positions a momentum balance integrates to, where the scene's other equations do not
  /// already give them).
  virtual std::vector<Equation> reserve() const { return {}; }
  /// Equations a solution must also satisfy, not solved: they follow from its equations at a
  /// general state but need not at a particular one (kinetics' rows left out at a sample point,
  /// where a coefficient vanishes at the solution: sin θ = 0). A branch that breaks one is no
  /// solution.
  virtual std::vector<Equation> checked() const { return {}; }
  /// Why it does not give unknown u where a result asks for it ("" when it has nothing to say).
  virtual std::string why_not(const ex&) const { return ""; }
};

/// Energy terms of one side.
struct EnergyTerms {
  ex T, V;
};

/// The energy analysis: T₁ + V₁ + Σ U₁→₂ = T₂ + V₂.
struct EnergyBalance : Balance {
  EnergyTerms at_from, at_to;
  std::vector<Work> works;
  std::vector<std::string> stored;  ///< the effects whose potential V holds ("name (kind)")
  std::vector<std::string> working;  ///< the names of the effects that do work (by V or by U), for a figure
  Equation equation;
  bool conservative = true;  ///< no non-conservative effect did work

  std::vector<Equation> equations() const override { return {equation}; }
  /// What works of zero, left out of `works`, took for granted.
  std::vector<Condition> unshown;
  std::vector<Condition> conditions() const override {
    std::vector<Condition> out = unshown;
    for (auto& w : works) out.insert(out.end(), w.holds.begin(), w.holds.end());
    return out;
  }
};

/// @throws SceneError when a work cannot be taken (path unknown, time-dependent couple …).
EnergyBalance energy(const model::Model& m, const model::Analysis& a, const Knowledge& k);

/// Work of effect `e` between states s1 → s2 (state symbols).
Work work(const model::Model& m, const model::Effect& e, int s1, int s2, const Knowledge& k);

/// One degree of freedom: the free coordinate s and the others as functions of it, from
/// constraints linear in a coordinate (later-declared coordinates are eliminated first) that hold
/// at both states s1 and s2.
struct Path {
  std::size_t s = 0;
  GiNaC::exmap q_of_s;
};
std::optional<Path> one_dof_path(const model::Model& m, int s1, int s2);

/// The work of an effect between two states from its loads (src/principles/loads.cpp): a force or
/// couple by its generalized forces; a drive of given power P, ∫P dt; kinetic friction, −μN
/// times the distance slid (a friction couple: −M times the angle turned). @throws SceneError
/// when it depends on the speeds along the way (a damper).
Work load_work(const model::Model& m, const model::Effect& e, int s1, int s2, const Knowledge& k);

/// The work of a force or couple from its generalized forces Q_i (constant in time):
/// Φ(q₂) − Φ(q₁) when Σ Q_i dq_i = dΦ, else the integral along the one-coordinate path.
/// `what` names it in messages ("couple", "force"); `how` is the exact case's formula. `k`: what
/// is known at the states (the direction of the motion toward an unknown end; how many switching
/// points to leave out, Knowledge::fewer_switches).
Work generalized_force_work(const model::Model& m, const model::Effect& e, const std::string& what,
                            const std::string& how, int s1, int s2, const Knowledge* k = nullptr);
/// The same for given generalized forces Q_i (one per coordinate).
Work generalized_force_work(const model::Model& m, const model::Effect& e, const std::vector<ex>& Q, const std::string& what,
                            const std::string& how, int s1, int s2, const Knowledge* k = nullptr);

/// The work of kinetic friction c whose slip keeps to a fixed line, with slip rate
/// v = Σ a_i(q) q̇_i along it: when that is the rate of a function of the coordinates (v = df/dt,
/// ∂a_i/∂q_j = ∂a_j/∂q_i), U = −c σ (f(q₂) − f(q₁)) with σ the sign of the slip (at the first
/// state, else the second, or `declared`) — no one-coordinate path needed (a block sliding on a
/// moving cart). With `moved` (a rate along the same line, = dg/dt), the work of that force on
/// the point moving at that rate: U = −c σ (g(q₂) − g(q₁)) (the friction on one of the two bodies
/// alone). Nothing when v (or `moved`) is not such a rate.
std::optional<Work> exact_slip_work(const model::Model& m, const model::Effect& e, std::optional<int> declared, const ex& c,
                                    const ex& v, const std::string& how, int s1, int s2, const Knowledge& k,
                                    const std::optional<ex>& moved = std::nullopt);

/// The work of kinetic friction c along the one-coordinate path, U = −c σ (ℓ(s₂) − ℓ(s₁)), with
/// dℓ/ds = `rate(path)` (a distance slid, or an angle turned) and σ the sign of the motion
/// (from the states, or `declared`).
Work friction_work(const model::Model& m, const model::Effect& e, std::optional<int> declared, const ex& c,
                   const std::function<ex(const Path&)>& rate, const std::string& how, int s1, int s2,
                   const Knowledge& k);

/// Does the motion get from state a.from to a.to of energy analysis `a` (balance `bal`, every
/// state symbol and parameter a number in `values`)? With one degree of freedom between them
/// (the constraints that hold fix every coordinate but one, the path coordinate s), the kinetic
/// energy along the way, K(s) = T₁ + V₁ + U₁→s − V(s), must stay ≥ 0: sampled at 256 points
/// from s₁ to s₂, the other coordinates following by Newton's method on the constraints.
/// Nothing is decided where the forms cannot be had in doubles (a held integral) or the path
/// cannot be followed. @throws SceneError naming where K turns negative.
///
/// `pushes`: surfaces that can only push (one-sided tracks) acting over the analysis, each with
/// its normal force N(q, q̇) in closed form, positive while it pushes: N ≥ 0 is followed along the
/// same samples (the rates from K along the path's tangent), and where it turns negative the
/// place the body leaves the surface is found by bisection. @throws SceneError naming it.
struct PushAlong {
  std::string effect;  ///< the track
  std::string body;    ///< what it holds ("the ball"), for the message
  ex N;                ///< generic (q, q̇, parameters): positive while it pushes
  SourcePos pos;       ///< where the track is declared
  bool pulls = false;  ///< a cord (its tension), not a surface
};
void check_reached(const model::Model& m, const model::Analysis& a, const EnergyBalance& bal, const GiNaC::exmap& values,
                   const std::vector<PushAlong>& pushes = {});

/// Constraint equations at a state (positions and velocities) and its `where` conditions.
std::vector<Equation> state_equations(const model::Model& m, int state);

/// Antiderivative of f in s, when one of the elementary rules applies.
std::optional<ex> antiderivative(const ex& f, const GiNaC::symbol& s);

}  // namespace kinergy::principles
