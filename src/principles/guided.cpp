// Bodies the coordinates hold to a fixed straight line without turning (a block on a table, a
// slider in a straight guide), in moments about a point: the support that holds one is a force
// normal to its line and a couple, unknown, but fixed by the body's own Newton–Euler equations
// (m ā·n = 0 and Ī α = 0), so its moment about P follows from the other loads on the body.
#include <algorithm>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/principles/momentum.hpp"

namespace kinergy::principles {

using namespace GiNaC;
using model::Analysis;
using model::Effect;
using model::Load;
using model::Model;

namespace {

/// The line body b keeps to: u when its centre keeps to a line (centre_line) and the body does
/// not turn (or is a particle); nothing otherwise.
std::optional<Guided> line_of(const Model& m, int b) {
  const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
  if (!B.inertia.is_zero() && !motion_free(m, model::trig_simplify(B.angle))) return std::nullopt;
  auto c = centre_line(m, b);
  if (!c) return std::nullopt;
  return Guided{b, c->ux, c->uy};
}

/// The moment about P its support adds for a force F at Q (and a couple M) on guided body g:
/// the support's normal force −(F·n) n at G and couple −((r_Q − r̄) × F + M), so
///   ΔM_P = −(r̄ − r_P) × n (F·n) − (r_Q − r̄) × F − M.
ex support_share(const Model& m, const Guided& g, const ex& px, const ex& py, const ex& qx, const ex& qy, const ex& Fx,
                 const ex& Fy, const ex& M) {
  const model::Body& B = m.bodies[static_cast<std::size_t>(g.body)];
  const ex nx = -g.uy, ny = g.ux;
  return -cross(B.x - px, B.y - py, nx, ny) * (Fx * nx + Fy * ny) - cross(qx - B.x, qy - B.y, Fx, Fy) - M;
}


}  // namespace

std::optional<CentreLine> centre_line(const Model& m, int b) {
  const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
  if (B.x.has(m.t) || B.y.has(m.t) || B.angle.has(m.t)) return std::nullopt;
  std::optional<CentreLine> c;
  bool with_centre = false, alone = false;
  for (auto& co : m.coords) {
    const ex dx = model::trig_simplify(B.x.diff(co.q)), dy = model::trig_simplify(B.y.diff(co.q));
    const bool turns = !vanishes(m, model::trig_simplify(B.angle.diff(co.q)));
    if (vanishes(m, dx) && vanishes(m, dy)) {
      alone = alone || turns;
      continue;
    }
    with_centre = with_centre || turns;
    if (!c) {
      // u = ∂r̄/∂q / |∂r̄/∂q|, which must not change with the motion
      const ex len = sqrt(model::trig_simplify(dx * dx + dy * dy));
      const ex ux = model::trig_simplify(dx / len), uy = model::trig_simplify(dy / len);
      if (!motion_free(m, ux) || !motion_free(m, uy)) return std::nullopt;
      c = CentreLine{ux, uy};
    }
    if (!vanishes(m, cross(c->ux, c->uy, dx, dy))) return std::nullopt;
  }
  if (!c) return std::nullopt;  // held still: no line
  c->turns_with_centre = with_centre;
  c->turns_alone = alone;
  return c;
}

const Guided* find_guided(const std::vector<Guided>& gs, int b) {
  auto it = std::find_if(gs.begin(), gs.end(), [&](const Guided& g) { return g.body == b; });
  return it == gs.end() ? nullptr : &*it;
}

std::vector<Guided> guided_bodies(const Model& m, const Analysis& a) {
  std::vector<Guided> out;
  for (int b : a.bodies)
    if (auto g = line_of(m, b)) out.push_back(*g);
  return out;
}

ex guided_moment(const Model& m, const Guided& g, const ex& px, const ex& py, const ex& Fx, const ex& Fy) {
  // the force at Q and the support's share: (r_Q − r_P) × F + ΔM_P = (r̄ − r_P) × u (F·u)
  const model::Body& B = m.bodies[static_cast<std::size_t>(g.body)];
  return model::trig_simplify(cross(B.x - px, B.y - py, g.ux, g.uy) * (Fx * g.ux + Fy * g.uy));
}

void check_guided_interactions(const Model& m, const Analysis& a, const std::vector<Guided>& gs, const ex& px, const ex& py) {
  if (gs.empty()) return;
  const std::string P = a.about()->text;
  auto refuse = [&](const std::string& what, int b, const SourcePos& pos) {
    throw SceneError(pos, what + " pushes on '" + m.bodies[static_cast<std::size_t>(b)].name +
                              "' across its line (or with a moment about its mass centre): the support that holds it to its line then has a moment about " +
                              P + " the analysis cannot know",
                     "take moments about a point on the body's line of motion, use an energy analysis, or leave '" +
                         m.bodies[static_cast<std::size_t>(b)].name + "' out of 'bodies' (declare its support so that its reaction is an unknown)");
  };
  for (auto& e : m.effects) {
    if (e.activity(a) == Effect::Activity::None) continue;
    // a load inside the set (both ends in it): each guided end's support takes its part across
    // the line; those parts must cancel over the set
    ex share = 0;
    int guided_end = -1;
    for (const Load& l : e.loads(m)) {
      if (!inside(a, l.at) || !l.partner || !inside(a, *l.partner)) continue;
      model::Wrench w = model::force_of(m, l);
      if (l.kind == Load::Kind::Slide) std::tie(w.Fx, w.Fy) = model::relative_velocity(m, l);  // its line (its sense does not matter here)
      if (l.kind == Load::Kind::Turn) w.M = 1;
      const auto [ax, ay] = m.position(l.at);
      const auto [bx, by] = l.kind == Load::Kind::Slide ? std::pair<ex, ex>{ax, ay} : m.position(*l.partner);
      if (const Guided* g = find_guided(gs, l.at.body)) {
        share += support_share(m, *g, px, py, ax, ay, w.Fx, w.Fy, w.M);
        guided_end = g->body;
      }
      if (const Guided* g = find_guided(gs, l.partner->body)) {
        share += support_share(m, *g, px, py, bx, by, -w.Fx, -w.Fy, -w.M);
        guided_end = g->body;
      }
    }
    if (guided_end >= 0 && !vanishes(m, share)) refuse("effect '" + e.name + "'", guided_end, e.pos);
    // a support between two bodies of the set: its force on a guided one is unknown
    if (auto r = e.reaction(m); r && r->kind != model::Reaction::Kind::Contact && inside(a, r->a) && inside(a, r->b))
      for (const model::PointRef* p : {&r->a, &r->b})
        if (const Guided* g = find_guided(gs, p->body)) {
          const auto [qx, qy] = m.position(*p);
          const bool pin = r->kind == model::Reaction::Kind::Pin;
          for (int k = 0; k < (pin ? 2 : 1); ++k) {
            const ex Fx = pin ? ex(k == 0 ? 1 : 0) : r->dir_x, Fy = pin ? ex(k == 0 ? 0 : 1) : r->dir_y;
            if (!vanishes(m, support_share(m, *g, px, py, qx, qy, Fx, Fy, 0))) refuse("the reaction of '" + e.name + "'", g->body, e.pos);
          }
        }
  }
  // a relation under 'constraints:' between bodies of the set (a cord): its pull on a guided body
  // is taken along the line through the mass centre, which holds only where the relation is
  // linear in the coordinates that move the body (a cord parallel to the line)
  for (std::size_t ci = 0; ci < m.constraints.size(); ++ci) {
    const auto& [c, pos] = m.constraints[ci];
    if (m.carrier(ci) || m.constraint_activity(ci, a) == Effect::Activity::None) continue;
    for (const Guided& g : gs) {
      const model::Body& B = m.bodies[static_cast<std::size_t>(g.body)];
      for (auto& co : m.coords) {
        if (!B.x.has(co.q) && !B.y.has(co.q)) continue;
        if (!c.has(co.q) || motion_free(m, model::trig_simplify(c.diff(co.q)))) continue;
        throw SceneError(pos, "the constraint '" + model::text(c) + " = 0' pulls on '" + B.name +
                                  "' in a direction that changes with the motion (it is not linear in " + co.name +
                                  "), so the support that holds it to its line has a moment about " + P + " the analysis cannot know",
                         "take moments about a point on its line of motion, or use an energy analysis");
      }
    }
  }
}

void check_internal_pairs(const Model& m, const Analysis& a) {
  for (auto& e : m.effects) {
    auto r = e.reaction(m);
    if (!r || r->kind != model::Reaction::Kind::Relation || !inside(a, r->a) || !inside(a, r->b) || e.activity(a) == Effect::Activity::None) continue;
    // J û on a at r_a, −J û on b at r_b: their moments cancel about every point only when
    // (r_a − r_b) × û = 0
    const auto [ax, ay] = m.position(r->a);
    const auto [bx, by] = m.position(r->b);
    if (vanishes(m, cross(ax - bx, ay - by, r->dir_x, r->dir_y))) continue;
    throw SceneError(e.pos, "the force of '" + e.name + "' acts along [" + model::text(r->dir_x) + ", " + model::text(r->dir_y) + "] at " +
                                r->a.text + " and at " + r->b.text + ", which are not on one line along it: the pair would have a moment of its own about " +
                                a.about()->text,
                     "give in 'at' places on the line it pulls along (a cord's two ends), or use an energy analysis");
  }
}

}  // namespace kinergy::principles
