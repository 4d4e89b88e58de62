// A constraint held by a named interaction — a gear mesh, a cord, rolling without slipping: a
// relation c(q) = 0 between coordinates and the two parties whose touching keeps it. Over the
// whole system its force does no work (it is one of the constraints); across a body set it is
// the force between the set and the rest, an unknown the analysis solves for and a result can
// ask for (`impulse(mesh, 1, 2)`).
//
// Its force is what the relation's multiplier λ stands for: a force F on the first party at its
// point, −F on the second at its point, whose virtual work is λ δc:
//   F·(∂r_A/∂q_i − ∂r_B/∂q_i) = λ ∂c/∂q_i   for every coordinate q_i.
// With D_i = ∂r_A/∂q_i − ∂r_B/∂q_i, F = λ f where D_i·f = ∂c/∂q_i for every i, least in norm
// (a part of the force along which neither point moves relative to the other does no work and
// cannot be told from the equations: it is taken as zero, a support takes it). The relation is
// held by such a force only when D_i·f = ∂c/∂q_i for every i: checked, naming the parties.
#include <cmath>
#include <optional>

#include "common.hpp"

namespace kinergy::effects {

namespace {

class Constraint : public Effect {
public:
  PointRef a, b;
  std::size_t index = 0;  ///< in the model's constraints
  ex fx = 0, fy = 0;      ///< F = λ f on party a (generic)
  ex ux = 0, uy = 0;      ///< f / |f|: the direction J is measured along

  // the relation: a dashed link between its parties' places (a mesh, a cord), named
  void draw(const Model& m, const At& at, Figure& f) const override {
    // a party that is a body's material point at a place (a mesh's pitch point, a rolling contact):
    // the circle round that body's centre through it — a gear's pitch circle, a wheel's rolling circle
    for (const PointRef* p : {&a, &b}) {
      if (p->body < 0 || !p->world_place) continue;
      const model::Body& B = m.bodies[static_cast<std::size_t>(p->body)];
      auto [px, py] = at.point(m.position(*p));
      const double gx = at(B.x), gy = at(B.y), r = std::hypot(px - gx, py - gy);
      if (std::isfinite(r) && r > 0) f.circle(gx, gy, r, Ink::Track);
    }
    if (auto p = joined(m, at, a, b)) {
      const auto [x1, y1, x2, y2] = *p;
      f.line(x1, y1, x2, y2, Ink::Hidden);
      f.label((x1 + x2) / 2, (y1 + y2) / 2, name);
    }
  }
  std::vector<int> bodies_acted(const Model&) const override { return bodies_of({a.body, b.body}); }

  bool carries(std::size_t k) const override { return k == index; }

  bool reaction_across(const std::vector<int>& set) const override {
    auto in = [&](int x) { return x >= 0 && principles::in_set(set, x); };
    return in(a.body) != in(b.body);
  }
  std::vector<std::string> reaction_parts() const override { return {"J"}; }

  /// How its impulse is named in a derivation: on which party, along which direction.
  std::string along(bool on_a) const {
    const PointRef& p = on_a ? a : b;
    return "on " + p.text + ", along " + (on_a ? "" : "-") + "[" + model::text(ux) + ", " + model::text(uy) + "]";
  }

  void pushes(const Model& m, const Analysis& an, const Knowledge&, std::vector<Push>& out) const override {
    bool ia = acts_on(an, a.body), ib = acts_on(an, b.body);
    if (ia == ib) return;  // internal to the set, or not acting on it
    auto it = an.reactions.find(name);
    if (it == an.reactions.end()) return;
    // on party a: J û; on party b: −J û
    ex J = ia ? it->second[0] : -it->second[0];
    Push p;
    p.unknown = true;
    p.reaction = true;
    p.Rx = J * ux;
    p.Ry = J * uy;
    auto [x, y] = m.position(ia ? a : b);
    p.arm_x = x;
    p.arm_y = y;
    p.what = "reaction impulse (unknown) " + along(ia);
    out.push_back(p);
  }

  std::pair<ex, ex> impulse(const Model& m, int, int ai) const override {
    const Analysis& an = m.analyses[ai];
    if (an.instant) {
      // the impulsive reaction λ of the relation: Λ f on party a
      const ex& lam = an.lambdas.at(index);
      return {lam * m.bind(fx, an.from), lam * m.bind(fy, an.from)};
    }
    auto it = an.reactions.find(name);
    if (it == an.reactions.end())
      throw InputError("constraint '" + name + "' does not join the bodies of the analysis between states " + m.states[an.from].name +
                           " and " + m.states[an.to].name + " to the rest",
                       "list in 'bodies' one of its parties (" + a.text + ", " + b.text + ") and not the other");
    if (!principles::motion_free(m, ux) || !principles::motion_free(m, uy))
      throw InputError("the force of constraint '" + name + "' turns with the motion (along [" + model::text(ux) + ", " +
                           model::text(uy) + "]), so its impulse has no components fixed by the analysis",
                       "ask for its impulse in an impact, or for the angular impulse it gives");
    return {it->second[0] * ux, it->second[0] * uy};
  }

  bool works_across(const Model&, const std::vector<int>& set) const override { return reaction_across(set); }

  // Its work on the set: the force F̄ û on the party inside (−F̄ û for the second party), at its
  // point P: U = F̄ ∫ ±û·dr_P, F̄ the average force over the distance, an unknown. As generalized
  // forces per unit F̄: Q_i = ±û·∂r_P/∂q_i.
  principles::Work work_across(const Model& m, const Analysis& an, const Knowledge&) const override {
    bool ia = acts_on(an, a.body);
    auto it = an.reactions.find(name);
    if (it == an.reactions.end()) throw std::logic_error("constraint '" + name + "' has no unknown in this energy analysis");
    const PointRef& p = ia ? a : b;
    ex sign = ia ? 1 : -1;
    std::vector<ex> Q;
    for (auto& co : m.coords) {
      auto [dx, dy] = m.position_derivative(p, co.q);
      Q.push_back(model::trig_simplify(sign * (ux * dx + uy * dy)));
    }
    principles::Work w = principles::generalized_force_work(m, *this, Q, "constraint force", "", an.from, an.to);
    w.U = it->second[0] * w.U;
    w.how = "U = F (average) times the distance " + p.text + " moves along " + (ia ? "" : "-") + "[" + model::text(ux) + ", " +
            model::text(uy) + "]";
    return w;
  }

  void motion(const Model&, int, simulate::Equations&) const override {}  // the relation is among the constraints
};

/// A party named by a bare body name, to be placed at `at`.
bool bare_body(const Model& m, const PointRef& p) { return p.body >= 0 && !p.world_place && p.text == m.bodies[p.body].name; }

void place(EffectReader& r, PointRef& p, const scene::Node& at) {
  const Model& m = r.model();
  if (p.body < 0) return;  // the ground or a fixed point: it does not move, its place does not matter
  if (!bare_body(m, p))
    throw SceneError(at.pos, "'at' places a party named by its body, but '" + p.text + "' is already a point",
                     "name the body alone in 'between' (" + m.bodies[p.body].name + "), or leave 'at' out");
  auto [wx, wy] = r.vec(at, "at", units::Dimension::length(), true, "a place is a pair of lengths (it may move: [x, 0])");
  p.world_place = true;
  p.wx = wx;
  p.wy = wy;
  p.text = m.bodies[p.body].name + " at [" + at.items[0].scalar + ", " + at.items[1].scalar + "]";  // as written
}

}  // namespace

std::shared_ptr<Effect> read_constraint(EffectReader& r, const EffectDef& ed) {
  auto e = make<Constraint>(ed);
  e->has_potential = true;  // V = 0: workless on the whole system
  r.only(ed, {"between", "at"});
  const Model& m = r.model();
  scene::Text rel = r.text_of(ed.arg, "constraint", "\"rA*phiA + rB*phiB = 0\"");
  const scene::Node& bn = r.option(ed, "between", "[gearA, gearB]");
  if (!bn.is_list() || bn.items.size() != 2)
    throw SceneError(bn.pos, "a constraint acts between two parties",
                     "write 'between: [gearA, gearB]' (bodies, body points, fixed points or ground)");
  e->a = r.party(bn.items[0]);
  e->b = r.party(bn.items[1]);
  if (e->a.body < 0 && e->b.body < 0)
    throw SceneError(bn.pos, "constraint '" + ed.name + "' joins two fixed parties", "name at least one body in 'between'");
  if (const scene::Node* at = ed.options.get("at")) {
    bool two = at->is_list() && at->items.size() == 2 && at->items[0].is_list();
    place(r, e->a, two ? at->items[0] : *at);
    place(r, e->b, two ? at->items[1] : *at);
  }
  e->index = r.constraint(rel, "constraint");
  const ex c = m.constraints[e->index].first;

  // f with F = λ f from the rows D_i·f = ∂c/∂q_i: two independent rows fix it (Cramer); when all
  // rows are along one line û, f = ∂c/∂q_i D_i/|D_i|² from any nonzero row (least norm: no part
  // across that line). Row by row, so that each stays in one unit.
  auto dr = [&](const PointRef& p, const GiNaC::symbol& q) -> std::pair<ex, ex> {
    if (p.body < 0) return {0, 0};
    return m.position_derivative(p, q);
  };
  std::vector<std::pair<ex, ex>> D;
  std::vector<ex> dc;
  for (auto& co : m.coords) {
    auto [ax, ay] = dr(e->a, co.q);
    auto [qx, qy] = dr(e->b, co.q);
    D.push_back({model::trig_simplify(ax - qx), model::trig_simplify(ay - qy)});
    dc.push_back(c.diff(co.q));
  }
  const std::string parties = e->a.text + " and " + e->b.text;
  std::optional<std::size_t> first;
  bool found = false;
  for (std::size_t i = 0; i < D.size() && !found; ++i) {
    if (principles::vanishes(m, D[i].first) && principles::vanishes(m, D[i].second)) continue;
    if (!first) {
      first = i;
      continue;
    }
    const auto& [Dix, Diy] = D[*first];
    const auto& [Djx, Djy] = D[i];
    ex det = model::trig_simplify(Dix * Djy - Diy * Djx);
    if (principles::vanishes(m, det)) continue;
    e->fx = (dc[*first] * Djy - dc[i] * Diy) / det;
    e->fy = (Dix * dc[i] - Djx * dc[*first]) / det;
    found = true;
  }
  if (!first)
    throw SceneError(bn.pos, "constraint '" + ed.name + "': " + parties + " never move relative to each other, so no force between them holds '" + rel.s + "'",
                     "name in 'between' (and 'at') the two parts whose contact keeps the relation");
  if (!found) {
    const auto& [Dx, Dy] = D[*first];
    e->fx = dc[*first] * Dx / (Dx * Dx + Dy * Dy);
    e->fy = dc[*first] * Dy / (Dx * Dx + Dy * Dy);
  }
  e->fx = model::trig_simplify(e->fx);
  e->fy = model::trig_simplify(e->fy);
  for (std::size_t i = 0; i < D.size(); ++i)
    if (!principles::vanishes(m, e->fx * D[i].first + e->fy * D[i].second - dc[i]))
      throw SceneError(bn.pos, "constraint '" + ed.name + "': no force between " + parties + " holds '" + rel.s +
                                   "' (along " + m.coords[i].name + " its work does not match the relation)",
                       "give in 'at' the place where the parts touch (the pitch point of a mesh, the contact point of a rolling body, "
                       "where a cord leaves a drum)");
  ex f2 = model::trig_simplify(e->fx * e->fx + e->fy * e->fy);
  ex f = model::root_simplify(sqrt(f2));
  e->ux = model::trig_simplify(e->fx / f);
  e->uy = model::trig_simplify(e->fy / f);
  return e;
}

}  // namespace kinergy::effects
