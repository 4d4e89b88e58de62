#include <algorithm>
#include <random>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/roots.hpp"
#include "kinergy/principles/principles.hpp"

namespace kinergy::principles {

/// Digits to which a work integral between known ends must settle as the scene is read (a check
/// that it has a value there: the value itself is taken when asked, to the digits asked).
constexpr int kIntegralCheckDigits = 20;

using namespace GiNaC;
using model::Effect;
using model::Model;

std::optional<ex> antiderivative(const ex& f, const symbol& s) { return model::antiderivative(f, s); }

// ---------------------------------------------------------------- paths

std::optional<Path> one_dof_path(const Model& m, int s1, int s2) {
  // the constraints that hold along the way (a cord gone slack at an earlier state does not)
  const auto cs = m.constraints_between(s1, s2);
  std::size_t n = m.coords.size();
  if (n == 0 || n - std::min(n, cs.size()) != 1 || cs.size() >= n)
    return std::nullopt;
  exmap sub;
  std::vector<bool> gone(n, false);
  for (auto& [c, pos] : cs) {
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
  // a force that switches (abs, max, min of the motion): its work is split where it switches
  // (piecewise_work), the only way an end the motion does not know yet is placed on its side
  for (auto& q : Q)
    if (q.has(abs(wild()))) return std::nullopt;
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

/// The sign σ of the motion a friction opposes between states s1 and s2. What the states tell
/// decides: each probe is a state-bound expression with the motion's sign (the change of a
/// coordinate, a rate at either state), known when given or found by an earlier analysis. A
/// declared direction (`direction:`) that they contradict is refused, naming both; one they do
/// not tell is taken, and checked on the solution: σ·probe ≥ 0 for every probe (`w.holds`), so a
/// wrong declaration is refused, never solved (friction would drive the motion). 0: not told, not
/// declared.
int friction_sign(const Model& m, const Effect& e, std::optional<int> declared, const std::vector<std::pair<ex, std::string>>& probes,
                  int s1, int s2, const Knowledge& k, Work& w) {
  const std::string S1 = m.states[s1].name, S2 = m.states[s2].name;
  const auto word = [](int s) { return std::string(s > 0 ? "positive" : "negative"); };
  for (auto& [probe, name] : probes) {
    auto v = k.value(probe);
    if (!v || v->is_zero()) continue;
    const int told = v->is_positive() ? 1 : -1;
    if (declared && *declared != told)
      throw SceneError(e.pos, "effect '" + e.name + "' declares 'direction: " + word(*declared) + "', but the motion from state '" + S1 +
                                  "' to '" + S2 + "' is " + word(told) + " (" + name + " = " + numerics::format(*v, 6) + ")",
                       "remove 'direction:' from '" + e.name + "' (the states tell it), or check the states");
    return told;
  }
  if (!declared) return 0;
  for (auto& [probe, name] : probes)
    w.holds.push_back({*declared * probe,
                       "effect '" + e.name + "' declares 'direction: " + word(*declared) + "', but the solution moves " + name +
                           " the other way (by {} in SI units): friction cannot drive the motion",
                       "give 'direction: " + word(-*declared) + "' on '" + e.name + "', or leave it out and give a rate at state '" + S1 +
                           "' or '" + S2 + "'",
                       e.pos, "effect '" + e.name + "' opposes the motion of " + name + " the declared way (" + word(*declared) + ")"});
  return *declared;
}

int motion_sign(const Model& m, const Effect& e, std::optional<int> declared, const Path& p, int s1, int s2,
                const Knowledge& k, Work& w) {
  const auto& c = m.coords[p.s];
  ex q1 = m.states[s1].sym.at(c.name).first, q2 = m.states[s2].sym.at(c.name).first;
  ex v1 = m.states[s1].sym.at(c.name).second, v2 = m.states[s2].sym.at(c.name).second;
  const std::string S1 = m.states[s1].name, S2 = m.states[s2].name;
  if (int sigma = friction_sign(m, e, declared,
                                {{q2 - q1, c.name + "@" + S2 + " - " + c.name + "@" + S1}, {v1, c.name + "_dot@" + S1}, {v2, c.name + "_dot@" + S2}},
                                s1, s2, k, w))
    return sigma;
  throw SceneError(e.pos, "effect '" + e.name + "': the direction of the motion from state '" + S1 +
                              "' to '" + S2 + "' is not known, so the sign of the friction work is not",
                   "give '" + c.name + "' at both states, a nonzero '" + c.name + "_dot', or 'direction: positive|negative' (of " +
                       c.name + ")");
}

}  // namespace

// ---------------------------------------------------------------- work

Work work(const Model& m, const Effect& e, int s1, int s2, const Knowledge& k) { return e.work(m, s1, s2, k); }

/// The zeros of g(s) strictly inside (lo, hi): sign changes on a grid of 512, refined to 40
/// digits; each as (closed form, value) — asin/acos of the solved sine or cosine when g is linear
/// in sin s or cos s alone and that closed form is the root found, else the number. Nothing when g
/// has no value somewhere on the grid, or touches zero without changing sign.
static std::optional<std::vector<std::pair<ex, numeric>>> switching_points(const ex& g, const symbol& s, const numeric& lo,
                                                                          const numeric& hi, const exmap& env) {
  std::vector<std::pair<ex, numeric>> out;
  exmap at = env;
  auto g_at = [&](const numeric& x) {
    at[s] = x;
    return numerics::evaluate(g, at, 40);
  };
  const int n = 512;
  std::optional<numeric> prev = g_at(lo);
  numeric x0 = lo;
  for (int i = 1; i <= n; ++i) {
    const numeric x1 = lo + (hi - lo) * numeric(i, n);
    auto f1 = g_at(x1);
    if (!prev || !f1) return std::nullopt;
    if (f1->is_zero() && i < n) return std::nullopt;  // exactly on the grid: a touch cannot be told from a crossing
    if (!prev->is_zero() && !f1->is_zero() && prev->is_negative() != f1->is_negative()) {
      auto r = numerics::bracketed_root(g_at, x0, x1, *prev, *f1, numerics::tenth(40), numerics::tenth(300), 50);
      if (!r) return std::nullopt;
      // a closed form: g = α sin s + β (or cos s), s₀ = asin(−β/α), π − asin(−β/α) (±acos)
      ex closed = *r;
      static const symbol z("z");
      const ex trig[2] = {sin(s), cos(s)};
      for (const ex& f : trig) {
        ex w = g.subs(f == z);
        if (w.has(s) || !w.is_polynomial(z) || w.degree(z) != 1) continue;
        ex c = -w.subs(z == 0) / w.diff(z);
        std::vector<ex> cands = f.is_equal(sin(s)) ? std::vector<ex>{asin(c), Pi - asin(c), asin(c) - Pi, asin(c) + 2 * Pi}
                                                   : std::vector<ex>{acos(c), -acos(c), 2 * Pi - acos(c), acos(c) - 2 * Pi};
        for (auto& k : cands) {
          auto v = numerics::evaluate(k, env, 40);
          if (v && abs(*v - *r) <= numerics::tenth(30) * (abs(*r) + 1)) {
            closed = k;
            break;
          }
        }
      }
      out.push_back({closed, *r});
    }
    x0 = x1;
    prev = f1;
  }
  return out;
}

/// The switching points (expression, value) of a force holding |g| for each g in `args`, along the
/// coordinate c from a to b (either may be unknown): a linear g's zero; a non-linear g's zeros
/// between the known ends, or toward an unknown end within a window on either side of the known
/// one (`window`, where they were looked for). Nothing when they cannot be had.
static std::optional<std::vector<std::pair<ex, numeric>>> switches_along(const std::vector<ex>& args, const model::Coordinate& c,
                                                                         const std::optional<numeric>& a, const std::optional<numeric>& b,
                                                                         const exmap& env,
                                                                         std::optional<std::pair<numeric, numeric>>& window) {
  const symbol& s = c.q;
  std::vector<std::pair<ex, numeric>> switches;
  for (auto& g : args) {
    ex d = g.diff(s);
    if (d.is_zero()) return std::nullopt;
    if (!d.has(s)) {
      ex s0 = normal(-g.subs(s == 0) / d);
      auto v = numerics::evaluate(s0, env, 40);
      if (!v) return std::nullopt;
      switches.push_back({s0, *v});
      continue;
    }
    // g not linear in s (a spring under a turning bar, d0 − a sin θ): its zeros between the two
    // known ends, found numerically and written in closed form where g is linear in sin s or cos s;
    // toward an unknown end, within a window on the side the motion goes (a turn of an angle, ten
    // times the known end's size of a length), the unknown end then checked to lie inside it
    numeric lo, hi;
    if (a && b) {
      lo = std::min(*a, *b);
      hi = std::max(*a, *b);
    } else {
      const numeric known = a ? *a : *b;
      const numeric span = units::si_name(c.dim).empty() ? ex_to<numeric>(evalf(2 * Pi)) : 10 * (abs(known) + 1);
      lo = known - span;
      hi = known + span;
      window = {lo, hi};
    }
    auto zeros = switching_points(g, s, lo, hi, env);
    if (!zeros) return std::nullopt;
    switches.insert(switches.end(), zeros->begin(), zeros->end());
  }
  return switches;
}

/// U = Σ over the pieces between consecutive cuts of ∫ Q ds, each |g| of `args` replaced by ±g
/// with the sign g has inside the piece. Nothing where a piece has no antiderivative.
static std::optional<ex> integrate_pieces(const ex& Q, const std::vector<ex>& args, const symbol& s,
                                          const std::vector<std::pair<ex, numeric>>& cuts, const exmap& env) {
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

/// ∫ Q ds from state s1 to s2 for Q holding |g(s)| with g linear in s (or, between two known
/// ends, any g whose zeros there are found): the ends (state values,
/// expressions of parameters) and the switching points s₀ = −g(0)/g′ between them, ordered by
/// their values; on each piece |g| = σ g with σ the sign of g at the piece's middle. A closed form
/// valid at the scene's values.
/// One end may be unknown (a bumper's greatest compression): the direction of the motion (the
/// sign of a rate given at a state) tells on which side of the known end it lies, and it is taken
/// past every switching point on that side (the body meets the bumper, or leaves the launcher) —
/// recorded in `holds` and checked on the solution, where a root that breaks it is dropped.
/// Nothing when both ends, a switching point or that direction have no value, or g is not linear.
static std::optional<ex> piecewise_work(const Model& m, const Effect& e, const ex& Q, const model::Coordinate& c, int s1, int s2,
                                        const Knowledge* know, Work& w, std::string& taken) {
  const int fewer = know ? know->fewer_switches : 0;
  const symbol& s = c.q;
  const exmap given = m.given_values(), env = m.numeric_environment();
  ex A = m.bind(ex(s), s1).subs(given), B = m.bind(ex(s), s2).subs(given);
  auto a = numerics::evaluate(A, env, 40), b = numerics::evaluate(B, env, 40);
  if (!a && !b) return std::nullopt;
  std::vector<ex> args;
  for (auto it = Q.preorder_begin(); it != Q.preorder_end(); ++it)
    if (is_ex_the_function(*it, abs) && it->op(0).has(s)) args.push_back(it->op(0));
  // the switching points: (expression, value)
  std::optional<std::pair<numeric, numeric>> window;  ///< where non-linear switches were looked for
  auto found = switches_along(args, c, a, b, env, window);
  if (!found) return std::nullopt;
  const std::vector<std::pair<ex, numeric>>& switches = *found;
  // the pieces' ends from the first state's end to the second's, in the order the motion meets them
  std::vector<std::pair<ex, numeric>> cuts;
  numeric beyond;  // a place past the last switching point (for the sign on the last piece)
  if (a && b) {
    cuts = {{A, *a}, {B, *b}};
    const numeric lo = std::min(*a, *b), hi = std::max(*a, *b);
    for (auto& c : switches)
      if (c.second > lo && c.second < hi) cuts.push_back(c);
    const bool up = *b >= *a;
    std::sort(cuts.begin(), cuts.end(), [&](auto& x, auto& y) { return up ? x.second < y.second : x.second > y.second; });
  } else {
    // σ: the direction of the motion from s1 to s2, from the sign of a rate given at a state, or
    // found by an earlier analysis
    std::optional<int> sigma;
    for (int st : {s1, s2}) {
      const ex rate = m.states[st].sym.at(c.name).second;
      auto v = numerics::evaluate(rate.subs(given), env, 40);
      if ((!v || v->is_zero()) && know) v = know->value(rate);
      if (!sigma && v && !v->is_zero()) sigma = v->is_positive() ? 1 : -1;
    }
    if (!sigma) return std::nullopt;
    const bool x_is_2 = !b;
    const int unknown = x_is_2 ? s2 : s1;
    const numeric k = x_is_2 ? *a : *b;
    const int side = x_is_2 ? *sigma : -*sigma;  // the unknown end lies on this side of the known one
    std::vector<std::pair<ex, numeric>> on_side;
    for (auto& sw : switches)
      if ((sw.second - k) * side > 0) on_side.push_back(sw);
    std::sort(on_side.begin(), on_side.end(), [&](auto& x, auto& y) { return (x.second - y.second) * side < 0; });
    ex X = x_is_2 ? B : A;
    w.switch_cases = static_cast<int>(on_side.size()) + 1;
    // the case taken: past all but the `fewer` farthest switching points, short of the next one
    std::optional<std::pair<ex, numeric>> next;
    if (std::size_t f = std::min(static_cast<std::size_t>(std::max(fewer, 0)), on_side.size()); f > 0) {
      next = on_side[on_side.size() - f];
      on_side.resize(on_side.size() - f);
    }
    cuts.push_back({x_is_2 ? A : B, k});
    cuts.insert(cuts.end(), on_side.begin(), on_side.end());
    const numeric last = cuts.back().second;
    beyond = next ? (last + next->second) / 2 : last + side * (abs(last) + 1);
    if (next)
      // taken short of the next switching point: (s₀ − X) σ_side > 0
      w.holds.push_back({(next->first - X) * side,
                         "the force of '" + e.name + "' switches at " + c.name + " = " + numerics::format(next->second, 6) +
                             ", and the energy equation took state '" + m.states[unknown].name + "' short of it, but the solution puts " +
                             c.name + "@" + m.states[unknown].name + " {} " + units::si_name(c.dim) + " past it",
                         "give " + c.name + " at state '" + m.states[unknown].name + "'", e.pos,
                         c.name + "@" + m.states[unknown].name + " is short of where the force of '" + e.name + "' switches"});
    if (!on_side.empty()) {
      // taken past the farthest switching point crossed: (X − s₀) σ_side > 0
      w.holds.push_back({(X - on_side.back().first) * side,
                       "the force of '" + e.name + "' switches at " + c.name + " = " + numerics::format(on_side.back().second, 6) +
                           ", and the energy equation took state '" + m.states[unknown].name + "' past it, but the solution puts " +
                           c.name + "@" + m.states[unknown].name + " {} " + units::si_name(c.dim) + " short of it: the motion does not get there",
                       "give " + c.name + " at state '" + m.states[unknown].name + "', or switch the force off over this analysis ('off:')",
                       e.pos, c.name + "@" + m.states[unknown].name + " is past where the force of '" + e.name + "' switches"});
    }
    if (window) {
      // the switching points were looked for within the window only: the end must lie inside it
      const numeric edge = side > 0 ? window->second : window->first;
      w.holds.push_back({(ex(edge) - X) * side,
                         "the force of '" + e.name + "' was split where it switches within " + c.name + " = " + numerics::format(window->first, 6) +
                             " .. " + numerics::format(window->second, 6) + ", but the solution puts " + c.name + "@" + m.states[unknown].name +
                             " {} " + units::si_name(c.dim) + " beyond",
                         "give " + c.name + " at state '" + m.states[unknown].name + "'", e.pos,
                         c.name + "@" + m.states[unknown].name + " lies within the range searched for where '" + e.name + "' switches"});
    }
    cuts.push_back({X, beyond});
    if (!x_is_2) std::reverse(cuts.begin(), cuts.end());
    taken = "; state " + m.states[unknown].name + " taken " +
            (on_side.empty() ? std::string() : "past " + c.name + " = " + numerics::format(on_side.back().second, 6)) +
            (on_side.empty() || !next ? "" : " and ") + (next ? "short of " + c.name + " = " + numerics::format(next->second, 6) : "");
  }
  return integrate_pieces(Q, args, s, cuts, env);
}

Work generalized_force_work(const Model& m, const Effect& e, const std::string& what, const std::string& how, int s1,
                            int s2, const Knowledge* k) {
  std::vector<ex> Q;
  for (std::size_t i = 0; i < m.coords.size(); ++i) Q.push_back(e.generalized_force(m, i));
  return generalized_force_work(m, e, Q, what, how, s1, s2, k);
}

Work generalized_force_work(const Model& m, const Effect& e, const std::vector<ex>& Q, const std::string& what,
                            const std::string& how, int s1, int s2, const Knowledge* k) {
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
  auto p = one_dof_path(m, s1, s2);
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
  if (Qs.has(abs(wild()))) {
    std::string taken;
    if (auto U = piecewise_work(m, e, Qs, m.coords[p->s], s1, s2, k, w, taken)) {
      w.U = *U;
      w.ends_only = true;
      w.how = "U = integral along " + m.coords[p->s].name + ", split where the force switches" + taken;
      return w;
    }
  }
  auto F = antiderivative(model::trig_simplify(Qs), s);
  if (!F) {
    // no elementary antiderivative: U = ∫_{s(1)}^{s(2)} Q ds held as integral(Q, ξ, s₁, s₂), as
    // erf would hold it; its value comes by quadrature (tanh–sinh in CLN, or Arb's rigorous
    // integration for proven digits), and where an end is unknown, by a numeric root for the end
    static const symbol xi("xi");
    const exmap given = m.given_values(), vals = m.parameter_values();
    auto a = numerics::evaluate(m.bind(ex(s), s1).subs(given), vals, 60);
    auto b = numerics::evaluate(m.bind(ex(s), s2).subs(given), vals, 60);
    if ((!a || !b) && Qs.has(abs(wild())))
      throw SceneError(e.pos, "the force of '" + e.name + "' switches along the path (it has abs, max or min), and " + m.coords[p->s].name +
                                  " is not known at state '" + m.states[!a ? s1 : s2].name + "'" + (!a && !b ? " nor at '" + m.states[s2].name + "'" : ", nor the direction of the motion") +
                                  ", so its work cannot be split where it switches",
                       "give " + m.coords[p->s].name + " at " + (!a && !b ? "one of the states" : "that state") +
                           (!a && !b ? std::string() : ", or a nonzero " + m.coords[p->s].name + "_dot at a state"));
    w.U = numerics::integral_of(Qs.subs(s == xi), xi, m.bind(ex(s), s1).subs(given), m.bind(ex(s), s2).subs(given));
    if (!a || !b) {
      // an end unknown: the integral takes its value once the root search gives the end a number
      w.how = "U = integral along " + m.coords[p->s].name + ", numerically at each trial end (no elementary antiderivative)";
      return w;
    }
    // both ends known: the integral must have a value there (checked once, as the scene is read)
    if (!numerics::integrate(model::trig_simplify(Qs), s, *a, *b, vals, kIntegralCheckDigits))
      throw SceneError(e.pos, "the work of '" + e.name + "' has no closed form integral along " + m.coords[p->s].name +
                                  ", and its numeric value does not settle between the states (a parameter without a value, or a "
                                  "singular integrand?)",
                       "give every parameter in it a value, or write the " + what + " in a form with an elementary antiderivative");
    w.how = "U = integral along " + m.coords[p->s].name + ", held as an integral (no elementary antiderivative)";
    return w;
  }
  w.U = m.bind(*F, s2) - m.bind(*F, s1);
  w.how = "U = integral along " + m.coords[p->s].name;
  return w;
}

std::optional<Work> exact_slip_work(const Model& m, const Effect& e, std::optional<int> declared, const ex& c, const ex& v,
                                    const std::string& how, int s1, int s2, const Knowledge& k, const std::optional<ex>& moved) {
  // f with df/dt = r = Σ a_i q̇_i (a_i = ∂r/∂q̇_i, free of the rates), when there is one
  auto integral = [&](const ex& r) -> std::optional<ex> {
    std::vector<ex> a;
    for (auto& co : m.coords) {
      ex ai = r.diff(co.qd);
      for (auto& x : m.coords)
        if (ai.has(x.qd)) return std::nullopt;
      a.push_back(ai);
    }
    return potential(m, a);
  };
  auto f = integral(v);
  if (!f) return std::nullopt;
  auto g = moved ? integral(*moved) : f;
  if (!g) return std::nullopt;
  Work w;
  // the slip's sign at either state, or from the change of f (the slip keeps its sign between the states)
  const std::string S1 = m.states[s1].name, S2 = m.states[s2].name;
  int sigma = friction_sign(m, e, declared,
                            {{m.bind(v, s1), "the slip at state " + S1}, {m.bind(v, s2), "the slip at state " + S2},
                             {m.bind(*f, s2) - m.bind(*f, s1), "the slip from state " + S1 + " to " + S2}},
                            s1, s2, k, w);
  if (!sigma)
    throw SceneError(e.pos, "effect '" + e.name + "': the direction of the slip from state '" + m.states[s1].name + "' to '" +
                                m.states[s2].name + "' is not known, so the sign of the friction work is not",
                     "give the rates at one of the states, or 'direction: positive|negative' (of the slip)");
  // U = −c σ (f(q₂) − f(q₁)): the distance slid is |Δf|, the slip keeping its sign between the states
  w.effect = e.name;
  w.U = -c * sigma * (m.bind(*g, s2) - m.bind(*g, s1));
  w.how = how;
  return w;
}

Work friction_work(const Model& m, const Effect& e, std::optional<int> declared, const ex& c,
                   const std::function<ex(const Path&)>& rate, const std::string& how, int s1, int s2,
                   const Knowledge& k) {
  Work w;
  w.effect = e.name;
  auto p = one_dof_path(m, s1, s2);
  if (!p)
    throw SceneError(e.pos, "the work of friction '" + e.name + "' depends on the path, and the scene has more than one degree of freedom",
                     "add constraints so one coordinate fixes the motion");
  const symbol& s = m.coords[p->s].q;
  // distance slid ℓ(s) with dℓ/ds = |∂r_P/∂s| (or angle turned, |∂φ/∂s|)
  auto L = antiderivative(rate(*p), s);
  if (!L)
    throw SceneError(e.pos, "the distance slid under '" + e.name + "' has no closed form along " + m.coords[p->s].name,
                     "describe the sliding point so its path is straight or circular");
  int sigma = motion_sign(m, e, declared, *p, s1, s2, k, w);
  // U = −μN · σ (ℓ(s₂) − ℓ(s₁))   (friction against the motion, monotone between the states)
  w.U = -c * sigma * (m.bind(*L, s2) - m.bind(*L, s1));
  w.how = how;
  return w;
}

}  // namespace kinergy::principles
