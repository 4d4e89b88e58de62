/// @file kinetics.hpp  Newton's second law at a state (kinetics at an instant): the accelerations
/// q̈ and the forces the supports exert there, from Newton–Euler for each body with the supports'
/// reactions as unknowns, the rates at the state from the other analyses or as given.
#pragma once
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
  std::vector<Condition> conditions() const override { return {}; }
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

}  // namespace kinergy::principles
