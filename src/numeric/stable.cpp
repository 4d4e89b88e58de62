#include "kinergy/numeric/stable.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "kinergy/expr/canonical.hpp"

namespace kinergy::numerics {

using namespace GiNaC;

namespace {

/// The factors of a term, in the order of their keys (not GiNaC's, which follows addresses).
std::vector<ex> factors(const ex& t) {
  if (!is_a<mul>(t)) return {t};
  std::vector<ex> f(t.begin(), t.end());
  std::stable_sort(f.begin(), f.end(), [](const ex& a, const ex& b) { return expr::key(a).text < expr::key(b).text; });
  return f;
}

bool same(const ex& a, const ex& b) { return a.is_equal(b) || (a - b).expand().is_zero(); }

bool is_fn(const ex& f, const char* name) { return is_a<function>(f) && ex_to<function>(f).get_name() == name; }

bool is_sqrt(const ex& f) { return is_a<power>(f) && f.op(1).is_equal(numeric(1, 2)); }
bool is_square(const ex& f) { return is_a<power>(f) && f.op(1).is_equal(2); }

/// t = A·g for a factor g of t with `pred`: the pairs (g, A).
template <class Pred>
std::vector<std::pair<ex, ex>> split_by(const ex& t, Pred pred) {
  std::vector<std::pair<ex, ex>> out;
  for (const ex& g : factors(t))
    if (pred(g)) out.emplace_back(g, t / g);
  return out;
}

/// sin and cos of r + kπ/2 as ± sin r or ± cos r: the quarter turns leave the argument exactly,
/// so a small r keeps its relative precision (cos(π/2 + r) = −sin r, not cos of a rounded sum).
struct ReduceQuarterTurns : map_function {
  ex operator()(const ex& e) override {
    ex m = e.map(*this);
    const bool is_sin = is_fn(m, "sin"), is_cos = is_fn(m, "cos");
    if (!(is_sin || is_cos) || !is_a<add>(m.op(0))) return m;
    const ex arg = m.op(0);
    const ex k = arg.coeff(Pi, 1) * 2;  // the argument holds (k/2) π
    if (!is_a<numeric>(k) || !ex_to<numeric>(k).is_integer() || k.is_zero()) return m;
    const ex r = (arg - k * Pi / 2).expand();
    if (r.has(Pi)) return m;
    const long q = ((ex_to<numeric>(k).to_long() % 4) + 4) % 4;  // quarter turns, mod a full turn
    // sin(r + qπ/2) = sin r, cos r, −sin r, −cos r;  cos(r + qπ/2) = cos r, −sin r, −cos r, sin r
    const long shift = is_sin ? q : q + 1;
    switch (shift % 4) {
      case 0: return sin(r);
      case 1: return cos(r);
      case 2: return -sin(r);
      default: return -cos(r);
    }
  }
};

ex reduce_quarter_turns(const ex& e) {
  ReduceQuarterTurns f;
  return f(e);
}

/// The rewrite of ti + tj when the pair is one of the cancelling patterns.
std::optional<ex> pair_rewrite(const ex& ti, const ex& tj) {
  // tj = B·f with f = cos x, sin x, √b or q²
  for (const ex& f : factors(tj)) {
    const ex B = tj / f;  // tj = B f
    const ex A = -B;      // the pattern A (… − f): ti must be built on A
    if (is_fn(f, "cos")) {
      const ex& x = f.op(0);
      // A − A cos x = 2A sin²(x/2)
      if (same(ti, A)) return 2 * A * pow(sin(x / 2), 2);
      // A + A cos x = 2A cos²(x/2)   (here ti = B)
      if (same(ti, B)) return 2 * B * pow(cos(x / 2), 2);
      // A sin x − A cos x = √2 A sin(x − π/4)
      for (auto& [g, C] : split_by(ti, [](const ex& g) { return is_fn(g, "sin"); }))
        if (g.op(0).is_equal(x) && same(C, A)) return reduce_quarter_turns(sqrt(ex(2)) * A * sin((x - Pi / 4).expand()));
      // A cos y − A cos x = −2A sin((y+x)/2) sin((y−x)/2)
      for (auto& [g, C] : split_by(ti, [](const ex& g) { return is_fn(g, "cos"); }))
        if (same(C, A) && !g.op(0).is_equal(x)) {
          const ex& y = g.op(0);
          return -2 * A * sin((y + x).expand() / 2) * sin((y - x).expand() / 2);
        }
    }
    if (is_fn(f, "sin")) {
      const ex& x = f.op(0);
      // A − A sin x = 2A sin²(π/4 − x/2)
      if (same(ti, A)) return 2 * A * pow(sin(Pi / 4 - x / 2), 2);
      // A + A sin x = 2A cos²(π/4 − x/2)
      if (same(ti, B)) return 2 * B * pow(cos(Pi / 4 - x / 2), 2);
      // A cos x − A sin x = √2 A cos(x + π/4)
      for (auto& [g, C] : split_by(ti, [](const ex& g) { return is_fn(g, "cos"); }))
        if (g.op(0).is_equal(x) && same(C, A)) return reduce_quarter_turns(sqrt(ex(2)) * A * cos((x + Pi / 4).expand()));
      // A sin y − A sin x = 2A cos((y+x)/2) sin((y−x)/2)
      for (auto& [g, C] : split_by(ti, [](const ex& g) { return is_fn(g, "sin"); }))
        if (same(C, A) && !g.op(0).is_equal(x)) {
          const ex& y = g.op(0);
          return 2 * A * cos((y + x).expand() / 2) * sin((y - x).expand() / 2);
        }
    }
    // a pair A sin x + A cos x (no cancellation of its own) becomes one term, which may then
    // cancel against a third: √2 + sin x − cos x
    if (is_fn(f, "cos")) {
      const ex& x = f.op(0);
      for (auto& [g, C] : split_by(ti, [](const ex& g) { return is_fn(g, "sin"); }))
        if (g.op(0).is_equal(x) && same(C, B)) return reduce_quarter_turns(sqrt(ex(2)) * B * sin((x + Pi / 4).expand()));
    }
    if (is_sqrt(f)) {
      const ex& b = f.op(0);
      // A √a − A √b = A (a − b)/(√a + √b)
      for (auto& [g, C] : split_by(ti, is_sqrt))
        if (same(C, A) && !g.is_equal(f)) {
          const ex& a = g.op(0);
          ex den = sqrt(a) + sqrt(b);
          if (den.is_zero()) continue;  // √a = −√b: nothing to divide by
          return A * (a - b).expand() / den;
        }
      // A c − A √b with c > 0 a number: c = √(c²)
      ex c = ti / A;
      if (is_a<numeric>(c) && ex_to<numeric>(c).is_positive())
        return A * (pow(c, 2) - b).expand() / (c + sqrt(b));
    }
    if (is_square(f)) {
      const ex& q = f.op(0);
      // A p² − A q² = A (p − q)(p + q)
      for (auto& [g, C] : split_by(ti, is_square))
        if (same(C, A) && !g.is_equal(f)) {
          const ex& p = g.op(0);
          return A * (p - q) * (p + q);
        }
      // A c − A q² with c = p² for a rational p: 1 − e² = (1 − e)(1 + e)
      ex c = ti / A;
      if (is_a<numeric>(c) && ex_to<numeric>(c).is_positive()) {
        ex p = sqrt(c);
        if (is_a<numeric>(p) && ex_to<numeric>(p).is_rational()) return A * (p - q) * (p + q);
      }
    }
  }
  return std::nullopt;
}

/// A term without its numeric coefficient, as text: terms that a pattern pairs (A and −A cos x,
/// A sin y and −A sin x) have equal signatures once the factor the pattern names is taken out.
std::string signature(const ex& t) {
  if (is_a<numeric>(t)) return "1";
  if (!is_a<mul>(t)) return expr::key(t).text;
  ex rest = 1;
  for (const ex& f : t)
    if (!is_a<numeric>(f)) rest *= f;
  return expr::key(rest).text;
}

bool special(const ex& f) { return is_fn(f, "cos") || is_fn(f, "sin") || is_sqrt(f) || is_square(f); }

/// The first pair (i, j), in the order of the exhaustive search (i, then j), that a pattern
/// rewrites; through an index of signatures, so that a sum of T terms costs about T lookups
/// instead of T² trials. A pattern pairs ti with tj = B·f only where ti, or ti without one of its
/// own sin/cos/√/square factors, has the signature of B.
/// Pairs of terms already tried without a rewrite: a rewrite replaces two terms by one and leaves
/// the others, so each later round tries only the pairs with the new term.
struct Failed {
  std::set<std::pair<ex, ex>, bool (*)(const std::pair<ex, ex>&, const std::pair<ex, ex>&)> pairs{
      [](const std::pair<ex, ex>& a, const std::pair<ex, ex>& b) {
        int c = a.first.compare(b.first);
        return c != 0 ? c < 0 : a.second.compare(b.second) < 0;
      }};
  std::optional<ex> rewrite(const ex& ti, const ex& tj) {
    if (pairs.count({ti, tj})) return std::nullopt;
    auto r = pair_rewrite(ti, tj);
    if (!r) pairs.insert({ti, tj});
    return r;
  }
};

std::optional<std::tuple<std::size_t, std::size_t, ex>> indexed_pair(const std::vector<ex>& terms, Failed& failed) {
  std::unordered_map<std::string, std::vector<std::size_t>> by_sig;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    by_sig[signature(terms[i])].push_back(i);
    for (const ex& g : factors(terms[i]))
      if (special(g)) by_sig[signature(terms[i] / g)].push_back(i);
  }
  std::map<std::pair<std::size_t, std::size_t>, bool> tried;
  std::optional<std::tuple<std::size_t, std::size_t, ex>> best;
  for (std::size_t j = 0; j < terms.size(); ++j)
    for (const ex& f : factors(terms[j])) {
      if (!special(f)) continue;
      auto it = by_sig.find(signature(terms[j] / f));
      if (it == by_sig.end()) continue;
      for (std::size_t i : it->second) {
        if (i == j || tried.count({i, j})) continue;
        tried[{i, j}] = true;
        if (best && std::make_pair(i, j) > std::make_pair(std::get<0>(*best), std::get<1>(*best))) continue;
        if (auto r = failed.rewrite(terms[i], terms[j])) best = std::make_tuple(i, j, *r);
      }
    }
  return best;
}

ex rewrite_sum(const ex& s) {
  // the terms in the order of their keys: where several pairs could be rewritten, the same pair
  // is, in every run (GiNaC's order follows addresses)
  std::vector<ex> terms(s.begin(), s.end());
  std::stable_sort(terms.begin(), terms.end(), [](const ex& a, const ex& b) { return expr::key(a).text < expr::key(b).text; });
  // a small sum: every pair is tried (a pattern may also match terms equal only once expanded);
  // a large one: only the pairs whose signatures agree
  constexpr std::size_t kExhaustive = 24;
  Failed failed;
  bool changed = true;
  while (changed) {
    changed = false;
    std::optional<std::tuple<std::size_t, std::size_t, ex>> hit;
    if (terms.size() > kExhaustive) {
      hit = indexed_pair(terms, failed);
    } else {
      for (std::size_t i = 0; i < terms.size() && !hit; ++i)
        for (std::size_t j = 0; j < terms.size() && !hit; ++j)
          if (i != j)
            if (auto r = failed.rewrite(terms[i], terms[j])) hit = std::make_tuple(i, j, *r);
    }
    if (!hit) break;
    // the pair becomes one product; the other terms stay
    auto [i, j, r] = *hit;
    std::vector<ex> rest;
    for (std::size_t k = 0; k < terms.size(); ++k)
      if (k != i && k != j) rest.push_back(terms[k]);
    rest.push_back(r);
    terms = rest;
    changed = terms.size() > 1;
  }
  ex out = 0;
  for (auto& t : terms) out += t;
  return out;
}

struct Rewrite : map_function {
  ex operator()(const ex& e) override {
    ex m = reduce_quarter_turns(e.map(*this));  // children first
    return is_a<add>(m) ? rewrite_sum(m) : m;
  }
};

}  // namespace

ex stable_form(const ex& e) {
  Rewrite r;
  try {
    return r(e);
  } catch (const std::exception&) {
    return e;  // a rewrite that GiNaC cannot form (a division by an expression that is zero): the form as it is
  }
}

}  // namespace kinergy::numerics
