#include "common.hpp"

namespace kinergy::effects {

std::pair<ex, ex> force_impulse(const Model& m, const Effect& e, const ex& Fx, const ex& Fy, const Analysis& a) {
  // ∫F dt over the interval for a force free of the motion
  for (auto& c : m.coords)
    if (Fx.has(c.q) || Fy.has(c.q) || Fx.has(c.qd) || Fy.has(c.qd))
      throw InputError("the force of '" + e.name + "' changes with the motion; its impulse has no closed form",
                       "ask for impulses of forces that are constant or functions of t");
  ex t1 = m.states[a.from].t, t2 = m.states[a.to].t;
  auto integral = [&](const ex& f) -> ex {
    if (!f.has(m.t)) return f * (t2 - t1);
    auto F = model::antiderivative(f, m.t);
    if (!F) throw InputError("the impulse of '" + e.name + "' has no closed form in t", "use an elementary function of t");
    return F->subs(m.t == t2) - F->subs(m.t == t1);
  };
  return {integral(Fx), integral(Fy)};
}

void refuse_elastic_push(const Effect& e, bool in_a, bool in_b) {
  if (in_a == in_b) return;
  throw SceneError(e.pos, "the " + e.kind + " '" + e.name + "' pushes with a force that changes with the motion; its impulse over a duration has no closed form",
                   "include both of its ends in the analysis' bodies, or use an energy analysis");
}

void refuse_speed_dependent_work(const Model& m, const Effect& e, int s1, int s2) {
  // U = −∫ c v² dt depends on how fast the motion went, not on the two states alone
  throw SceneError(e.pos, "the work of the " + e.kind + " '" + e.name + "' depends on the speeds all along the motion, not on states '" +
                              m.states[s1].name + "' and '" + m.states[s2].name + "' alone",
                   "simulate the scene (kinergy simulate) for its work, or remove the damper from an energy analysis");
}

}  // namespace kinergy::effects
