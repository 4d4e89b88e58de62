/// @file model.hpp  SceneDef → Model: symbols with units, bodies, kinematics by differentiation,
/// kinetic and potential energy, effects, states. Pure GiNaC; never sees YAML.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/model/analysis.hpp"
#include "kinergy/model/effect.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/units/units.hpp"

namespace kinergy::model {

using GiNaC::ex;
using units::Dimension;

struct Parameter {
  std::string name;
  SourcePos pos;
  ex sym;                  ///< possymbol when its value is positive (or it has none), else realsymbol
  Dimension dim;
  std::optional<ex> value; ///< exact SI value
  bool unknown = false;    ///< "unknown UNIT": solved for
  /// A result runs over it or asks for it (an extreme's variable, a least value's parameter): not
  /// a parameter of the closed forms, so never given a sampled value.
  bool ranged = false;
  bool angle = false;      ///< written in rad, deg or rev (dimensionless, but not a pure number)
  /// `in: [lo, hi]` (SI): the range it lies in — a value is checked against it, and where it has
  /// none, its sampled values are drawn inside it.
  std::optional<std::pair<ex, ex>> in;  ///< (exact: `180 deg` is π)
  /// Without a value and not solved for (`r: m`): its closed forms hold it as a symbol.
  bool without_value() const { return !value && !unknown; }
};

struct Coordinate {
  std::string name;
  SourcePos pos;
  GiNaC::realsymbol q, qd;  ///< q and q_dot (generic, not bound to a state)
  Dimension dim;
  GiNaC::realsymbol qdd;    ///< q_ddot (generic): kinetics at an instant
  std::string label = {};   ///< `label:`: how figures name it (TeX), "" for a name derived from its own
};

struct Body {
  std::string name;
  SourcePos pos;
  ex mass, inertia;            ///< m and centroidal Ī
  std::string shape;           ///< its inertia shape's name (model/inertia.hpp): how it is drawn ("" for a composite body)
  std::vector<ex> sizes;       ///< the shape's sizes (lengths; Ī for `centroidal`)
  ex x, y, angle;              ///< mass centre and body angle in coordinates (and t)
  std::map<std::string, std::pair<ex, ex>> points;  ///< body axes through G
  /// A part of a composite body (welded to the others): its own mass, shape and Ī about its
  /// centre, its centre in body axes through the body's G and its turn there.
  struct Part {
    std::string name;
    ex mass, inertia;
    std::string shape;
    std::vector<ex> sizes;
    ex lx, ly, angle;
  };
  std::vector<Part> parts;  ///< a composite body's parts (empty for a body of one shape)
  /// How it is drawn where its inertia has no outline (`drawn_as`): "disk" (a circle of radius
  /// drawn_sizes[0]) or "plate" (a rectangle), "" for its inertia's own shape. Drawing only.
  std::string drawn_shape;
  /// `label:`: how figures name it (TeX), "" for a name derived from its own. Drawing only.
  std::string label;
  std::vector<ex> drawn_sizes;
  /// The lengths that size it, for drawing and time scales: its shape's sizes, or a composite
  /// body's parts' sizes and their centres' offsets from G.
  std::vector<ex> lengths() const {
    std::vector<ex> out = sizes;
    for (auto& p : parts) {
      out.insert(out.end(), p.sizes.begin(), p.sizes.end());
      out.insert(out.end(), {p.lx, p.ly});
    }
    return out;
  }
  ex ref_x = 0, ref_y = 0;  ///< a composite body: its reference point (where the scene measures its parts from), in body axes through G
};

struct State {
  std::string name;
  SourcePos pos;
  std::map<std::string, std::pair<GiNaC::realsymbol, GiNaC::realsymbol>> sym;  ///< q → (q@S, q_dot@S)
  GiNaC::realsymbol t;                   ///< t@S
  GiNaC::exmap given;                    ///< state symbol → value (parameters)
  /// Kinetics at an instant: each generic q̈ and support reaction (Model::instant_reactions,
  /// instant_lambdas) → its symbol at this state (theta_ddot@2, Rx_pivot@2).
  GiNaC::exmap instant;
  std::vector<std::pair<ex, SourcePos>> where;  ///< bound conditions (== 0)
};

/// Momentum along one direction n̂ (`along: x`, `y` or [nx, ny]): the momentum kind's option.
struct Along {
  ex nx = 0, ny = 0;
  std::string name;  ///< as the scene writes it (for messages and the derivation)
};

/// The moment point of an angular momentum analysis (`about:`).
struct About {
  PointRef point;
};

/// What strikes in an impact: its contact effects and the unknown impulses they bring (J along
/// n, Jt along the tangent when rough, by effect name), and one impulsive reaction λ per
/// constraint (0 where the constraint is switched off).
struct Struck {
  std::vector<int> contacts;
  std::map<std::string, std::pair<ex, ex>> impulses;
  std::vector<ex> lambdas;
};

struct Analysis {
  std::string kind;  ///< energy, momentum, angular_momentum, impact (for messages)
  const AnalysisKind* type = nullptr;  ///< what it does (src/analyses/)
  SourcePos pos;
  int from = -1, to = -1;
  std::vector<int> bodies;        ///< the body set (all bodies unless listed)
  bool conserved = false;         ///< claimed conserved: checked against the effects
  /// What its kind reads besides the states and the body set (the kind's file fills it): a
  /// momentum analysis's direction, an angular one's point, an impact's parties; nothing else.
  std::variant<std::monostate, Along, About, Struck> options;
  /// An impact: no time passes, positions do not change (its kind says so: type->instant()).
  bool instant() const;
  /// Does it take the scene's given impulses (blows) at its first state: an impact, and a
  /// momentum analysis over a duration (principles::effect_pushes)? Energy and kinetics do not.
  bool takes_blows() const;
  /// The direction of a momentum analysis along one only (nullptr: along x and y).
  const Along* along() const { return std::get_if<Along>(&options); }
  /// The moment point of an angular momentum analysis (nullptr for another kind).
  const PointRef* about() const {
    auto* a = std::get_if<About>(&options);
    return a ? &a->point : nullptr;
  }
  /// What strikes in an impact (nullptr for another kind).
  const Struck* struck() const { return std::get_if<Struck>(&options); }
  /// Unknown average forces or impulses of the supports across its body set, by effect name:
  /// pin reactions (Rx, Ry) and constraint reactions (J) over a duration (momentum), the average
  /// force of an interaction that does work on the set (energy).
  std::map<std::string, std::vector<ex>> reactions;
  std::vector<ex> unknowns;       ///< every unknown it brings, in a stable order
  /// Positions at its states that a result asks for and the states do not give: an analysis
  /// whose kind integrates its momenta to positions (AnalysisKind::gives_positions) adds the
  /// equations that give them.
  std::vector<ex> positions_asked;
};

/// How to pick between roots for a named result.
struct RootSpec {
  enum class Kind { None, Positive, Negative, Interval } kind = Kind::None;
  ex lo, hi;
};

struct Find {
  std::string name;
  SourcePos pos;
  ex value;               ///< bound to states (state symbols, parameters)
  RootSpec root;
  Dimension dim;
  std::optional<units::Unit> unit;
  /// The greatest or least value of `value` as the parameter `p` (without a value) runs over
  /// [lo, hi], or where it is reached (`location`).
  struct Extreme {
    bool largest = true, location = false;
    ex p, lo, hi;
    std::string p_name;
    SourcePos pos;
  };
  std::optional<Extreme> extreme;
  /// The least (greatest) value of the parameter p for which state `state` is reached: the
  /// kinetic energy there (`value` is T@state) stays ≥ 0 — at every position of the path when a
  /// parameter `along` places the state, over [lo, hi].
  struct Reach {
    bool least = true;
    ex p;
    std::string p_name;
    int state = 0;
    std::optional<ex> along;
    std::string along_name;
    ex lo, hi;
    SourcePos pos;
  };
  std::optional<Reach> reach;
};

struct Expect {
  std::string name;
  SourcePos pos;
  std::optional<ex> form;
  SourcePos form_pos;
  std::optional<units::Quantity> value;
  SourcePos value_pos;
  double rtol = 0;  ///< the value may differ by this relative amount (a book's rounding)
};

/// Dimension mismatch: the two terms and their dimensions.
struct DimensionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Model {
public:
  /// @throws SceneError naming file, line, key and fix.
  static Model build(const scene::SceneDef& def);

  std::string file, title, description;
  std::vector<Parameter> params;
  std::vector<Coordinate> coords;
  std::map<std::string, std::pair<ex, ex>> fixed_points;
  /// `label:` of a point (TeX): a fixed point's by its name, a body's point by "body.point".
  /// Drawing only.
  std::map<std::string, std::string> point_labels;
  std::vector<Body> bodies;
  std::vector<std::pair<ex, SourcePos>> constraints;  ///< generic, == 0
  EffectList effects;
  std::vector<State> states;
  std::vector<Analysis> analyses;
  std::vector<Find> finds;
  std::vector<Expect> expects;
  GiNaC::realsymbol t{"t"};
  /// Kinetics at an instant: what each support pushes with at a state, as generic unknowns — a
  /// pin's Rx, Ry, a track's N along its normal, a relation's F along û (constraint effects) —
  /// by effect name; and the multiplier λ_k of each constraint no effect holds (by index; unused
  /// for one an effect holds). Bound to a state by bind().
  std::map<std::string, std::vector<GiNaC::realsymbol>> instant_reactions;
  std::vector<GiNaC::realsymbol> instant_lambdas;

  // --- kinematics (generic: coordinates, rates, t) ---
  std::pair<ex, ex> position(const PointRef& p) const;
  std::pair<ex, ex> velocity(const PointRef& p) const;
  ex omega(int body) const;
  /// d/dt of a generic expression of q and t: Σ ∂e/∂q q̇ + ∂e/∂t.
  ex rate(const ex& e) const;
  /// The whole time derivative of a generic expression of q, q̇ and t:
  /// d/dt e = Σ ∂e/∂q q̇ + Σ ∂e/∂q̇ q̈ + ∂e/∂t (an acceleration from a velocity).
  ex d_dt(const ex& e) const;
  /// The rates q̇ as a list (to collect in).
  GiNaC::lst rates() const;

  // --- energies (generic, simplified) ---
  ex kinetic_energy() const;
  ex kinetic_energy(int body) const;
  /// M(q) = Σ Jᵀ m J + Jωᵀ Ī Jω, entries simplified.
  GiNaC::matrix mass_matrix() const;
  ex potential_energy() const;
  ex potential_energy(const Effect& e) const { return e.potential(*this); }  ///< 0 for effects without a potential
  bool conservative(const Effect& e) const { return e.conservative(); }
  /// Length of a spring from its squared length d² (see the .cpp for the sign rule).
  ex spring_length(const ex& d2) const;
  /// Generalized force Q_i of effect e along coordinate i (non-conservative part included;
  /// conservative effects give −∂V/∂q_i). Friction needs velocities and is not covered here.
  ex generalized_force(const Effect& e, std::size_t i) const { return e.generalized_force(*this, i); }
  /// Power of an effect, Σ Q_i q̇_i (friction: −μN|v|).
  ex power(const Effect& e) const { return e.power(*this); }
  /// Angular momentum of all bodies about point P: Σ Ī ω + (r_G − r_P) × m v̄.
  ex angular_momentum(const PointRef& p) const;
  /// The same for a set of bodies.
  ex angular_momentum(const PointRef& p, const std::vector<int>& bodies) const;
  /// Linear momentum Σ m v̄ of a set of bodies.
  std::pair<ex, ex> linear_momentum(const std::vector<int>& bodies) const;
  /// ∂r_P/∂q (for a material point at a world place: ∂r_G/∂q + ∂φ/∂q k × (w − r_G)).
  std::pair<ex, ex> position_derivative(const PointRef& p, const GiNaC::symbol& q) const;
  /// Impulse (x, y) of an effect over an analysis' interval: a contact's J n (+ Jt t), a pin's
  /// reaction (an unknown, or in an impact the body's momentum change minus the other impulses
  /// on it), a given impulse, ∫F dt of a constant or time-dependent force.
  /// @throws InputError when the effect has no impulse there.
  std::pair<ex, ex> impulse(int effect, int analysis) const;
  /// Kinetic energy lost at a contact in an impact, −½[(1 − e) J v_n⁻ + Jt v_t⁻]
  /// (= ½(1 − e²) m_eff v_n⁻² for one smooth contact), free of the cancellation of T₁ − T₂.
  ex impact_loss(int contact, int analysis) const;
  /// An impact party as the impact principle reads it: effect i, which must be a contact
  /// (checked when the model was built), with its reaction's parties, normal n̂ from a into b,
  /// restitution e and whether it sticks.
  struct Contact {
    std::string name;
    SourcePos pos;
    PointRef a, b;
    ex nx, ny, e;
    bool stick = false;
    bool lodged = false;  ///< `lodges: true`: b embeds in a
  };
  Contact contact(int i) const;
  /// Is effect e a contact (an impact party)?
  bool is_contact(const Effect& e) const;
  /// The effect that holds constraint k (a `constraint` effect, a contact that stays closed after
  /// its impact), or nullptr (`constraints:`).
  const Effect* carrier(std::size_t k) const;
  /// A contact that stays closed after its impact (Reaction::holds): the state that impact ends
  /// at, from which on it holds its parties together; −1 when no impact analysis strikes it, or no
  /// analysis follows that impact.
  int closed_from(const Effect& e) const;
  /// Such a contact's normal n̂ (generic) while it is closed: n̂₀ as written, turned with the body
  /// whose surface it is since it closed, n̂ = Rot(φ − φ@S) n̂₀ (fixed for a ground surface).
  std::pair<ex, ex> closed_normal(const Effect& e) const;
  /// Does constraint k hold at state s (its positions; with `rate`, its rates too)? A constraint
  /// effect switched off at S holds up to S (a cord that goes slack there), one switched on at
  /// S from S on — its rates from S on unless an impact starts at S (it engages in the impact).
  bool constraint_at(std::size_t k, int s, bool rate) const;
  /// How constraint k acts over analysis a: throughout, not at all, or switched inside it.
  Effect::Activity constraint_activity(std::size_t k, const Analysis& a) const;
  /// The constraints that hold throughout analysis a. @throws SceneError when one is switched
  /// inside it (split the analysis at that state).
  std::vector<std::pair<ex, SourcePos>> constraints_over(const Analysis& a) const;
  /// The constraints that hold at both states s1 and s2 (the path between them).
  std::vector<std::pair<ex, SourcePos>> constraints_between(int s1, int s2) const;
  /// The analysis between two states (−1 when none).
  int analysis_between(int from, int to, const std::string& effect = "") const;

  // --- states ---
  int state_index(const std::string& name) const;  ///< −1 when none
  ex bind(const ex& e, int state) const;           ///< generic → state symbols
  /// Positions (and t) from one state, rates from another: velocities just after an impact.
  ex bind_mixed(const ex& e, int position_state, int rate_state) const;
  GiNaC::exmap parameter_values() const;           ///< parameter symbol → exact value
  GiNaC::exmap given_values() const;               ///< every state's given values, one map
  /// Values for numeric decisions (root choice, directions, zero tests): the parameters' values,
  /// and for a parameter given without a value (taken as positive) a fixed sample value.
  GiNaC::exmap numeric_environment() const;
  /// Which sample values numeric_environment gives parameters without values: 0, the first;
  /// another where a solve at the first has no solution there (masses that would have to move a
  /// heavier one up): the choices are then made at sample `sample` (sample_value(p, 0, sample)).
  int sample = 0;
  /// Value k of stream `stream` of a parameter without a value, exact to three digits, from a
  /// fixed sequence of its name, the stream and k (the same on every run and machine): an angle
  /// in [0.2, 1.4] rad, a pure number in [0.1, 0.9] (a friction coefficient, a restitution),
  /// anything else — taken as positive, as the closed forms take it — in [1/10, 10] of its SI
  /// unit, spread evenly in its logarithm (wide enough that a stiff spring or a heavy block the
  /// solution needs is among them); one with a range `in: [lo, hi]` inside the middle 90 % of it
  /// (more digits where three would leave it).
  static GiNaC::numeric sample_value(const Parameter& p, int stream, int k);
  /// The significant digits a sampled value is exact to (3, or more: sample_value).
  static int sample_digits(const GiNaC::numeric& v);
  /// Does e hold a parameter without a value (Parameter::without_value)? Every one when e is
  /// left out: does the scene have any?
  bool unvalued(const GiNaC::ex& e) const;
  bool unvalued() const;
  const Parameter* parameter(const std::string& n) const;
  /// The sign of an expression of parameters that all have values (+1 or −1), 0 when it depends
  /// on anything else or is zero: a factor that keeps its sign for the scene as given.
  int fixed_sign(const ex& e) const;
  /// Every symbol of the model with its dimension (parameters, q, q̇, t, state symbols).
  const std::map<ex, Dimension, GiNaC::ex_is_less>& dimensions() const { return dims_; }
  /// Dimension of an expression. @throws DimensionError naming the two mismatched terms.
  Dimension dimension(const ex& e) const;

  PointRef point(const std::string& text) const;  ///< @throws InputError
  int body_index(const std::string& name) const;
  int effect_index(const std::string& name) const;

  /// Expression context for find/expect/where texts (`T`, `speed(P)`, `X@S`, …).
  ex parse(const std::string& text, const SourcePos& pos, bool allow_states = true) const;

private:
  std::map<ex, Dimension, GiNaC::ex_is_less> dims_;
  std::map<std::string, ex> names_;  ///< parameter, coordinate, rate names → symbol
  void add_symbol(const ex& s, const Dimension& d) { dims_[s] = d; }
  friend class Builder;
  friend class SceneContext;
};

}  // namespace kinergy::model
