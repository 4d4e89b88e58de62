/// @file kinetics.hpp  Newton's second law at a state (kinetics at an instant): the accelerations
/// q̈ and the forces the supports exert there, from Newton–Euler for each body with the supports'
/// reactions as unknowns, the rates at the state from the other analyses or as given.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"

namespace kinergy::principles {

/// A force or couple on a body at the state, as the free-body diagram shows it.
struct BodyLoad {
  std::string effect;  ///< the effect (or support) it comes from
  int body = -1;
  ex x = 0, y = 0;     ///< its point (at the state)
  ex Fx = 0, Fy = 0;   ///< its force (at the state)
  ex M = 0;            ///< its couple
  bool unknown = false;  ///< a support's reaction (holds unknowns)
  std::string symbol;    ///< how a diagram writes it (its load's symbol: "W", "F"; "": the effect's name)
};

/// A body's accelerations at the state: its kinetic diagram is m ā and Ī α.
struct BodyAcceleration {
  int body = -1;
  ex ax = 0, ay = 0;  ///< ā, of its mass centre
  ex alpha = 0;       ///< α
};

/// The equations of kinetics at one state.
struct KineticsBalance : Balance {
  struct Row {
    enum class Kind { Motion, Constraint, ForceX, ForceY, Moment };
    Kind kind = Kind::Motion;
    int body = -1;      ///< ForceX, ForceY, Moment: whose
    int coordinate = -1;  ///< Motion: along which; Constraint: which constraint
    Equation equation;  ///< bound to the state
    bool used = false;  ///< among the independent equations solved (the others are checked)
  };
  int state = -1;
  std::vector<Row> rows;
  std::vector<BodyLoad> loads;  ///< every force and couple on the bodies of the set
  std::vector<BodyAcceleration> accelerations;  ///< of each body of the set, at the state
  std::vector<ex> unknowns;     ///< at the state: q̈, the reactions, the multipliers

  std::vector<Equation> equations() const override {
    std::vector<Equation> out;
    for (auto& r : rows)
      if (r.used) out.push_back(r.equation);
    return out;
  }
  /// What it took for granted: the sense of a friction couple at rest at the state (σ α_rel ≥ 0).
  std::vector<Condition> holds;
  std::vector<Condition> conditions() const override { return holds; }
  std::vector<Equation> checked() const override {
    std::vector<Equation> out;
    for (auto& r : rows)
      if (!r.used) out.push_back(r.equation);
    return out;
  }
};

/// The unknowns kinetics at state `s` brings for body set `bodies`: q̈ of every coordinate, the
/// reaction of each support acting on a body of the set, the multiplier of each constraint no
/// effect holds (all bound to s). @throws SceneError when an effect switches at s.
std::vector<ex> kinetics_unknowns(const model::Model& m, const model::Analysis& a);

/// Newton's second law at the analysis' state: Lagrange's equation along each coordinate
/// (Σ_b m a_G·∂r_G/∂q_i + Ī α ∂φ/∂q_i = Q_i + the constraints' forces), each constraint's second
/// rate c̈ = 0, and for each body of the set ΣF = m a_G and ΣM_G = Ī α with the supports'
/// reactions. The independent ones are solved; each other one is checked to follow from them
/// (at sample values) — one that does not means a support the scene does not declare.
/// @throws SceneError (an undeclared support, reactions that Newton's law does not determine).
KineticsBalance kinetics(const model::Model& m, const model::Analysis& a, const Knowledge& k);

/// Forces of supports at a general instant of a motion, in closed form (functions of t, q, q̇ and
/// the parameters): Lagrange's equations and Newton–Euler for each of `bodies`, the effects `on`
/// acting and the constraints `held` holding (by index), solved for q̈, the reactions on those
/// bodies and the multipliers; each of `wanted` (generic symbols of Model::instant_reactions) is
/// returned. `what` names the motion in messages. @throws SceneError where Newton's law leaves a
/// force open, or a support the scene does not declare acts on one of the bodies.
std::vector<ex> support_forces(const model::Model& m, const std::vector<bool>& on, const std::vector<bool>& held, const std::vector<int>& bodies,
                               const std::vector<ex>& wanted, const std::string& what, const SourcePos& pos);
/// The bodies whose Newton–Euler equations give a static-friction relation's F and N: its parties'
/// and its normal track's.
std::vector<int> friction_bodies(const model::Model& m, const model::Reaction& r);

/// Static friction of the relations that state it (|F| ≤ μ_s |N|: a rolling contact, `mu_s` on a
/// constraint effect), judged where each acts: at the state of a kinetics analysis (the F and N
/// it solves for), at both ends of an analysis over an interval (F and N in closed form from
/// Newton–Euler over its motion: support_forces). Each is μ_s |N| − |F| ≥ 0, showing the ratio
/// |F|/|N| it needs. `along`: the analyses over an interval where that ratio changes with the
/// motion, so that its states alone do not settle it (the simulation checks it along the way).
/// @throws SceneError in an impact (not checked there), or where Newton's law leaves F or N open.
struct FrictionLimit {
  std::string effect, normal, mu;  ///< the relation, its track, μ_s as written (and its value)
  int state = -1;
  Condition holds;  ///< μ_s N − |F| ≥ 0 at the state, `shown`: |F|/N (N as the surface presses; |N| for a guide)
};
struct FrictionLimits {
  std::vector<FrictionLimit> at_states;  ///< one per relation and state, in order
  std::vector<int> along;
};
FrictionLimits static_friction_limits(const model::Model& m);

/// Surfaces that can only push (a one-sided track, model::Reaction::one_sided): N ≥ 0 wherever each
/// acts — at the state of a kinetics analysis (the N it solves for), at both ends of an analysis
/// over an interval (N in closed form from Newton–Euler over its motion: support_forces), and
/// over a momentum analysis across it its impulse ∫N dt ≥ 0; for an energy analysis, N itself
/// for following it along the way (check_reached). Where Newton's law does not give N in closed
/// form (a force the scene does not declare on the body), `unchecked` says so and why.
struct OneSidedLimit {
  std::string effect;
  int state = -1;  ///< −1: over an analysis (its impulse)
  Condition pushes;
};
struct OneSidedLimits {
  std::vector<OneSidedLimit> at_states;
  std::map<int, std::vector<PushAlong>> along;  ///< by analysis over an interval (an energy analysis follows them)
  std::vector<std::string> unchecked;
};
OneSidedLimits one_sided_limits(const model::Model& m);

}  // namespace kinergy::principles
