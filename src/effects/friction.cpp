// Kinetic friction μN at a sliding point (a known normal force), against the sliding — on the
// ground, or between two bodies (`against: body`: a block sliding on a moving cart), where it
// opposes the slip of the one over the other and acts on each, equal and opposite.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Friction : public Effect {
public:
  PointRef a;
  std::optional<PointRef> b;  ///< the other body's material point at the same place (`against`)
  ex mu = 0, normal = 0;
  std::optional<int> direction;  ///< the sign of the motion it opposes, if declared

  // a short hatched stroke at the sliding point along its slip (the slip at unit rates of the
  // coordinates; along x when that is zero), named
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto [x, y] = at.point(m.position(a));
    At unit = at;
    for (auto& c : m.coords) unit.values[c.qd] = 1;
    auto [sx, sy] = slip(m);
    double ux = unit(sx), uy = unit(sy), u = std::hypot(ux, uy);
    if (!(u > 0)) ux = 1, uy = 0, u = 1;
    ux /= u, uy /= u;
    const double g = f.glyph();
    f.line(x - 2 * g * ux, y - 2 * g * uy, x + 2 * g * ux, y + 2 * g * uy, Ink::Support);
    for (int i = 0; i < 5; ++i) {
      const double bx = x + (i - 2) * g * ux, by = y + (i - 2) * g * uy;
      f.line(bx, by, bx - 0.4 * g * ux + 0.5 * g * uy, by - 0.4 * g * uy - 0.5 * g * ux, Ink::Support);
    }
    f.label(x, y, name);
  }
  std::vector<int> bodies_acted(const Model&) const override { return b ? bodies_of({a.body, b->body}) : bodies_of({a.body}); }

  /// The slip: v_rel = v_A − v_B (B the other body's material point there; the ground: 0).
  std::pair<ex, ex> slip(const Model& m) const {
    auto [vx, vy] = m.velocity(a);
    if (!b) return {vx, vy};
    auto [ux, uy] = m.velocity(*b);
    return {vx - ux, vy - uy};
  }

  ex power(const Model& m) const override {
    // P = −μ N |v_rel|: F·v_A on the one plus (−F)·v_B on the other
    auto [vx, vy] = slip(m);
    return -mu * normal * sqrt(model::trig_simplify(vx * vx + vy * vy));
  }

  principles::Work work(const Model& m, int s1, int s2, const Knowledge& k) const override {
    // a slip along a fixed line that is the rate of a function of the coordinates: U = −μN σ Δf
    auto [sx, sy] = slip(m);
    const bool along_x = principles::vanishes(m, sy), along_y = principles::vanishes(m, sx);
    if (along_x != along_y)
      if (auto w = principles::exact_slip_work(m, *this, direction, mu * normal, along_x ? sx : sy,
                                               "U = -mu N * distance slid" + std::string(b ? " (of one body over the other)" : ""), s1, s2, k))
        return *w;
    // distance slid: dℓ/ds = |∂r_P/∂s|, the velocity at ṡ = 1 with the others following
    auto slid = [&](const principles::Path& p) {
      const GiNaC::symbol& s = m.coords[p.s].q;
      auto [x, y] = slip(m);
      GiNaC::exmap rates;
      for (std::size_t j = 0; j < m.coords.size(); ++j) {
        ex qj = j == p.s ? ex(s) : m.coords[j].q.subs(p.q_of_s);
        rates[m.coords[j].qd] = qj.diff(s);
      }
      ex vx = x.subs(rates).subs(p.q_of_s), vy = y.subs(rates).subs(p.q_of_s);
      return sqrt(model::trig_simplify(vx * vx + vy * vy));
    };
    return principles::friction_work(m, *this, direction, mu * normal, slid, "U = -mu N * distance", s1, s2, k);
  }

  // across an energy analysis of a set holding one of the two bodies: the work of the friction on
  // that body, −μN σ ê on A (σ the sign of the slip along its line ê), +μN σ ê on B's material
  // point under A: U = ∓μN σ Δg with dg/dt = v·ê of that point
  principles::Work work_across(const Model& m, const Analysis& an, const Knowledge& k) const override {
    const bool on_a = acts_on(an, a.body);
    auto [sx, sy] = slip(m);
    const bool along_x = principles::vanishes(m, sy), along_y = principles::vanishes(m, sx);
    auto [vx, vy] = on_a ? m.velocity(a) : m.velocity(*b);
    std::optional<principles::Work> w;
    if (along_x != along_y)
      w = principles::exact_slip_work(m, *this, direction, (on_a ? 1 : -1) * mu * normal, along_x ? sx : sy,
                                      "U = " + std::string(on_a ? "-" : "") + "mu N * distance " + (on_a ? a.text : b->text) +
                                          " moves along the slip",
                                      an.from, an.to, k, along_x ? vx : vy);
    if (!w)
      throw SceneError(pos, "friction '" + name + "' acts between a body of this energy analysis and one outside it, and its work on " +
                                (on_a ? a.text : b->text) + " cannot be taken: its slip is not along a fixed line, or the distance "
                                "moved along it is not a function of the coordinates",
                       "analyse both bodies together, or use an impulse-momentum analysis of the one");
    return *w;
  }

  /// The friction force on A over analysis an: −μN û, û the direction of A's slip (over B) along
  /// its fixed line at the first state.
  std::pair<ex, ex> force_on_a(const Model& m, const Analysis& an, const Knowledge& k,
                               std::vector<principles::Condition>* holds = nullptr) const {
    auto [vx, vy] = slip(m);
    bool x0 = principles::vanishes(m, vy), y0 = principles::vanishes(m, vx);
    if (x0 && !y0) return {-mu * normal * principles::motion_direction(m, *this, direction, vx, an, k, "sliding", holds), 0};
    if (y0 && !x0) return {0, -mu * normal * principles::motion_direction(m, *this, direction, vy, an, k, "sliding", holds)};
    throw SceneError(pos, "friction '" + name + "' slides along a changing direction; its impulse needs the motion in time",
                     "use friction whose contact slides along a fixed line (x or y)");
  }

  void pushes(const Model& m, const Analysis& an, const Knowledge& k, std::vector<Push>& out) const override {
    const bool on_a = acts_on(an, a.body), on_b = b && acts_on(an, b->body);
    if (!on_a && !on_b) return;
    if (on_a && on_b) return;  // between two bodies of the set: equal and opposite at one place
    // kinetic friction −μN û on A against its slip over B at the first state (+μN û on B)
    Push p;
    auto [Fx, Fy] = force_on_a(m, an, k, &p.holds);
    const int sign = on_a ? 1 : -1;
    p.Fx = sign * Fx;
    p.Fy = sign * Fy;
    auto [x, y] = m.position(a);
    p.arm_x = x;
    p.arm_y = y;
    out.push_back(p);
  }

  // ∫F dt on A over a momentum analysis: the constant −μN û times t₂ − t₁
  std::pair<ex, ex> impulse(const Model& m, int self, int ai) const override {
    const Analysis& an = m.analyses[static_cast<std::size_t>(ai)];
    if (an.instant) return Effect::impulse(m, self, ai);
    auto [Fx, Fy] = force_on_a(m, an, Knowledge(m));
    return force_impulse(m, *this, Fx, Fy, an);
  }

  void motion(const Model& m, int self, simulate::Equations& eq) const override {
    // the slip velocity of the material point under the friction (over the other body's): the
    // force −μN û on A and +μN û on B give Q = −μN (∂v_rel/∂q̇)ᵀ û
    auto [vx, vy] = slip(m);
    eq.friction.push_back({self, false, simulate::linear_rate(m, vx), simulate::linear_rate(m, vy), mu * normal});
  }
};

}  // namespace

std::shared_ptr<Effect> read_friction(EffectReader& r, const EffectDef& ed) {
  auto e = make<Friction>(ed);
  r.only(ed, {"mu", "normal", "at", "direction", "against"});
  e->a = r.acting_point(ed);
  if (auto* other = ed.options.get("against")) {
    // the other body's material point at the same place
    PointRef b;
    b.body = r.body_ref(*other, "against");
    if (b.body == e->a.body)
      throw SceneError(other->pos, "friction '" + ed.name + "' acts against the body it slides with", "name the other body it slides on");
    auto [x, y] = r.model().position(e->a);
    b.world_place = true;
    b.wx = x;
    b.wy = y;
    b.text = other->scalar + " under " + e->a.text;
    e->b = b;
  }
  e->mu = non_negative(r, ed, "mu", "mu_k", Dimension{}, "a friction coefficient is a pure number", "the friction coefficient");
  e->normal = non_negative(r, ed, "normal", "m*g", force_dim(), "a normal force is in N (or lb)", "the normal force");
  e->direction = r.direction_of(ed);
  return e;
}

}  // namespace kinergy::effects
