/// @file effect.hpp  An effect kind as a type: everything the engine asks of one effect.
///
/// Each kind (gravity, spring, couple, pin, contact, …) is one class in its own file under
/// src/effects/, deriving from `Effect` and registered by name in src/effects/registry.cpp (the one
/// table of kinds). The builder reads a kind's options through `EffectReader`; principles,
/// simulator and emitters ask the effect itself and never look at its kind's name.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <boost/iterator/indirect_iterator.hpp>
#include <ginac/ginac.h>

#include "kinergy/common/error.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/units/units.hpp"

namespace kinergy::draw {
class Figure;
struct At;
}

namespace kinergy::model {

using GiNaC::ex;
class Model;
struct Analysis;
class Knowledge;
struct Work;

/// A place that moves with the model: a body point, a body's mass centre, a fixed point, or
/// the material point of a body that is at a given world place (`at`).
struct PointRef {
  std::string text;
  int body = -1;          ///< -1: fixed point
  bool world_place = false;  ///< body material point at world place (wx, wy)
  bool ground = false;    ///< the fixed ground (a contact party without a point)
  ex lx = 0, ly = 0;      ///< body-local offset from G
  ex wx = 0, wy = 0;      ///< fixed point / world place
};

/// One load an effect puts on a body at a state, as expressions of q, q̇ and t: what its force
/// law says it does. Principles derive from its loads, once, the effect's generalized force,
/// power, work, impulse over a duration and terms of the equations of motion.
///   Given: a force F at `at` (a body point, its mass centre, or its material point at a place)
///          and a couple M on at's body.
///   Slide: kinetic friction, a force of size `size` at `at` against its slip over `partner`
///          (the ground when there is none): F = −size v̂_rel.
///   Turn:  a friction couple of size `size` on at's body against its turning (relative to
///          partner's body): M = −size sgn ω_rel.
/// An interaction names its other party (`partner`): −F acts at that point, −M on its body
/// (Newton's third law, written once here); a party that is a fixed point or the ground is
/// not a body, and takes the reaction out of the scene. A load without a partner comes from
/// outside the bodies (a field, a push the scene gives).
struct Load {
  enum class Kind { Given, Slide, Turn };
  Kind kind = Kind::Given;
  PointRef at;
  ex Fx = 0, Fy = 0, M = 0;
  ex size = 0;
  std::optional<PointRef> partner;
  std::optional<int> direction;  ///< Slide/Turn: the declared sign of the motion it opposes
  std::string singular;          ///< why its value may be undefined (a drive's P/ω at ω = 0), or ""
  /// How a diagram writes it, as a textbook does ("W" a weight, "F" a friction), the body's name
  /// added as a subscript where a diagram has several bodies; "": by its effect's name
  std::string symbol;
};

/// The reaction of a support, or the impulse of a contact: what it can push with (unknown until an
/// analysis solves for it), along which directions, and where. The principles make from this,
/// once, its unknowns in each analysis that isolates a body it holds, its pushes, impulses and
/// work across a body set, and its part in an impact.
///   Pin:      R = (Rx, Ry) on party a at a, −R on party b: the coordinates keep a and b together.
///   Track:    N n̂ on party a (n̂ = dir, generic): the coordinates keep a on the track.
///   Relation: J û on party a, −J û on party b (û = dir): constraint `constraint` of the model
///             held by their touching (a mesh, a cord, rolling), its multiplier's force λ f
///             (f = (fx, fy)) on a.
///   Contact:  J n̂ + Jt t̂ on party b, −that on party a, in impacts only (n̂ = dir, from a into
///             b; t̂ = (−n_y, n_x)); restitution e, `stick`: it does not slide after the impact.
struct Reaction {
  enum class Kind { Pin, Track, Relation, Contact };
  Kind kind = Kind::Pin;
  PointRef a, b;
  ex dir_x = 0, dir_y = 0;
  ex fx = 0, fy = 0;
  std::size_t constraint = 0;
  ex e = 0;
  bool stick = false;
  /// A relation held by static friction (rolling without slipping, `mu_s` on a constraint
  /// effect): its force may be at most μ_s |N|, N the normal force of the track effect named
  /// `normal`. μ_s = 0: no limit stated.
  ex mu_s = 0;
  std::string normal;
  /// Its kinetic friction once it slips, `mu_k` (−1: not said): a simulation that frees the
  /// rolling body from its surface lets it slide against −μ_k N (simulate/freed.cpp).
  ex mu_k = -1;
  /// A track that can only push (a surface: N ≥ 0, n̂ the way it pushes); false for a guide that
  /// holds both ways.
  bool one_sided = false;
  /// A track: how far its point is off it, along n̂ (> 0: apart, on the side a surface pushes
  /// toward; 0 wherever the coordinates keep the point on it), for a simulation that lets the body
  /// leave a surface (simulate/freed.cpp) or checks that the coordinates hold it; and, for a
  /// surface, `e`, the restitution when the body strikes it again (−1: not said).
  ex gap = 0;
  /// One-sided and a cord (`cord: [O, bob]`): N is its tension, pulling the point toward O; it
  /// goes slack where N falls to zero, and snaps taut (an impact, with e) where it straightens.
  bool pulls = false;
  /// A contact that stays closed after its impact (plastic and rough: e = 0, `tangential: stick`):
  /// from the state its impact ends at (Model::closed_from), a pin holding b's point at a's — the
  /// model's constraints `holds`, x then y of r_b − r_a = 0, their multipliers the force R on b
  /// (−R on a) — whose push along n̂ can only be ≥ 0, n̂ turning with body `turns` (the party
  /// whose surface it is: a wheel's rim on a corner; −1: fixed, a ground surface).
  std::vector<std::size_t> holds;
  int turns = -1;
  /// `lodges: true`: b embeds in a at the impact (a bullet in a block) and holds both ways from
  /// then on — no push checked, never let go (a contact that stays closed otherwise only pushes).
  bool lodged = false;
  SourcePos limit_pos;  ///< where `mu_s` is written
  /// The names of its unknowns over a duration: Rx, Ry (pin), N (track), J (relation); a
  /// contact has none (it acts in impacts only).
  std::vector<std::string> parts() const;
  /// Does it join a body of `set` to a party outside it (a fixed party, the ground, a body not in
  /// the set) with a reaction over a duration? (A contact acts only in impacts: no.)
  bool across(const std::vector<int>& set) const;
  /// The bodies it joins (a fixed party is not a body).
  std::vector<int> bodies() const;
  /// The sign rule (docs/scene-format.md, "Signs of forces"): a support's force is reported on its
  /// first party that is a body — a, unless a is the ground or a fixed point.
  bool a_first() const { return a.body >= 0 && !a.ground; }
  /// That party, and the other one (which takes the opposite force).
  const PointRef& first() const { return a_first() ? a : b; }
  const PointRef& second() const { return a_first() ? b : a; }

  static Reaction pin(PointRef a, PointRef b);
  static Reaction track(PointRef a, ex nx, ex ny);
  static Reaction relation(PointRef a, PointRef b, ex ux, ex uy, ex fx, ex fy, std::size_t constraint);
  static Reaction contact(PointRef a, PointRef b, ex nx, ex ny, ex e, bool stick);
};

/// How a support that acts one way is spoken of: a surface that only pushes, or a cord that only
/// pulls (Reaction::pulls), holding `body`.
struct OneWay {
  std::string lets_go;  ///< "ball leaves 'dome'" / "cord 'string' goes slack"
  std::string force;    ///< "normal force" / "tension"
  std::string only;     ///< "a surface can only push" / "a cord can only pull"
  std::string acts;     ///< "the surface of 'dome' pushes on ball" / "cord 'string' pulls on bob"
  std::string would;    ///< "the surface of 'dome' would have to pull on ball" / "cord 'string' would have to push on bob"
  std::string keeps;    ///< "keeps ball on 'dome'" / "keeps cord 'string' taut"
  std::string is;       ///< "the surface" / "the cord"
  std::string verb;     ///< "leaves" / "goes slack"
  std::string ask;      ///< the state where it lets go: `where: ["N(dome) = 0"]` / `where: ["T(string) = 0"]`
};
OneWay one_way(bool pulls, const std::string& body, const std::string& effect);

/// The kinematics a load's force and couple work along (src/model/loads.cpp):
/// v_rel = v_at − v_partner (the partner's point, 0 for a fixed party or none).
std::pair<ex, ex> relative_velocity(const Model& m, const Load& l);
/// φ_rel = the angle of at's body − the partner's body's (0 for a fixed party or none).
ex relative_angle(const Model& m, const Load& l);
/// ω_rel = ω of at's body − ω of the partner's body (0 for a fixed party or none).
ex relative_omega(const Model& m, const Load& l);
/// A load's force F and couple M at a generic state: as declared (Given); Slide: F = −size v̂_rel;
/// Turn: M = −size sgn ω_rel. What every principle takes as the load's push.
struct Wrench {
  ex Fx = 0, Fy = 0, M = 0;
};
Wrench force_of(const Model& m, const Load& l);
/// Q_i = F·∂(r_at − r_partner)/∂q_i + M ∂(φ_at − φ_partner)/∂q_i; Slide: −size v̂_rel·∂v_rel/∂q̇_i;
/// Turn: −size sgn(ω_rel) ∂ω_rel/∂q̇_i.
ex generalized_force(const Model& m, const Load& l, std::size_t i);
/// P = F·v_rel + M ω_rel; Slide: −size |v_rel|; Turn: −size |ω_rel|.
ex power(const Model& m, const Load& l);
/// Does it change with the motion (its value holds a coordinate or a rate)?
bool changes_with_motion(const Model& m, const Load& l);

/// A given impulse J at a point: it acts only in impacts.
struct Blow {
  PointRef at;
  ex Jx = 0, Jy = 0;
};

/// What an effect kind may ask of the scene builder while it reads its options: each call
/// checks its input and throws a SceneError naming the place and a fix.
class EffectReader {
public:
  virtual ~EffectReader() = default;
  virtual const Model& model() const = 0;
  /// The option `key` (throws when it is missing, with `example` in the fix).
  virtual const scene::Node& option(const scene::EffectDef& e, const std::string& key, const std::string& example) = 0;
  /// Refuse any key but these (and the kind's own key).
  virtual void only(const scene::EffectDef& e, std::vector<std::string> keys) = 0;
  virtual scene::Text text_of(const scene::Node& n, const std::string& key, const std::string& example) = 0;
  virtual PointRef point_ref(const scene::Node& n, const std::string& key) = 0;
  /// A contact party: a point, a body, or `ground`.
  virtual PointRef party(const scene::Node& n) = 0;
  virtual int body_ref(const scene::Node& n, const std::string& key) = 0;
  /// `KIND: body` or `KIND: [a, b]` (between two bodies): (body, body2 or −1).
  virtual std::pair<int, int> one_or_two_bodies(const scene::EffectDef& e, const std::string& what) = 0;
  /// `KIND: body.P`, or `KIND: body` with `at: [x, y]` (the body's material point at that place).
  virtual PointRef acting_point(const scene::EffectDef& e) = 0;
  /// An expression of parameters (or, with `geometry`, of coordinates and t too) of dimension `want`.
  virtual ex quantity(const scene::Text& t, bool geometry, const units::Dimension& want, const std::string& key,
                      const std::string& fix) = 0;
  /// A pair [x, y] of such expressions.
  virtual std::pair<ex, ex> vec(const scene::Node& n, const std::string& key, const units::Dimension& d, bool geometry,
                                const std::string& fix) = 0;
  /// Refuse a value that is not positive (or negative when `allow_zero`).
  virtual void positive(const ex& e, const SourcePos& pos, const std::string& what, bool allow_zero = false) = 0;
  virtual std::optional<GiNaC::numeric> value_of(const ex& e, const SourcePos& pos, const std::string& what) = 0;
  /// Where a value is written: a lone parameter's value, else `use`.
  virtual SourcePos value_place(const ex& e, const SourcePos& use) = 0;
  /// `direction: positive|negative` of a friction effect.
  virtual std::optional<int> direction_of(const scene::EffectDef& e) = 0;
  /// A new unknown impulse of the given dimension (a contact's, a constraint's reaction).
  virtual ex unknown(const std::string& name, const units::Dimension& d) = 0;
  /// A relation "lhs = rhs" between coordinates, checked (units, a coordinate in it, not already
  /// among `constraints:`) and added to the model's constraints: its index there.
  virtual std::size_t constraint(const scene::Text& t, const std::string& key) = 0;
  /// A relation c(q) = 0 an effect derives itself (a contact that stays closed: r_b − r_a = 0),
  /// added to the model's constraints: its index there.
  virtual std::size_t relation(const ex& c, const SourcePos& pos) = 0;
};

/// One effect of a scene. Defaults describe an effect that does nothing in that respect.
class Effect {
public:
  std::string name;
  std::string kind;  ///< the name it was registered under (for messages only)
  SourcePos pos;
  std::string label;  ///< `label:`: how figures name its force or couple (TeX), "" for the default
  /// Acts from state `on` to state `off` (indices in the order the states are listed; −1: from
  /// the first, to the last): a motor disconnected at 2, a brake applied from 2 on.
  int on = -1, off = -1;
  /// It has a potential V (`potential`), set by its kind: its work is −ΔV, its Q_i = −∂V/∂q_i (a
  /// support that does no work has V = 0).
  bool has_potential = false;

  /// How it acts over an analysis: throughout, not at all, or in part (switched inside it).
  enum class Activity { Whole, None, Part };
  Activity activity(const Analysis& a) const;
  /// The states bounding the part of analysis `a` where it acts (with Part: one of them is its
  /// switching state).
  std::pair<int, int> active_span(const Analysis& a) const;
  /// How it acts at one state (an instant): it acts there, it does not, or it switches there
  /// (on or off: its force jumps, so it has no one value there).
  enum class AtState { Acts, Not, Switches };
  AtState at_state(int s) const;

  virtual ~Effect() = default;

  // --- what it is: every principle derives what it needs from these -------------------------
  /// What it does to the bodies at a state (none: a support, a contact, a blow).
  virtual std::vector<Load> loads(const Model&) const { return {}; }
  /// V (generic), where it has one (`has_potential`; a support that does no work: 0).
  virtual ex potential(const Model&) const { return 0; }
  /// The unknown reaction of a support, or a contact's impulse (none for the rest).
  virtual std::optional<Reaction> reaction(const Model&) const { return std::nullopt; }
  /// A given impulse, for effects that are one.
  virtual const Blow* blow() const { return nullptr; }

  // --- what a kind may answer itself, when the general rule does not fit (said in its file) ---
  /// The work between two states (state symbols, `model/work.hpp`): from its loads by default
  /// (principles::load_work).
  virtual Work work(const Model& m, int s1, int s2, const Knowledge& k) const;
  /// Its work on the bodies of energy analysis `a` when it acts on some of them and on bodies
  /// outside too (a weight: the set's own; a reaction: its unknown average force times the
  /// distance its point moves along it). @throws SceneError when that work is not known.
  virtual Work work_across(const Model& m, const Analysis& a, const Knowledge& k) const;

  // --- derived, the same for every kind (src/effects/effect.cpp) -----------------------------
  bool conservative() const { return has_potential; }
  /// Q_i along coordinate i: −∂V/∂q_i for conservative effects, else from its loads.
  ex generalized_force(const Model& m, std::size_t i) const;
  /// P = Σ Q_i q̇_i (conservative: −dV/dt), else from its loads.
  ex power(const Model& m) const;
  /// The bodies it acts on (a fixed party is not a body; gravity: every body).
  std::vector<int> bodies_acted(const Model& m) const;
  /// A given impulse strikes once: at the first state of the earliest analysis (by that state)
  /// that takes blows (Analysis::takes_blows: an impact, a momentum analysis over a duration) and
  /// over which it acts. That state, or none (not a blow; no such analysis).
  std::optional<int> strike_state(const Model& m) const;
  /// Does it strike in analysis a (a blow, at a's first state)?
  bool strikes_in(const Model& m, const Analysis& a) const;
  /// Impulse (x, y) over analysis `ai` (`impulse_x`, `impulse_y`); `self` is this effect's index.
  /// @throws InputError when it has none there.
  std::pair<ex, ex> impulse(const Model& m, int self, int ai) const;
  /// `impulse(effect, S1, S2)`: the size of that impulse (a contact's: J, along its normal).
  ex impulse_size(const Model& m, int ai, const ex& x, const ex& y) const;
  /// The impulse this effect gives body `b` in impact `ai` (a contact's, a blow's), known
  /// or as unknowns: a pin's reaction is the momentum change less these.
  std::pair<ex, ex> impact_impulse_on(const Model& m, int b, int ai) const;
  /// Energy lost at this effect in impact `ai` (a contact). @throws InputError otherwise.
  ex impact_loss(const Model& m, int ai) const;

  // --- pictures ---
  /// Draw itself into a figure of the scene at a state (`at` gives numbers of expressions
  /// there): a pin as a joint, a spring as a zigzag, a force as an arrow … Nothing by default.
  virtual void draw(const Model& /*m*/, const draw::At& /*at*/, draw::Figure& /*f*/) const {}
  /// Check what it declares: with `state` −1, for every value of the coordinates, once every
  /// effect is read (the constraints complete); else at that solved state (`values`: state
  /// symbols and parameters → numbers). @throws SceneError when it does not hold (a point off its
  /// track).
  virtual void check(const Model&, int /*state*/, const GiNaC::exmap& /*values*/) const {}
};

/// The effects of a model, iterated as `const Effect&`.
class EffectList {
  using Vec = std::vector<std::shared_ptr<const Effect>>;

public:
  using const_iterator = boost::indirect_iterator<Vec::const_iterator, const Effect>;
  const_iterator begin() const { return v_.begin(); }
  const_iterator end() const { return v_.end(); }
  std::size_t size() const { return v_.size(); }
  bool empty() const { return v_.empty(); }
  const Effect& operator[](std::size_t i) const { return *v_[i]; }
  void push_back(std::shared_ptr<const Effect> e) { v_.push_back(std::move(e)); }

private:
  Vec v_;
};

/// One entry of the table of effect kinds: its name and how it reads its options.
struct EffectKind {
  std::string name;
  std::function<std::shared_ptr<Effect>(EffectReader&, const scene::EffectDef&)> read;
};

/// The table of effect kinds (src/effects/registry.cpp).
const std::vector<EffectKind>& effect_kinds();

}  // namespace kinergy::model
