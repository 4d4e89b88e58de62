// Plain-text printing of closed forms as a person writes them:
//   sqrt(3*g*sin(theta2)/l)   rather than   sqrt(sin(theta2))*l^(-1/2)*sqrt(3)*sqrt(g)
#include <algorithm>
#include <sstream>

#include "kinergy/emit/emit.hpp"
#include "factors.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::emit {

using namespace GiNaC;

namespace {

using detail::Factor;
using detail::Factors;
using detail::classify;
using detail::flip_sum;
using detail::negative_term;

enum Prec { kSum = 1, kProduct = 2, kPower = 3, kAtom = 4 };

std::string print(const ex& e, int ctx);

/// Texts printed in place of some symbols (a parameter's value with its unit), or none.
thread_local const SymbolTexts* g_names = nullptr;

/// The text that decides the order of terms and factors: always the text without the
/// replacements, so that a form with values put in keeps the order of the form itself.
std::string key(const ex& e, int ctx) {
  const SymbolTexts* saved = g_names;
  g_names = nullptr;
  std::string s = print(e, ctx);
  g_names = saved;
  return s;
}

std::string number(const numeric& n) {
  if (n.is_rational()) {
    std::ostringstream os;
    os << n;
    return os.str();
  }
  return numerics::format(n, 15);
}

// GiNaC orders terms by hashes that change from run to run (they mix in type addresses), so
// output order is decided here: numbers, then names, then functions, then sums; ties by text.
int rank(const ex& x) {
  if (is_a<numeric>(x)) return 0;
  ex b = is_a<power>(x) ? x.op(0) : x;
  if (is_a<symbol>(b) || is_a<constant>(b)) return 1;
  if (is_a<function>(b)) return 2;
  return 3;
}

std::string factor_text(const Factor& f) {
  if (f.k == 1) return print(f.base, kProduct);
  std::string k = number(f.k);
  if (!f.k.is_integer()) k = "(" + k + ")";  // 2^(1/4), never 2^1/4
  return print(f.base, kAtom) + "^" + k;
}

std::string join(std::vector<Factor> v) {
  std::vector<std::pair<std::pair<int, std::string>, std::string>> keyed;
  for (auto& x : v) keyed.push_back({{rank(x.base), key(x.base, kAtom)}, factor_text(x)});
  std::stable_sort(keyed.begin(), keyed.end(), [](auto& a, auto& b) { return a.first < b.first; });
  std::string s;
  for (auto& x : keyed) s += (s.empty() ? "" : "*") + x.second;
  return s;
}

std::string join(const exvector& v) {
  std::vector<Factor> f;
  for (auto& x : v) f.push_back({x, 1});
  std::string s = join(f);
  // a lone product under a root's division bar still needs its parentheses
  if (v.size() == 1 && is_a<mul>(v[0])) s = "(" + s + ")";
  return s;
}

std::string product(const ex& e, int ctx) {
  Factors f = detail::split(e);
  bool neg = f.coef.is_negative();
  numeric c = neg ? -f.coef : f.coef;
  auto has_number = [](const exvector& v) {
    for (auto& x : v)
      if (is_a<numeric>(x)) return true;
    return false;
  };
  // fold the coefficient into the root when that gives one reduced fraction (2/3·√(3x) → √(4x/3));
  // a plain integer in front of a root without numbers stays outside (2·√x)
  bool fold = (!f.root_num.empty() || !f.root_den.empty()) && c.is_rational() &&
              (c.denom() != 1 || has_number(f.root_num) || has_number(f.root_den));
  if (fold) {
    // (p/q)·√(a·X/b) = √(p² a X / (q² b)): one root, numbers reduced
    numeric rn = c.numer() * c.numer(), rd = c.denom() * c.denom();
    detail::take_root_numbers(f, rn, rd);
    if (rn != 1) f.root_num.insert(f.root_num.begin(), rn);
    if (rd != 1) f.root_den.insert(f.root_den.begin(), rd);
    c = 1;
  }
  std::string top, bottom;
  if (!c.is_integer() && c.is_rational()) {
    if (c.numer() != 1 || (f.num.empty() && f.root_num.empty())) top = number(c.numer());
    bottom = number(c.denom());
  } else if (c != 1 || (f.num.empty() && f.root_num.empty())) {
    top = number(c);
  }
  std::string n = join(f.num);
  if (!n.empty()) top += (top.empty() ? "" : "*") + n;
  if (!f.root_num.empty() || !f.root_den.empty()) {
    bool lone = f.root_num.size() == 1 && f.root_den.empty();
    std::string in = f.root_num.empty() ? "1" : lone ? print(f.root_num[0], 0) : join(f.root_num);
    if (!f.root_den.empty()) {
      std::string d = join(f.root_den);
      in += "/" + (f.root_den.size() > 1 ? "(" + d + ")" : d);
    }
    top += (top.empty() ? "" : "*") + std::string("sqrt(") + in + ")";
  }
  std::string d = join(f.den);
  if (!d.empty()) bottom += (bottom.empty() ? "" : "*") + d;
  std::size_t nd = f.den.size() + (c.denom() != 1 ? 1 : 0);
  std::string s = top;
  if (!bottom.empty()) s += "/" + (nd > 1 ? "(" + bottom + ")" : bottom);
  if (neg) s = "-" + s;
  if (ctx > kProduct || (neg && ctx >= kProduct)) return "(" + s + ")";
  return s;
}

std::string print(const ex& e, int ctx) {
  if (is_a<numeric>(e)) {
    numeric n = ex_to<numeric>(e);
    std::string s = number(n);
    bool compound = n.is_negative() || (n.is_rational() && !n.is_integer());
    return compound && ctx >= kProduct ? "(" + s + ")" : s;
  }
  if (is_a<constant>(e) && e.is_equal(Pi)) return "pi";
  if (is_a<symbol>(e)) {
    if (g_names) {
      auto it = g_names->find(e);
      if (it != g_names->end()) return ctx >= kProduct ? "(" + it->second + ")" : it->second;
    }
    return ex_to<symbol>(e).get_name();
  }
  if (is_a<add>(e)) {
    std::string s;
    // terms with a positive sign first reads better: "g*m + sqrt(…)" not "-… + …"
    exvector pos, negs;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      ex t = e.op(i);
      bool neg = (is_a<numeric>(t) && ex_to<numeric>(t).is_negative()) ||
                 (is_a<mul>(t) && is_a<numeric>(t.op(t.nops() - 1)) && ex_to<numeric>(t.op(t.nops() - 1)).is_negative());
      (neg ? negs : pos).push_back(t);
    }
    auto by_text = [](exvector& v, bool negate) {
      std::vector<std::pair<std::string, ex>> k;
      for (auto& t : v) k.push_back({key(negate ? ex(-t) : t, kSum), t});
      std::stable_sort(k.begin(), k.end(), [](auto& a, auto& b) {
        // plain names before numbers-first products: "g*m + …"; then alphabetical
        return a.first < b.first;
      });
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = k[i].second;
    };
    by_text(pos, false);
    by_text(negs, true);
    // a term may print with a sign of its own (a product that flipped a sum): "a - m*(x - y)",
    // never "a + -m*(y - x)"
    auto put = [&](const ex& t, bool minus) {
      std::string x = print(t, kSum);
      if (!x.empty() && x[0] == '-') {
        x = x.substr(1);
        minus = !minus;
      }
      s += s.empty() ? (minus ? "-" : "") : (minus ? " - " : " + ");
      s += x;
    };
    for (auto& t : pos) put(t, false);
    for (auto& t : negs) put(-t, true);
    return ctx > kSum ? "(" + s + ")" : s;
  }
  if (is_a<mul>(e)) return product(e, ctx);
  if (is_a<power>(e)) {
    ex k = e.op(1);
    if (is_a<numeric>(k) && ex_to<numeric>(k).is_rational() &&
        (ex_to<numeric>(k).is_negative() || ex_to<numeric>(k).denom() == 2))
      return product(e, ctx);
    std::string s = print(e.op(0), kAtom) + "^" + print(k, kAtom);
    return ctx > kPower ? "(" + s + ")" : s;
  }
  if (is_a<function>(e)) {
    std::string s = ex_to<function>(e).get_name() + "(";
    for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + print(e.op(i), 0);
    return s + ")";
  }
  std::ostringstream os;
  os << e;
  return os.str();
}

}  // namespace

std::string plain(const ex& e) { return print(e, 0); }

std::string plain(const ex& e, const SymbolTexts& names) {
  const SymbolTexts* saved = g_names;
  g_names = &names;
  std::string s;
  try {
    s = print(e, 0);
  } catch (...) {
    g_names = saved;
    throw;
  }
  g_names = saved;
  return s;
}

namespace detail {

bool negative_term(const ex& t) {
  return (is_a<numeric>(t) && ex_to<numeric>(t).is_negative()) ||
         (is_a<mul>(t) && is_a<numeric>(t.op(t.nops() - 1)) && ex_to<numeric>(t.op(t.nops() - 1)).is_negative());
}

// A sum and its negative print alike but for the sign: pick the one with more positive terms
// (ties: the one whose first term, in text order, is positive), so r − R and −(R − r) agree.
bool flip_sum(const ex& b) {
  if (!is_a<add>(b)) return false;
  int pos = 0, neg = 0;
  std::string first;
  bool first_neg = false;
  for (std::size_t i = 0; i < b.nops(); ++i) {
    bool n = negative_term(b.op(i));
    (n ? neg : pos)++;
    std::string k = key(n ? ex(-b.op(i)) : b.op(i), kSum);
    if (first.empty() || k < first) {
      first = k;
      first_neg = n;
    }
  }
  return neg > pos || (neg == pos && first_neg);
}

void classify(const ex& f, Factors& out) {
  if (is_a<numeric>(f)) {
    out.coef *= ex_to<numeric>(f);
    return;
  }
  ex b = f, k = 1;
  if (is_a<power>(f)) {
    b = f.op(0);
    k = f.op(1);
  }
  if (!is_a<numeric>(k) || !ex_to<numeric>(k).is_rational()) {
    out.num.push_back({f, 1});
    return;
  }
  numeric q = ex_to<numeric>(k);
  if (is_a<numeric>(b) && ex_to<numeric>(b).is_rational() && q.denom() == 2) {
    // √(p/q) = √p / √q
    numeric r = ex_to<numeric>(b);
    bool up = q.is_positive();
    (up ? out.root_num : out.root_den).push_back(r.numer());
    (up ? out.root_den : out.root_num).push_back(r.denom());
    numeric whole = (up ? q : -q) - numeric(1, 2);  // r^(n + 1/2) = r^n √r
    if (!whole.is_zero()) out.coef *= ex_to<numeric>(pow(r, up ? whole : -whole));
    return;
  }
  if (q.is_integer() && flip_sum(b)) {
    b = -b;  // an add: GiNaC distributes the sign over its terms
    if (q.is_odd()) out.coef = -out.coef;
  }
  bool neg = q.is_negative();
  numeric a = neg ? -q : q;
  auto& plain = neg ? out.den : out.num;
  exvector& root = neg ? out.root_den : out.root_num;
  if (a.denom() == 2) {
    // x^(n + 1/2) = x^n · √x
    numeric whole = (a - numeric(1, 2));
    if (!whole.is_zero()) plain.push_back({b, whole});
    root.push_back(b);
  } else {
    plain.push_back({b, a});
  }
}

Factors split(const ex& e) {
  Factors f;
  if (is_a<mul>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) classify(e.op(i), f);
  else
    classify(e, f);
  return f;
}

void take_root_numbers(Factors& f, numeric& rn, numeric& rd) {
  auto take = [](exvector& v, numeric& into) {
    exvector keep;
    for (auto& x : v) {
      if (is_a<numeric>(x) && ex_to<numeric>(x).is_integer()) into *= ex_to<numeric>(x);
      else keep.push_back(x);
    }
    v = keep;
  };
  take(f.root_num, rn);
  take(f.root_den, rd);
  numeric g = gcd(rn, rd);
  rn = rn / g;
  rd = rd / g;
}

}  // namespace detail

}  // namespace kinergy::emit
