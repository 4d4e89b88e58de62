// What the principles derive from an effect's loads, once for every kind: the work between two
// states, the pushes on a body set over a duration, and the impulse ∫F dt.
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

/// ∫_{t₁}^{t₂} f dt over analysis a, for f free of the motion.
ex over_time(const Model& m, const Effect& e, const ex& f, const Analysis& a) {
  ex t1 = m.states[a.from].t, t2 = m.states[a.to].t;
  if (!f.has(m.t)) return f * (t2 - t1);
  auto F = model::antiderivative(f, m.t);
  if (!F) throw InputError("the impulse of '" + e.name + "' has no closed form in t", "use an elementary function of t");
  return F->subs(m.t == t2) - F->subs(m.t == t1);
}

}  // namespace

// A load that changes with the motion and acts across the set (a spring with one end in it, a
// torsion spring on a body held by the ground) has no impulse of its own over a duration.
void refuse_changing_push(const Effect& e, const Load& l) {
  const bool couple = l.Fx.is_zero() && l.Fy.is_zero() && l.kind == Load::Kind::Given;
  const bool two_bodies = l.partner && l.partner->body >= 0 && l.at.body >= 0;
  throw SceneError(e.pos, "the " + e.kind + " '" + e.name + "' " + (couple ? "turns with a couple" : "pushes with a force") +
                              " that changes with the motion; its impulse over a duration has no closed form",
                   two_bodies ? "include both of its ends in the analysis' bodies, or use an energy analysis" : "use an energy analysis");
}

void load_pushes(const Model& m, const Effect& e, const Analysis& a, const Knowledge& k, std::vector<Push>& out) {
  for (const Load& l : e.loads(m)) {
    const int side = side_on(a, l);
    if (side == 0) continue;  // not on the set, or internal to it
    Push p;
    switch (l.kind) {
      case Load::Kind::Given:
        // an interaction's force that changes with the motion: no impulse of its own (a load from
        // outside is taken as it is, component by component)
        if ((l.partner || !l.singular.empty()) && model::changes_with_motion(m, l)) refuse_changing_push(e, l);
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
  if (a.instant)
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
        ex rel = (l.at.body >= 0 ? m.bodies[l.at.body].angle : ex(0)) -
                 (l.partner && l.partner->body >= 0 ? m.bodies[l.partner->body].angle : ex(0));
        ex phi = rel.subs(p.q_of_s);
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

}  // namespace kinergy::principles
