// What the principles derive from an effect's loads, once for every kind: the work between two
// states, the pushes on a body set over a duration, and the impulse ∫F dt.
#include <algorithm>
#include <tuple>

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

/// Is body b (≥ 0) in the analysis' set?
bool on_set(const Analysis& a, int b) { return b >= 0 && in_set(a.bodies, b); }

/// The side of a load on the set: +1 its own body there, −1 only its partner's, 0 neither or both
/// (an interaction inside the set: equal and opposite, along one line).
int side_on(const Analysis& a, const Load& l) {
  const bool on = on_set(a, l.at.body), pon = l.partner && on_set(a, l.partner->body);
  return on == pon ? 0 : on ? 1 : -1;
}

/// The direction of a kinetic friction force on its point over analysis a: −size û, û the slip's
/// fixed line (x or y) in the sense of the motion at the first state (or declared).
std::pair<ex, ex> sliding_force(const Model& m, const Effect& e, const Load& l, const Analysis& a, const Knowledge& k,
                                std::vector<Condition>* holds) {
  auto [vx, vy] = model::relative_velocity(m, l);
  const bool x0 = vanishes(m, vy), y0 = vanishes(m, vx);
  if (x0 && !y0) return {-l.size * motion_direction(m, e, l.direction, vx, a, k, "sliding", holds), 0};
  if (y0 && !x0) return {0, -l.size * motion_direction(m, e, l.direction, vy, a, k, "sliding", holds)};
  throw SceneError(e.pos, "friction '" + e.name + "' slides along a changing direction; its impulse needs the motion in time",
                   "use friction whose contact slides along a fixed line (x or y)");
}

/// ∫_{t₁}^{t₂} f dt over analysis a (a result's impulse: refused as an input).
ex over_time(const Model& m, const Effect& e, const ex& f, const Analysis& a) {
  auto I = over_duration(m, f, a);
  if (!I) throw InputError("the impulse of '" + e.name + "' has no closed form in t", "use an elementary function of t");
  return *I;
}

// A load that changes with the motion and acts across the set (a spring with one end in it, a
// torsion spring on a body held by the ground) has no impulse of its own over a duration: said
// where a balance needs it (a force through the point of moments needs none).
void mark_changing_push(const Effect& e, const Load& l, Push& p) {
  const bool couple = l.Fx.is_zero() && l.Fy.is_zero() && l.kind == Load::Kind::Given;
  const bool two_bodies = l.partner && l.partner->body >= 0 && l.at.body >= 0;
  p.changing = "the " + e.kind + " '" + e.name + "' " + (couple ? "turns with a couple" : "pushes with a force") +
               " that changes with the motion; its impulse over a duration has no closed form";
  p.changing_fix = two_bodies ? "include both of its ends in the analysis' bodies, or use an energy analysis" : "use an energy analysis";
}

}  // namespace

std::optional<ex> over_duration(const Model& m, const ex& f, const Analysis& a) {
  // ∫_{t₁}^{t₂} f dt: f (t₂ − t₁) for a constant, else F(t₂) − F(t₁) with F an antiderivative
  ex t1 = m.states[a.from].t, t2 = m.states[a.to].t;
  if (!f.has(m.t)) return f * (t2 - t1);
  auto F = model::antiderivative(f, m.t);
  if (!F) return std::nullopt;
  return F->subs(m.t == t2) - F->subs(m.t == t1);
}

std::optional<ex> twice_over_duration(const Model& m, const ex& f, const Analysis& a) {
  // ∫_{t₁}^{t₂} ∫_{t₁}^{t} f dt' dt: f (t₂ − t₁)²/2 for a constant; else, with F' = f and A' = F,
  // A(t₂) − A(t₁) − F(t₁) (t₂ − t₁)
  ex t1 = m.states[a.from].t, t2 = m.states[a.to].t;
  if (!f.has(m.t)) return f * pow(t2 - t1, 2) / 2;
  auto F = model::antiderivative(f, m.t);
  if (!F) return std::nullopt;
  auto A = model::antiderivative(*F, m.t);
  if (!A) return std::nullopt;
  return A->subs(m.t == t2) - A->subs(m.t == t1) - F->subs(m.t == t1) * (t2 - t1);
}

void load_pushes(const Model& m, const Effect& e, const Analysis& a, const Knowledge& k, std::vector<Push>& out) {
  for (const Load& l : e.loads(m)) {
    const int side = side_on(a, l);
    if (side == 0) continue;  // not on the set, or internal to it
    Push p;
    p.body = side > 0 ? l.at.body : l.partner->body;
    p.symbol = l.symbol;
    switch (l.kind) {
      case Load::Kind::Given:
        // an interaction's force that changes with the motion: no impulse of its own (a load from
        // outside is taken as it is, component by component)
        if ((l.partner || !l.singular.empty()) && model::changes_with_motion(m, l)) mark_changing_push(e, l, p);
        p.Fx = side * l.Fx;
        p.Fy = side * l.Fy;
        p.M = side * l.M;
        break;
      case Load::Kind::Slide: {
        // kinetic friction −μN û on its point against its slip at the first state (+μN û on the partner)
        auto [Fx, Fy] = sliding_force(m, e, l, a, k, &p.holds);
        p.Fx = side * Fx;
        p.Fy = side * Fy;
        break;
      }
      case Load::Kind::Turn:
        // a friction couple −M against the turning at the first state
        p.M = -side * l.size * motion_direction(m, e, l.direction, model::relative_omega(m, l), a, k, "rotation", &p.holds);
        break;
    }
    // a force at its point (a friction force: at the one place both parties touch; a force on
    // the partner: at the partner's point); a couple has no point
    if (l.kind == Load::Kind::Slide || (l.kind == Load::Kind::Given && !(l.Fx.is_zero() && l.Fy.is_zero()))) {
      auto [x, y] = m.position(side > 0 || l.kind == Load::Kind::Slide ? l.at : *l.partner);
      p.arm_x = x;
      p.arm_y = y;
    }
    out.push_back(p);
  }
}

std::pair<ex, ex> load_impulse(const Model& m, const Effect& e, int ai) {
  const Analysis& a = m.analyses[static_cast<std::size_t>(ai)];
  if (a.instant())
    throw InputError("effect '" + e.name + "' (" + e.kind + ") has no impulse to report between states " + m.states[a.from].name +
                         " and " + m.states[a.to].name,
                     "ask for the impulse of a contact, a pin, a given impulse, or a force over a momentum analysis");
  // ∫F dt of its forces on the set's bodies (of every force it puts on a body, when it puts none there)
  const std::vector<Load> loads = e.loads(m);
  const bool any = std::any_of(loads.begin(), loads.end(), [&](const Load& l) { return side_on(a, l) != 0; });
  ex Fx = 0, Fy = 0;
  for (const Load& l : loads) {
    const int side = any ? side_on(a, l) : 1;
    if (side == 0) continue;
    auto [fx, fy] = l.kind == Load::Kind::Slide ? sliding_force(m, e, l, a, Knowledge(m), nullptr) : std::pair<ex, ex>{l.Fx, l.Fy};
    Fx += side * fx;
    Fy += side * fy;
  }
  for (auto& c : m.coords)
    if (Fx.has(c.q) || Fy.has(c.q) || Fx.has(c.qd) || Fy.has(c.qd))
      throw InputError("the force of '" + e.name + "' changes with the motion; its impulse has no closed form",
                       "ask for impulses of forces that are constant or functions of t");
  return {over_time(m, e, Fx, a), over_time(m, e, Fy, a)};
}

Work load_work(const Model& m, const Effect& e, int s1, int s2, const Knowledge& k) {
  const std::vector<Load> loads = e.loads(m);
  if (loads.empty()) {
    Work w;
    w.effect = e.name;
    w.U = 0;
    w.how = "no work";
    return w;
  }
  if (loads.size() == 1 && loads[0].kind != Load::Kind::Given) {
    const Load& l = loads[0];
    if (l.kind == Load::Kind::Turn) {
      // U = −M × the angle turned: dℓ/ds = |∂φ_rel/∂s| along the path
      auto turned = [&](const Path& p) {
        ex phi = model::relative_angle(m, l).subs(p.q_of_s);
        return sqrt(model::trig_simplify(pow(phi.diff(m.coords[p.s].q), 2)));
      };
      return friction_work(m, e, l.direction, l.size, turned, "U = -M * angle turned", s1, s2, k);
    }
    // kinetic friction: a slip along a fixed line that is the rate of a function of the
    // coordinates gives U = −μN σ Δf; else −μN × the distance slid along the one-coordinate path
    auto [sx, sy] = model::relative_velocity(m, l);
    const bool along_x = vanishes(m, sy), along_y = vanishes(m, sx);
    const bool two = l.partner && l.partner->body >= 0;
    if (along_x != along_y)
      if (auto w = exact_slip_work(m, e, l.direction, l.size, along_x ? sx : sy,
                                   "U = -mu N * distance slid" + std::string(two ? " (of one body over the other)" : ""), s1, s2, k))
        return *w;
    // distance slid: dℓ/ds = |v_rel| at ṡ = 1 with the others following
    auto slid = [&, slip_x = sx, slip_y = sy](const Path& p) {
      const GiNaC::symbol& s = m.coords[p.s].q;
      GiNaC::exmap rates;
      for (std::size_t j = 0; j < m.coords.size(); ++j) {
        ex qj = j == p.s ? ex(s) : m.coords[j].q.subs(p.q_of_s);
        rates[m.coords[j].qd] = qj.diff(s);
      }
      ex vx = slip_x.subs(rates).subs(p.q_of_s), vy = slip_y.subs(rates).subs(p.q_of_s);
      return sqrt(model::trig_simplify(vx * vx + vy * vy));
    };
    return friction_work(m, e, l.direction, l.size, slid, "U = -mu N * distance", s1, s2, k);
  }
  for (const Load& l : loads)
    if (l.kind != Load::Kind::Given)
      throw std::logic_error("effect '" + e.name + "': friction together with other loads in one effect");
  bool on_rates = false, couples_only = true;
  for (const Load& l : loads) {
    for (auto& c : m.coords) on_rates = on_rates || l.Fx.has(c.qd) || l.Fy.has(c.qd) || l.M.has(c.qd);
    couples_only = couples_only && l.Fx.is_zero() && l.Fy.is_zero();
  }
  if (on_rates) {
    // a load that depends on the speeds: its work is ∫P dt, known from the states alone only when
    // the power P = Σ F·v + M ω is (a drive of given power): U = ∫ P dt
    ex P = e.power(m);
    if (motion_free(m, P)) {
      Work w;
      w.effect = e.name;
      ex t1 = m.states[s1].t, t2 = m.states[s2].t;
      if (!P.has(m.t)) {
        w.U = P * (t2 - t1);
        w.how = "U = P (t2 - t1)";
      } else {
        auto F = model::antiderivative(P, m.t);
        if (!F) throw SceneError(e.pos, "the power of '" + e.name + "' has no antiderivative in t", "use an elementary function of t");
        w.U = F->subs(m.t == t2) - F->subs(m.t == t1);
        w.how = "U = integral of P dt";
      }
      return w;
    }
    // U = −∫ c v² dt depends on how fast the motion went, not on the two states alone
    throw SceneError(e.pos, "the work of the " + e.kind + " '" + e.name + "' depends on the speeds all along the motion, not on states '" +
                                m.states[s1].name + "' and '" + m.states[s2].name + "' alone",
                     "simulate the scene (kinergy simulate) for its work, or remove the damper from an energy analysis");
  }
  return couples_only ? generalized_force_work(m, e, "couple", "U = integral of M dphi", s1, s2, &k)
                      : generalized_force_work(m, e, "force", "U = integral of F . dr", s1, s2, &k);
}

// The pushes of an effect on a body set over a duration: its loads', its reaction's, a given
// impulse's (at its point, no time integral).
void effect_pushes(const Model& m, const Effect& e, const Analysis& a, const Knowledge& k, std::vector<Push>& out) {
  load_pushes(m, e, a, k, out);
  if (auto r = e.reaction(m)) reaction_pushes(m, e, *r, a, out);
  if (const model::Blow* j = e.blow(); j && j->at.body >= 0 && in_set(a.bodies, j->at.body) && e.strikes_in(m, a)) {
    Push p;  // the impulse itself (no time integral)
    p.Rx = j->Jx;
    p.Ry = j->Jy;
    p.unknown = true;
    p.body = j->at.body;
    std::tie(p.arm_x, p.arm_y) = m.position(j->at);
    out.push_back(p);
  }
}

// ---------------------------------------------------------------- reactions

bool inside(const Analysis& a, const model::PointRef& p) { return p.body >= 0 && !p.ground && in_set(a.bodies, p.body); }

namespace {

[[noreturn]] void no_impulse(const Model& m, const Effect& e, const Analysis& a) {
  throw InputError("effect '" + e.name + "' (" + e.kind + ") has no impulse to report between states " + m.states[a.from].name + " and " +
                       m.states[a.to].name,
                   "ask for the impulse of a contact, a pin, a given impulse, or a force over a momentum analysis");
}

/// How a relation's impulse is named in a derivation: on which party, along which direction.
std::string along(const model::Reaction& r, bool on_a) {
  const model::PointRef& p = on_a ? r.a : r.b;
  return "on " + p.text + ", along " + (on_a ? "" : "-") + "[" + model::text(r.dir_x) + ", " + model::text(r.dir_y) + "]";
}

/// The fixed line the point of a pin's party inside `set` moves along: x (0) or y (1).
std::optional<int> line_inside(const Model& m, const model::Reaction& r, const std::vector<int>& set) {
  const model::PointRef& p = in_set(set, r.a.body) ? r.a : r.b;
  auto [vx, vy] = m.velocity(p);
  const bool x = vanishes(m, vy), y = vanishes(m, vx);
  if (x == y) return std::nullopt;
  return x ? 0 : 1;
}

}  // namespace

bool holds(const Model& m, const Effect& e, int body) {
  auto r = e.reaction(m);
  return r && r->kind == model::Reaction::Kind::Pin && (r->a.body == body || r->b.body == body);
}

bool works_across(const Model& m, const model::Reaction& r, const std::vector<int>& set) {
  if (!r.across(set)) return false;
  switch (r.kind) {
    case model::Reaction::Kind::Pin:
      // a collar on its rod: the reaction's component along the pinned point's fixed line works
      return r.a.body >= 0 && r.b.body >= 0 && line_inside(m, r, set).has_value();
    case model::Reaction::Kind::Relation:
      return true;
    default:
      return false;
  }
}

void reaction_pushes(const Model& m, const Effect& e, const model::Reaction& r, const Analysis& a, std::vector<Push>& out) {
  auto it = a.reactions.find(e.name);
  if (r.kind == model::Reaction::Kind::Contact || !r.across(a.bodies) || it == a.reactions.end()) return;
  // the unknown impulse on the party inside the set, at its point
  const bool on_a = inside(a, r.a);
  Push p;
  p.unknown = true;
  p.reaction = true;
  switch (r.kind) {
    case model::Reaction::Kind::Pin: {
      // (Rx, Ry) on its first party that is a body, −(Rx, Ry) on the other (the sign rule)
      p.implied = true;
      const int s = on_a == r.a_first() ? 1 : -1;
      p.Rx = s * it->second[0];
      p.Ry = s * it->second[1];
      if (s < 0) p.what = "reaction impulse (unknown) of '" + e.name + "', -(Rx, Ry) on " + r.b.text + " (Rx, Ry on " + r.a.text + ")";
      break;
    }
    case model::Reaction::Kind::Track:
      // N n̂ on the point
      p.implied = true;
      p.Rx = it->second[0] * r.dir_x;
      p.Ry = it->second[0] * r.dir_y;
      p.what = "normal reaction impulse (unknown) of the track on " + r.a.text;
      break;
    default: {
      // a relation: J û on party a, −J û on party b
      ex J = on_a ? it->second[0] : -it->second[0];
      p.Rx = J * r.dir_x;
      p.Ry = J * r.dir_y;
      p.what = "reaction impulse (unknown) " + along(r, on_a);
      break;
    }
  }
  std::tie(p.arm_x, p.arm_y) = m.position(on_a ? r.a : r.b);
  p.body = (on_a ? r.a : r.b).body;
  out.push_back(p);
}

/// A pin's impulse in an impact: the pinned body's momentum change less the other impulses on it.
static std::pair<ex, ex> pin_impact_impulse(const Model& m, const Effect& e, const model::Reaction& r, int self, int ai) {
  const Analysis& an = m.analyses[static_cast<std::size_t>(ai)];
  int bi = r.b.body >= 0 ? r.b.body : r.a.body;
  if (bi < 0) throw InputError("pin '" + e.name + "' joins no body", "pin a body point to a point");
  const model::Body& B = m.bodies[static_cast<std::size_t>(bi)];
  for (std::size_t k = 0; k < m.constraints.size(); ++k) {
    const auto& c = m.constraints[k];
    // (a contact that closes in this impact holds its parties from the state after it on: its
    // relations carry no impulse here beside the contact's own)
    if (!m.constraint_at(k, an.from, true)) continue;
    for (auto& co : m.coords)
      if (c.first.has(co.q) && (B.x.has(co.q) || B.y.has(co.q) || B.angle.has(co.q)))
        throw InputError("the impulse of pin '" + e.name + "' cannot be told apart from the constraint impulses on '" + B.name + "'",
                         "describe the body's motion with coordinates that need no constraint");
  }
  for (std::size_t j = 0; j < m.effects.size(); ++j) {
    const Effect& o = m.effects[j];
    if (static_cast<int>(j) != self && holds(m, o, bi))
      throw InputError("body '" + B.name + "' has two pins, '" + e.name + "' and '" + o.name + "'; their impulses cannot be told apart",
                       "ask for the impulse of a pin that holds a body alone");
  }
  // R = m (v̄⁺ − v̄⁻) − Σ P (contact impulses and given blows on the body); reported on the
  // pin's first party that is a body (the sign rule): −R when that is the other one
  ex vx = m.rate(B.x), vy = m.rate(B.y);
  ex Rx = B.mass * (m.bind_mixed(vx, an.from, an.to) - m.bind(vx, an.from));
  ex Ry = B.mass * (m.bind_mixed(vy, an.from, an.to) - m.bind(vy, an.from));
  for (auto& o : m.effects) {
    auto [Px, Py] = o.impact_impulse_on(m, bi, ai);
    Rx -= Px;
    Ry -= Py;
  }
  const int s = bi == r.first().body ? 1 : -1;
  return {s * Rx, s * Ry};
}

std::pair<ex, ex> reaction_impulse(const Model& m, const Effect& e, const model::Reaction& r, int self, int ai) {
  const Analysis& an = m.analyses[static_cast<std::size_t>(ai)];
  auto it = an.reactions.find(e.name);
  switch (r.kind) {
    case model::Reaction::Kind::Contact: {
      const model::Struck* st = an.struck();
      if (!st || !st->impulses.count(e.name))
        throw InputError("contact '" + e.name + "' takes no part in an impact between states " + m.states[an.from].name + " and " +
                             m.states[an.to].name,
                         "name it in the impact's 'contact' or 'contacts'");
      // P = J n + Jt t on party b,  t = (−n_y, n_x); reported on the first party that is a body
      // (the sign rule): −P on a
      auto [J, Jt] = st->impulses.at(e.name);
      const int s = r.a_first() ? -1 : 1;
      return {s * (J * r.dir_x - Jt * r.dir_y), s * (J * r.dir_y + Jt * r.dir_x)};
    }
    case model::Reaction::Kind::Pin:
      if (an.instant()) return pin_impact_impulse(m, e, r, self, ai);
      if (it == an.reactions.end())
        throw InputError("pin '" + e.name + "' is not external to the bodies of the analysis between states " + m.states[an.from].name +
                             " and " + m.states[an.to].name,
                         "list in 'bodies' the body the pin holds, and not the body on its other side");
      return {it->second[0], it->second[1]};
    case model::Reaction::Kind::Track:
      if (an.instant() || it == an.reactions.end()) no_impulse(m, e, an);
      if (!motion_free(m, model::trig_simplify(r.dir_x)) || !motion_free(m, model::trig_simplify(r.dir_y)))
        throw InputError("the normal of track '" + e.name + "' turns with the motion, so its impulse has no fixed components",
                         "ask for the impulse of a straight track, or for its moment");
      return {it->second[0] * r.dir_x, it->second[0] * r.dir_y};
    case model::Reaction::Kind::Relation:
      if (an.instant()) {
        // the impulsive reaction Λ of the relation: Λ f on party a
        const ex& lam = an.struck()->lambdas.at(r.constraint);
        return {lam * m.bind(r.fx, an.from), lam * m.bind(r.fy, an.from)};
      }
      if (it == an.reactions.end())
        throw InputError("constraint '" + e.name + "' does not join the bodies of the analysis between states " + m.states[an.from].name +
                             " and " + m.states[an.to].name + " to the rest",
                         "list in 'bodies' one of its parties (" + r.a.text + ", " + r.b.text + ") and not the other");
      if (!motion_free(m, r.dir_x) || !motion_free(m, r.dir_y))
        throw InputError("the force of constraint '" + e.name + "' turns with the motion (along [" + model::text(r.dir_x) + ", " +
                             model::text(r.dir_y) + "]), so its impulse has no components fixed by the analysis",
                         "ask for its impulse in an impact, or for the angular impulse it gives");
      return {it->second[0] * r.dir_x, it->second[0] * r.dir_y};
  }
  no_impulse(m, e, an);
}

Work reaction_work_across(const Model& m, const Effect& e, const model::Reaction* rp, const Analysis& an) {
  auto it = an.reactions.find(e.name);
  if (rp && rp->kind == model::Reaction::Kind::Pin) {
    const model::Reaction& r = *rp;
    // U = F̄ Δs: F̄ the average force on the party inside along +x (or +y) over the distance, s
    // that coordinate of its point
    if (it == an.reactions.end() || !works_across(m, r, an.bodies))
      throw SceneError(an.pos, "pin '" + e.name + "' joins a body of this energy analysis to one outside it, and the pinned point does not "
                                   "keep to a fixed line (x or y): the work of its reaction is not one unknown force times a distance",
                       "list both bodies it joins in 'bodies', or take its reaction from an impulse-momentum analysis of the body");
    const bool ia = inside(an, r.a);
    const model::PointRef& p = ia ? r.a : r.b;
    const int line = *line_inside(m, r, an.bodies);
    auto [x, y] = m.position(p);
    const ex s = line == 0 ? x : y;
    // (F on the first party that is a body: −F on the other, the sign rule)
    const int sign = ia == r.a_first() ? 1 : -1;
    Work w;
    w.effect = e.name;
    w.U = sign * it->second[0] * model::trig_simplify(m.bind(s, an.to) - m.bind(s, an.from));
    w.how = "U = " + std::string(sign < 0 ? "-" : "") + "F (average, on " + r.first().text + " along " + (line == 0 ? "x" : "y") +
            ") times the distance " + p.text + " moves along it";
    return w;
  }
  if (rp && rp->kind == model::Reaction::Kind::Relation) {
    const model::Reaction& r = *rp;
    // the force F̄ û on the party inside (−F̄ û for the second party), at its point P:
    // U = F̄ ∫ ±û·dr_P, F̄ the average force over the distance, an unknown; as generalized forces
    // per unit F̄: Q_i = ±û·∂r_P/∂q_i
    if (it == an.reactions.end()) throw std::logic_error("constraint '" + e.name + "' has no unknown in this energy analysis");
    const bool ia = inside(an, r.a);
    const model::PointRef& p = ia ? r.a : r.b;
    ex sign = ia ? 1 : -1;
    std::vector<ex> Q;
    for (auto& co : m.coords) {
      auto [dx, dy] = m.position_derivative(p, co.q);
      Q.push_back(model::trig_simplify(sign * (r.dir_x * dx + r.dir_y * dy)));
    }
    Work w = generalized_force_work(m, e, Q, "constraint force", "", an.from, an.to);
    w.U = it->second[0] * w.U;
    w.how = "U = F (average) times the distance " + p.text + " moves along " + (ia ? "" : "-") + "[" + model::text(r.dir_x) + ", " +
            model::text(r.dir_y) + "]";
    return w;
  }
  std::string all;
  for (int b : e.bodies_acted(m)) all += (all.empty() ? "" : ", ") + m.bodies[static_cast<std::size_t>(b)].name;
  throw SceneError(an.pos, "effect '" + e.name + "' (" + e.kind + ") acts on bodies inside this energy analysis' set and outside it; its work on the set alone is not known",
                   "list in 'bodies' every body it acts on (" + all + "), or name the interaction as a constraint effect "
                   "('NAME: {constraint: \"…\", between: [A, B], at: [x, y]}') so that its average force is an unknown");
}

}  // namespace kinergy::principles
