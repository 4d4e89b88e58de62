#include "kinergy/problem.hpp"


#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <cln/real.h>
#include <cln/rational.h>

#include "kinergy/common/error.hpp"
#include "kinergy/model/poses.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/roots.hpp"
#include "kinergy/numeric/tape.hpp"
#include "kinergy/numeric/ball.hpp"
#include "kinergy/numeric/evaluator.hpp"
#include "kinergy/numeric/trace.hpp"
#include "kinergy/principles/kinetics.hpp"
#include "kinergy/print/plain.hpp"

namespace kinergy {

using namespace GiNaC;
using model::Model;

namespace {



/// The sign e is proven to keep wherever it is real, from its form alone (+1: e ≥ 0, −1: e ≤ 0,
/// 0: not proven): positive symbols and numbers, even powers, square roots (principal, ≥ 0),
/// exp, cosh, abs and acos; a product by its factors, a sum whose terms all share a sign.
int proven_sign(const ex& e) {
  if (is_a<numeric>(e)) return !ex_to<numeric>(e).is_real() ? 0 : ex_to<numeric>(e).is_negative() ? -1 : 1;
  if (is_a<symbol>(e)) return e.info(info_flags::positive) ? 1 : 0;
  if (is_a<GiNaC::power>(e)) {
    if (!is_a<numeric>(e.op(1))) return proven_sign(e.op(0)) == 1 ? 1 : 0;
    const numeric k = ex_to<numeric>(e.op(1));
    if (k.is_even()) return 1;
    if (k.is_integer()) return proven_sign(e.op(0));
    if (k.denom() == 2) return 1;  // a square root's powers, where real
    return proven_sign(e.op(0)) == 1 ? 1 : 0;
  }
  if (is_a<mul>(e)) {
    int s = 1;
    for (std::size_t i = 0; i < e.nops() && s; ++i) s *= proven_sign(e.op(i));
    return s;
  }
  if (is_a<add>(e)) {
    int s = proven_sign(e.op(0));
    for (std::size_t i = 1; i < e.nops() && s; ++i)
      if (proven_sign(e.op(i)) != s) s = 0;
    return s;
  }
  if (is_ex_the_function(e, exp) || is_ex_the_function(e, cosh) || is_ex_the_function(e, abs) || is_ex_the_function(e, acos)) return 1;
  return 0;
}

/// What decides the sign of e where it is not proven: e's factors of unproven sign (a
/// denominator's as a numerator: 1/x has x's sign), times the sign of the rest. e ≥ 0 exactly
/// where this is ≥ 0 (and e real).
ex sign_core(const ex& e) {
  if (!is_a<mul>(e)) return e;
  ex core = 1;
  int sign = 1;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    const ex f = e.op(i);
    if (const int s = proven_sign(f)) {
      sign *= s;
      continue;
    }
    // x^(-n) (n odd) has the sign of x
    if (is_a<GiNaC::power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_integer() && ex_to<numeric>(f.op(1)).is_negative())
      core *= f.op(0);
    else
      core *= f;
  }
  return sign * core;
}

bool has_float(const ex& e) {
  if (is_a<numeric>(e)) return !ex_to<numeric>(e).is_rational() && !ex_to<numeric>(e).is_crational();
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_float(e.op(i))) return true;
  return false;
}


/// ": the root for u of 0 = …" — the equation a result found by one numeric root solves, where
/// it is short enough to read in one line (its implicit form, for an author who wants one).
std::string solves_text(const Result& r) {
  if (r.roots.size() != 1) return "";
  const std::string eq = emit::plain(model::tidy(r.roots[0].residual)), u = emit::plain(r.roots[0].u);
  if (eq.size() > 240) return "";
  return ": the root for " + u + " of 0 = " + eq;
}

/// A result with neither a closed form nor a number (a numeric root of an equation in parameters
/// without values): so at every sample of them, so not tried at another.
struct NoFormError : SceneError {
  using SceneError::SceneError;
};

struct Selector {
  const Model& m;
  const exmap& env;
  const exmap& given_;  ///< every state's given values

  std::optional<numeric> find_value(const model::Find& f, const solve::Branch& b) const {
    const exmap& given = given_;
    ex v;
    try {
      v = f.value.subs(given).subs(b.sol);
    } catch (const std::exception&) {
      return std::nullopt;  // undefined on this branch (a division by zero): no value to compare
    }
    auto out = numerics::evaluate(v, env, 30);
    // no working precision up to the limit holds the argument of a sin or cos: the roots cannot
    // be told apart, and "(? or ?)" would not say why
    if (!out && numerics::beyond_precision(v, env, 30))
      throw SceneError(f.pos, "'" + f.name + "' cannot be evaluated (to choose among its solutions): it holds the sine or "
                                  "cosine of an angle too large for 20000 digits of working precision",
                       "give the angle reduced to one turn (below 360 deg or 2*pi rad)");
    return out;
  }

  /// Does value v (of form `form`, in the parameters) meet root choice r?
  bool meets(const model::RootSpec& r, const numeric& v, const ex& form) const {
    using K = model::RootSpec::Kind;
    if (r.kind == K::Positive) return v.is_positive();
    if (r.kind == K::Negative) return v.is_negative();
    if (r.kind == K::Interval) {
      auto lo = numerics::evaluate(r.lo, env, 30), hi = numerics::evaluate(r.hi, env, 30);
      // (the choice reads the signs of v − lo and hi − v: noted for a sweep)
      if (lo && numerics::tracing()) numerics::note(form - r.lo, v - *lo);
      if (hi && numerics::tracing()) numerics::note(r.hi - form, *hi - v);
      return lo && hi && *lo <= v && v <= *hi;
    }
    return true;
  }

  /// f's value on branch b as a form in the parameters (what find_value evaluates).
  ex find_form(const model::Find& f, const solve::Branch& b) const {
    try {
      return f.value.subs(given_).subs(b.sol);
    } catch (const std::exception&) {
      return f.value;
    }
  }

  // continuity: a rate keeps the sign of the motion between the states of each analysis; with
  // `rates_alone`, where the change of the coordinate is not known, the rate keeps its sign from
  // one state to the other (a tie-breaker for values no result asks for: a motion that does not
  // turn back between two times)
  bool continuous(const solve::Branch& b, bool rates_alone = false) const {
    const exmap& g = given_;
    auto val = [&](const ex& s) -> std::optional<numeric> {
      try {
        return numerics::evaluate(s.subs(g).subs(b.sol), env, 30);
      } catch (const std::exception&) {
        return std::nullopt;
      }
    };
    for (auto& a : m.analyses)
      for (auto& c : m.coords) {
        if (a.type->impulsive()) break;  // impulses may reverse a motion; energy alone keeps it going
        auto& [q1, v1] = m.states[a.from].sym.at(c.name);
        auto& [q2, v2] = m.states[a.to].sym.at(c.name);
        auto d = val(q2 - q1), r1 = val(v1), r2 = val(v2);
        // a sign, 0 within 1e-20 (each side of the band noted for a sweep)
        auto sgn = [](const std::optional<numeric>& x, const ex& form) {
          if (!x) return 0;
          const numeric tol = numerics::tenth(20);
          if (numerics::tracing()) {
            numerics::note(form - tol, *x - tol);
            numerics::note(form + tol, *x + tol);
          }
          double v = x->to_double();
          return v > 1e-20 ? 1 : (v < -1e-20 ? -1 : 0);
        };
        auto form = [&](const ex& s) {
          if (!numerics::tracing()) return s;  // (the forms only a sweep's trace reads)
          try {
            return s.subs(g).subs(b.sol);
          } catch (const std::exception&) {
            return s;
          }
        };
        int sd = sgn(d, form(q2 - q1)), s1 = sgn(r1, form(v1)), s2 = sgn(r2, form(v2));
        if (sd != 0 && s2 != 0 && sd != s2) return false;
        if (sd != 0 && s1 != 0 && sd != s1) return false;
        if (rates_alone && !d && s1 != 0 && s2 != 0 && s1 != s2) return false;
      }
    return true;
  }

  solve::Branch pick(const std::vector<solve::Branch>& bs) const {
    std::vector<solve::Branch> ok;
    for (auto& b : bs) {
      bool good = true;
      for (auto& f : m.finds) {
        if (f.root.kind == model::RootSpec::Kind::None) continue;
        auto v = find_value(f, b);
        if (v && !meets(f.root, *v, numerics::tracing() ? find_form(f, b) : ex())) good = false;
      }
      if (good) ok.push_back(b);
    }
    if (ok.empty()) {
      for (auto& f : m.finds)
        if (f.root.kind != model::RootSpec::Kind::None)
          throw SceneError(f.pos, "no solution has '" + f.name + "' with the root asked for",
                           "check 'root:' of '" + f.name + "' (the solutions are " + values(bs, f) + ")");
      throw SceneError(m.finds.empty() ? m.analyses.front().pos : m.finds.front().pos, "no solution meets the root choices",
                       "check the 'root:' options");
    }
    if (ok.size() > 1) {
      std::vector<solve::Branch> cont;
      for (auto& b : ok)
        if (continuous(b)) cont.push_back(b);
      if (!cont.empty()) ok = cont;
    }
    if (ok.size() > 1) {
      std::vector<solve::Branch> cont;
      for (auto& b : ok)
        if (continuous(b, true)) cont.push_back(b);
      if (!cont.empty()) ok = cont;
    }
    if (ok.size() > 1) ok = first_along_motion(ok);
    if (ok.size() > 1) {
      for (auto& f : m.finds) {
        auto v0 = find_value(f, ok[0]);
        for (std::size_t i = 1; i < ok.size(); ++i) {
          auto vi = find_value(f, ok[i]);
          bool same = v0 && vi && abs(*v0 - *vi) <= abs(*v0) * numeric(1, 1000000000) + numeric(1, 100000000);
          if (v0 && vi && numerics::tracing()) {
            const ex f0 = find_form(f, ok[0]);
            numerics::note(abs(f0) * numeric(1, 1000000000) + numeric(1, 100000000) - abs(f0 - find_form(f, ok[i])),
                           abs(*v0) * numeric(1, 1000000000) + numeric(1, 100000000) - abs(*v0 - *vi));
          }
          if (!same)
            throw SceneError(f.pos, "'" + f.name + "' has more than one solution (" + values(ok, f) + ")",
                             "choose one with 'root: positive', 'root: negative' or 'root: {in: [lo, hi]}'");
        }
      }
    }
    return ok.front();
  }

  /// A state defined by a condition (`where`) is the first along the motion at which it holds:
  /// of branches that differ only in where such a state lies, the one the motion meets first —
  /// the least time after the analysis' first state where its time is solved, else the least
  /// way along the coordinate that moves most (each branch's state already reached: the kinetic
  /// energy ≥ 0 on the way, and on the side the motion goes). Branches the rule cannot order
  /// are all kept (the caller says they differ).
  std::vector<solve::Branch> first_along_motion(const std::vector<solve::Branch>& bs) const {
    auto val = [&](const solve::Branch& b, const ex& s) -> std::optional<numeric> {
      try {
        auto v = numerics::evaluate(s.subs(given_).subs(b.sol), env, 30);
        if (v && v->is_real()) return v;
      } catch (const std::exception&) {
      }
      return std::nullopt;
    };
    std::vector<solve::Branch> out = bs;
    for (auto& a : m.analyses) {
      const model::State &S1 = m.states[a.from], &S2 = m.states[a.to];
      if (S2.where.empty() || a.type->impulsive() || out.size() < 2) continue;
      // the measure of how far along the motion state 2 lies, on each branch
      std::vector<std::optional<numeric>> way;
      std::vector<ex> way_form;  // (each in the parameters, for a sweep's notes)
      auto form = [&](const solve::Branch& b, const ex& s) {
        try {
          return s.subs(given_).subs(b.sol);
        } catch (const std::exception&) {
          return s;
        }
      };
      if (!given_.count(S2.t)) {
        for (auto& b : out) {
          way.push_back(val(b, S2.t - S1.t));
          way_form.push_back(form(b, S2.t - S1.t));
        }
      }
      if (std::any_of(way.begin(), way.end(), [](const auto& w) { return !w; })) {
        // no time solved: by the way the coordinates go
        way.clear();
        way_form.clear();
        // the coordinate that changes most between the states, relative to its size
        std::size_t p = 0;
        numeric best = -1;
        for (std::size_t i = 0; i < m.coords.size(); ++i)
          for (auto& b : out) {
            const auto& [q1, v1] = S1.sym.at(m.coords[i].name);
            const auto& [q2, v2] = S2.sym.at(m.coords[i].name);
            auto x1 = val(b, q1), x2 = val(b, q2);
            if (!x1 || !x2) continue;
            const numeric d = abs(*x2 - *x1) / std::max({abs(*x1), abs(*x2), numerics::tenth(30)});
            if (d > best) best = d, p = i;
          }
        const auto& [q1, v1] = S1.sym.at(m.coords[p].name);
        const auto& [q2, v2] = S2.sym.at(m.coords[p].name);
        for (auto& b : out) {
          auto d = val(b, q2 - q1);
          way.push_back(d ? std::optional<numeric>(abs(*d)) : std::nullopt);
          way_form.push_back(abs(form(b, q2 - q1)));
        }
      }
      if (std::any_of(way.begin(), way.end(), [](const auto& w) { return !w || w->is_negative(); })) continue;
      std::size_t at_least = 0;
      for (std::size_t i = 1; i < way.size(); ++i)
        if (*way[i] < *way[at_least]) at_least = i;
      const numeric least = *way[at_least], tol = numerics::tenth(20) * (abs(least) + 1);
      // (the same place within 1e-20 relative: branches that differ elsewhere stay for the caller)
      std::vector<solve::Branch> first;
      for (std::size_t i = 0; i < out.size(); ++i) {
        if (numerics::tracing()) numerics::note(way_form[i] - way_form[at_least] - tol, *way[i] - least - tol);
        if (*way[i] - least <= tol) first.push_back(out[i]);
      }
      out = first;
    }
    return out;
  }

  /// The branches' values of f, "1.5 or -1.5"; where f holds a parameter without a value (or
  /// has no number on a branch), its forms, "sqrt(2*g*h) or -sqrt(2*g*h)".
  std::string values(const std::vector<solve::Branch>& bs, const model::Find& f) const {
    bool forms = false;
    for (auto& b : bs) {
      const ex form = find_form(f, b);
      forms = forms || !find_value(f, b) || m.unvalued(form);
    }
    std::string s;
    for (auto& b : bs) {
      auto v = find_value(f, b);
      // (the printer of results: the same text on every run, whatever GiNaC's term order)
      std::string one = forms || !v ? emit::plain(model::tidy_result(find_form(f, b))) : numerics::format(*v, 6);
      s += (s.empty() ? "" : " or ") + one;
    }
    return s;
  }
};

}  // namespace

std::string Value::note() const {
  switch (how) {
    case How::Exact: return "exact";
    case How::Double: return "double, |error| <= " + numerics::format_double(bound, 2);
    case How::Precise:
      if (proven) return "proven: ball radius " + numerics::format(numerics::round_up2((hi - lo) / 2), 2) + ", " + std::to_string(working) + " digits";
      return "not proven: two working precisions agree, " + std::to_string(working) + " digits";
    case How::Zero:
      if (proven) return "sign not fixed: |value| <= " + numerics::format(numerics::round_up2(std::max(abs(lo), abs(hi))), 2) + " (proven)";
      return "zero: |value| < " + numerics::format(numeric(bound), 2);
  }
  return "";
}

std::pair<std::string, std::string> Value::ball(int digits) const {
  if (!proven) return {numerics::format(v, digits), ""};
  // mid printed, then a radius that covers [lo, hi] around the printed mid (an exact value: the
  // point itself, and the radius covers only its rounding)
  const numeric mid = how == How::Exact ? v : (lo + hi) / 2;
  const std::string m = numerics::format(mid, digits + 10);
  const numeric printed = numerics::round_sig(mid, digits + 10);
  return {m, numerics::format(numerics::round_up2((hi - lo) / 2 + abs(mid - printed)), 2)};
}

std::optional<numeric> Result::value(const exmap& env, int digits) const {
  auto v = evaluate(env, digits, false);
  if (!v) return std::nullopt;
  return v->v;
}

std::optional<Value> Result::evaluate(const exmap& env, int digits, bool prefer_double) const {
  if (!closed_form && !roots.empty() && !(prefer_double && digits <= 15)) {
    const long max_bits = numerics::bits_for(std::max(20000, 8 * digits));
    std::optional<numerics::Proven> p;
    if (roots.size() == 1 && of_roots.is_equal(roots[0].u)) {
      // the root itself: v = u / unit_factor solves r(v · unit_factor) = 0, its digits proven on balls
      symbol v("v");
      const ex r = roots[0].residual.subs(roots[0].u == v * unit_factor);
      auto at = [&](const ex& x) { return numerics::evaluate(x / unit_factor, env, digits + 20); };
      auto x0 = at(roots[0].at), lo = at(roots[0].lo), hi = at(roots[0].hi);
      if (x0 && lo && hi) p = numerics::root_digits(r, v, *x0, std::min(*lo, *hi), std::max(*lo, *hi), env, digits, max_bits);
    } else {
      // an expression of the roots: each root enclosed on balls, the expression on those enclosures
      p = numerics::digits_at_roots(of_roots / unit_factor, roots, env, digits, max_bits);
    }
    if (p) {
      const long working = numerics::digits_in(p->bits);
      switch (p->kind) {
        case numerics::Proven::Kind::Exact: return Value{p->value, Value::How::Exact, 0, 0, true, p->value, p->value};
        case numerics::Proven::Kind::Digits: return Value{p->value, Value::How::Precise, working, 0, true, p->at.lo, p->at.hi};
        case numerics::Proven::Kind::Unsigned: {
          const numeric m = std::max(abs(p->at.lo), abs(p->at.hi));
          return Value{0, Value::How::Zero, working, numerics::round_up2(m).to_double(), true, p->at.lo, p->at.hi};
        }
      }
    }
  }
  if (!closed_form && digits > kRootDigits)
    throw SceneError(pos, "'" + name + "' has no closed form (it holds a number found numerically, by a root or a stationary point), found to " + std::to_string(kRootDigits) +
                              " significant digits; " + std::to_string(digits) + " were asked",
                     "ask for --digits " + std::to_string(kRootDigits) + " or fewer");
  numerics::Evaluator ev(closed / unit_factor, env);
  if (prefer_double && digits <= 15) {
    // the double's digits are right when the whole interval value ± bound rounds to them
    if (auto f = ev.fast(); f && std::isfinite(f->value) && std::isfinite(f->bound)) {
      // (exactly: in doubles, value ± bound would round back to value when bound < ½ ulp)
      const numeric v = numerics::exact(f->value), b = numerics::exact(f->bound);
      numeric lo = numerics::round_sig(v - b, digits);
      numeric hi = numerics::round_sig(v + b, digits);
      if (f->bound == 0 || lo == hi)
        return Value{v, Value::How::Double, 0, f->bound, false, {}, {}};
    }
  }
  std::optional<numerics::Precise> d;
  try {
    // the default (prefer_double) is not a proof: where the double cannot decide, two CLN
    // precisions that agree do, as fast as the double's own fallback should be; asked for digits
    // (--digits), ball arithmetic proves them
    d = prefer_double ? ev.settled(digits) : ev.digits(digits);
  } catch (const std::domain_error& e) {
    throw SceneError(pos, "'" + name + "' cannot be evaluated: " + e.what(), "check the sizes of the angles in it");
  }
  if (!d) return std::nullopt;
  if (d->exact) return Value{d->value, Value::How::Exact, 0, 0, true, d->value, d->value};
  if (d->zero_bound) return Value{0, Value::How::Zero, d->working, d->bound, d->proven, d->lo, d->hi};
  return Value{d->value, Value::How::Precise, d->working, 0, d->proven, d->lo, d->hi};
}

bool Solution::drew_on(const principles::Equation& e) const {
  return std::any_of(drawn_on.begin(), drawn_on.end(),
                     [&](const principles::Equation& d) { return d.lhs.is_equal(e.lhs) && d.rhs.is_equal(e.rhs) && d.label == e.label; });
}

namespace {

/// The kinetic energy K(s, p) over a path s ∈ [lo, hi] on a grid of n intervals (or at one
/// place, without a path), for the scan of a least (greatest) parameter value p. Each grid
/// point's K is first enclosed in doubles with its inputs' rounding (K compiled to a tape of
/// (p, s)); CLN at 45 digits (`at`) takes only the points the enclosures cannot settle, so the
/// answers are the same as taking every point at 45 digits, at about a hundredth of the time.
/// Without a tape (K holds a work integral, or a sweep traces the solve) every point is CLN's.
class PathScan {
public:
  struct Low {
    numeric K, s;
    int i = 0;  ///< grid index (0 or n: an end)
  };
  using At = std::function<std::optional<numeric>(const numeric& s, const numeric& p)>;

  PathScan(numeric lo, numeric hi, bool path, std::optional<numerics::Tape> tape, At at)
      : lo_(std::move(lo)), hi_(std::move(hi)), path_(path), tape_(std::move(tape)), at_(std::move(at)) {}

  /// The least K over the grid, at its first grid point (nothing where K is nowhere defined).
  std::optional<Low> lowest(const numeric& p, int n) {
    const std::vector<numeric>& grid = enclose_grid(p, n);
    // a point whose enclosure lies wholly above another's is not the least
    double upper = HUGE_VAL;
    for (auto& e : box_)
      if (!e.maybe_undefined) upper = std::min(upper, e.value + e.bound);
    std::optional<Low> best;
    for (std::size_t i = 0; i < box_.size(); ++i) {
      if (!box_[i].maybe_undefined && box_[i].value - box_[i].bound > upper) continue;
      if (auto v = at_(grid[i], p); v && (!best || *v < best->K)) best = Low{*v, grid[i], static_cast<int>(i)};
    }
    return best;
  }

  /// K ≥ 0 at every grid point where it is defined, and defined at one at least.
  bool admissible(const numeric& p, int n) {
    // where the enclosures tell K's sign at every point, they answer alone
    enclose_grid(p, n);
    bool positive = true;
    for (auto& e : box_) {
      if (!e.maybe_undefined && e.value + e.bound < 0) return false;
      positive = positive && !e.maybe_undefined && e.value - e.bound > 0;
    }
    if (positive) return true;
    auto l = lowest(p, n);
    return l && !l->K.is_negative();
  }

private:
  /// The grid's points for n (kept), and box_[i], K's enclosure at point i: each exact input
  /// within a unit in the last place of its double (and the least subnormal) of it, so that the
  /// exact K there lies in the enclosure, where it is defined.
  const std::vector<numeric>& enclose_grid(const numeric& p, int n) {
    const int last = path_ ? n : 0;
    std::vector<numeric>& grid = grids_[n];
    std::vector<double>& grid_d = grids_d_[n];
    for (int i = static_cast<int>(grid.size()); i <= last; ++i) {
      grid.push_back(lo_ + (hi_ - lo_) * numeric(i, n));
      grid_d.push_back(grid.back().to_double());
    }
    box_.assign(last + 1, numerics::Enclosed{0, 0, true});
    if (!tape_) return grid;
    const double p_d = p.to_double();
    for (int i = 0; i <= last; ++i) {
      const double mid[2] = {p_d, grid_d[i]};
      const double radius[2] = {std::abs(mid[0]) * 0x1p-52 + 0x1p-1074, std::abs(mid[1]) * 0x1p-52 + 0x1p-1074};
      tape_->enclose(mid, radius, &box_[i]);
      if (!std::isfinite(box_[i].value) || !std::isfinite(box_[i].bound)) box_[i].maybe_undefined = true;
    }
    return grid;
  }

  numeric lo_, hi_;
  bool path_;
  std::optional<numerics::Tape> tape_;
  At at_;
  std::vector<numerics::Enclosed> box_;
  std::map<int, std::vector<numeric>> grids_;    ///< the path's n + 1 positions, for each n asked
  std::map<int, std::vector<double>> grids_d_;   ///< the same as doubles
};

/// The steps of solving a scene: the unknowns, the equations of each analysis in order (what
/// one determines is known to the next), the solver, the choice among its branches, the results.
class SceneSolver {
public:
  SceneSolver(Solution& sol, int fewer_switches)
      : sol_(sol), m(sol.model), env(m.numeric_environment()), given(m.given_values()), fewer_switches_(fewer_switches) {}

  void run() {
    knowledge();
    collect_unknowns();
    root_hints();
    for (std::size_t ai = 0; ai < m.analyses.size(); ++ai) analysis(ai);
    // the static friction the rolling contacts state, at the states of the analyses they act in
    const principles::FrictionLimits limits = principles::static_friction_limits(m);
    sol_.friction_limits = limits.at_states;
    sol_.friction_along = limits.along;
    // the surfaces that can only push, at the states and along the way of the analyses they act in
    one_sided_ = principles::one_sided_limits(m);
    sol_.one_sided_unchecked = one_sided_.unchecked;
    // states that results name but no analysis uses still obey the constraints
    for (auto& f : m.finds)
      for (std::size_t s = 0; s < m.states.size(); ++s)
        for (auto& [name, qs] : m.states[s].sym)
          if (f.value.has(qs.first) || f.value.has(qs.second)) add_state(static_cast<int>(s));
    for (auto& e : sol_.equations) check_units(e);
    choose(solve(sol_.equations));
    // (again while they bring in more: a chain of analyses, x@3 from x@2 from x@1)
    for (int round = 0; round < 8 && draw_on_reserves(); ++round) choose(solve(sol_.equations));
    solve_in_roots();
    for (auto& f : m.finds) sol_.results.push_back(result(f));
  }

private:
  Solution& sol_;
  const Model& m;
  const exmap env;
  const exmap given;
  std::optional<principles::Knowledge> know_;
  std::vector<ex> unknowns;
  exmap reference;  ///< a coordinate's value at another state, for numeric root searches
  exmap in_roots_;  ///< the chosen branch's unknowns as expressions of its numeric roots (solve_in_roots)
  std::vector<numerics::RootOf> found_roots_;  ///< those roots, each after the roots its equation holds
  std::map<ex, std::pair<ex, ex>, ex_is_less> ranges;  ///< root ranges of results that are one unknown
  std::set<int> states_in;
  int fewer_switches_ = 0;  ///< see principles::Knowledge::fewer_switches
  principles::OneSidedLimits one_sided_;  ///< N ≥ 0 of the surfaces that only push

  // the constraints evaluated at the values given may be undefined there (x/tan(theta), theta = pi/2)
  static SceneError undefined(const SourcePos& pos, const std::string& what, const std::exception& err) {
    return SceneError(pos, what + " is undefined for the values given at the states (" + model::math_fault(err) + ")",
                      "check the values given at the states");
  }

  void knowledge() {
    try {
      know_.emplace(m);
      know_->fewer_switches = fewer_switches_;
    } catch (const std::exception& err) {
      throw undefined(m.constraints.empty() ? SourcePos{m.file, 1, 1} : m.constraints.front().second, "a constraint", err);
    }
  }

  /// State values not given, parameters written `unknown`, and the impulses the analyses bring.
  void collect_unknowns() {
    for (auto& s : m.states) {
      for (auto& c : m.coords)
        for (const ex& x : {ex(s.sym.at(c.name).first), ex(s.sym.at(c.name).second)})
          if (!given.count(x)) unknowns.push_back(x);
      if (!given.count(s.t)) unknowns.push_back(s.t);
    }
    for (auto& p : m.params)
      if (p.unknown) unknowns.push_back(p.sym);
    for (auto& a : m.analyses)  // impulses the analyses bring: contacts, pins, constraints
      for (auto& u : a.unknowns)
        if (std::find_if(unknowns.begin(), unknowns.end(), [&](const ex& x) { return x.is_equal(u); }) == unknowns.end())
          unknowns.push_back(u);
  }

  /// Where to look for numeric roots: a coordinate's value at the other state of an analysis, and
  /// the root range of a result that is one unknown.
  void root_hints() {
    for (auto& a : m.analyses)
      for (auto& c : m.coords) {
        ex q1 = m.states[a.from].sym.at(c.name).first, q2 = m.states[a.to].sym.at(c.name).first;
        if (auto it = given.find(q1); it != given.end()) reference[q2] = it->second;
      }
    for (auto& f : m.finds) {
      if (f.root.kind != model::RootSpec::Kind::Interval) continue;
      try {
        ex v = f.value.subs(given);
        if (is_a<symbol>(v)) ranges[v] = {f.root.lo, f.root.hi};
      } catch (const std::exception&) {
        // undefined at the given values: reported with the result itself
      }
    }
  }

  /// The unknowns a result still holds with the chosen branch.
  std::vector<ex> undetermined() const {
    std::vector<ex> out;
    for (auto& f : m.finds) {
      ex c;
      try {
        c = f.value.subs(given).subs(sol_.branch.sol);
      } catch (const std::exception&) {
        continue;  // reported with the result
      }
      for (auto& u : unknowns)
        if (c.has(u) && std::none_of(out.begin(), out.end(), [&](const ex& x) { return x.is_equal(u); })) out.push_back(u);
    }
    return out;
  }

  /// Add the balances' reserve equations that hold an unknown a result is left with (the
  /// positions a momentum balance integrates to). Whether any was added.
  bool draw_on_reserves() {
    std::vector<ex> open = undetermined();
    bool added = false;
    // and what the equations drawn on bring in (x@3 from x@2: the analysis before gives x@2)
    for (bool more = !open.empty(); more;) {
      more = false;
      for (auto& b : sol_.balances)
        for (auto& e : b->reserve()) {
          const ex r = e.residual();
          if (sol_.drew_on(e) || std::none_of(open.begin(), open.end(), [&](const ex& u) { return r.has(u); })) continue;
          check_units(e);
          sol_.equations.push_back(e);
          sol_.drawn_on.push_back(e);
          added = more = true;
          for (auto& u : unknowns)
            if (r.has(u) && std::none_of(open.begin(), open.end(), [&](const ex& x) { return x.is_equal(u); })) open.push_back(u);
        }
    }
    return added;
  }

  void add_state(int s) {
    if (!states_in.insert(s).second) return;
    for (auto& e : principles::state_equations(m, s)) sol_.equations.push_back(e);
  }

  void check_units(const principles::Equation& e) const {
    try {
      m.dimension(e.residual());
    } catch (const model::DimensionError& err) {
      throw SceneError(e.pos, "inconsistent units in the " + e.label + ": " + err.what(),
                       "check the units of the parameters in these terms");
    }
  }

  /// The equations of analysis ai (and of its states).
  void analysis(std::size_t ai) {
    const auto& a = m.analyses[ai];
    add_state(a.from);
    add_state(a.to);
    // an effect switched inside it does its work up to (or from) its switching state: that state's
    // positions are in the equation, and its constraints hold there
    for (auto& e : m.effects)
      if (e.activity(a) == model::Effect::Activity::Part)
        for (int st : {e.on, e.off})
          if (st > std::min(a.from, a.to) && st < std::max(a.from, a.to)) add_state(st);
    try {
      a.type->equations(m, a, *know_, sol_);
    } catch (const SceneError&) {
      throw;
    } catch (const std::exception& err) {
      throw undefined(a.pos, "the " + a.kind + " analysis", err);
    }
    if (ai + 1 < m.analyses.size()) {
      // what this analysis determines is known to the next (a direction of motion, say)
      try {
        solve::Branch b = Selector{m, env, given}.pick(solve(sol_.equations));
        for (auto& [k, v] : b.sol)
          if (auto x = numerics::evaluate(v, env, 30)) know_->set(k, *x, numerics::tracing() ? v.subs(given) : ex(*x));
      } catch (const SceneError&) {
        // decided later, with every equation
      }
    }
  }

  std::vector<solve::Branch> solve(const std::vector<principles::Equation>& eqs) const { return solve(eqs, unknowns, env); }
  std::vector<solve::Branch> solve(const std::vector<principles::Equation>& eqs, const std::vector<ex>& us, const exmap& e) const {
    solve::Problem p{eqs, us, given, e, reference, ranges, {}, {}};
    for (auto& a : m.analyses) p.impulses.insert(a.unknowns.begin(), a.unknowns.end());
    for (auto& x : m.params)
      if (!x.value && !x.unknown) p.stand_ins.insert(x.sym);
    try {
      return solve::solve(p);
    } catch (const solve::SolveError& e) {
      SourcePos pos = e.pos().line > 0 ? e.pos() : (m.analyses.empty() ? SourcePos{m.file, 1, 1} : m.analyses.front().pos);
      throw SceneError(pos, e.what(), e.fix());
    }
  }

  /// The chosen branch's unknowns as expressions of the unknowns it found by numeric roots, so that
  /// a value solved from a root's number can be proven from the root's own equation: solved again
  /// with each root whose equation holds no other root's number taken as known (its number in env,
  /// for the solver's decisions), and the branch whose values agree with the chosen one kept. A
  /// root of an equation that held an earlier root's number (two roots chained) is then found
  /// again, its equation now in the earlier root's symbol, and taken as known in turn. Unknowns
  /// with no root's number in them keep their closed form.
  void solve_in_roots() {
    const solve::Branch& b = sol_.branch;
    if (b.roots.empty()) return;
    exmap in, with_roots = env;
    std::vector<numerics::RootOf> found;
    auto know = [&](const ex& u, const solve::NumericRoot& nr, const ex& at) {
      in[u] = u;
      with_roots[u] = at;
      found.push_back({u, nr.residual, ex_to<numeric>(at), nr.lo, nr.hi});
    };
    for (auto& [u, nr] : b.roots)
      if (!has_float(nr.residual) && is_a<numeric>(b.sol.at(u))) know(u, nr, b.sol.at(u));
    for (int level = 0; level < 4 && !found.empty(); ++level) {
      std::vector<ex> rest;
      bool needed = false;
      for (auto& u : unknowns) {
        auto it = b.sol.find(u);
        if (in.count(u) || it == b.sol.end()) continue;  // (an unknown nothing fixed stays one)
        rest.push_back(u);
        needed = needed || has_float(it->second);
      }
      if (!needed) {
        for (auto& u : rest) in[u] = b.sol.at(u);
        in_roots_ = in;
        found_roots_ = found;
        return;
      }
      std::vector<solve::Branch> again;
      try {
        again = solve(sol_.equations, rest, with_roots);
      } catch (const std::exception&) {
        return;  // not solved so: the values solved from the roots stay numbers
      }
      const solve::Branch* same = nullptr;
      for (auto& c : again) {
        bool agree = true;
        for (auto& u : rest) {
          auto ci = c.sol.find(u);
          auto bi = b.sol.find(u);
          if (ci == c.sol.end() || bi == b.sol.end()) {
            agree = false;
            break;
          }
          auto x = numerics::evaluate(ci->second.subs(given), with_roots, 30), y = numerics::evaluate(bi->second.subs(given), env, 30);
          agree = agree && x && y && abs(*x - *y) <= numerics::tenth(20) * (abs(*y) + 1);
        }
        if (agree) {
          same = &c;
          break;
        }
      }
      if (!same) return;
      if (same->roots.empty()) {
        for (auto& u : rest) in[u] = same->sol.at(u);
        in_roots_ = in;
        found_roots_ = found;
        return;
      }
      // roots found again, their equations now in the known roots' symbols: known in turn
      const std::size_t before = found.size();
      for (auto& [u, nr] : same->roots)
        if (!has_float(nr.residual) && is_a<numeric>(same->sol.at(u))) know(u, nr, same->sol.at(u));
      if (found.size() == before) return;
    }
  }

  /// The branch the results' root choices and continuity select; each analysis checks it.
  void choose(const std::vector<solve::Branch>& branches) {
    // a branch that breaks what the effects declare (a point off its track, a one-sided spring
    // taken as acting where it does not) is no solution of the scene
    std::vector<solve::Branch> kept;
    std::vector<std::pair<solve::Branch, SceneError>> broken;  // (what each dropped branch breaks)
    for (auto& b : branches) {
      try {
        check_declared(b);
        kept.push_back(b);
      } catch (const SceneError& e) {
        broken.push_back({b, e});
      }
    }
    if (kept.empty()) throw broken.front().second;
    // a branch whose states the motion does not reach (the kinetic energy negative on the way, a
    // rest on the far side of the way the motion goes) is no solution either; a root choice that
    // asks for one is refused with that reason
    std::vector<solve::Branch> reached;
    std::vector<std::pair<solve::Branch, SceneError>> unreached;
    for (auto& b : kept) {
      try {
        check_reached(b);
        reached.push_back(b);
      } catch (const SceneError& e) {
        unreached.push_back({b, e});
      }
    }
    if (reached.empty()) throw unreached.front().second;
    try {
      sol_.branch = Selector{m, env, given}.pick(reached);  // (one branch too: its root choices are checked)
    } catch (const SceneError&) {
      // the root choice asked for a solution the motion does not reach: say why (where no root
      // was asked for, the choice among those reached stands as it is)
      const Selector sel{m, env, given};
      const bool asked = std::any_of(m.finds.begin(), m.finds.end(), [](const model::Find& f) { return f.root.kind != model::RootSpec::Kind::None; });
      // (does branch b give every result the root asked for?)
      auto meets = [&](const solve::Branch& b) {
        bool all = asked;
        for (auto& f : m.finds) {
          if (f.root.kind == model::RootSpec::Kind::None) continue;
          auto v = sel.find_value(f, b);
          all = all && (!v || sel.meets(f.root, *v, numerics::tracing() ? sel.find_form(f, b) : ex()));
        }
        return all;
      };
      for (auto& [b, why] : unreached)
        if (meets(b)) throw SceneError(why.pos(), "the root asked for gives a solution the motion does not reach: " + why.problem(), why.fix());
      // or one that breaks what the scene declares (a body through a surface that only pushes)
      for (auto& [b, why] : broken)
        if (meets(b))
          throw SceneError(why.pos(), "the root asked for gives a solution the scene's supports do not allow: " + why.problem(), why.fix());
      throw;
    }
    for (auto& a : m.analyses) {
      forward_in_time(a);
      a.type->check(m, a, given, sol_.branch, env);
    }
    // static friction is a verdict on the solution chosen, not a choice between roots
    for (const principles::FrictionLimit& l : sol_.friction_limits) {
      hold(l.holds, sol_.branch);
    }
    valid_where();
  }

  /// Every state symbol branch b gives a number (given or solved), and the parameters' values.
  exmap numbers_of(const solve::Branch& b) const {
    exmap values = env;
    for (const exmap* part : {static_cast<const exmap*>(&given), static_cast<const exmap*>(&b.sol)})
      for (auto& [k, v] : *part) {
        try {
          ex x = v.subs(given).subs(b.sol).subs(env).evalf();
          if (is_a<numeric>(x)) values[k] = x;
        } catch (const std::exception&) {
        }
      }
    return values;
  }

  /// The same symbols' forms in the parameters (branch b): what a sweep follows the checks on
  /// numbers_of by (numerics::TraceForms).
  exmap forms_of(const solve::Branch& b) const {
    exmap forms;
    for (const exmap* part : {static_cast<const exmap*>(&given), static_cast<const exmap*>(&b.sol)})
      for (auto& [k, v] : *part) {
        try {
          forms[k] = v.subs(given).subs(b.sol);
        } catch (const std::exception&) {
          forms[k] = v;
        }
      }
    return forms;
  }

  /// Does the motion reach each energy analysis' end state (branch b)?
  ///  - a coordinate at rest at the end state whose rate at the start is not zero comes to rest
  ///    the way it moves: (q₂ − q₁) q̇₁ > 0 (to lie the other way it must stop, and turn, first);
  ///  - with one degree of freedom between the states, the kinetic energy stays ≥ 0 along the way
  ///    (principles::check_reached).
  /// Skipped where the kinetic energy between the ends cannot be had (a force that switches,
  /// split where the end lies; an average force of an isolated set; a parameter without a value).
  void check_reached(const solve::Branch& b) const {
    const exmap values = numbers_of(b);
    const exmap forms = numerics::tracing() ? forms_of(b) : exmap();
    const numerics::TraceForms traced(forms);
    auto value = [&](const ex& e) -> std::optional<numeric> {
      ex x = e.subs(values);
      if (is_a<numeric>(x) && ex_to<numeric>(x).is_real()) return ex_to<numeric>(x);
      return std::nullopt;
    };
    for (std::size_t ai = 0; ai < m.analyses.size(); ++ai) {
      const auto& a = m.analyses[ai];
      if (a.type->impulsive()) continue;  // energy alone keeps a motion going one way
      const auto &S1 = m.states[a.from], &S2 = m.states[a.to];
      // the end state's place solved to be the start itself (every coordinate and rate the same):
      // the energy equation holds there trivially and tells nothing of where the motion goes
      bool same = true, solved = false;
      for (auto& c : m.coords)
        for (int part = 0; part < 2 && same; ++part) {
          const ex x1 = part ? ex(S1.sym.at(c.name).second) : ex(S1.sym.at(c.name).first);
          const ex x2 = part ? ex(S2.sym.at(c.name).second) : ex(S2.sym.at(c.name).first);
          auto v1 = value(x1), v2 = value(x2);
          same = v1 && v2 && abs(*v2 - *v1) <= numerics::tenth(25) * (abs(*v1) + abs(*v2));
          if (v1 && v2 && numerics::tracing()) numerics::note(numerics::tenth(25) * (abs(x1) + abs(x2)) - abs(x2 - x1), numerics::tenth(25) * (abs(*v1) + abs(*v2)) - abs(*v2 - *v1));
          solved = solved || (part == 0 && !given.count(x2));  // where it ends was solved for, not given
        }
      if (same && solved)
        throw SceneError(a.pos, "this solution puts state '" + S2.name + "' where state '" + S1.name + "' is, with the same rates: the energy "
                                    "equation holds there trivially, and says nothing of where the motion goes",
                         "choose the other root ('root:' of the result), or give state '" + S2.name + "' something that tells it apart "
                         "(a position, a time)");
      for (auto& c : m.coords) {
        auto q1 = value(S1.sym.at(c.name).first), q2 = value(S2.sym.at(c.name).first);
        auto v1 = value(S1.sym.at(c.name).second), v2 = value(S2.sym.at(c.name).second);
        if (v1 && numerics::tracing()) numerics::note(S1.sym.at(c.name).second, *v1);
        if (v2 && numerics::tracing()) numerics::note(S2.sym.at(c.name).second, *v2);
        if (q1 && q2 && v1 && numerics::tracing()) numerics::note((S2.sym.at(c.name).first - S1.sym.at(c.name).first) * S1.sym.at(c.name).second, (*q2 - *q1) * *v1);
        if (!q1 || !q2 || !v1 || !v2 || !v2->is_zero() || v1->is_zero() || (*q2 - *q1) * *v1 >= 0) continue;
        const std::string unit = units::si_name(c.dim).empty() ? "rad" : units::si_name(c.dim);
        throw SceneError(a.pos, "state '" + S2.name + "' has " + c.name + " at rest on the other side of state '" + S1.name + "' than the motion goes: " +
                                    c.name + "_dot@" + S1.name + " = " + numerics::format(*v1, 6) + " " + unit + "/s, so " + c.name +
                                    " comes to rest first at " + c.name + (v1->is_positive() ? " > " : " < ") + numerics::format(*q1, 6) + " " + unit +
                                    ", but this solution puts " + c.name + "@" + S2.name + " = " + numerics::format(*q2, 6) + " " + unit,
                         "choose the root on the side the motion goes ('root:' of the result), or check the rates given at state '" + S1.name + "'");
      }
      if (a.bodies.size() != m.bodies.size() || !a.reactions.empty()) continue;
      const principles::EnergyBalance* energy = sol_.balance<principles::EnergyBalance>(ai);
      if (!energy) continue;
      const auto& bal = *energy;
      if (std::any_of(bal.works.begin(), bal.works.end(), [](const principles::Work& w) { return w.ends_only; })) continue;
      if (m.unvalued(bal.equation.residual().subs(given))) continue;
      static const std::vector<principles::PushAlong> none;
      auto along = one_sided_.along.find(static_cast<int>(ai));
      principles::check_reached(m, a, bal, values, along == one_sided_.along.end() ? none : along->second);
    }
    // a surface that can only push does so at every state where it acts (a state past the place
    // the body leaves it is not reached)
    for (const principles::OneSidedLimit& l : one_sided_.at_states) hold(l.pushes, b);
  }

  /// The conditions of the chosen branch that hold parameters without values: each e ≥ 0 is
  /// stated with the closed forms (Solution::valid_where).
  void valid_where() {
    // a root the scene itself takes of an expression of its parameters (a state's place,
    // -sqrt(r^2 - (r - h)^2)) is real: that expression is ≥ 0 wherever the scene holds, and fixes
    // the sign of its factors under a root of a condition (√((2hr − h²)²/r²) = (2hr − h²)/r)
    std::vector<ex> radicands;
    for (auto& [k, v] : m.given_values()) {
      (void)k;
      for (const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
        if (is_a<GiNaC::power>(*it) && it->op(1).is_equal(numeric(1, 2)) && m.unvalued(it->op(0))) radicands.push_back(normal(it->op(0)));
    }
    const model::SignOf sign = [&](const ex& y) {
      if (int s = m.fixed_sign(y)) return s;
      for (const ex& r : radicands) {
        try {
          const ex q = normal(r / y);
          if (q.info(info_flags::positive)) return 1;
          if ((-q).info(info_flags::positive)) return -1;
        } catch (const std::exception&) {
        }
      }
      return 0;
    };
    std::vector<principles::Condition> all;
    for (const principles::FrictionLimit& l : sol_.friction_limits) {
      all.push_back(l.holds);
    }
    for (auto& bal : sol_.balances)
      for (const principles::Condition& c : bal->conditions()) all.push_back(c);
    for (const principles::OneSidedLimit& l : one_sided_.at_states) all.push_back(l.pushes);
    // the root a result asks for, chosen at a sample: stated where its form does not prove it,
    // by what decides its sign (−sqrt(X)/(r sin θ₂) > 0 where −sin θ₂ ≥ 0)
    for (auto& f : m.finds) {
      if (f.root.kind != model::RootSpec::Kind::Positive && f.root.kind != model::RootSpec::Kind::Negative) continue;
      const bool positive = f.root.kind == model::RootSpec::Kind::Positive;
      ex v;
      try {
        v = model::tidy(f.value.subs(given).subs(sol_.branch.sol));
      } catch (const std::exception&) {
        continue;
      }
      if (!m.unvalued(v) || proven_sign(v) == (positive ? 1 : -1)) continue;
      principles::Condition k;
      k.e = sign_core(positive ? v : -v);
      k.what = "'" + f.name + "' has the other sign than 'root: " + (positive ? "positive" : "negative") + "' asks";
      k.fix = "check 'root:' of '" + f.name + "'";
      k.pos = f.pos;
      k.assumed = "'" + f.name + "' " + (positive ? "> 0" : "< 0") + ", the root asked for";
      all.push_back(k);
    }
    for (const principles::Condition& c : all) {
      ex e;
      try {
        e = factor(normal(model::root_simplify(model::trig_simplify(c.e.subs(given).subs(sol_.branch.sol)), radicands.empty() ? nullptr : sign)));
      } catch (const std::exception&) {
        continue;
      }
      if (!m.unvalued(e)) continue;
      principles::Condition k = c;
      k.e = e;
      if (k.assumed.empty()) k.assumed = c.what.substr(0, c.what.find(" ({}"));
      if (std::none_of(sol_.valid_where.begin(), sol_.valid_where.end(), [&](const principles::Condition& x) { return x.e.is_equal(e); }))
        sol_.valid_where.push_back(k);
    }
  }

  /// Condition c (e ≥ 0) holds on branch b. One on a parameter without a value is stated with the
  /// closed form, not judged at the sample values that stand in for it (Solution::valid_where).
  /// @throws SceneError when it does not, showing by how much ("{}") and c.shown ("{v}").
  void hold(const principles::Condition& c, const solve::Branch& b) const {
    if (m.unvalued(c.e.subs(given).subs(b.sol))) return;
    auto v = numerics::evaluate(c.e.subs(given).subs(b.sol), env, 30);
    if (!v || !v->is_negative()) return;
    // a value at the edge, left negative by rounding alone (a normal force that is zero where
    // the state is defined by it vanishing), holds
    if (numerics::negligible(c.e.subs(given).subs(b.sol), env, 30).value_or(false)) return;
    std::string what = c.what;
    what.replace(what.find("{}"), 2, numerics::format(-*v, 6));
    if (auto at = what.find("{v}"); at != std::string::npos) {
      std::optional<GiNaC::numeric> shown;
      try {
        shown = numerics::evaluate(c.shown.subs(given).subs(b.sol), env, 30);
      } catch (const std::exception&) {
        // (a ratio whose denominator vanishes: a friction force with no normal force)
      }
      what.replace(at, 3, shown ? numerics::format(*shown, 6) : std::string("infinite (no normal force)"));
    }
    throw SceneError(c.pos, what, c.fix);
  }

  /// What the effects declare holds at every solved state of branch b.
  void check_declared(const solve::Branch& b) const {
    const exmap values = numbers_of(b);
    const exmap forms = numerics::tracing() ? forms_of(b) : exmap();
    const numerics::TraceForms traced(forms);
    for (auto& e : m.effects)
      for (std::size_t s = 0; s < m.states.size(); ++s) e.check(m, static_cast<int>(s), values);
    // no two bodies in one place at a state (model/poses.hpp)
    for (std::size_t s = 0; s < m.states.size(); ++s)
      if (const auto o = model::overlapping_at(m, static_cast<int>(s), values); !o.empty())
        throw SceneError(m.states[s].pos, "at state '" + m.states[s].name + "' " + o.front() + ": two bodies cannot be in one place",
                         "give state '" + m.states[s].name + "' positions that keep them apart, or join the two (a pin, a contact) where "
                         "one is meant to stand over the other");
    // what the equations took for granted (a switching force passed, a declared direction of
    // sliding): e ≥ 0
    for (auto& bal : sol_.balances)
      for (auto& c : bal->conditions()) hold(c, b);
    // the equations that follow from the solved ones at a general state must hold here too
    for (auto& bal : sol_.balances)
      for (auto& q : bal->checked()) {
        ex r;
        try {
          r = q.residual().subs(given).subs(b.sol);
        } catch (const std::exception&) {
          continue;  // undefined at this branch: its own equations say so
        }
        auto zero = numerics::negligible(r, env, 30);
        if (!zero || *zero) continue;
        auto v = numerics::evaluate(r, env, 30);
        throw SceneError(q.pos, "the " + q.label + " does not hold on this solution (off by " + (v ? numerics::format(*v, 6) : std::string("?")) +
                                    " in SI units), so it is no solution of the scene",
                         "check the states' conditions; a state where a support's force vanishes may be reached only on one side");
      }
  }

  /// "the parameters' values", or, where some have none, the sample taken for them ("a = 0.15, …").
  std::string values_text() const {
    std::string out;
    for (auto& p : m.params)
      if (p.without_value())
        if (auto it = env.find(p.sym); it != env.end() && is_a<numeric>(it->second))
          out += (out.empty() ? "" : ", ") + p.name + " = " + numerics::format(ex_to<numeric>(it->second), 3);
    return out.empty() ? "the parameters' values" : "the sampled values " + out;
  }

  /// A range `over: [lo, hi]` at the parameters' values (samples for those without: where lo ≥ hi
  /// there, the sample lies outside the scene's domain).
  std::pair<numeric, numeric> range_at(const ex& lo_e, const ex& hi_e, const SourcePos& pos, const std::string& name, int digits) const {
    auto lo = numerics::evaluate(lo_e, env, digits), hi = numerics::evaluate(hi_e, env, digits);
    if (!lo || !hi || !lo->is_real() || !hi->is_real())
      throw SceneError(pos, "the range of '" + name + "' has no value", "give its ends as numbers, or as expressions of the parameters");
    if (!(*lo < *hi))
      throw SceneError(pos, "the range of '" + name + "' is empty at " + values_text() + ": its lower end " + numerics::format(*lo, 6) +
                                " is not below its upper end " + numerics::format(*hi, 6),
                       "write the range [lo, hi] with lo < hi for every value of the parameters");
    return {*lo, *hi};
  }

  /// The greatest or least value of r.closed as f's parameter p runs over [lo, hi] (or where it
  /// is reached): the stationary points df/dp = 0 inside (sign changes of df/dp on a grid of 400,
  /// refined by bisection to 45 digits), the second derivative there (< 0 at a maximum, > 0 at a
  /// minimum), and the ends; the best of them. Numbers: the result is marked "no closed form".
  /// 10^−n

  void extreme(const model::Find& f, Result& r) const {
    numerics::note_untraced("where '" + f.name + "' is greatest or least (found by a scan)");
    const auto& x = *f.extreme;
    const symbol& p = ex_to<symbol>(x.p);
    const int digits = 45;
    exmap at = env;
    auto value_at = [&](const ex& e, const numeric& v) {
      at[p] = v;
      return numerics::evaluate(e, at, digits);
    };
    ex F = r.closed, dF = F.diff(p), d2F = dF.diff(p);
    const auto [lo_v, hi_v] = range_at(x.lo, x.hi, x.pos, x.p_name, digits);
    const std::optional<numeric> lo = lo_v, hi = hi_v;
    const std::string what = x.largest ? "greatest" : "least";
    // the candidates: (p, F(p), how)
    struct Cand {
      enum class Where { End, Stationary, NotThatKind };  ///< an end of the range; dF/dp = 0 (of the kind asked, or not)
      Where where;
      numeric p, F;
      std::string second;  ///< a stationary point: its second derivative, and what that makes it
      numeric lo, hi;  ///< a stationary point: the bracket dF/dp changes sign in
    };
    std::vector<Cand> cands;
    for (const numeric& e : {*lo, *hi})
      if (auto v = value_at(F, e)) cands.push_back({Cand::Where::End, e, *v, "", e, e});
    const int N = 400;
    std::optional<numeric> prev;
    numeric prev_p = *lo;
    for (int i = 0; i <= N; ++i) {
      numeric pi = *lo + (*hi - *lo) * numeric(i, N);
      auto d = value_at(dF, pi);
      if (d && prev && ((d->is_negative() && prev->is_positive()) || (d->is_positive() && prev->is_negative()) || d->is_zero())) {
        // refine the sign change in [prev_p, pi]: dF/dp = 0
        auto r = d->is_zero() ? std::optional<numeric>(pi)
                              : numerics::bracketed_root([&](const numeric& c) { return value_at(dF, c); }, prev_p, pi, *prev, *d,
                                                         numerics::tenth(digits), numerics::tenth(digits), digits + 10);
        if (!r) continue;
        numeric root = *r;
        auto v = value_at(F, root);
        auto s2 = value_at(d2F, root);
        if (v && s2) {
          bool kind_ok = x.largest ? s2->is_negative() : s2->is_positive();
          cands.push_back({kind_ok ? Cand::Where::Stationary : Cand::Where::NotThatKind, root, *v,
                           "second derivative " + numerics::format(*s2, 6) + (kind_ok ? (x.largest ? " < 0, a maximum" : " > 0, a minimum") : ""),
                           d->is_zero() ? pi : prev_p, pi});
        }
      }
      if (d) {
        prev = d;
        prev_p = pi;
      }
    }
    if (cands.empty())
      throw SceneError(f.pos, "'" + f.name + "' has no value over the range of '" + x.p_name + "'",
                       "check the range 'over' and the scene's values");
    const Cand* best = nullptr;
    for (auto& c : cands)
      if (c.where != Cand::Where::NotThatKind &&
          (!best || (x.largest ? c.F > best->F : c.F < best->F)))
        best = &c;
    if (!best) best = &cands.front();
    std::ostringstream note;
    note << "stationary where d/d" << x.p_name << " = 0";
    bool any = false;
    for (auto& c : cands)
      if (c.where != Cand::Where::End) {
        note << (any ? "; " : " at ") << x.p_name << " = " << numerics::format(c.p, 8) << " (" << c.second << ")";
        any = true;
      }
    if (!any) note << " nowhere inside the range";
    note << "; the " << what << " value " << numerics::format(best->F, 8) << " at " << x.p_name << " = " << numerics::format(best->p, 8)
         << (best->where == Cand::Where::End ? ", an end of the range" : "");
    r.extreme_note = note.str();
    r.extreme_of = F;
    r.closed = x.location ? ex(best->p) : ex(best->F);
    r.closed_form = false;
    // the place in closed form: an end of the range, or the stationary condition solved for p
    // (the root that is the number found); the value there follows
    std::optional<ex> place;
    if (best->where == Cand::Where::End) place = best->p == *lo ? x.lo : x.hi;
    else place = stationary_place(dF, p, best->p);
    if (!place && best->where != Cand::Where::End && !has_float(F)) {
      // no closed form for the stationary point p*: its digits are proven as a root of dF/dp = 0
      // in its bracket, and the value there as F on p*'s enclosure
      r.of_roots = x.location ? ex(p) : F;
      r.roots = {numerics::RootOf{p, dF, best->p, best->lo, best->hi}};
    }
    if (!place) return;
    ex at_place = model::factored(model::root_simplify(model::tidy(F.subs(p == *place)), [this](const ex& y) { return m.fixed_sign(y); }));
    auto pv = numerics::evaluate(*place, env, digits), fv = numerics::evaluate(at_place, env, digits);
    const numeric close = numerics::tenth(30);
    if (!pv || !fv || abs(*pv - best->p) > close * (abs(best->p) + 1) || abs(*fv - best->F) > close * (abs(best->F) + 1)) return;
    r.closed = x.location ? *place : at_place;
    r.closed_form = true;
  }

  /// The root of dF/dp = 0 that is the stationary point p* found numerically, in closed form when
  /// the solver finds one (a polynomial in p, or in sin p, cos p or tan p alone).
  std::optional<ex> stationary_place(const ex& dF, const symbol& p, const numeric& p_star) const {
    principles::Equation eq{model::tidy(dF).normal().numer(), 0, "stationary", "stationary condition", {}};
    exmap e = env;
    e.erase(p);
    solve::Problem pr{{eq}, {p}, {}, e, {}, {}, {}, {}};
    std::vector<solve::Branch> branches;
    try {
      branches = solve::solve(pr);
    } catch (const std::exception&) {
      return std::nullopt;  // no closed form: the number stands
    }
    for (auto& b : branches) {
      auto it = b.sol.find(p);
      if (it == b.sol.end() || b.numeric_only.count(p)) continue;
      ex c = model::tidy(model::root_simplify(model::tidy(it->second), [this](const ex& y) { return m.fixed_sign(y); }).eval());
      auto v = numerics::evaluate(c, env, 45);
      if (v && abs(*v - p_star) <= numerics::tenth(30) * (abs(p_star) + 1)) return c;
    }
    return std::nullopt;
  }

  /// The kinetic energy at the state must depend on the parameter, and every other parameter in
  /// it needs a value. @throws SceneError naming the one that does not.
  void check_reach(const ex& K, const model::Find::Reach& x, const std::string& S, const std::string& what) const {
    if (!K.has(x.p))
      throw SceneError(x.pos, "the kinetic energy at state '" + S + "' does not depend on '" + x.p_name + "' (" + model::text(K) + ")",
                       "name the parameter that sets the motion toward state '" + S + "' (a speed or position at an earlier state)");
    // another parameter without a value: the bound is found at a sample of it, and stands only
    // in closed form (reach_closed), else refused as neither a form nor a number (result())
    (void)what;
  }

  /// A stationary binding position exactly: a simple rational (or a rational multiple of π,
  /// denominator ≤ 360) at which ∂K/∂along vanishes to 40 digits, if there is one.
  std::optional<ex> exact_position(const ex& K, const model::Find::Reach& x, const numeric& s_bind, const numeric& p_star, int digits,
                                   const std::function<std::optional<numeric>(const ex&, const numeric&, const numeric&)>& K_at) const {
    std::optional<ex> exact_s;
    ex dK = K.diff(ex_to<symbol>(*x.along));
    numeric scale = abs(*K_at(K.diff(ex_to<symbol>(x.p)), s_bind, p_star)) + 1;
    for (const ex& unit : {ex(1), ex(Pi)})
      for (int den = 1; den <= 360 && !exact_s; ++den) {
        numeric u = *numerics::evaluate(unit, env, digits);
        numeric k(cln::round1(cln::the<cln::cl_R>(ex_to<numeric>(s_bind * den / u).to_cl_N())));
        ex cand = unit * k / den;
        auto c = numerics::evaluate(cand, env, digits);
        auto d = c ? K_at(dK, *c, p_star) : std::nullopt;
        if (d && abs(*c - s_bind) < numerics::tenth(30) * (abs(s_bind) + 1) &&
            abs(*d) < scale * numerics::tenth(40))
          exact_s = cand;
      }
    return exact_s;
  }

  /// The bound in closed form where the binding position is exact: K(s, p) = 0 of degree ≤ 2 in
  /// p, the root that is the number found (to 30 digits).
  std::optional<ex> reach_closed(const ex& K, const model::Find::Reach& x, const std::optional<ex>& exact_s, const numeric& p_star,
                                 int digits) const {
    std::optional<ex> closed;
    ex e = K;
    if (x.along) e = e.subs(*x.along == *exact_s);
    e = model::tidy(e);
    ex num_e = e.normal().numer();
    if (num_e.is_polynomial(x.p) && num_e.degree(x.p) >= 1 && num_e.degree(x.p) <= 2) {
      ex p2 = num_e.coeff(x.p, 2), p1 = num_e.coeff(x.p, 1), p0 = num_e.coeff(x.p, 0);
      std::vector<ex> roots;
      if (p2.is_zero()) {
        roots.push_back(-p0 / p1);
      } else if (p1.is_zero()) {
        roots.push_back(sqrt(-p0 / p2));
      } else {
        ex d = sqrt(p1 * p1 - 4 * p2 * p0);
        roots = {(-p1 + d) / (2 * p2), (-p1 - d) / (2 * p2)};
      }
      for (auto& c : roots) {
        ex t = model::factored(model::root_simplify(model::tidy(c), [this](const ex& y) { return m.fixed_sign(y); }));
        auto v = numerics::evaluate(t, env, digits);
        if (v && v->is_real() && abs(*v - p_star) <= abs(p_star) * numerics::tenth(30)) {
          closed = t;
          break;
        }
      }
    }
    return closed;
  }

  /// How the bound was found, for the derivation.
  static std::string reach_note(const model::Find::Reach& x, const std::string& S, const std::string& path, const numeric& s_bind,
                                bool at_end, const numeric& p_star) {
    std::ostringstream note;
    note << "it is " << (x.along ? "least over the path" : "taken at the state itself");
    if (x.along)
      note << " at " << x.along_name << " = " << numerics::format(s_bind, 8) << (at_end ? " (an end of the path)" : " (where its derivative along the path is zero)");
    note << ", and zero there for " << x.p_name << " = " << numerics::format(p_star, 8) << "; state " << S << " is reached" << path
         << " for " << x.p_name << (x.least ? " above " : " below ") << numerics::format(p_star, 8)
         << " (at that value itself its kinetic energy there is zero: it comes to rest at that place, or only creeps up to it)";
    return note.str();
  }

  /// K compiled to a tape of (p, along) for reach's scan, the other parameters at their values;
  /// none where K holds what a double tape does not take (a work integral).
  std::optional<numerics::Tape> tape_of(const ex& K, const model::Find::Reach& x) const {
    std::vector<ex> inputs{x.p};
    if (x.along) inputs.push_back(*x.along);
    exmap values = env;  // (p and along are the tape's inputs, whatever values env has for them)
    for (auto& in : inputs) values.erase(in);
    try {
      return numerics::Tape::compile(K.subs(values), inputs);
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }

  /// The least (greatest) value of f's parameter p for which its state S is reached: the
  /// kinetic energy K = T@S from the solution must be ≥ 0 at S, and — when a parameter `along`
  /// places S — at every position of the path, along ∈ [lo, hi]:
  ///   g(p) = min over the path of K(along, p) ≥ 0.
  /// The admissible p are found on a scan p = 2^k (SI, k = −20…40) and their bound refined: by
  /// bisection on g, then on h(p) = K at the binding position (an end of the path, or the
  /// stationary point ∂K/∂along = 0 inside it) to 45 digits. Where the binding position is exact
  /// (an end) and K is a polynomial of degree ≤ 2 in p, the bound is also solved in closed form
  /// and must agree with the number.
  void reach(const model::Find& f, Result& r) const {
    const auto& x = *f.reach;
    const int digits = 45;
    const std::string S = m.states[x.state].name;
    const std::string what = x.least ? "least" : "greatest";
    ex K = r.closed;
    check_reach(K, x, S, what);
    auto two_to = [](int k) { return ex_to<numeric>(pow(numeric(2), k)); };
    exmap at = env;
    auto K_at = [&](const ex& e, const numeric& s, const numeric& p) -> std::optional<numeric> {
      at[x.p] = p;
      if (x.along) at[*x.along] = s;
      auto v = numerics::evaluate(e, at, digits);
      if (v && !v->is_real()) return std::nullopt;
      return v;
    };
    numeric lo = 0, hi = 0;
    if (x.along) std::tie(lo, hi) = range_at(x.lo, x.hi, x.pos, x.along_name, digits);
    // the lowest kinetic energy over the path, on a grid of n intervals
    PathScan scan(lo, hi, x.along.has_value(), numerics::tracing() ? std::nullopt : tape_of(K, x),
                  [&](const numeric& s, const numeric& p) { return K_at(K, s, p); });
    using Low = PathScan::Low;
    auto lowest = [&](const numeric& p, int n) { return scan.lowest(p, n); };
    auto admissible = [&](const numeric& p, int n) { return scan.admissible(p, n); };
    // scan: the admissible p form [p*, ∞) for a least value, (0, p*] for a greatest
    const int k0 = -20, k1 = 40;
    std::optional<int> edge;  // first admissible k (least) / last admissible k (greatest)
    for (int k = k0; k <= k1; ++k) {
      bool ok = admissible(two_to(k), 100);
      if (x.least && ok && !edge) edge = k;
      if (!x.least && ok) edge = k;
      if (!x.least && !ok && edge) break;
    }
    std::string path = x.along ? " at every position of the path (" + x.along_name + " from " + numerics::format(lo, 6) + " to " +
                                     numerics::format(hi, 6) + ")"
                               : "";
    if (!edge)
      throw SceneError(x.pos, "state '" + S + "' is not reached for any value of '" + x.p_name + "' from 2^" + std::to_string(k0) +
                                  " to 2^" + std::to_string(k1) + " (SI): the kinetic energy there stays negative" + path,
                       "check the states and the effects: the motion toward state '" + S + "' cannot get there");
    if ((x.least && *edge == k0) || (!x.least && *edge == k1))
      throw SceneError(x.pos, "state '" + S + "' is reached for every value of '" + x.p_name + "' " +
                                  (x.least ? "down to 2^" + std::to_string(k0) : "up to 2^" + std::to_string(k1)) +
                                  " (SI): there is no " + what + " value to find",
                       "check 'reaches' and the states: the kinetic energy at state '" + S + "' should fall to zero as '" + x.p_name +
                           "' " + (x.least ? "decreases" : "increases"));
    // the bracket: a (not admissible), b (admissible)
    numeric a = two_to(x.least ? *edge - 1 : *edge + 1), b = two_to(*edge);
    for (int it = 0; it < 24; ++it) {
      numeric c = (a + b) / 2;
      (admissible(c, 100) ? b : a) = c;
    }
    // the binding position at b, and h(p) = K there
    std::optional<Low> bind = lowest(b, 400);
    std::optional<numeric> s_star;  // interior stationary point, refined per p
    auto stationary = [&](const numeric& p, const numeric& s0, const numeric& s1) -> std::optional<numeric> {
      // ∂K/∂along = 0 inside [s0, s1]
      ex dK = K.diff(ex_to<symbol>(*x.along));
      auto f = [&](const numeric& s) { return K_at(dK, s, p); };
      auto d0 = f(s0), d1 = f(s1);
      if (!d0 || !d1) return std::nullopt;
      return numerics::bracketed_root(f, s0, s1, *d0, *d1, numerics::tenth(digits), numerics::tenth(digits), digits + 10);
    };
    const int n = 400;
    const bool at_end = !x.along || bind->i == 0 || bind->i == n;
    numeric step = (hi - lo) / n;
    auto h = [&](const numeric& p) -> std::optional<numeric> {
      if (at_end) return K_at(K, bind->s, p);
      s_star = stationary(p, bind->s - step, bind->s + step);
      if (!s_star) return std::nullopt;
      return K_at(K, *s_star, p);
    };
    // Illinois (regula falsi) on h over [a, b], kept by bisection where it stalls
    // the grid's least value lies above the true one: move the ends apart until h brackets zero
    auto ha = h(a), hb = h(b);
    for (numeric grow = numeric(1, 1000000); grow < 1 && hb && hb->is_negative(); grow *= 4) {
      b = x.least ? b * (1 + grow) : b / (1 + grow);
      hb = h(b);
    }
    for (numeric grow = numeric(1, 1000000); grow < 1 && ha && !ha->is_negative(); grow *= 4) {
      a = x.least ? a / (1 + grow) : a * (1 + grow);
      ha = h(a);
    }
    if (!ha || !hb || !ha->is_negative() || hb->is_negative())
      throw SceneError(x.pos, "the " + what + " value of '" + x.p_name + "' for which state '" + S + "' is reached could not be isolated" + path,
                       "give 'over' a narrower range of the path, or check the states");
    auto root = numerics::bracketed_root(h, a, b, *ha, *hb, numerics::tenth(digits), 0, digits + 10);
    if (!root)
      throw SceneError(x.pos, "the " + what + " value of '" + x.p_name + "' for which state '" + S + "' is reached could not be isolated" + path,
                       "give 'over' a narrower range of the path, or check the states");
    numeric p_star = *root;
    numeric s_bind = at_end ? bind->s : (s_star ? *s_star : bind->s);
    // the binding position exactly: an end, or a stationary point that is a simple rational (or
    // rational multiple of π, denominator ≤ 360) at which ∂K/∂along vanishes to 40 digits
    std::optional<ex> exact_s;
    if (x.along && at_end) exact_s = bind->i == 0 ? x.lo : x.hi;
    if (x.along && !at_end) exact_s = exact_position(K, x, s_bind, p_star, digits, K_at);
    // in parameters without values, where no simple number is it: ∂K/∂along = 0 solved for it
    // (a form free of p, the root that is the number found)
    const bool in_symbols = std::any_of(m.params.begin(), m.params.end(), [&](const model::Parameter& q) {
      return q.without_value() && K.has(q.sym) && !q.sym.is_equal(x.p) && !(x.along && q.sym.is_equal(*x.along));
    });
    if (x.along && !at_end && !exact_s && in_symbols) {
      const ex dK = K.diff(ex_to<symbol>(*x.along));
      if (!dK.has(x.p))
        if (auto c = stationary_place(dK, ex_to<symbol>(*x.along), s_bind); c && !c->has(x.p)) exact_s = c;
    }
    // the closed form, where the binding position is exact: K(s, p) = 0 of degree ≤ 2 in p
    std::optional<ex> closed;
    if (!x.along || exact_s) closed = reach_closed(K, x, exact_s, p_star, digits);
    r.extreme_note = reach_note(x, S, path, s_bind, at_end, p_star);
    r.extreme_of = K;
    r.extreme_what = "the kinetic energy at state " + S + " as a function of " + x.p_name + (x.along ? " and " + x.along_name : "");
    r.closed = closed ? *closed : ex(p_star);
    r.closed_form = closed.has_value();
  }

  /// A motion runs forward in time: a solved duration t₂ − t₁ < 0 would put the second state
  /// before the first (a motor weaker than the friction it must overcome, say).
  void forward_in_time(const model::Analysis& a) const {
    if (a.instant()) return;
    const auto &S1 = m.states[a.from], &S2 = m.states[a.to];
    if (given.count(S1.t) && given.count(S2.t)) return;  // both given: checked when the model was built
    std::optional<numeric> d;
    try {
      d = numerics::evaluate((S2.t - S1.t).subs(given).subs(sol_.branch.sol), env, 30);
    } catch (const std::exception&) {
      return;  // undefined there: reported with the results that need it
    }
    if (!d || !d->is_negative()) return;
    throw SceneError(a.pos, "the " + a.kind + " analysis from state '" + S1.name + "' to '" + S2.name + "' needs t@" + S2.name +
                                " - t@" + S1.name + " = " + numerics::format(*d, 6) + " s: state '" + S2.name +
                                "' would come before state '" + S1.name + "' (the effects between them act against the change asked for)",
                     "check the sizes and directions of the effects, or what is given at state '" + S2.name + "'");
  }

  /// One named result: its closed form (every unknown in it determined) and value.
  Result result(const model::Find& f) const {
    const Solution& sol = sol_;
  Result r;
  r.name = f.name;
  r.pos = f.pos;
  r.dim = f.dim;
  ex c;
  try {
    c = f.value.subs(given).subs(sol.branch.sol);
  } catch (const std::exception& err) {
    throw SceneError(f.pos, "'" + f.name + "' is undefined at the states (" + model::math_fault(err) + ")",
                     "check the value of '" + f.name + "' and the values given at its states");
  }
  for (auto& u : unknowns)
    if (c.has(u)) {
      std::size_t n = sol.equations.size();
      // an impulse left free means the state values around it are missing, not the impulse
      bool impulse = false;
      for (auto& a : m.analyses)
        for (auto& x : a.unknowns) impulse = impulse || x.is_equal(u);
      // the state values that nothing fixed are what is missing
      // the state values that were solved only in terms of the free impulse are what is missing
      std::string missing;
      if (impulse)
        for (auto& x : unknowns) {
          bool is_impulse = false;
          for (auto& a : m.analyses)
            for (auto& y : a.unknowns) is_impulse = is_impulse || y.is_equal(x);
          auto it = sol.branch.sol.find(x);
          if (!is_impulse && it != sol.branch.sol.end() && it->second.has(u))
            missing += (missing.empty() ? "" : ", ") + model::text(x);
        }
      // an analysis that would give it and says why it does not (a momentum balance whose
      // pushes are not known in time does not integrate to positions)
      std::string why;
      for (std::size_t ai = 0; ai < sol.balances.size() && why.empty(); ++ai)
        if (std::string w = sol.balances[ai]->why_not(u); !w.empty())
          why = "; the " + m.analyses[ai].kind + " analysis " + m.states[m.analyses[ai].from].name + " -> " + m.states[m.analyses[ai].to].name +
                " does not give it: " + w;
      throw SceneError(f.pos, "'" + f.name + "' is not determined: " + model::text(u) + (impulse ? " (an impulse)" : "") +
                                  " is unknown (the analyses give " + std::to_string(n) +
                                  (n == 1 ? " equation" : " equations") + " for more unknowns)" + why,
                       impulse ? "give " + (missing.empty() ? std::string("the missing values at the states around that analysis") : missing) +
                                     " (velocities before an impact, a time), or add an analysis"
                               : "give " + model::text(u) + " at its state, or add an analysis or a 'where' condition that fixes it");
    }
  // a float in the result comes only from a numeric root: no closed form
  r.closed_form = !has_float(c);
  r.closed = model::factored(model::root_simplify(model::tidy_result(model::tidy_function_arguments(c)),
                                                  [this](const ex& x) { return m.fixed_sign(x); }));
  // a value that holds numbers found by numeric roots: the same value as an expression of the
  // roots (for proving its digits)
  if (!r.closed_form && !in_roots_.empty()) {
    try {
      const ex g = f.value.subs(given).subs(in_roots_);
      bool free = !has_float(g);
      for (auto& u : unknowns)
        free = free && (!g.has(u) || std::any_of(found_roots_.begin(), found_roots_.end(), [&](const numerics::RootOf& x) { return x.u.is_equal(u); }));
      if (free) {
        // the roots g holds, and those their equations hold, each after the ones it needs
        std::vector<bool> take(found_roots_.size(), false);
        for (std::size_t i = found_roots_.size(); i-- > 0;) {
          take[i] = g.has(found_roots_[i].u);
          for (std::size_t j = i + 1; j < found_roots_.size(); ++j) take[i] = take[i] || (take[j] && found_roots_[j].residual.has(found_roots_[i].u));
        }
        for (std::size_t i = 0; i < found_roots_.size(); ++i)
          if (take[i]) r.roots.push_back(found_roots_[i]);
        r.of_roots = g;
      }
    } catch (const std::exception&) {
      r.roots.clear();
    }
  }
  if (f.extreme) extreme(f, r);
  if (f.reach) reach(f, r);
  if (f.unit) {
    r.unit = f.unit->text;
    r.unit_factor = f.unit->factor;
  } else {
    r.unit = units::si_name(f.dim);
  }
  bool all_values = true;
  const model::Parameter* missing = nullptr;
  // a numeric root holds the parameters of its equation (every one, where it does not say)
  auto holds = [&](const model::Parameter& p) {
    if (r.closed_form) return r.closed.has(p.sym);
    if (r.roots.empty()) return p.without_value() && !p.ranged;
    return std::any_of(r.roots.begin(), r.roots.end(), [&](const numerics::RootOf& x) { return x.residual.has(p.sym); });
  };
  for (auto& p : m.params)
    if (!p.value && (r.closed_form || !p.ranged) && holds(p)) {
      all_values = false;
      if (!missing) missing = &p;
    }
  // neither a form nor a number: a root of an equation in parameters without values
  if (!all_values && !r.closed_form)
    throw NoFormError(f.pos, "'" + f.name + "' has no closed form (" +
                                 (f.reach ? std::string("its bound is found numerically, by a scan and bisection") :
                                  f.extreme ? std::string("its extreme is found numerically, by a scan") :
                                              std::string("it is a root of an equation found numerically") + solves_text(r)) + "), and parameter '" + missing->name +
                                "' has no value, so neither a form nor a number can be given",
                     "give the parameters values (the root is then found for them), e.g. '" + missing->name + ": " +
                         (units::si_name(missing->dim).empty() ? std::string("30 deg") : "2 " + units::si_name(missing->dim)) + "'");
  // a unit on the result, or a claimed number, asks for a number
  bool number_asked = f.unit.has_value();
  for (auto& x : m.expects) number_asked = number_asked || (x.name == f.name && x.value);
  if (!all_values && number_asked)
    throw SceneError(missing->pos, "parameter '" + missing->name + "' has no value, but a number is asked for '" +
                                       f.name + "'",
                     "give it a value with its unit, e.g. '" + missing->name + ": " +
                         (units::si_name(missing->dim).empty() ? std::string("30 deg") : "2 " + units::si_name(missing->dim)) + "'");
  if (all_values) {
    auto v = numerics::evaluate(r.closed, env, 30);
    if (!v)
      throw SceneError(f.pos, "'" + f.name + "' has no real value (" + model::text(r.closed) + ")",
                       "check the states and parameters: this result is undefined or complex for them");
    r.si = v;
  }
    return r;
  }
};

}  // namespace

GiNaC::exmap parameter_values(const Solution& s) {
  GiNaC::exmap v = s.model.parameter_values();
  for (auto& p : s.model.params)
    if (p.unknown) {
      auto it = s.branch.sol.find(p.sym);
      if (it != s.branch.sol.end()) v[p.sym] = it->second.subs(v);
    }
  return v;
}

const principles::Condition* failing_condition(const Solution& s) {
  const exmap env = s.model.numeric_environment();
  for (auto& c : s.valid_where) {
    std::optional<numeric> v;
    try {
      v = numerics::evaluate(c.e, env, 30);
    } catch (const std::exception&) {
    }
    if (!v || !v->is_real() || v->is_negative()) return &c;
  }
  return nullptr;
}

bool admissible(const Solution& at, std::string& why) {
  const model::Model& m = at.model;
  const exmap given = m.given_values(), env = m.numeric_environment();
  auto number = [&](const ex& e) -> std::optional<numeric> {
    try {
      return numerics::evaluate(e.subs(given).subs(at.branch.sol).subs(given), env, 30);
    } catch (const std::exception&) {
      return std::nullopt;
    }
  };
  if (const principles::Condition* c = failing_condition(at)) {
    why = c->assumed.empty() ? "a condition of the solution fails" : c->assumed;
    return false;
  }
  for (auto& r : at.results) {
    std::optional<numeric> v;
    try {
      v = r.value(env, 15);
    } catch (const std::exception&) {
    }
    if (!v || !v->is_real()) {
      why = "'" + r.name + "' has no real value there";
      return false;
    }
  }
  for (auto& a : m.analyses) {
    if (a.from < 0 || a.to < 0 || a.instant()) continue;
    auto t1 = number(m.states[static_cast<std::size_t>(a.from)].t), t2 = number(m.states[static_cast<std::size_t>(a.to)].t);
    if (t1 && t2 && t1->is_real() && t2->is_real() && *t2 < *t1) {
      why = "state '" + m.states[static_cast<std::size_t>(a.to)].name + "' comes before '" + m.states[static_cast<std::size_t>(a.from)].name + "'";
      return false;
    }
  }
  return true;
}

Solution solve_scene(const scene::SceneDef& def) {
  Model base = Model::build(def);
  const bool free = std::any_of(base.params.begin(), base.params.end(), [](const model::Parameter& p) { return p.without_value() && !p.ranged; });
  // A force that switches on the way to a state whose position is unknown: the case taken first
  // is past every switching point; while it has no solution, one switching point fewer.
  // Parameters without values: the numeric choices (a root, a sign, the first state along the
  // motion) are made at sample values of them; where a case has no solution at the first sample
  // (an Atwood machine whose sampled masses would lift the heavier block), it is tried at the
  // next, up to kSolveSamples, before a switching point fewer. The closed forms hold where the
  // choices fall the same way: the confirmation checks them at samples of its own. Where no
  // case has a solution at any sample, the first error.
  // A solution whose own conditions (valid_where) fail at the sample its choices were made at
  // chose outside its domain (a rod whose sampled speed would take it off the wall at once, where
  // only the horizontal rod has N = 0): the next sample is tried, and that solution kept only
  // where none does better.
  // Once a solution is found outside its domain, further samples are first tried on its closed
  // forms (admissible: its conditions met, its results real — no solve), up to kSampleSearch, and
  // the scene solved again only at one that passes.
  std::optional<SceneError> first;
  std::optional<Solution> outside;
  int cases = 1;
  for (int fewer = 0; fewer < cases; ++fewer) {
    int solves = 0;
    for (int k = 0; k < (free ? kSampleSearch : 1) && solves < kSolveSamples; ++k) {
      if (outside) {
        Solution probe = *outside;
        probe.model.sample = k;
        std::string why;
        if (!admissible(probe, why)) continue;
      }
      ++solves;
      base.sample = k;
      Solution sol{base, {}, {}, {}, {}, {}, {}, def, {}, {}, {}, {}};
      try {
        SceneSolver(sol, fewer).run();
        if (!free || !failing_condition(sol)) return sol;
        if (!outside) outside = std::move(sol);
        continue;
      } catch (const NoFormError&) {
        throw;  // (so at every sample)
      } catch (const SceneError& e) {
        if (!first) first = e;
        for (auto* bal : sol.balances_of<principles::EnergyBalance>())
          for (auto& w : bal->works) cases = std::max(cases, w.switch_cases);
      }
    }
    if (outside) return std::move(*outside);  // (no sample inside its domain: the first found)
  }
  throw *first;
}

Solution solve_file(const std::string& path) { return solve_scene(scene::load_file(path)); }

}  // namespace kinergy
