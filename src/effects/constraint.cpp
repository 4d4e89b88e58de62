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
  ex fx = 0, fy = 0;      ///< F = λ f on party a, the first that is a body (generic)
  ex ux = 0, uy = 0;      ///< ±f / |f| up (or along +x): the direction J and F are counted along
  ex mu_s = 0;            ///< static friction that holds it: |F| ≤ μ_s |N| (0: none stated)
  ex mu_k = -1;           ///< kinetic friction once it slips (a simulation's sliding; −1: not said)
  std::string normal;     ///< the track effect whose normal force N presses the parties together
  SourcePos limit_pos;

  // the relation: its parties' places (a mesh's pitch circles, a cord between them), named
  void draw(const Model& m, const At& at, Figure& f) const override {
    // a party that is a body's material point at a place (a mesh's pitch point, a rolling contact):
    // the circle round that body's centre through it — a gear's pitch circle, a wheel's rolling circle
    for (const PointRef* p : {&a, &b}) {
      if (p->body < 0 || !p->world_place) continue;
      const model::Body& B = m.bodies[static_cast<std::size_t>(p->body)];
      auto [px, py] = at.point(m.position(*p));
      const double gx = at(B.x), gy = at(B.y), r = std::hypot(px - gx, py - gy);
      if (std::isfinite(r) && r > 0 && !f.has_circle(gx, gy, r)) f.circle(gx, gy, r, Ink::Track);
      // the place itself: where the parts touch (the surface under it is drawn from the kinematics;
      // not named, as a textbook draws a mesh or a rolling contact)
      if (std::isfinite(px) && std::isfinite(py)) f.circle(px, py, 0.25 * f.glyph(), Ink::Support, true);
    }
    // between two places of the parties (a cord from a drum's rim to a block): the cord, solid
    if (auto p = joined(m, at, a, b)) {
      const auto [x1, y1, x2, y2] = *p;
      f.line(x1, y1, x2, y2, Ink::Cord);
    }
  }

  // J û on party a, −J û on party b: the force of the relation's multiplier, λ f
  std::optional<model::Reaction> reaction(const Model&) const override {
    model::Reaction r = model::Reaction::relation(a, b, ux, uy, fx, fy, index);
    r.mu_s = mu_s;
    r.mu_k = mu_k;
    r.normal = normal;
    r.limit_pos = limit_pos;
    return r;
  }

  // `normal` names a track effect that pushes on a body of this relation (its normal force N is
  // what static friction μ_s |N| is measured against)
  void check(const Model& m, int state, const GiNaC::exmap&) const override {
    if (state != -1 || normal.empty()) return;
    const int i = m.effect_index(normal);
    const auto r = i >= 0 ? m.effects[static_cast<std::size_t>(i)].reaction(m) : std::nullopt;
    if (!r || r->kind != model::Reaction::Kind::Track)
      throw SceneError(limit_pos, "constraint '" + name + "': 'normal: " + normal + "' " + (i < 0 ? "names no effect" : "is not a track") +
                                      ": μ_s is measured against the normal force of the surface the parts roll on",
                       "name the track effect of that surface (e.g. 'floor: {track: disk, line: {through: [0, r], along: [1, 0]}}', then "
                       "'normal: floor')");
    for (int b : r->bodies())
      if (b == a.body || b == this->b.body) return;
    throw SceneError(limit_pos, "constraint '" + name + "': track '" + normal + "' holds " + r->a.text + ", which is not a party of '" + name + "' (" +
                                    a.text + ", " + this->b.text + ")",
                     "name the track of the surface under the rolling body");
  }
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
  r.only(ed, {"between", "at", "mu_s", "normal", "mu_k"});
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
  // the sign rule (docs/scene-format.md, "Signs of forces"): the force reported is the one on the
  // first party that is a body (λ f on a, so a fixed first party changes places with the body:
  // −λ f on it), counted along û = ±f/|f| taken up (or, horizontal, along +x) — what the
  // relation's sign, as written, does not change
  if (e->a.body < 0 || e->a.ground) {
    std::swap(e->a, e->b);
    e->fx = -e->fx;
    e->fy = -e->fy;
  }
  ex f2 = model::trig_simplify(e->fx * e->fx + e->fy * e->fy);
  ex f = model::root_simplify(sqrt(f2));
  const int sense = axis_sense(m, e->fx / f, e->fy / f);
  e->ux = model::trig_simplify(sense * e->fx / f);
  e->uy = model::trig_simplify(sense * e->fy / f);
  // static friction that keeps it (a rolling contact): |F| ≤ μ_s |N|, N of a named track
  const scene::Node* mu = ed.options.get("mu_s");
  const scene::Node* nn = ed.options.get("normal");
  if (mu || nn) {
    if (!mu || !nn)
      throw SceneError((mu ? mu : nn)->pos, "constraint '" + ed.name + "': 'mu_s' and 'normal' go together",
                       "give both: 'mu_s: 0.3, normal: floor' (the coefficient of static friction, and the track whose normal force it multiplies)");
    e->mu_s = non_negative(r, ed, "mu_s", "0.3", Dimension{}, "a friction coefficient is a pure number", "the coefficient of static friction");
    if (e->mu_s.is_zero())
      throw SceneError(mu->pos, "constraint '" + ed.name + "': mu_s = 0 holds no friction, so nothing rolls without slipping",
                       "give the coefficient of static friction (> 0), or leave 'mu_s' out (no limit checked)");
    if (!nn->is_scalar() || nn->scalar.empty())
      throw SceneError(nn->pos, "constraint '" + ed.name + "': 'normal' names a track effect", "write 'normal: floor'");
    e->normal = nn->scalar;
    e->limit_pos = mu->pos;
  }
  if (const scene::Node* mk = ed.options.get("mu_k")) {
    // μ_k: the friction once the contact slips, −μ_k N against the slip (only a simulation goes on past a slip)
    if (!mu)
      throw SceneError(mk->pos, "constraint '" + ed.name + "': 'mu_k' is the friction once a rolling contact slips, and nothing says when it slips",
                       "give 'mu_s' and 'normal' with it (the static friction that holds it, and the track whose normal force it multiplies)");
    e->mu_k = non_negative(r, ed, "mu_k", "0.25", Dimension{}, "a friction coefficient is a pure number", "the coefficient of kinetic friction");
  }
  return e;
}

}  // namespace kinergy::effects
