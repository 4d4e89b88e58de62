#include <algorithm>
#include <random>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/principles/principles.hpp"

namespace kinergy::principles {

/// Digits of a work integral taken numerically: those of a numeric root, and a margin.
constexpr int kIntegralDigits = 45;

using namespace GiNaC;
using model::Effect;
using model::Model;

std::optional<ex> antiderivative(const ex& f, const symbol& s) { return model::antiderivative(f, s); }

// ---------------------------------------------------------------- paths

std::optional<Path> one_dof_path(const Model& m) {
  std::size_t n = m.coords.size();
  if (n == 0 || n - std::min(n, m.constraints.size()) != 1 || m.constraints.size() >= n)
    return std::nullopt;
  exmap sub;
  std::vector<bool> gone(n, false);
  for (auto& [c, pos] : m.constraints) {
    ex r = c.subs(sub);
    bool done = false;
    for (std::size_t j = n; j-- > 0 && !done;) {
      if (gone[j]) continue;
      const symbol& q = m.coords[j].q;
      ex a = r.diff(q);
      if (a.is_zero() || a.has(q)) continue;
      bool free = true;
      for (auto& co : m.coords) free = free && !a.has(co.q);
      if (!free) continue;
      ex val = (-r.subs(q == 0) / a).expand();
      for (auto& [k, v] : sub) v = v.subs(q == val);
      sub[q] = val;
      gone[j] = true;
      done = true;
    }
    if (!done) return std::nullopt;
  }
  Path p;
  for (std::size_t j = 0; j < n; ++j)
    if (!gone[j]) p.s = j;
  p.q_of_s = sub;
  return p;
}

namespace {

/// Φ with dΦ = Σ Q_i dq_i when that form is exact (checked), else nothing.
std::optional<ex> potential(const Model& m, const std::vector<ex>& Q) {
  std::size_t n = Q.size();
  exmap env = m.numeric_environment();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2, 2);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      // exact ⇔ ∂Q_i/∂q_j = ∂Q_j/∂q_i
      ex d = model::trig_simplify(Q[i].diff(m.coords[j].q) - Q[j].diff(m.coords[i].q));
      if (d.is_zero()) continue;
      for (int k = 0; k < 3; ++k) {
        exmap at = env;
        for (auto& c : m.coords) at[c.q] = numeric(u(rng));
        if (!numerics::negligible(d, at).value_or(false)) return std::nullopt;
      }
    }
  ex phi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ex r = model::trig_simplify(Q[i] - phi.diff(m.coords[i].q));
    auto a = antiderivative(r, m.coords[i].q);
    if (!a) return std::nullopt;
    phi += *a;
  }
  return phi;
}

int motion_sign(const Model& m, const Effect& e, std::optional<int> declared, const Path& p, int s1, int s2,
                const Knowledge& k) {
  if (declared) return *declared;
  const auto& c = m.coords[p.s];
  ex q1 = m.states[s1].sym.at(c.name).first, q2 = m.states[s2].sym.at(c.name).first;
  ex v1 = m.states[s1].sym.at(c.name).second, v2 = m.states[s2].sym.at(c.name).second;
  for (const ex& probe : {ex(q2 - q1), v1, v2}) {
    auto v = k.value(probe);
    if (v && !v->is_zero()) return v->is_positive() ? 1 : -1;
  }
  throw SceneError(e.pos, "effect '" + e.name + "': the direction of the motion from state '" + m.states[s1].name +
                              "' to '" + m.states[s2].name + "' is not known, so the sign of the friction work is not",
                   "give '" + c.name + "' at both states, a nonzero '" + c.name + "_dot', or 'direction: positive|negative' (of " +
                       c.name + ")");
}

}  // namespace

// ---------------------------------------------------------------- work

Work work(const Model& m, const Effect& e, int s1, int s2, const Knowledge& k) { return e.work(m, s1, s2, k); }

/// ∫ Q ds from state s1 to s2 for Q holding |g(s)| with g linear in s: the ends (state values,
/// expressions of parameters) and the switching points s₀ = −g(0)/g′ between them, ordered by
/// their values; on each piece |g| = σ g with σ the sign of g at the piece's middle. A closed form
/// valid at the scene's values. Nothing when an end or a switching point has no value, or g is not
/// linear.
static std::optional<ex> piecewise_work(const Model& m, const ex& Q, const symbol& s, int s1, int s2) {
  const exmap given = m.given_values(), env = m.numeric_environment();
  ex A = m.bind(ex(s), s1).subs(given), B = m.bind(ex(s), s2).subs(given);
  auto a = numerics::evaluate(A, env, 40), b = numerics::evaluate(B, env, 40);
  if (!a || !b) return std::nullopt;
  std::vector<ex> args;
  for (auto it = Q.preorder_begin(); it != Q.preorder_end(); ++it)
    if (is_ex_the_function(*it, abs) && it->op(0).has(s)) args.push_back(it->op(0));
  // the pieces' ends: (expression, value)
  std::vector<std::pair<ex, numeric>> cuts = {{A, *a}, {B, *b}};
  const numeric lo = std::min(*a, *b), hi = std::max(*a, *b);
  for (auto& g : args) {
    ex d = g.diff(s);
    if (d.has(s) || d.is_zero()) return std::nullopt;
    ex s0 = normal(-g.subs(s == 0) / d);
    auto v = numerics::evaluate(s0, env, 40);
    if (!v) return std::nullopt;
    if (*v > lo && *v < hi) cuts.push_back({s0, *v});
  }
  const bool up = *b >= *a;
  std::sort(cuts.begin(), cuts.end(), [&](auto& x, auto& y) { return up ? x.second < y.second : x.second > y.second; });
  ex U = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i].second == cuts[i + 1].second) continue;
    numeric mid = (cuts[i].second + cuts[i + 1].second) / 2;
    exmap at = env;
    at[s] = mid;
    exmap sign;
    for (auto& g : args) {
      auto gv = numerics::evaluate(g, at, 40);
      if (!gv) return std::nullopt;
      sign[abs(g)] = gv->is_negative() ? -g : g;
    }
    auto F = antiderivative(model::trig_simplify(Q.subs(sign)), s);
    if (!F) return std::nullopt;
    U += F->subs(s == cuts[i + 1].first) - F->subs(s == cuts[i].first);
  }
  return U;
}

Work generalized_force_work(const Model& m, const Effect& e, const std::string& what, const std::string& how, int s1,
                            int s2) {
  std::vector<ex> Q;
  for (std::size_t i = 0; i < m.coords.size(); ++i) Q.push_back(e.generalized_force(m, i));
  return generalized_force_work(m, e, Q, what, how, s1, s2);
}

Work generalized_force_work(const Model& m, const Effect& e, const std::vector<ex>& Q, const std::string& what,
                            const std::string& how, int s1, int s2) {
  Work w;
  w.effect = e.name;
  bool timed = false;
  for (auto& q : Q) timed = timed || q.has(m.t);
  if (timed)
    throw SceneError(e.pos, "effect '" + e.name + "' depends on time t, so its work needs the motion in time",
                     "use an impulse-momentum analysis, or give the " + what + " as a function of the coordinates");
  if (auto phi = potential(m, Q)) {
    // U = Φ(q₂) − Φ(q₁) when Σ Q_i dq_i = dΦ (constant forces and couples, gradient fields)
    w.U = m.bind(*phi, s2) - m.bind(*phi, s1);
    w.how = how;
    return w;
  }
  auto p = one_dof_path(m);
  if (!p)
    throw SceneError(e.pos, "the work of '" + e.name + "' depends on the path, and the scene has more than one degree of freedom",
                     "add constraints so one coordinate fixes the motion, or make the " + what + " constant");
  // U = ∫ Σ Q_j(q(s)) ∂q_j/∂s ds along the one-coordinate path
  const symbol& s = m.coords[p->s].q;
  ex Qs = 0;
  for (std::size_t j = 0; j < m.coords.size(); ++j) {
    ex qj = j == p->s ? ex(s) : m.coords[j].q.subs(p->q_of_s);
    Qs += Q[j].subs(p->q_of_s) * qj.diff(s);
  }
  // a force written with abs (max, min) of the motion: split the path where each |g(s)| turns
  // (g(s₀) = 0 between the ends, the switching point) and integrate each piece with |g| = ±g
  if (Qs.has(abs(wild())))
    if (auto U = piecewise_work(m, Qs, s, s1, s2)) {
      w.U = *U;
      w.how = "U = integral along " + m.coords[p->s].name + ", split where the force switches";
      return w;
    }
  auto F = antiderivative(model::trig_simplify(Qs), s);
  if (!F) {
    // no elementary antiderivative: U = ∫ Q ds numerically, where both ends and every parameter
    // in it are known numbers (then marked "no closed form", as a numeric root is)
    const exmap given = m.given_values(), vals = m.parameter_values();
    auto a = numerics::evaluate(m.bind(ex(s), s1).subs(given), vals, 60);
    auto b = numerics::evaluate(m.bind(ex(s), s2).subs(given), vals, 60);
    if ((!a || !b) && Qs.has(abs(wild())))
      throw SceneError(e.pos, "the force of '" + e.name + "' switches along the path (it has abs, max or min), and " + m.coords[p->s].name +
                                  " is not known at state '" + m.states[!a ? s1 : s2].name + "', so its work cannot be split where it switches",
                       "give " + m.coords[p->s].name + " at that state; a bumper or a launcher whose end is unknown is a spring with "
                       "'acts: compression'");
    if (!a || !b)
      throw SceneError(e.pos, "the work of '" + e.name + "' has no closed form integral along " + m.coords[p->s].name +
                                  ", and its value cannot be taken numerically: " + m.coords[p->s].name + " is not known at state '" +
                                  m.states[!a ? s1 : s2].name + "'",
                       "give " + m.coords[p->s].name + " at both states, or write the " + what +
                           " in a form with an elementary antiderivative");
    auto I = numerics::integrate(model::trig_simplify(Qs), s, *a, *b, vals, kIntegralDigits);
    if (!I)
      throw SceneError(e.pos, "the work of '" + e.name + "' has no closed form integral along " + m.coords[p->s].name +
                                  ", and its numeric value does not settle between the states (a parameter without a value, or a "
                                  "singular integrand?)",
                       "give every parameter in it a value, or write the " + what + " in a form with an elementary antiderivative");
    w.U = *I;
    w.how = "U = integral along " + m.coords[p->s].name + ", numerically (no closed form)";
    return w;
  }
  w.U = m.bind(*F, s2) - m.bind(*F, s1);
  w.how = "U = integral along " + m.coords[p->s].name;
  return w;
}

Work friction_work(const Model& m, const Effect& e, std::optional<int> declared, const ex& c,
                   const std::function<ex(const Path&)>& rate, const std::string& how, int s1, int s2,
                   const Knowledge& k) {
  Work w;
  w.effect = e.name;
  auto p = one_dof_path(m);
  if (!p)
    throw SceneError(e.pos, "the work of friction '" + e.name + "' depends on the path, and the scene has more than one degree of freedom",
                     "add constraints so one coordinate fixes the motion");
  const symbol& s = m.coords[p->s].q;
  // distance slid ℓ(s) with dℓ/ds = |∂r_P/∂s| (or angle turned, |∂φ/∂s|)
  auto L = antiderivative(rate(*p), s);
  if (!L)
    throw SceneError(e.pos, "the distance slid under '" + e.name + "' has no closed form along " + m.coords[p->s].name,
                     "describe the sliding point so its path is straight or circular");
  int sigma = motion_sign(m, e, declared, *p, s1, s2, k);
  // U = −μN · σ (ℓ(s₂) − ℓ(s₁))   (friction against the motion, monotone between the states)
  w.U = -c * sigma * (m.bind(*L, s2) - m.bind(*L, s1));
  w.how = how;
  return w;
}

}  // namespace kinergy::principles
