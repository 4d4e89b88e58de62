// What every effect answers the same way, from what its kind declares (its loads, its potential,
// its reaction, a given impulse): the principles' derivations, once.
#include "kinergy/model/effect.hpp"

#include <algorithm>
#include <limits>

#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"

namespace kinergy::model {

Effect::Activity Effect::activity(const Analysis& a) const {
  if (on < 0 && off < 0) return Activity::Whole;
  int lo = std::min(a.from, a.to), hi = std::max(a.from, a.to);
  int start = on < 0 ? std::numeric_limits<int>::min() : on, end = off < 0 ? std::numeric_limits<int>::max() : off;
  if (hi <= start || lo >= end) return a.instant() && lo == start ? Activity::Whole : Activity::None;
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

Effect::AtState Effect::at_state(int s) const {
  if (on == s || off == s) return AtState::Switches;
  return (on < 0 || on < s) && (off < 0 || s < off) ? AtState::Acts : AtState::Not;
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

std::optional<int> Effect::strike_state(const Model& m) const {
  if (!blow()) return std::nullopt;
  std::optional<int> first;
  for (auto& a : m.analyses)
    if (a.takes_blows() && activity(a) != Activity::None && (!first || a.from < *first)) first = a.from;
  return first;
}

bool Effect::strikes_in(const Model& m, const Analysis& a) const {
  return blow() && a.takes_blows() && activity(a) != Activity::None && strike_state(m) == a.from;
}

std::vector<int> Effect::bodies_acted(const Model& m) const {
  std::vector<int> out;
  auto add_body = [&](int b) {
    if (b >= 0 && std::find(out.begin(), out.end(), b) == out.end()) out.push_back(b);
  };
  auto add = [&](const PointRef& p) {
    if (!p.ground) add_body(p.body);
  };
  for (const Load& l : loads(m)) {
    add(l.at);
    if (l.partner) add(*l.partner);
  }
  if (auto r = reaction(m))
    for (int b : r->bodies()) add_body(b);
  if (const Blow* j = blow()) add(j->at);
  return out;
}

principles::Work Effect::work(const Model& m, int s1, int s2, const principles::Knowledge& k) const {
  return principles::load_work(m, *this, s1, s2, k);
}

principles::Work Effect::work_across(const Model& m, const Analysis& a, const principles::Knowledge&) const {
  auto r = reaction(m);
  return principles::reaction_work_across(m, *this, r ? &*r : nullptr, a);
}

std::pair<ex, ex> Effect::impulse(const Model& m, int self, int ai) const {
  if (auto r = reaction(m)) return principles::reaction_impulse(m, *this, *r, self, ai);
  if (const Blow* j = blow()) {
    // (switched off, or not yet on, over the analysis, or struck before it: it does not strike there)
    if (!strikes_in(m, m.analyses[static_cast<std::size_t>(ai)])) return {0, 0};
    return {j->Jx, j->Jy};
  }
  return principles::load_impulse(m, *this, ai);
}

ex Effect::impulse_size(const Model& m, int ai, const ex& x, const ex& y) const {
  // a contact's is J, its impulse along its normal
  auto r = reaction(m);
  const Struck* st = m.analyses[static_cast<std::size_t>(ai)].struck();
  if (r && r->kind == Reaction::Kind::Contact && st && st->impulses.count(name)) return st->impulses.at(name).first;
  return sqrt(x * x + y * y);
}

std::pair<ex, ex> Effect::impact_impulse_on(const Model& m, int body, int ai) const {
  const Analysis& a = m.analyses[static_cast<std::size_t>(ai)];
  if (const Blow* j = blow()) {
    if (j->at.body != body || !strikes_in(m, a)) return {0, 0};
    return {j->Jx, j->Jy};
  }
  auto r = reaction(m);
  if (!r || r->kind != Reaction::Kind::Contact || !a.struck() || !a.struck()->impulses.count(name)) return {0, 0};
  // P on the first party that is a body (impulse: the sign rule), −P on the other
  auto [Px, Py] = impulse(m, -1, ai);
  const model::PointRef &first = r->first(), &other = r->second();
  int sign = (first.body == body && !first.ground ? 1 : 0) - (other.body == body && !other.ground ? 1 : 0);
  return {sign * Px, sign * Py};
}

ex Effect::impact_loss(const Model& m, int ai) const {
  const Analysis& an = m.analyses[static_cast<std::size_t>(ai)];
  auto r = reaction(m);
  if (!r || r->kind != Reaction::Kind::Contact || !an.instant())
    throw InputError("'loss' takes a contact and the two states of its impact", "write loss(hit, before, after)");
  auto it = an.struck()->impulses.find(name);  // an instant analysis is an impact
  if (it == an.struck()->impulses.end())
    throw InputError("contact '" + name + "' takes no part in that impact", "name it in the impact's contacts");
  auto [J, Jt] = it->second;
  auto vel = [&](const PointRef& p) -> std::pair<ex, ex> {
    if (p.ground) return {0, 0};
    return m.velocity(p);
  };
  auto [vbx, vby] = vel(r->b);
  auto [vax, vay] = vel(r->a);
  ex vn = m.bind((vbx - vax) * r->dir_x + (vby - vay) * r->dir_y, an.from);
  ex vt = m.bind(-(vbx - vax) * r->dir_y + (vby - vay) * r->dir_x, an.from);
  // T⁺ − T⁻ = Σ P·(v⁻ + v⁺)/2 with v_n⁺ = −e v_n⁻ and (stick) v_t⁺ = 0:
  //   lost = −½ [(1 − e) J v_n⁻ + Jt v_t⁻]
  return -((1 - r->e) * J * vn + (r->stick ? ex(Jt * vt) : ex(0))) / 2;
}

}  // namespace kinergy::model
