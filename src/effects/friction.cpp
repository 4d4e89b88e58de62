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
    // rubbing at a body's mass centre (a block drawn round it): the stroke on the body's edge on the
    // ground's side — the normal to the slip that points down (or left on an upright slip)
    if (a.body >= 0 && !a.world_place && a.lx.is_zero() && a.ly.is_zero() && (!b || b->body < 0)) {
      double nx = uy, ny = -ux;
      if (ny > 1e-9 || (std::fabs(ny) <= 1e-9 && nx > 0)) nx = -nx, ny = -ny;
      const double edge = f.reach("body " + m.bodies[static_cast<std::size_t>(a.body)].name, x, y, nx, ny);
      x += nx * edge, y += ny * edge;
    }
    f.line(x - 2 * g * ux, y - 2 * g * uy, x + 2 * g * ux, y + 2 * g * uy, Ink::Support);
    for (int i = 0; i < 5; ++i) {
      const double bx = x + (i - 2) * g * ux, by = y + (i - 2) * g * uy;
      f.line(bx, by, bx - 0.4 * g * ux + 0.5 * g * uy, by - 0.4 * g * uy - 0.5 * g * ux, Ink::Support);
    }
    const draw::Name mu_k = value_label(mu, "\u03bc");
    f.label(x, y, mu_k.text, mu_k.text == "\u03bc" ? "\\mu" : mu_k.tex);
  }

  // μN at A against its slip over B (or the ground), −that on B
  std::vector<model::Load> loads(const Model&) const override {
    model::Load l;
    l.kind = model::Load::Kind::Slide;
    l.at = a;
    l.partner = b;
    l.size = mu * normal;
    l.direction = direction;
    l.symbol = load_symbol(*this, "F");  // a friction force (or its label)
    return {l};
  }

  /// The slip: v_rel = v_A − v_B (B the other body's material point there; the ground: 0), as
  /// its load's relative velocity.
  std::pair<ex, ex> slip(const Model& m) const { return model::relative_velocity(m, loads(m).front()); }

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
