#include "kinergy/solve/solver.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>
#include <tuple>

#include "kinergy/common/interrupt.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/digits.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/roots.hpp"
#include "kinergy/numeric/trace.hpp"

namespace kinergy::solve {

using namespace GiNaC;
using principles::Equation;

namespace {



constexpr int kWork = 40;  // working digits for decisions

std::optional<numeric> num(const ex& e, const exmap& env) { return numerics::evaluate(e, env, kWork); }


/// Zero to working precision (relative to the size of its terms)?
bool numerically_zero(const ex& e, const exmap& env, bool& known) {
  auto z = numerics::negligible(e, env, kWork);
  known = z.has_value();
  return z.value_or(false);
}

struct State {
  Branch b;
  std::vector<Equation> eqs;
  /// Signs the branch took for granted: each expression ≥ 0 on its solution (a √(p²) or |p| taken
  /// as ±p), or the branch is no solution.
  std::vector<ex> signs;
};

/// A √(c p²) or |p| in e whose p holds one of `unknowns` (c free of them): (the term, c, p).
std::optional<std::tuple<ex, ex, ex>> root_of_square(const ex& e, const std::function<bool(const ex&)>& has_unknown) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    const ex& x = *it;
    if (is_ex_the_function(x, abs) && has_unknown(x.op(0))) return std::make_tuple(x, ex(1), x.op(0));
    if (!is_a<power>(x) || !x.op(1).is_equal(numeric(1, 2)) || !has_unknown(x.op(0))) continue;
    ex f;
    try {
      ex nd = numer_denom(model::trig_simplify(x.op(0)));
      f = model::factor_any(nd.op(0)) / model::factor_any(nd.op(1));
    } catch (const std::exception&) {
      continue;
    }
    ex c = 1, p;
    for (auto& y : model::factors_of(f)) {
      if (p.is_zero() && is_a<power>(y) && y.op(1).is_equal(2) && has_unknown(y.op(0))) p = y.op(0);
      else c *= y;
    }
    if (!p.is_zero() && !has_unknown(c)) return std::make_tuple(x, c, p);
  }
  return std::nullopt;
}

class Solver {
public:
  explicit Solver(const Problem& p) : p_(p) {}

  std::vector<Branch> run() {
    State s;
    for (auto& e : p_.equations) {
      Equation q = e;
      try {
        q.lhs = q.lhs.subs(p_.given);
        q.rhs = q.rhs.subs(p_.given);
      } catch (const std::exception& err) {
        throw SolveError("the " + q.label + " is undefined for the values given at the states (" + model::math_fault(err) + ")",
                         "check the values given at the states (a position where a formula divides by zero?)", q.pos);
      }
      s.eqs.push_back(q);
    }
    work_.push_back(s);
    std::optional<SolveError> last;
    while (!work_.empty()) {
      poll_interrupt();
      State st = std::move(work_.back());
      work_.pop_back();
      try {
        step(st);
      } catch (const SolveError& e) {
        last = e;
      }
      if (done_.size() + work_.size() > 32)
        throw SolveError("too many solution branches", "add root choices to the results", {});
    }
    if (done_.empty()) {
      if (last) throw *last;
      throw SolveError("no solution", "check the states and analyses", {});
    }
    return done_;
  }

private:
  const Problem& p_;

  /// Whether e's value is fixed by the given values (no stand-in for a parameter without one).
  bool decided(const ex& e) const {
    for (auto& s : p_.stand_ins)
      if (e.has(s)) return false;
    return true;
  }
  std::vector<State> work_;
  std::vector<Branch> done_;

  std::vector<ex> products_;  ///< unknowns standing for a product of two (w = F t)
  /// Residuals with unknowns found not to vanish identically: each step prunes every equation
  /// again, and most are as they were (an unknown solved touches only the equations that hold it)
  std::set<ex, GiNaC::ex_is_less> not_identities_;

  std::vector<ex> unknowns_in(const ex& e) const {
    std::vector<ex> u;
    for (auto& x : p_.unknowns)
      if (e.has(x)) u.push_back(x);
    for (auto& x : products_)
      if (e.has(x)) u.push_back(x);
    return u;
  }

  bool free_of_unknowns(const ex& e) const {
    for (auto& x : p_.unknowns)
      if (e.has(x)) return false;
    for (auto& x : products_)
      if (e.has(x)) return false;
    return true;
  }

  void assign(State& st, const ex& u, const ex& value, const std::string& how) {
    ex v = value;
    try {
      for (auto& [k, val] : st.b.sol) val = val.subs(u == v);
    } catch (const std::exception& err) {
      throw SolveError("the solution " + model::text(u) + " = " + model::text(v) + " makes an earlier result undefined (" + model::math_fault(err) + ")",
                       "check the values given at the states", {});
    }
    st.b.sol[u] = v;
    for (auto& q : st.eqs) {
      try {
        q.lhs = q.lhs.subs(u == v);
        q.rhs = q.rhs.subs(u == v);
      } catch (const std::exception& err) {
        // Newton's law at a state where a force of the motion has no value: kinetic friction
        // where nothing slides (its direction v/|v| is 0/0), a drive at rest
        const bool at_instant = q.principle == "kinetics";
        throw SolveError("the " + q.label + " is undefined when " + model::text(u) + " = " + model::text(v) + " (" + model::math_fault(err) + ")" +
                             (at_instant ? ": a kinetic friction where nothing slides (or a drive at rest) has no force there" : ""),
                         at_instant ? "take the kinetics at a state where it slides, or hold the rolling there with a constraint effect "
                                      "(its force is then a reaction: F(name)@S)"
                                    : "check the values given at the states",
                         q.pos);
      }
    }
    st.b.steps.push_back(model::text(u) + " from " + how);
  }

  // Drop satisfied equations; an equation without unknowns that does not hold kills the branch.
  void prune(State& st) {
    std::vector<Equation> keep;
    for (auto& q : st.eqs) {
      ex r = q.residual();
      if (!free_of_unknowns(r)) {
        // an equation that reduces to 0 = 0 once the solved unknowns are in says nothing more
        if (model::ex_size(r) < 300 && !not_identities_.count(r)) {
          if (normal(r).is_zero()) continue;
          not_identities_.insert(r);
        }
        keep.push_back(q);
        continue;
      }
      if (model::trig_simplify(r).is_zero()) continue;
      bool known = false;
      if (numerically_zero(r, p_.env, known)) continue;
      if (!known) continue;  // cannot tell (symbolic parameters): trust it
      auto v = num(r, p_.env);
      throw SolveError("the equations contradict each other: the " + q.label + " is off by " +
                           numerics::format(*v, 6) + " (in SI units)",
                       "check the values given at the states; one of them cannot hold with the others", q.pos);
    }
    st.eqs = keep;
  }

  void step(State st) {
    for (;;) {
      poll_interrupt();
      prune(st);
      if (st.eqs.empty()) {
        // a sign taken for granted that the solution breaks: not a solution (the other case is)
        for (auto& sg : st.signs) {
          ex v;
          try {
            v = sg.subs(st.b.sol).subs(p_.given);
          } catch (const std::exception&) {
            continue;
          }
          bool known = false;
          auto x = num(v, p_.env);
          if (x && x->is_negative() && !numerically_zero(v, p_.env, known)) return;
        }
        for (auto& w : products_) st.b.sol.erase(w);  // stand-ins, not results
        done_.push_back(st.b);
        return;
      }
      if (linear_step(st)) continue;
      if (product_step(st)) continue;
      single_unknown_step(st);
      return;  // the branches it made are on the work list
    }
  }

  // An equation linear in an unknown u with a coefficient free of unknowns: u = −b/a.
  bool linear_step(State& st) {
    int best = -1;
    ex best_u, best_a, best_b;
    std::size_t best_n = 0;
    for (std::size_t i = 0; i < st.eqs.size(); ++i) {
      ex r = st.eqs[i].residual();
      auto us = unknowns_in(r);
      for (auto& u : us) {
        ex a = r.diff(ex_to<symbol>(u));
        if (a.has(u) || !free_of_unknowns(a)) continue;
        bool known = false;
        if (a.is_zero() || numerically_zero(a, p_.env, known)) continue;
        if (best < 0 || us.size() < best_n) {
          best = static_cast<int>(i);
          best_u = u;
          best_a = a;
          best_b = r.subs(u == 0);
          best_n = us.size();
        }
        break;
      }
    }
    if (best < 0) return false;
    std::string how = st.eqs[best].label + " (linear)";
    st.eqs.erase(st.eqs.begin() + best);  // used up: it holds by construction
    assign(st, best_u, model::tidy(-best_b / best_a), how);
    return true;
  }

  // A product of unknowns that stands together: when an unknown F appears, in every equation
  // that has it, only where F t does (t another unknown) — an average force and a duration, in
  // F (t₂ − t₁) — then w = F t is an unknown of its own and F = w/t: the system becomes linear
  // in w (and t) where it was bilinear in F and t.
  bool product_step(State& st) {
    std::vector<ex> all;
    for (auto& q : st.eqs)
      for (auto& u : unknowns_in(q.residual()))
        if (std::find_if(all.begin(), all.end(), [&](const ex& x) { return x.is_equal(u); }) == all.end()) all.push_back(u);
    for (auto& F : all)
      for (auto& t : all) {
        if (F.is_equal(t)) continue;
        GiNaC::realsymbol w(model::text(F) + "*" + model::text(t));
        bool ok = true, progress = false;
        for (auto& q : st.eqs) {
          ex r = q.residual();
          if (!r.has(F)) continue;
          ex r2;
          try {
            r2 = normal(r.subs(F == w / t));
          } catch (const std::exception&) {
            ok = false;
            break;
          }
          // F gone for good, and t not divided by: r is a polynomial in F t (and t)
          if (r2.has(F) || numer_denom(r2).op(1).has(t)) {
            ok = false;
            break;
          }
          ex a = r2.diff(w);
          bool known = false;
          if (!a.has(w) && free_of_unknowns(a) && !a.is_zero() && !numerically_zero(a, p_.env, known)) progress = true;
        }
        if (!ok || !progress) continue;
        products_.push_back(w);
        assign(st, F, w / t, model::text(t) + " (product)");
        return true;
      }
    return false;
  }

  // One branch per root. The equation solved holds there by construction and leaves the branch
  // (its residual with a float root folds to one number that no relative test can judge).
  void branch(const State& st, const Equation& solved, const ex& u, const std::vector<ex>& roots,
              const std::string& how, bool numeric_root = false, const std::vector<NumericRoot>& found = {}) {
    for (std::size_t k = 0; k < roots.size(); ++k) {
      const ex& r = roots[k];
      State s = st;
      for (std::size_t i = 0; i < s.eqs.size(); ++i)
        if (s.eqs[i].residual().is_equal(solved.residual())) {
          s.eqs.erase(s.eqs.begin() + static_cast<long>(i));
          break;
        }
      assign(s, u, r, how);
      if (numeric_root) s.b.numeric_only.insert(u);
      if (k < found.size()) s.b.roots[u] = found[k];
      work_.push_back(std::move(s));
    }
  }

  void single_unknown_step(const State& st) {
    // the equation with fewest unknowns; prefer one unknown
    int best = -1;
    std::size_t best_n = 0;
    for (std::size_t i = 0; i < st.eqs.size(); ++i) {
      auto n = unknowns_in(st.eqs[i].residual()).size();
      if (best < 0 || n < best_n) {
        best = static_cast<int>(i);
        best_n = n;
      }
    }
    const Equation& q = st.eqs[best];
    ex r = q.residual();
    auto us = unknowns_in(r);
    if (us.size() != 1) {
      if (square_step(st)) return;
      std::string names;
      for (auto& u : us) names += (names.empty() ? "" : ", ") + model::text(u);
      throw SolveError("cannot solve the " + q.label + ": it is nonlinear in several unknowns (" + names + ")",
                       "give more values at the states, or add an analysis that fixes one of them", q.pos);
    }
    const symbol& u = ex_to<symbol>(us[0]);
    std::string how = q.label;
    // √(c p²) = √c |p| and |p| with p holding the unknown: one case for each sign of p, each
    // checked on its solution (p ≥ 0, p ≤ 0), so the equation keeps a closed form
    if (auto sq = root_of_square(r, [&](const ex& x) { return x.has(u); })) {
      const auto& [term, c, p] = *sq;
      for (int sign : {1, -1}) {
        State s = st;
        const ex value = sign * sqrt(c) * p;
        for (auto& e : s.eqs) {
          e.lhs = e.lhs.subs(term == value);
          e.rhs = e.rhs.subs(term == value);
        }
        s.signs.push_back(sign * p);
        s.b.steps.push_back(model::text(term) + " taken as " + model::text(value) + " (checked on the solution)");
        work_.push_back(std::move(s));
      }
      return;
    }
    // quadratic: a u² + b u + c = 0
    ex d2 = r.diff(u, 2);
    if (!d2.has(u) && !d2.is_zero() && r.diff(u, 3).is_zero()) {
      ex a = d2 / 2, b = r.diff(u).subs(u == 0), c = r.subs(u == 0);
      bool known = false;
      if (b.is_zero() || numerically_zero(b, p_.env, known)) {
        ex sq = model::tidy(-c) / model::tidy(a);  // u = ±√(−c/a), numerator and denominator tidied apart
        if (model::ex_size(sq) < 600) sq = model::tidy(sq);
        auto v = decided(sq) ? num(sq, p_.env) : std::nullopt;
        if (v && v->is_negative() && p_.impulses.count(u))
          // an impulse stands for the velocity it is tied to (v⁺ − v⁻ = J/m): say it of the motion
          throw SolveError("the " + q.label + " has no real solution: the motion cannot reach that state with these values "
                               "(its kinetic energy would be negative, and the impulse " + model::text(u) + " that depends on it imaginary)",
                           "check the states and parameters: the energy given at the start is not enough", q.pos);
        if (v && v->is_negative())
          throw SolveError("the " + q.label + " has no real solution for " + model::text(u) + ": " + model::text(u) +
                               "^2 would be " + numerics::format(*v, 6) + " (negative)",
                           "the state cannot be reached with these values (the kinetic energy would be negative); check the states and parameters",
                           q.pos);
        ex root = sqrt(sq);
        branch(st, q, u, {root, -root}, how + " (quadratic)");
        return;
      }
      ex disc = model::tidy(b * b - 4 * a * c);
      auto v = decided(disc) ? num(disc, p_.env) : std::nullopt;
      if (v && v->is_negative())
        throw SolveError("the " + q.label + " has no real solution for " + model::text(u),
                         "the state cannot be reached with these values; check the states and parameters", q.pos);
      branch(st, q, u, {model::tidy((-b + sqrt(disc)) / (2 * a)), model::tidy((-b - sqrt(disc)) / (2 * a))},
             how + " (quadratic)");
      return;
    }
    // a product is zero where one of its factors is: sin θ (3 cos θ − 2) = 0 — each factor that
    // holds u solved on its own, one branch each
    auto [arg, rt] = one_trig_argument(r, u);
    {
      Equation qn = q;
      if (!arg.is_equal(u)) qn.lhs = rt, qn.rhs = 0;  // (its trigonometric parts in the one argument, for factoring)
      if (factor_step(st, qn, u)) return;
    }
    // trigonometric: polynomial of degree ≤ 2 in sin(w), cos(w) or tan(w) alone, w = a u + b the
    // one argument (a, b free of unknowns; sin(−w) = −sin w, cos(−w) = cos w, tan(−w) = −tan w):
    // a rolling relation that puts θ = −r φ/(R + r) leaves sin(r φ/(R + r)); u = (w − b)/a
    symbol z("z");
    for (int kind = 0; kind < 3; ++kind) {
      ex f = kind == 0 ? sin(arg) : kind == 1 ? cos(arg) : tan(arg);
      ex w = rt.subs(f == z);
      if (w.has(u) || !w.is_polynomial(z) || w.degree(z) < 1 || w.degree(z) > 2) continue;
      std::vector<ex> zs;
      if (w.degree(z) == 1) {
        zs.push_back(model::tidy(-w.subs(z == 0) / w.diff(z)));
      } else {
        ex a = w.diff(z, 2) / 2, b = w.diff(z).subs(z == 0), c = w.subs(z == 0);
        ex disc = model::tidy(b * b - 4 * a * c);
        auto v = num(disc, p_.env);
        if (v && v->is_negative()) continue;
        zs = {model::tidy((-b + sqrt(disc)) / (2 * a)), model::tidy((-b - sqrt(disc)) / (2 * a))};
      }
      std::vector<ex> roots;
      for (auto& zz : zs) {
        auto zv = num(zz, p_.env);
        if (kind < 2 && zv && abs(*zv) > 1) continue;  // |sin|, |cos| ≤ 1
        if (kind == 0) roots.insert(roots.end(), {asin(zz), Pi - asin(zz)});
        else if (kind == 1) roots.insert(roots.end(), {acos(zz), -acos(zz)});
        else roots.insert(roots.end(), {atan(zz), atan(zz) + Pi});
      }
      if (!arg.is_equal(u)) {
        // w = a u + b  ⇒  u = (w − b)/a
        const ex a = arg.diff(u), b = arg.subs(u == 0);
        for (auto& x : roots) x = model::tidy((x - b) / a);
      }
      if (roots.empty())
        throw SolveError("the " + q.label + " has no real solution for " + model::text(u),
                         "the position cannot be reached with these values; check the states and parameters", q.pos);
      branch(st, q, u, roots, how + " (trigonometric)");
      return;
    }
    if (sinusoid(st, q, u, arg, rt, how)) return;
    numeric_roots(st, q, u);
  }

  // A cos w + B sin w + C = 0 (A, B, C free of unknowns; a wheel pinned at a corner: where its
  // centre is above it), w = a u + b the one argument. With t = tan(w/2), cos w = (1 − t²)/(1 + t²),
  // sin w = 2t/(1 + t²):  (C − A) t² + 2B t + (A + C) = 0, and w = 2 atan t for each real root
  // (w = π, where t is infinite, when C = A).
  bool sinusoid(const State& st, const Equation& q, const symbol& u, const ex& arg, const ex& rt, const std::string& how) {
    symbol sn("sn"), cs("cs");
    const ex w = expand(rt.subs(lst{sin(arg) == sn, cos(arg) == cs}));
    if (w.has(u) || !w.is_polynomial(lst{sn, cs}) || w.degree(sn) != 1 || w.degree(cs) != 1 || !w.diff(sn).diff(cs).is_zero()) return false;
    const ex A = model::tidy(w.diff(cs)), B = model::tidy(w.diff(sn)), C = model::tidy(w.subs(lst{sn == 0, cs == 0}));
    if (!free_of_unknowns(A) || !free_of_unknowns(B) || !free_of_unknowns(C)) return false;
    std::vector<ex> roots;
    const ex a2 = model::tidy(C - A);
    bool known = false;
    if (C.is_zero() && !numerically_zero(B, p_.env, known)) {
      // A cos w + B sin w = 0: (cos w, sin w) = ±(B, −A)/R, R = √(A² + B²), so w = −sgn(A) acos(B/R)
      // and that + π (acos keeps cos w as it stands: −acos((r − h)/r), not an arctangent of roots)
      const ex R = model::root_simplify(model::tidy(sqrt(model::tidy(A * A + B * B))));
      const auto a = num(A, p_.env);
      const ex w0 = a && !a->is_zero() ? (a->is_positive() ? -1 : 1) * acos(model::tidy(B / R)) : atan(model::tidy(-A / B));
      roots = {w0, w0 + Pi};
    } else if (numerically_zero(a2, p_.env, known)) {
      // B t + A = 0 (the other root is w = π)
      if (numerically_zero(B, p_.env, known)) return false;
      roots = {model::tidy(2 * atan(-A / B)), Pi};
    } else {
      const ex disc = model::tidy(B * B - (C - A) * (A + C));
      auto v = num(disc, p_.env);
      if (!v) return false;
      if (v->is_negative())
        throw SolveError("the " + q.label + " has no real solution for " + model::text(u), "the position cannot be reached with these values; check the states and parameters",
                         q.pos);
      for (const ex& t : {model::tidy((-B + sqrt(disc)) / a2), model::tidy((-B - sqrt(disc)) / a2)}) roots.push_back(model::tidy(2 * atan(t)));
    }
    if (!arg.is_equal(u)) {
      const ex a = arg.diff(u), b = arg.subs(u == 0);  // w = a u + b  ⇒  u = (w − b)/a
      for (auto& x : roots) x = model::tidy((x - b) / a);
    }
    branch(st, q, u, roots, how + " (trigonometric)");
    return true;
  }

  // Several unknowns, and an equation in which one of them, u, appears only squared with a
  // coefficient free of unknowns: a u² + c = 0 with c holding the others ⇒ u = ±√(−c/a), one
  // branch each, −c/a ≥ 0 checked on the solution (energy, m v²/2 = m g R (1 − cos θ), gives the
  // rate in terms of the position that another equation then fixes).
  // Only where the equations left are as many as their unknowns: with fewer, the system is
  // underdetermined, and saying so beats a branch per sign.
  bool square_step(const State& st) {
    std::vector<ex> all;
    for (auto& q : st.eqs)
      for (auto& u : unknowns_in(q.residual()))
        if (std::none_of(all.begin(), all.end(), [&](const ex& x) { return x.is_equal(u); })) all.push_back(u);
    if (all.size() > st.eqs.size()) return false;
    for (auto& q : st.eqs) {
      const ex r = q.residual();
      for (auto& x : unknowns_in(r)) {
        if (!is_a<symbol>(x)) continue;
        const symbol& u = ex_to<symbol>(x);
        const ex d2 = r.diff(u, 2);
        if (d2.is_zero() || d2.has(u) || !free_of_unknowns(d2) || !r.diff(u, 3).is_zero()) continue;
        if (!normal(r.diff(u).subs(u == 0)).is_zero()) continue;  // a term odd in u
        bool known = false;
        if (numerically_zero(d2, p_.env, known)) continue;
        const ex sq = model::tidy(-r.subs(u == 0)) / model::tidy(d2 / 2);
        State s = st;
        s.signs.push_back(sq);
        branch(s, q, u, {sqrt(sq), -sqrt(sq)}, q.label + " (its square)");
        return true;
      }
    }
    return false;
  }

  /// The one argument w = a u + b of every sin, cos and tan in r that holds u (a, b free of
  /// unknowns, a ≠ 0), with r rewritten in it (sin(−w) → −sin w, cos(−w) → cos w, tan(−w) →
  /// −tan w); (u, r) where there is no such one argument.
  std::pair<ex, ex> one_trig_argument(const ex& r, const symbol& u) const {
    std::optional<ex> w;
    for (auto it = r.preorder_begin(); it != r.preorder_end(); ++it) {
      const ex& x = *it;
      if (!(is_ex_the_function(x, sin) || is_ex_the_function(x, cos) || is_ex_the_function(x, tan)) || !x.op(0).has(u)) continue;
      const ex a = x.op(0).expand();
      if (!w) {
        const ex d = a.diff(u);
        if (d.has(u) || !free_of_unknowns(d) || d.is_zero() || !free_of_unknowns(a.subs(u == 0))) return {u, r};
        w = a;
      } else if (!(a - *w).expand().is_zero() && !(a + *w).expand().is_zero()) {
        return {u, r};
      }
    }
    if (!w || w->is_equal(u)) return {u, r};
    ex out = r;
    try {
      const ex mw = (-*w).expand();
      out = out.subs(lst{sin(mw) == -sin(*w), cos(mw) == cos(*w), tan(mw) == -tan(*w)}, subs_options::no_pattern);
      for (auto it = out.preorder_begin(); it != out.preorder_end(); ++it)
        if ((is_ex_the_function(*it, sin) || is_ex_the_function(*it, cos) || is_ex_the_function(*it, tan)) && it->op(0).has(u) &&
            !it->op(0).is_equal(*w))
          return {u, r};  // an argument written another way than w: left as it was
    } catch (const std::exception&) {
      return {u, r};
    }
    return {*w, out};
  }

  // u solved from each factor of q's residual that holds it, when it has two or more.
  bool factor_step(const State& st, const Equation& q, const symbol& u) {
    exvector parts;
    try {
      parts = model::factors_of(model::factor_any(numer_denom(q.residual()).op(0)));
    } catch (const std::exception&) {
      return false;
    }
    exvector with_u;
    for (auto& f : parts)
      if (f.has(u)) with_u.push_back(is_a<power>(f) && f.op(1).info(info_flags::posint) ? f.op(0) : f);
    if (with_u.size() < 2) return false;
    // each factor first (solved next), the equation itself kept: a root of a factor where the
    // rest is undefined (0/0: sin θ/tan θ at θ = 0) is then no root
    for (auto& f : with_u) {
      State s = st;
      s.eqs.insert(s.eqs.begin(), {f, 0, q.principle, q.label, q.pos});
      work_.push_back(std::move(s));
    }
    return true;
  }

  // No closed form: find the sign changes of the residual around a reference and refine.
  /// Residual at u = x with `digits` working digits (nothing where it is undefined).
  std::optional<numeric> residual_at(const ex& r, const symbol& u, const numeric& x, int digits) const {
    exmap m = p_.env;
    m[u] = x;
    return numerics::evaluate(r, m, digits);
  }

  /// A root in [a, b] where the residual changes sign, at working precision.
  std::optional<numeric> refine(const ex& r, const symbol& u, const numeric& a, const numeric& b, const numeric& fa,
                                const numeric& fb) const {
    const int digits = kWork + 10;
    // first at 10 digits (a work integral by quadrature in doubles), then at the working digits
    return numerics::staged_root([&](const numeric& x) { return residual_at(r, u, x, 10); },
                                 [&](const numeric& x) { return residual_at(r, u, x, digits); }, a, b, fa, fb, numerics::tenth(kWork),
                                 numerics::tenth(300), digits);
  }

  // No closed form: find the sign changes of the residual around a reference and refine.
  void numeric_roots(const State& st, const Equation& q, const symbol& u) {
    // where a scan finds roots is no sign of a form a sweep could follow
    numerics::note_untraced("a numeric root of " + model::text(u) + " (found by a scan)");
    ex r = q.residual();
    double ref = 0;
    if (auto it = p_.reference.find(u); it != p_.reference.end())
      if (auto v = num(it->second, p_.env)) ref = v->to_double();
    double span = 10 * (1 + std::abs(ref));
    if (auto it = p_.ranges.find(u); it != p_.ranges.end()) {
      // the result's root range is where to look
      auto lo = num(it->second.first, p_.env), hi = num(it->second.second, p_.env);
      if (lo && hi && *lo < *hi) {
        ref = ((*lo + *hi) / 2).to_double();
        span = ((*hi - *lo) / 2).to_double();
      }
    }
    // a work integral taken by quadrature at each trial costs ~10³ evaluations: a coarser grid
    bool quadrature = false;
    for (auto it = r.preorder_begin(); it != r.preorder_end(); ++it) quadrature = quadrature || numerics::is_integral(*it);
    const int n = quadrature ? 100 : 2000;
    const int scan_digits = quadrature ? 6 : 20;  // the signs only: a quadrature at 6 digits is cheap
    std::vector<ex> roots;
    std::vector<NumericRoot> found;  // each root's bracket, for proving its digits later
    {
      const numerics::DigitsScope precision(kWork + 10);  // the scan's working precision, to its end
      auto keep = [&](const numeric& x, const numeric& lo, const numeric& hi) {
        // a root only where the residual vanishes against the size of its terms (not a pole)
        exmap at = p_.env;
        at[u] = x;
        bool known = false;
        if (numerically_zero(r, at, known) || !known) {
          roots.push_back(x);
          found.push_back({r, lo, hi});
        }
      };
      auto grid = [&](int i) { return numeric(ref) - numeric(span) + numeric(2 * span) * numeric(i, n); };
      // the sign changes on the grid (and its exact zeros), then the nine nearest the reference
      // refined: a residual with many roots (a pendulum against pin friction has two a turn) keeps
      // the ones about the motion, not the first nine from the grid's left end
      struct Bracket {
        numeric x0, x1;
        bool exact;
      };
      std::vector<Bracket> brackets;
      numeric x0 = grid(0);
      auto f0 = residual_at(r, u, x0, scan_digits);
      if (f0 && f0->is_zero()) brackets.push_back({x0, x0, true});
      for (int i = 1; i <= n; ++i) {
        poll_interrupt();  // (2000 residuals: Ctrl-C from Python stops the scan here)
        numeric x1 = grid(i);
        auto f1 = residual_at(r, u, x1, scan_digits);
        if (f1 && f1->is_zero()) brackets.push_back({x1, x1, true});  // exactly on the grid
        else if (f0 && f1 && !f0->is_zero() && (f0->is_negative() != f1->is_negative())) brackets.push_back({x0, x1, false});
        x0 = x1;
        f0 = f1;
      }
      const numeric centre(ref);
      std::stable_sort(brackets.begin(), brackets.end(), [&](const Bracket& p, const Bracket& q) {
        return abs((p.x0 + p.x1) / 2 - centre) < abs((q.x0 + q.x1) / 2 - centre);
      });
      for (auto& br : brackets) {
        if (roots.size() > 8) break;
        if (br.exact) {
          keep(br.x0, br.x0, br.x0);
          continue;
        }
        auto a = residual_at(r, u, br.x0, kWork + 10), b = residual_at(r, u, br.x1, kWork + 10);
        if (a && b) {
          auto x = refine(r, u, br.x0, br.x1, *a, *b);
          if (x) keep(*x, br.x0, br.x1);
        }
      }
    }
    if (roots.empty())
      throw SolveError("the " + q.label + " has no closed form for " + model::text(u) + " and no root was found near " +
                           numerics::format(numeric(ref), 6),
                       "give the unknown a range with root: {in: [lo, hi]} on the result", q.pos);
    branch(st, q, u, roots, q.label + " (numeric root, no closed form)", true, found);
  }
};

}  // namespace

std::vector<Branch> solve(const Problem& p) { return Solver(p).run(); }

}  // namespace kinergy::solve
