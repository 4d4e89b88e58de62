#include <algorithm>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"

namespace kinergy::principles {

using namespace GiNaC;
using model::Model;

EnergyBalance energy(const Model& m, const model::Analysis& a, const Knowledge& k) {
  m.constraints_over(a);  // none switched inside the analysis (the coordinates differ on either side)
  // a blow strikes at the first state of the impact or momentum analysis that takes it, the rates
  // there being those before it: work and energy from that state (or across it) would leave it out
  for (auto& e : m.effects)
    if (auto s = e.strike_state(m); s && *s >= std::min(a.from, a.to) && *s < std::max(a.from, a.to))
      throw SceneError(a.pos, "the energy analysis from state '" + m.states[a.from].name + "' to '" + m.states[a.to].name + "' " +
                                  (*s == a.from ? "starts at" : "passes") + " state '" + m.states[*s].name + "', where the given impulse '" + e.name +
                                  "' strikes (its rates there are those before the blow), and work and energy do not take a blow",
                       "take the energy from a state after the blow: add an impact analysis from '" + m.states[*s].name +
                           "' to a new state (its rates just after), and start the energy analysis there");
  EnergyBalance b;
  const bool whole = a.bodies.size() == m.bodies.size();
  // a body set (isolated): its own kinetic energy; each effect acting only on it counts whole,
  // one acting only outside it not at all, one acting inside and outside by its work on the set
  ex T = 0, V = 0;
  if (whole) {
    T = m.kinetic_energy();
  } else {
    for (int bi : a.bodies) T += m.kinetic_energy(bi);
    T = model::collect_simplify(T, m.rates());
  }
  ex U = 0;
  for (auto& e : m.effects) {
    // an effect switched on or off inside the analysis does its work over its own part of it:
    // U = work from its first to its last state there (a conservative one: −ΔV over that part)
    const auto act = e.activity(a);
    if (act == model::Effect::Activity::None) continue;
    if (act == model::Effect::Activity::Part) {
      auto [s1, s2] = e.active_span(a);
      if (!whole)
        throw SceneError(a.pos, "effect '" + e.name + "' is switched at state '" + m.states[e.on >= 0 && e.on > std::min(a.from, a.to) ? e.on : e.off].name +
                                    "' inside this energy analysis of isolated bodies",
                         "split the analysis at that state");
      Work w = m.conservative(e) ? Work{e.name, -(m.bind(e.potential(m), s2) - m.bind(e.potential(m), s1)), "U = -(change of V)", {}, 1}
                                 : work(m, e, s1, s2, k);
      w.how += " from state " + m.states[s1].name + " to " + m.states[s2].name + " (where it acts)";
      U += w.U;
      b.works.push_back(w);
      b.working.push_back(e.name);
      continue;
    }
    std::size_t inside = 0, acted = 0;
    if (!whole) {
      for (int bi : e.bodies_acted(m)) {
        ++acted;
        if (in_set(a.bodies, bi)) ++inside;
      }
      if (inside == 0) continue;
    }
    Work w;
    if (!whole && inside < acted) {
      w = e.work_across(m, a, k);
    } else if (m.conservative(e)) {
      ex Ve = e.potential(m);
      V += Ve;
      if (!Ve.is_zero()) {
        b.stored.push_back(e.name == e.kind ? e.name : e.name + " (" + e.kind + ")");
        b.working.push_back(e.name);
      }
      continue;
    } else {
      w = work(m, e, a.from, a.to, k);
    }
    // a work of zero is left out (what it took for granted still checked: a launcher spring not
    // compressed at either state), but not one split where its force switches: the case taken,
    // past how many switching points, is part of the solution, and another may be tried
    if (w.U.is_zero() && w.switch_cases <= 1) {
      b.unshown.insert(b.unshown.end(), w.holds.begin(), w.holds.end());
      continue;
    }
    U += w.U;
    b.works.push_back(w);
    b.working.push_back(e.name);
  }
  b.at_from = {m.bind(T, a.from), m.bind(V, a.from)};
  b.at_to = {m.bind(T, a.to), m.bind(V, a.to)};
  b.conservative = b.works.empty();
  // T₁ + V₁ + U₁→₂ = T₂ + V₂
  const std::string S1 = m.states[a.from].name, S2 = m.states[a.to].name;
  b.equation.lhs = b.at_from.T + b.at_from.V + U;
  b.equation.rhs = b.at_to.T + b.at_to.V;
  b.equation.principle = b.conservative ? "conservation of energy" : "work-energy";
  b.equation.label = b.equation.principle + ", states " + S1 + " -> " + S2;
  b.equation.pos = a.pos;
  return b;
}

std::vector<Equation> state_equations(const Model& m, int s) {
  std::vector<Equation> out;
  const std::string S = m.states[s].name;
  for (std::size_t k = 0; k < m.constraints.size(); ++k) {
    const auto& [c, pos] = m.constraints[k];
    if (!m.constraint_at(k, s, false)) continue;  // a constraint effect switched off (or not yet on) there
    out.push_back({m.bind(c, s), 0, "constraint", "constraint at state " + S, pos});
    // the constraint holds at every instant, so its rate vanishes: Σ ∂c/∂q q̇ = 0
    if (!m.constraint_at(k, s, true)) continue;  // it engages in an impact starting at s
    ex r = model::trig_simplify(m.rate(c));
    if (!r.is_zero()) out.push_back({m.bind(r, s), 0, "constraint", "constraint rate at state " + S, pos});
  }
  for (auto& [w, pos] : m.states[s].where) out.push_back({w, 0, "condition", "condition at state " + S, pos});
  return out;
}

}  // namespace kinergy::principles
