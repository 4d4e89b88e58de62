// What an effect answers when its kind says nothing else: no potential, no work, no impulse.
#include "kinergy/model/effect.hpp"

#include <algorithm>
#include <limits>

#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"
#include "kinergy/simulate/equations.hpp"

namespace kinergy::model {

Effect::Activity Effect::activity(const Analysis& a) const {
  if (on < 0 && off < 0) return Activity::Whole;
  int lo = std::min(a.from, a.to), hi = std::max(a.from, a.to);
  int start = on < 0 ? std::numeric_limits<int>::min() : on, end = off < 0 ? std::numeric_limits<int>::max() : off;
  if (hi <= start || lo >= end) return a.instant && lo == start ? Activity::Whole : Activity::None;
  if (start <= lo && hi <= end) return Activity::Whole;
  return Activity::Part;
}

std::pair<int, int> Effect::active_span(const Analysis& a) const {
  int lo = a.from, hi = a.to;
  bool forward = a.from <= a.to;
  int start = on < 0 ? std::min(lo, hi) : std::max(std::min(lo, hi), on);
  int end = off < 0 ? std::max(lo, hi) : std::min(std::max(lo, hi), off);
  return forward ? std::pair<int, int>{start, end} : std::pair<int, int>{end, start};
}

ex Effect::generalized_force(const Model& m, std::size_t i) const {
  if (conservative()) return -potential(m).diff(m.coords[i].q);  // Q_i = −∂V/∂q_i
  return 0;
}

ex Effect::power(const Model& m) const {
  ex P = 0;  // conservative: P = −dV/dt
  if (conservative()) P = -m.rate(potential(m));
  return collect_simplify(P, m.rates());
}

principles::Work Effect::work(const Model&, int, int, const principles::Knowledge&) const {
  principles::Work w;
  w.effect = name;
  w.U = 0;
  w.how = "no work";
  return w;
}

principles::Work Effect::work_across(const Model& m, const Analysis& a, const principles::Knowledge&) const {
  std::string all;
  for (int b : bodies_acted(m)) all += (all.empty() ? "" : ", ") + m.bodies[b].name;
  throw SceneError(a.pos, "effect '" + name + "' (" + kind + ") acts on bodies inside this energy analysis' set and outside it; its work on the set alone is not known",
                   "list in 'bodies' every body it acts on (" + all + "), or name the interaction as a constraint effect "
                   "('NAME: {constraint: \"…\", between: [A, B], at: [x, y]}') so that its average force is an unknown");
}

void Effect::pushes(const Model&, const Analysis&, const principles::Knowledge&, std::vector<principles::Push>&) const {}

std::pair<ex, ex> Effect::impulse(const Model& m, int, int ai) const {
  const Analysis& a = m.analyses[ai];
  throw InputError("effect '" + name + "' (" + kind + ") has no impulse to report between states " + m.states[a.from].name +
                       " and " + m.states[a.to].name,
                   "ask for the impulse of a contact, a pin, a given impulse, or a force over a momentum analysis");
}

ex Effect::impulse_size(const Model&, int, const ex& x, const ex& y) const { return sqrt(x * x + y * y); }

ex Effect::impact_loss(const Model&, int) const {
  throw InputError("'loss' takes a contact and the two states of its impact", "write loss(hit, before, after)");
}

void Effect::motion(const Model& m, int self, simulate::Equations& eq) const {
  // a potential's generalized force Q_i = −∂V/∂q_i
  if (conservative()) {
    eq.forces.push_back(simulate::force_term(m, *this, self));
    return;
  }
  throw SceneError(pos, "effect '" + name + "' of kind '" + kind + "' cannot be simulated",
                   "remove it from the scene to simulate the rest");
}

}  // namespace kinergy::model
