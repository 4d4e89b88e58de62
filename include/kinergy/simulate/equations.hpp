/// @file equations.hpp  Equations of motion of a model, M(q) q̈ + c(q, q̇, t) = Σ Q_effect,
/// with the scene's holonomic constraints as rows A(q) q̈ = γ, built from the kinematics
/// (Σ Jᵀ m J), never by differentiating a Lagrangian twice. Only the effects the scene lists
/// contribute a term; the parts that switch during a motion (Coulomb friction sliding or
/// sticking, contacts striking or resting) are kept as their ingredients (a velocity, its
/// Jacobian row, its velocity-product acceleration) for the simulator to combine.
#pragma once
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/model/model.hpp"

namespace kinergy::simulate {

using GiNaC::ex;

/// A velocity that is linear in the rates: v = J q̇ + b, with dv/dt = J q̈ + a0 (a0: the
/// acceleration with q̈ = 0, from the velocity products and the explicit time dependence).
struct LinearRate {
  ex v;                  ///< v(q, q̇, t)
  std::vector<ex> J;     ///< ∂v/∂q̇_i
  ex a0;                 ///< dv/dt at q̈ = 0
};

/// One smooth effect's generalized force Q (gravity, a spring, a couple, a force, a damper).
struct ForceTerm {
  int effect;                 ///< index into Model::effects
  std::vector<ex> Q;          ///< Q_i(q, q̇, t)
  bool conservative = false;  ///< Q = −∂V/∂q (its work is tracked through V)
  ex power;                   ///< Σ Q_i q̇_i (non-conservative effects)
  std::string singular;       ///< why it may be undefined ("" when it cannot be), for messages
};

/// Coulomb friction of known normal force N (kinetic μ): a point's slip velocity (friction) or
/// a body's angular velocity (friction_couple). Sliding: Q = −μN Jᵀ v/|v| (a couple: −M sgn ω Jω);
/// sticking: the slip velocity is held at zero by a constraint whose force stays within μN.
struct FrictionTerm {
  int effect;
  bool rotary = false;             ///< friction_couple
  LinearRate x, y;                 ///< slip velocity components (rotary: x is ω, y unused)
  ex limit;                        ///< μN (or M): the largest friction force (couple)
};

/// A contact: gap g(q, t) = (r_b − r_a)·n̂ (≥ 0 apart), its rate v_n, and the tangential rate.
struct ContactTerm {
  int effect;
  ex gap;
  LinearRate normal, tangent;  ///< n̂·(v_b − v_a), t̂·(v_b − v_a) with t̂ = (−n_y, n_x)
  ex e;                         ///< coefficient of restitution
  bool stick = false;           ///< rough: no tangential slip after an impact
  /// A surface that only pushes (a one-sided track), its body freed to leave it: the gap opens
  /// where the surface's push falls to zero (simulate/freed.cpp)
  bool surface = false;
  /// A rolling contact on that surface (a `constraint` effect with mu_s whose normal is it, by
  /// index; −1: none): its relation's rate is the tangent, held at zero while |F| ≤ μ_s N; past
  /// that it slides against μ_k N (mu_k < 0: not said, the run stops there). `force_per`: the
  /// friction force per unit of the tangent row's multiplier, |f| with F = λ f.
  int rolling = -1;
  ex mu_s = 0, mu_k = -1, force_per = 1;
  /// Rough and resting (held at its point: a wheel pivoting about the corner it struck), its
  /// normal turns with the body whose surface it is: that body's angle (0: a fixed surface). Its
  /// push is N = λ_n cos Δ + λ_t sin Δ, Δ the angle turned since it came to rest.
  ex turn = 0;
  /// Lodged (`lodges: true`): once at rest it never lets go, whatever its push.
  bool lodged = false;
};

/// A given impulse J at a point (acts once, at the first instant).
struct ImpulseTerm {
  int effect;
  std::vector<ex> P;  ///< generalized impulse P_i = J · ∂r/∂q_i
};

struct Equations {
  std::vector<ex> q, qd;             ///< the model's coordinates and rates (its realsymbols)
  ex t;
  GiNaC::matrix M;                   ///< M(q) = Σ m Jᵀ J + Ī Jωᵀ Jω
  std::vector<ex> c;                 ///< velocity products: Σ m Jᵀ a0_G + Ī Jω α0
  std::vector<ForceTerm> forces;
  std::vector<FrictionTerm> friction;
  std::vector<ContactTerm> contacts;
  std::vector<ImpulseTerm> impulses;
  std::vector<ex> g;                 ///< holonomic constraints g(q, t) = 0
  GiNaC::matrix A;                   ///< ∂g/∂q (m × n)
  std::vector<ex> gt;                ///< ∂g/∂t
  std::vector<ex> gamma;             ///< A q̈ = γ = −d/dt(A q̇ + ∂g/∂t) at q̈ = 0
  ex T, V;                           ///< kinetic and potential energy

  /// Every term printed: M, c, each effect's Q under its own name, the constraint rows.
  std::string text(const model::Model& m) const;
};

/// The equations of motion of a model (generic symbols: parameters not substituted).
/// @throws SceneError naming an effect the simulation cannot take (its place and why).
/// `on`: which effects act (by index; empty: all).
Equations equations_of_motion(const model::Model& m, const std::vector<bool>& on = {});

/// v = Σ J_i q̇_i + b as its Jacobian row and dv/dt at q̈ = 0.
LinearRate linear_rate(const model::Model& m, const ex& v);
/// The term of an effect from its generalized forces Q_i = e.generalized_force(i) (with its power
/// when it is not conservative).
ForceTerm force_term(const model::Model& m, const model::Effect& e, int self);
/// The terms of an effect from its loads (a conservative one: Q = −∂V/∂q; kinetic friction: its
/// slip and limit; the rest: Q_i from the loads, with their power).
void load_terms(const model::Model& m, const model::Effect& e, int self, Equations& eq);
/// The term of effect `self` with the given Q_i.
ForceTerm force_term(const model::Model& m, int self, std::vector<ex> Q, bool conservative);

}  // namespace kinergy::simulate
