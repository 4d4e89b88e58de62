/// @file momentum.hpp  Impulse and momentum between two states, and impacts.
#pragma once
#include <string>
#include <vector>

#include "kinergy/principles/principles.hpp"

namespace kinergy::principles {

/// A force (and where it acts) that an effect exerts on the body set over the interval, or an
/// impulse it gives there (an unknown reaction, a given impulse).
struct Push {
  ex Fx = 0, Fy = 0;        ///< force (generic; may depend on t)
  ex arm_x = 0, arm_y = 0;  ///< application point (generic)
  ex M = 0;                 ///< a couple (generic)
  bool unknown = false;     ///< an impulse (Rx, Ry), not a force to integrate
  bool reaction = false;    ///< that impulse is an unknown support reaction (a pin's, a constraint's)
  bool implied = false;     ///< the support is one the coordinates imply (a pin), not a relation between them
  ex Rx = 0, Ry = 0;
  std::string what;         ///< how a derivation names it, when not by the defaults
  std::string symbol;       ///< how a diagram writes it (its load's symbol: "W", "F"; "": the effect's name)
  bool assumed = false;     ///< shown by its direction only: a support whose size the equations do not give (∫N dt)
  int body = -1;            ///< the body it acts on (−1: the set, where it is not one body's)
  std::vector<Condition> holds;  ///< what it took for granted (a declared direction of sliding): checked on the solution
  /// A force of an interaction that changes with the motion (a spring with one end on the set):
  /// it has no impulse of its own over a duration. Refused (this message, this fix) only where a
  /// balance needs it: a component along n, a moment about P that is not zero.
  std::string changing, changing_fix;
};

/// An effect's push as a diagram shows it.
struct Shown {
  std::string effect;
  Push push;
};

/// Is body b in the set?
bool in_set(const std::vector<int>& s, int b);
/// Is point p on a body of analysis a's set?
bool inside(const model::Analysis& a, const model::PointRef& p);
/// The plane cross product a × b = a_x b_y − a_y b_x (a moment about the origin, a parallelism test).
inline ex cross(const ex& ax, const ex& ay, const ex& bx, const ex& by) { return ax * by - ay * bx; }
/// Zero for every value of the coordinates (symbolic, then numeric at random points)?
bool vanishes(const model::Model& m, const ex& e);
/// Free of the coordinates and rates?
bool motion_free(const model::Model& m, const ex& e);
/// Direction of sliding (or turning) over the interval: the sign of `generic` at the first
/// state, or — starting from rest — at the second; a `declared` one they contradict is refused,
/// one they do not tell is taken and checked on the solution (`holds`: the sign of `generic` at
/// both states). @throws SceneError when neither tells it, or they disagree.
int motion_direction(const model::Model& m, const model::Effect& e, std::optional<int> declared, const ex& generic,
                     const model::Analysis& a, const Knowledge& k, const std::string& what, std::vector<Condition>* holds = nullptr);

/// A body of a set that its coordinates hold to a fixed straight line without turning (a block on
/// a table, a slider in a straight guide), and the line's unit direction u (src/principles/guided.cpp).
struct Guided {
  int body = -1;
  ex ux = 0, uy = 0;
};
/// The fixed straight line body b's mass centre keeps to (every ∂r̄/∂q_i along one constant u; none
/// where it is held still or moves otherwise), and how the coordinates turn the body: one that
/// moves its centre turns it too (rolling written into the coordinates), one turns it alone.
struct CentreLine {
  ex ux = 0, uy = 0;
  bool turns_with_centre = false, turns_alone = false;
};
std::optional<CentreLine> centre_line(const model::Model& m, int b);
/// The bodies of analysis a's set so held.
std::vector<Guided> guided_bodies(const model::Model& m, const model::Analysis& a);
/// The entry of body b in gs, or nullptr when b is not guided.
const Guided* find_guided(const std::vector<Guided>& gs, int b);
/// The moment about P of a force F on guided body g together with what its support adds to
/// balance it across the line and about the mass centre (m ā·n = 0, Ī α = 0): (r̄ − r_P) × u (F·u).
ex guided_moment(const model::Model& m, const Guided& g, const ex& px, const ex& py, const ex& Fx, const ex& Fy);
/// @throws SceneError where a load or a support inside the set pushes on a guided body across its
/// line (or with a moment about its mass centre) in a way the moments about (px, py) cannot know.
/// @throws SceneError where a relation effect between two bodies of the set pushes on them at
/// places not on one line along its force (the equal and opposite pair would have a moment).
void check_internal_pairs(const model::Model& m, const model::Analysis& a);
void check_guided_interactions(const model::Model& m, const model::Analysis& a, const std::vector<Guided>& g, const ex& px,
                               const ex& py);

/// The pushes of an effect's loads on the bodies of a momentum analysis (src/principles/loads.cpp):
/// each load on a body of the set (its partner's reaction, when only the partner is in the set);
/// none for an interaction inside the set; kinetic friction in the sense against the motion at
/// the first state. @throws SceneError for an interaction whose load changes with the motion.
void load_pushes(const model::Model& m, const model::Effect& e, const model::Analysis& a, const Knowledge& k,
                 std::vector<Push>& out);
/// Everything an effect exerts on the bodies of a momentum analysis over its duration: its loads'
/// pushes, its reaction's unknown impulse across the set, a given impulse. @throws SceneError
/// when they cannot be integrated.
void effect_pushes(const model::Model& m, const model::Effect& e, const model::Analysis& a, const Knowledge& k,
                   std::vector<Push>& out);
/// ∫_{t₁}^{t₂} f dt over analysis a, for f free of the motion (constant, or of t); nothing when it
/// has no elementary antiderivative.
std::optional<ex> over_duration(const model::Model& m, const ex& f, const model::Analysis& a);
/// ∫_{t₁}^{t₂} ∫_{t₁}^{t} f dt' dt over analysis a (what a push adds to the set's first moment, the
/// positions at the end), for f free of the motion; nothing when it has no elementary form.
std::optional<ex> twice_over_duration(const model::Model& m, const ex& f, const model::Analysis& a);
/// ∫F dt over analysis `ai` of the effect's forces on its bodies (those on the analysis' set,
/// where it has some). @throws InputError in an impact, or when a force changes with the motion.
std::pair<ex, ex> load_impulse(const model::Model& m, const model::Effect& e, int ai);

/// Is it a pin holding body `body` (so that the body's momentum change less the other impulses in
/// an impact is its impulse)?
bool holds(const model::Model& m, const model::Effect& e, int body);
/// Does an energy analysis of `set` need the reaction's average force as an unknown (a relation
/// between the set and a body outside or the ground; a pin whose point inside keeps to a fixed
/// line)?
bool works_across(const model::Model& m, const model::Reaction& r, const std::vector<int>& set);
/// The unknown reaction impulse of a support joining the set to the rest, on the party inside.
void reaction_pushes(const model::Model& m, const model::Effect& e, const model::Reaction& r, const model::Analysis& a,
                     std::vector<Push>& out);
/// The impulse of a support or a contact over analysis `ai`: its unknowns there, a contact's
/// J n̂ + Jt t̂, in an impact a pin's as the pinned body's momentum change less the other impulses
/// on it and a relation's as its multiplier's Λ f. @throws InputError when it has none there.
std::pair<ex, ex> reaction_impulse(const model::Model& m, const model::Effect& e, const model::Reaction& r, int self, int ai);
/// Its work across an energy analysis' set: the unknown average force times the distance its
/// point moves along it (`r`: the effect's reaction, or none). @throws SceneError when that is not
/// one unknown times a distance.
Work reaction_work_across(const model::Model& m, const model::Effect& e, const model::Reaction* r, const model::Analysis& a);

/// One external impulse in a component equation.
struct ImpulseTerm {
  enum class Kind { Integral, Reaction, Given };  ///< ∫F dt (or ∫M dt); an unknown reaction; a given impulse
  std::string effect;
  ex value;
  std::string how;  ///< "∫F dt", "unknown pin reaction", …
  Kind kind = Kind::Integral;
};

/// The equations of one momentum analysis, component by component.
struct MomentumBalance : Balance {
  /// Where the pushes are known functions of time, the momentum integrates once more to the
  /// positions at the end: the momentum L = dΦ/dt of Φ = Σ m r̄·n (linear), Φ = Σ h_i q_i
  /// (angular, when H = Σ h_i q̇_i with constant h_i), and
  ///   Φ₂ = Φ₁ + L₁ (t₂ − t₁) + Σ ∫_{t₁}^{t₂}∫_{t₁}^{t} F dt' dt.
  struct Displacement {
    ex before, after;  ///< Φ at the two states
    ex drift;          ///< L₁ (t₂ − t₁)
    std::vector<ImpulseTerm> terms;  ///< each push's double integral
    Equation equation;
  };
  struct Component {
    std::string name;  ///< "x", "y", "along (nx, ny)", "moment about O"
    ex before, after;  ///< momentum (or angular momentum) at the two states
    std::vector<ImpulseTerm> impulses;
    Equation equation;
    /// Its second integral, when a result asks for a position it holds (Analysis::positions_asked)
    /// and every push on it is a known function of time: in reserve (Balance::reserve).
    std::optional<Displacement> displacement;
    std::vector<ex> positions;  ///< the positions asked that its second integral holds
    std::string no_positions;   ///< why it has none, when asked ("" otherwise)
  };
  std::vector<Component> components;
  std::vector<Shown> shown;  ///< every force and impulse on the set, for its impulse–momentum diagram
  bool conserved = false;
  bool angular = false;  ///< angular (about a point), else linear
  std::vector<Condition> holds;  ///< what its pushes took for granted, checked on the solution
  /// Guided bodies (Guided) whose implied support answers a load across their line: the derivation
  /// says how their loads' moments were taken.
  std::vector<int> supported;

  std::vector<Equation> equations() const override {
    std::vector<Equation> out;
    for (auto& c : components) out.push_back(c.equation);
    return out;
  }
  std::vector<Condition> conditions() const override { return holds; }
  std::string why_not(const ex& u) const override {
    for (auto& c : components)
      if (!c.no_positions.empty())
        for (auto& x : c.positions)
          if (x.is_equal(u)) return c.no_positions;
    return "";
  }
  std::vector<Equation> reserve() const override {
    std::vector<Equation> out;
    for (auto& c : components)
      if (c.displacement) out.push_back(c.displacement->equation);
    return out;
  }
};

/// Linear impulse–momentum Σ m v̄₂·n = Σ m v̄₁·n + Σ ∫F·n dt for the analysis' bodies.
/// @throws SceneError when an impulse cannot be taken, or a conservation claim is false.
MomentumBalance linear_momentum(const model::Model& m, const model::Analysis& a, const Knowledge& k);

/// Angular impulse–momentum Σ H_P₂ = Σ H_P₁ + Σ ∫M_P dt.
MomentumBalance angular_momentum(const model::Model& m, const model::Analysis& a, const Knowledge& k);

/// The equations of an impact: generalized impulse–momentum along each coordinate (pins and
/// constraints carry workless impulsive reactions), restitution and stick conditions at each
/// contact, positions unchanged.
struct ImpactBalance : Balance {
  std::vector<Equation> momentum;     ///< one per coordinate that the impact moves
  std::vector<int> along;             ///< momentum[i] is along the coordinate coords[along[i]]
  std::vector<Equation> restitution;  ///< one per contact (and stick conditions)
  std::vector<Equation> positions;    ///< q_after = q_before
  /// The impulses on each body (Push::body), for the impact's diagrams: contact impulses at the
  /// contact point, given blows, and each pin's impulsive reaction.
  std::vector<Shown> shown;

  /// The positions kept, then the momentum along each coordinate, then restitution.
  std::vector<Equation> equations() const override {
    std::vector<Equation> out;
    for (auto* group : {&positions, &momentum, &restitution}) out.insert(out.end(), group->begin(), group->end());
    return out;
  }
  std::vector<Condition> conditions() const override { return {}; }
};

ImpactBalance impact(const model::Model& m, const model::Analysis& a, const Knowledge& k);

}  // namespace kinergy::principles
