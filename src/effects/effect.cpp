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
  ex Q = 0;                                                       // Q_i = Σ over its loads
  for (const Load& l : loads(m)) Q += model::generalized_force(m, l, i);
  return Q;
}

ex Effect::power(const Model& m) const {
  if (conservative()) return collect_simplify(-m.rate(potential(m)), m.rates());  // P = −dV/dt
  ex P = 0;                                                                        // P = Σ over its loads
  for (const Load& l : loads(m)) P += model::power(m, l);
  return P;
}

std::vector<int> Effect::bodies_acted(const Model& m) const {
  std::vector<int> out;
  auto add = [&](const PointRef& p) {
    if (p.body >= 0 && !p.ground && std::find(out.begin(), out.end(), p.body) == out.end()) out.push_back(p.body);
  };
  for (const Load& l : loads(m)) {
    add(l.at);
    if (l.partner) add(*l.partner);
  }
  return out;
}

principles::Work Effect::work(const Model& m, int s1, int s2, const principles::Knowledge& k) const {
  return principles::load_work(m, *this, s1, s2, k);
}

principles::Work Effect::work_across(const Model& m, const Analysis& a, const principles::Knowledge&) const {
  std::string all;
  for (int b : bodies_acted(m)) all += (all.empty() ? "" : ", ") + m.bodies[b].name;
  throw SceneError(a.pos, "effect '" + name + "' (" + kind + ") acts on bodies inside this energy analysis' set and outside it; its work on the set alone is not known",
                   "list in 'bodies' every body it acts on (" + all + "), or name the interaction as a constraint effect "
                   "('NAME: {constraint: \"…\", between: [A, B], at: [x, y]}') so that its average force is an unknown");
}

void Effect::pushes(const Model& m, const Analysis& a, const principles::Knowledge& k, std::vector<principles::Push>& out) const {
  principles::load_pushes(m, *this, a, k, out);
}

std::pair<ex, ex> Effect::impulse(const Model& m, int, int ai) const { return principles::load_impulse(m, *this, ai); }

ex Effect::impulse_size(const Model&, int, const ex& x, const ex& y) const { return sqrt(x * x + y * y); }

ex Effect::impact_loss(const Model&, int) const {
  throw InputError("'loss' takes a contact and the two states of its impact", "write loss(hit, before, after)");
}

void Effect::motion(const Model& m, int self, simulate::Equations& eq) const { simulate::load_terms(m, *this, self, eq); }

}  // namespace kinergy::model
