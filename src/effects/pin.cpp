// A pin: two points that the coordinates keep together (a support the scene names, so that
// its reaction can be asked for). It does no work; its reaction is an unknown of a momentum
// analysis across it, and in an impact the pinned body's momentum change less the other impulses.
#include "common.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::effects {

namespace {

class Pin : public Effect {
public:
  PointRef a, b;
  std::vector<int> bodies_acted(const Model&) const override { return bodies_of({a.body, b.body}); }

  bool holds(int body) const override { return a.body == body || b.body == body; }

  bool reaction_across(const std::vector<int>& set) const override {
    auto in = [&](int x) { return x >= 0 && principles::in_set(set, x); };
    return in(a.body) != in(b.body);
  }

  /// The fixed line the point of the party inside `set` moves along: x ([1, 0]) or y ([0, 1]).
  std::optional<int> line_inside(const Model& m, const std::vector<int>& set) const {
    const PointRef& p = principles::in_set(set, a.body) ? a : b;
    auto [vx, vy] = m.velocity(p);
    const bool x = principles::vanishes(m, vy), y = principles::vanishes(m, vx);
    if (x == y) return std::nullopt;
    return x ? 0 : 1;
  }

  // across an energy analysis of a set whose pinned point moves along a fixed line (a collar on
  // its rod): the reaction's component along that line does the work, an unknown average force
  bool works_across(const Model& m, const std::vector<int>& set) const override {
    return reaction_across(set) && a.body >= 0 && b.body >= 0 && line_inside(m, set).has_value();
  }

  // U = F̄ Δs: F̄ the average force on the party inside along +x (or +y) over the distance, s that
  // coordinate of its point
  principles::Work work_across(const Model& m, const Analysis& an, const Knowledge&) const override {
    auto it = an.reactions.find(name);
    if (it == an.reactions.end() || !works_across(m, an.bodies))
      throw SceneError(an.pos, "pin '" + name + "' joins a body of this energy analysis to one outside it, and the pinned point does not "
                                   "keep to a fixed line (x or y): the work of its reaction is not one unknown force times a distance",
                       "list both bodies it joins in 'bodies', or take its reaction from an impulse-momentum analysis of the body");
    const PointRef& p = acts_on(an, a.body) ? a : b;
    const int line = *line_inside(m, an.bodies);
    auto [x, y] = m.position(p);
    const ex s = line == 0 ? x : y;
    principles::Work w;
    w.effect = name;
    w.U = it->second[0] * model::trig_simplify(m.bind(s, an.to) - m.bind(s, an.from));
    w.how = "U = F (average, on " + p.text + " along " + (line == 0 ? "x" : "y") + ") times the distance " + p.text + " moves along it";
    return w;
  }

  void pushes(const Model& m, const Analysis& an, const Knowledge&, std::vector<Push>& out) const override {
    bool ia = acts_on(an, a.body), ib = acts_on(an, b.body);
    if (ia == ib) return;  // internal, or not acting on the set
    auto it = an.reactions.find(name);
    if (it == an.reactions.end()) return;
    Push p;
    p.unknown = true;
    p.reaction = true;
    p.implied = true;
    p.Rx = it->second[0];
    p.Ry = it->second[1];
    auto [x, y] = m.position(ia ? a : b);
    p.arm_x = x;
    p.arm_y = y;
    out.push_back(p);
  }

  std::pair<ex, ex> impulse(const Model& m, int self, int ai) const override {
    const Analysis& an = m.analyses[ai];
    if (!an.instant) {
      auto it = an.reactions.find(name);
      if (it == an.reactions.end())
        throw InputError("pin '" + name + "' is not external to the bodies of the analysis between states " +
                             m.states[an.from].name + " and " + m.states[an.to].name,
                         "list in 'bodies' the body the pin holds, and not the body on its other side");
      return {it->second[0], it->second[1]};
    }
    // impact: the impulse on the pinned body = its momentum change minus the other impulses on it
    int bi = b.body >= 0 ? b.body : a.body;
    if (bi < 0) throw InputError("pin '" + name + "' joins no body", "pin a body point to a point");
    const model::Body& B = m.bodies[bi];
    for (auto& c : m.constraints)
      for (auto& co : m.coords)
        if (c.first.has(co.q) && (B.x.has(co.q) || B.y.has(co.q) || B.angle.has(co.q)))
          throw InputError("the impulse of pin '" + name + "' cannot be told apart from the constraint impulses on '" + B.name + "'",
                           "describe the body's motion with coordinates that need no constraint");
    for (std::size_t j = 0; j < m.effects.size(); ++j) {
      const Effect& o = m.effects[j];
      if (static_cast<int>(j) != self && o.holds(bi))
        throw InputError("body '" + B.name + "' has two pins, '" + name + "' and '" + o.name +
                             "'; their impulses cannot be told apart",
                         "ask for the impulse of a pin that holds a body alone");
    }
    // R = m (v̄⁺ − v̄⁻) − Σ P (contact impulses and given blows on the body)
    ex vx = m.rate(B.x), vy = m.rate(B.y);
    ex Rx = B.mass * (m.bind_mixed(vx, an.from, an.to) - m.bind(vx, an.from));
    ex Ry = B.mass * (m.bind_mixed(vy, an.from, an.to) - m.bind(vy, an.from));
    for (auto& o : m.effects) {
      auto [Px, Py] = o.impact_impulse_on(m, bi, ai);
      Rx -= Px;
      Ry -= Py;
    }
    return {Rx, Ry};
  }

  void motion(const Model&, int, simulate::Equations&) const override {}  // the coordinates keep the points together

  // a joint: a ring at the pinned point, on hatched ground when one side is a fixed point
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto [x, y] = at.point(m.position(b.body >= 0 ? b : a));
    f.circle(x, y, f.glyph() * 0.45, Ink::Support);
    if (a.body < 0 || b.body < 0) f.ground(x, y);
  }
};

// A pin declares that two points coincide for every value of the coordinates.
void check_pin(const Model& m, const Pin& e, const SourcePos& pos) {
  auto [xa, ya] = m.position(e.a);
  auto [xb, yb] = m.position(e.b);
  ex dx = model::trig_simplify(xa - xb), dy = model::trig_simplify(ya - yb);
  if (dx.is_zero() && dy.is_zero()) return;
  for (const GiNaC::exmap& at : random_positions(m, m.parameter_values(), 12345)) {
    ex gx, gy;
    try {
      gx = dx.subs(at).evalf();
      gy = dy.subs(at).evalf();
    } catch (const std::exception&) {
      continue;  // undefined at this sample position: try another
    }
    if (!GiNaC::is_a<GiNaC::numeric>(gx) || !GiNaC::is_a<GiNaC::numeric>(gy)) return;  // symbolic parameters: trust it
    // how far apart, in CLN's numbers (a point 1e400 m away is no double)
    const GiNaC::numeric& nx = GiNaC::ex_to<GiNaC::numeric>(gx);
    const GiNaC::numeric& ny = GiNaC::ex_to<GiNaC::numeric>(gy);
    const GiNaC::numeric d = GiNaC::sqrt(nx * nx + ny * ny);
    // apart, against the size of the positions themselves (a scene may be a millimetre across)
    if (!numerics::negligible(dx, at).value_or(true) || !numerics::negligible(dy, at).value_or(true))
      throw SceneError(pos, "pin '" + e.name + "': " + e.a.text + " and " + e.b.text +
                                " do not coincide (apart by " + numerics::format(d, 6) + " m at some position)",
                       "fix the body's position/angle or the point so the pinned points stay together");
  }
}

}  // namespace

std::shared_ptr<Effect> read_pin(EffectReader& r, const EffectDef& ed) {
  auto e = make<Pin>(ed);
  e->has_potential = true;  // V = 0: it does no work
  r.only(ed, {});
  std::tie(e->a, e->b) = two_points(r, ed, "a pin joins two points", "write 'pin: [O, bar.O]'");
  check_pin(r.model(), *e, ed.arg.pos);
  return e;
}

}  // namespace kinergy::effects
