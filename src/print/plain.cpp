// Plain-text printing of closed forms as a person writes them:
//   sqrt(3*g*sin(theta2)/l)   rather than   sqrt(sin(theta2))*l^(-1/2)*sqrt(3)*sqrt(g)
#include <algorithm>
#include <sstream>

#include "kinergy/print/plain.hpp"

#include "kinergy/print/factors.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::emit {

using namespace GiNaC;

namespace {

using detail::Factor;
using detail::Factors;
using enum detail::Prec;
using detail::classify;
using detail::flip_sum;

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


std::string product(const ex& e, int ctx) {
  Factors f = detail::split(e, ctx == 0);
  bool root_minus = detail::flatten_roots(f);
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
  // a root stands in the numerator (with only numbers under it after the fold, √(1/3) too)
  const bool root = !f.root_num.empty() || !f.root_den.empty();
  if (!c.is_integer() && c.is_rational()) {
    if (c.numer() != 1 || (f.num.empty() && !root)) top = number(c.numer());
    bottom = number(c.denom());
  } else if (c != 1 || (f.num.empty() && !root)) {
    top = number(c);
  }
  std::string n = join(f.num);
  if (!n.empty()) top += (top.empty() ? "" : "*") + n;
  if (!f.root_num.empty() || !f.root_den.empty()) {
    // what stands under the root, printed as one product (its sums turned as a product's are,
    // the sign kept apart back on it)
    ex inner = root_minus ? -1 : 1;
    for (auto& x : f.root_num) inner = inner * x;
    for (auto& x : f.root_den) inner = inner / x;
    top += (top.empty() ? "" : "*") + std::string("sqrt(") + print(inner, 0) + ")";
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
    // each term with its sign as printed (a product takes the sign of a sum it flipped, so
    // GiNaC's own choice of signs inside does not show): positive terms first ("g*m + sqrt(…)",
    // not "-… + …"), each group in the order of its text
    std::vector<detail::Term> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const ex& term = e.op(i);
      std::string k = key(term, kSum);
      bool neg = !k.empty() && k[0] == '-';
      if (neg) k = k.substr(1);
      // a term with a negative number in front is printed negated ("1 - e", with a value "1 - 0.5")
      bool coef_neg = (is_a<numeric>(term) && ex_to<numeric>(term).is_negative()) ||
                      (is_a<mul>(term) && is_a<numeric>(term.op(term.nops() - 1)) &&
                       ex_to<numeric>(term.op(term.nops() - 1)).is_negative());
      std::string t = coef_neg && neg ? print(-term, kSum) : print(term, kSum);
      if (!t.empty() && t[0] == '-') t = t.substr(1);
      terms.push_back({neg, k, t});
    }
    std::string s = detail::join_terms(std::move(terms));
    return ctx > kSum ? "(" + s + ")" : s;
  }
  if (is_a<mul>(e)) return product(e, ctx);
  if (is_a<power>(e)) {
    ex k = e.op(1);
    if (detail::printed_as_product(e)) return product(e, ctx);
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

// A sum and its negative print alike but for the sign: pick the one with more positive terms
// (ties: the one whose first term, in text order, is positive), so r − R and −(R − r) agree.
// A term's sign is the one it prints with: GiNaC's own choice of sign for a sum inside a term
// (it depends on its term order, so on addresses) changes neither the count nor the texts.
namespace {
/// A sum's terms as they print: (negative, text without the sign), each printed once.
std::vector<std::pair<bool, std::string>> signed_keys(const ex& b) {
  std::vector<std::pair<bool, std::string>> out;
  for (std::size_t i = 0; i < b.nops(); ++i) {
    std::string k = key(b.op(i), kSum);
    bool n = !k.empty() && k[0] == '-';
    out.push_back({n, n ? k.substr(1) : k});
  }
  return out;
}

int balance_of(const std::vector<std::pair<bool, std::string>>& keys) {
  int balance = 0;
  for (auto& [n, k] : keys) balance += n ? -1 : 1;
  return balance;
}
}  // namespace

int sum_orientation(const ex& b) { return is_a<add>(b) ? balance_of(signed_keys(b)) : 0; }

bool flip_sum(const ex& b) {
  if (!is_a<add>(b)) return false;
  auto keys = signed_keys(b);
  int o = balance_of(keys);
  if (o != 0) return o < 0;  // more negative terms than positive
  // a tie: the first term in text order positive
  std::size_t first = 0;
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i].second < keys[first].second) first = i;
  return keys[first].first;
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

Factors split(const ex& e, bool turn_positive) {
  Factors f;
  if (is_a<mul>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) classify(e.op(i), f);
  else
    classify(e, f);
  // A product reads better positive: when it comes out negative, a sum in it (to an odd power)
  // with as many negative terms as positive, or one more positive, is turned round instead:
  // 3·(a + b − c − d)/m rather than −3·(c + d − a − b)/m, (m·u − J)/m rather than −(J − m·u)/m.
  // The choice depends on the product's value and the texts only, never on which way round
  // GiNaC stored a sum. Only for a product that stands alone: a term of a sum keeps the sign
  // its sums give it, so that a term and its negative print alike but for the sign.
  if (turn_positive && f.coef.is_negative()) {
    Factor* best = nullptr;
    std::pair<int, std::string> best_key;
    for (auto* group : {&f.num, &f.den})
      for (auto& x : *group) {
        if (!x.k.is_integer() || !x.k.is_odd() || !is_a<add>(x.base)) continue;
        int balance = sum_orientation(x.base);
        if (balance < 0 || balance > 1) continue;
        std::pair<int, std::string> k{balance, key(x.base, kAtom)};
        if (!best || k < best_key) {
          best = &x;
          best_key = k;
        }
      }
    if (best) {
      best->base = -best->base;
      f.coef = -f.coef;
    }
  }
  return f;
}

// The products in a root's groups taken apart: a factor x^−k goes to the other group as x^k,
// a fraction's numerator and denominator to their groups. A number's sign is kept apart (GiNaC
// gives a product's coefficient the sign that makes up for the signs it chose for the sums in
// it) and returned, so that the numbers reduced next are the same in every run.
bool flatten_roots(Factors& f) {
  bool minus = false;
  auto take = [&minus](exvector& up, exvector& down) {
    exvector keep, more_down;
    for (auto& x : up) {
      // (a b)⁻¹ under a root goes below its bar as a b does, however GiNaC holds it (one power
      // of the product, or a product of powers: which one follows its term order, so addresses)
      if (is_a<power>(x) && is_a<numeric>(x.op(1)) && ex_to<numeric>(x.op(1)).is_negative()) {
        more_down.push_back(pow(x.op(0), -x.op(1)));
        continue;
      }
      if (!is_a<mul>(x)) {
        keep.push_back(x);
        continue;
      }
      for (std::size_t i = 0; i < x.nops(); ++i) {
        const ex& y = x.op(i);
        if (is_a<numeric>(y) && ex_to<numeric>(y).is_rational()) {
          if (ex_to<numeric>(y).is_negative()) minus = !minus;
          keep.push_back(abs(ex_to<numeric>(y).numer()));
          more_down.push_back(ex_to<numeric>(y).denom());
        } else if (is_a<power>(y) && is_a<numeric>(y.op(1)) && ex_to<numeric>(y.op(1)).is_negative()) {
          more_down.push_back(pow(y.op(0), -y.op(1)));
        } else {
          keep.push_back(y);
        }
      }
    }
    up = keep;
    down.insert(down.end(), more_down.begin(), more_down.end());
  };
  take(f.root_num, f.root_den);
  take(f.root_den, f.root_num);
  auto drop_ones = [](exvector& v) {
    exvector keep;
    for (auto& x : v)
      if (!x.is_equal(1)) keep.push_back(x);
    v = keep;
  };
  drop_ones(f.root_num);
  drop_ones(f.root_den);
  return minus;
}

bool printed_as_product(const ex& power) {
  const ex& k = power.op(1);
  if (!is_a<numeric>(k) || !ex_to<numeric>(k).is_rational()) return false;
  const numeric& q = ex_to<numeric>(k);
  return q.is_negative() || q.denom() == 2 || (q.is_integer() && is_a<add>(power.op(0)));
}

std::string join_terms(std::vector<Term> terms) {
  std::stable_sort(terms.begin(), terms.end(), [](const Term& a, const Term& b) {
    return std::make_pair(a.negative, a.key) < std::make_pair(b.negative, b.key);
  });
  std::string s;
  for (auto& t : terms) s += s.empty() ? (t.negative ? "-" : "") + t.text : (t.negative ? " - " : " + ") + t.text;
  return s;
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
