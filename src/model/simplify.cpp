#include "kinergy/model/simplify.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

namespace kinergy::model {

using namespace GiNaC;

ex tidy(const ex& e) {
  ex x = trig_simplify(e);
  if (ex_size(x) < 1500) {
    ex n = normal(x);
    if (ex_size(n) <= ex_size(x) + 4) x = n;
  }
  return x;
}

ex tidy_result(const ex& e) {
  ex x = tidy(e);
  if (ex_size(x) < 1500) return x;
  // a result the solving left large (the forces of a body pinned in free coordinates, after
  // substitution upon substitution): normalised once, its functions and roots standing in as
  // symbols, kept when shorter
  try {
    exmap repl;
    ex p = x.to_rational(repl);
    ex n = normal(p).subs(repl);
    ex t = trig_simplify(n);
    if (ex_size(t) < ex_size(x)) x = t;
  } catch (const std::exception&) {
  }
  return x;
}

namespace {
ex factor_any_uncached(const ex& e) {
  // factor() works on polynomials: functions (cos β, √…) stand in as temporary symbols
  exmap repl;
  ex p = e.to_polynomial(repl);
  ex f = factor(p);
  // factor() leaves an irreducible factor in a nested form that follows GiNaC's choice of main
  // variable (by term order, so by addresses): each factor is written expanded instead
  ex out = 1;
  for (auto& x : factors_of(f)) {
    if (is_a<add>(x)) out *= x.expand();
    else if (is_a<GiNaC::power>(x) && is_a<add>(x.op(0))) out *= pow(x.op(0).expand(), x.op(1));
    else out *= x;
  }
  exmap back;
  for (auto& [sym, orig] : repl) back[sym] = orig;
  return out.subs(back);
}
}  // namespace

ex factor_any(const ex& e) {
  // the same form is factored again and again while a scene is solved (over the 78 derivations
  // in one batch: 1441 calls, 451 distinct forms; GiNaC's factor was 18 % of the batch's time):
  // each is kept, keyed by the form (its value depends on the form alone)
  static thread_local std::map<ex, ex, ex_is_less> kept;
  if (auto it = kept.find(e); it != kept.end()) return it->second;
  // and a form is often factored again as its negative (a residual's two sides): factor(−e) =
  // −factor(e)
  if (auto it = kept.find(-e); it != kept.end()) return -it->second;
  ex f = factor_any_uncached(e);
  if (kept.size() > 2048) kept.clear();  // (bounded: a long batch keeps no old scene alive for long)
  kept.emplace(e, f);
  return f;
}

namespace {
struct tidy_arguments : public map_function {
  ex operator()(const ex& e) override {
    ex m = e.map(*this);
    if (!is_a<function>(m)) return m;
    exvector args;
    for (std::size_t i = 0; i < m.nops(); ++i) args.push_back(factored(tidy(m.op(i))));
    return ex_to<function>(m).thiscontainer(args);
  }
};
}  // namespace

ex tidy_function_arguments(const ex& e) { return tidy_arguments()(e); }

ex factored(const ex& e) {
  // numerator and denominator factored apart, kept only when that is shorter
  if (ex_size(e) > 1500) return e;
  try {
    // numer_denom() normalises (so expands) what stands under a root: factored again there
    ex nd = numer_denom(e);
    ex f = root_simplify(factor_any(nd.op(0)) / factor_any(nd.op(1)));
    return ex_size(f) < ex_size(e) ? f : e;
  } catch (const std::exception&) {
    return e;  // not a rational function GiNaC can factor
  }
}

exvector factors_of(const ex& e) {
  exvector fs;
  if (is_a<mul>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) fs.push_back(e.op(i));
  else
    fs.push_back(e);
  return fs;
}

std::string text(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

std::string math_fault(const std::exception& err) {
  std::string w = err.what();
  if (w.find("division by zero") != std::string::npos) return "a division by zero";
  if (w.find("log(0)") != std::string::npos) return "log(0)";
  if (w.find("pole") != std::string::npos) return "a function at a pole, like tan at pi/2";
  return w;
}

std::size_t ex_size(const ex& e) {
  // GiNaC writes a sum that is a factor with the sign its term order picks (the order depends
  // on addresses), so −1 coefficients are not counted: a form and its sign-flipped twin have
  // one size. A product counts its other factors, and its coefficient when that is not ±1.
  if (is_a<mul>(e)) {
    std::size_t n = 0, factors = 0;
    bool unit = true;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (is_a<numeric>(e.op(i))) {
        unit = abs(ex_to<numeric>(e.op(i))) == 1;
        continue;
      }
      n += ex_size(e.op(i));
      ++factors;
    }
    if (factors == 1 && unit) return n;  // −x counts as x
    return 1 + n + (unit ? 0 : 1);
  }
  if (is_a<numeric>(e)) return 1;
  std::size_t n = 1;
  for (std::size_t i = 0; i < e.nops(); ++i) n += ex_size(e.op(i));
  return n;
}

namespace {

// Replace f(a)^n (n ≥ 2) by f(a)^(n mod 2) · (1 − g(a)²)^(n div 2), where {f, g} = {cos, sin}.
struct reduce_power : public map_function {
  bool cos_to_sin;
  explicit reduce_power(bool c) : cos_to_sin(c) {}
  ex operator()(const ex& e) override {
    if (is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_pos_integer()) {
      const ex& b = e.op(0);
      long n = ex_to<numeric>(e.op(1)).to_long();
      bool match = cos_to_sin ? is_ex_the_function(b, cos) : is_ex_the_function(b, sin);
      if (match && n >= 2) {
        ex other = cos_to_sin ? sin(b.op(0)) : cos(b.op(0));
        return pow(b, n % 2) * pow(1 - pow(other, 2), n / 2);
      }
    }
    return e.map(*this);
  }
};

// sin(x + nπ/2) and cos(x + nπ/2) with integer n: quarter-turn shifts, and odd/even symmetry.
struct unshift : public map_function {
  ex operator()(const ex& e) override {
    ex m = e.map(*this);
    bool is_sin = is_ex_the_function(m, sin), is_cos = is_ex_the_function(m, cos);
    if (!is_sin && !is_cos) return m;
    ex arg = m.op(0);
    // split arg = x + c·π
    numeric c = 0;
    ex x = arg;
    if (is_a<add>(arg)) {
      x = 0;
      for (std::size_t i = 0; i < arg.nops(); ++i) {
        ex t = arg.op(i);
        ex k = t / Pi;
        if (is_a<numeric>(k) && ex_to<numeric>(k).is_rational()) c += ex_to<numeric>(k);
        else x += t;
      }
    }
    numeric n2 = c * 2;
    if (!n2.is_integer() || c.is_zero()) {
      // symmetry only: sin(−y) = −sin(y), cos(−y) = cos(y)
      if (is_a<mul>(arg) && is_a<numeric>(arg.op(arg.nops() - 1)) &&
          ex_to<numeric>(arg.op(arg.nops() - 1)).is_negative())
        return is_sin ? -sin(-arg) : cos(-arg);
      return m;
    }
    long n = ((n2.to_long() % 4) + 4) % 4;
    ex sx = (*this)(sin(x)), cx = (*this)(cos(x));
    if (is_sin) {
      ex r[4] = {sx, cx, -sx, -cx};  // sin(x + nπ/2)
      return r[n];
    }
    ex r[4] = {cx, -sx, -cx, sx};  // cos(x + nπ/2)
    return r[n];
  }
};

// √(c·p²·q) → |p|·√(c·q) for p positive (a positive symbol, or a positive number), and
// √(c·p^(2k)·q) → (σp)^k·√(c·q) for p of a fixed sign σ (`sign`).
struct unroot : public map_function {
  SignOf sign;
  explicit unroot(SignOf s = nullptr) : sign(std::move(s)) {}
  ex operator()(const ex& e) override {
    ex m = e.map(*this);
    if (!is_a<GiNaC::power>(m) || !is_a<numeric>(m.op(1))) return m;
    numeric k = ex_to<numeric>(m.op(1));
    if (k.denom() != 2) return m;
    ex b = m.op(0);
    if (ex_size(b) > 300) return m;  // factoring large expressions costs more than it gives
    ex f;
    try {
      // numerator and denominator factored apart (factor() takes a denominator for a symbol)
      ex nd = numer_denom(normal(b));
      f = factor_any(nd.op(0)) / factor_any(nd.op(1));
    } catch (const std::exception&) {
      return m;
    }
    ex out = 1, in = 1;
    for (auto& x : factors_of(f)) {
      if (is_a<GiNaC::power>(x) && is_a<numeric>(x.op(1)) && ex_to<numeric>(x.op(1)).is_integer() &&
          x.op(0).info(info_flags::positive)) {
        long p = ex_to<numeric>(x.op(1)).to_long();
        out *= pow(x.op(0), p / 2);
        in *= pow(x.op(0), p % 2);
      } else if (int s = 0; sign && is_a<GiNaC::power>(x) && is_a<numeric>(x.op(1)) && ex_to<numeric>(x.op(1)).is_even() &&
                            (s = sign(x.op(0))) != 0) {
        // (p^(2k))^(1/2) = |p|^k = (σp)^k
        out *= pow(s * x.op(0), ex_to<numeric>(x.op(1)).to_long() / 2);
      } else {
        in *= x;
      }
    }
    if (out.is_equal(1))  // nothing comes out: keep the shorter of the two forms
      return ex_size(f) < ex_size(b) ? pow(f, k) : m;
    return pow(out, k * 2) * pow(in, k);
  }
};

// √a·√b = √(a·b) for a > 0 (any b): every half-integer power of a positive base in a product
// goes under one root, and into the one square root of a base of unknown sign when the product
// has exactly one; GiNaC cancels what it can there. GiNaC leaves l^(1/2)·(l·m)^(−1/2) or
// √2·√(2x) apart, and whether a form arrives split one way or another follows its term order
// (so addresses).
struct merge_roots : public map_function {
  ex operator()(const ex& e) override {
    ex m = e.map(*this);
    if (!is_a<mul>(m)) return m;
    ex inside = 1, rest = 1, other;
    int positive = 0, others = 0;
    for (std::size_t i = 0; i < m.nops(); ++i) {
      const ex& f = m.op(i);
      bool half = is_a<GiNaC::power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).denom() == 2;
      if (half && f.op(0).info(info_flags::positive)) {
        inside *= pow(f.op(0), f.op(1) * 2);  // b^k = (b^(2k))^(1/2), b > 0
        ++positive;
        continue;
      }
      if (half && f.op(1).is_equal(numeric(1, 2))) {
        other = f.op(0);
        ++others;
      }
      rest *= f;
    }
    if (positive == 0 || (positive == 1 && others != 1)) return m;
    if (others == 1) return (rest / sqrt(other)) * sqrt(inside * other);  // √a·√b = √(a·b), a > 0
    return rest * sqrt(inside);
  }
};

}  // namespace

ex unshift_trig(const ex& e) { return unshift()(e); }

ex root_simplify(const ex& e, const SignOf& sign) { return unroot(sign)(merge_roots()(e)); }

ex trig_simplify(const ex& e) {
  ex x = unshift()(e).expand();
  if (!x.has(sin(wild())) && !x.has(cos(wild()))) return x;
  reduce_power c2s(true), s2c(false);
  ex a = c2s(x).expand();
  ex b = s2c(x).expand();
  std::size_t sx = ex_size(x), sa = ex_size(a), sb = ex_size(b);
  if (sa <= sb && sa <= sx) return a;
  if (sb <= sx) return b;
  return x;
}

ex collect_simplify(const ex& e, const lst& rates) {
  // distributed collection in the rates, then simplify each coefficient
  ex c = collect(e.expand(), rates, true);
  exvector terms;
  if (is_a<add>(c))
    for (std::size_t i = 0; i < c.nops(); ++i) terms.push_back(c.op(i));
  else
    terms.push_back(c);
  exmap by_mono;  // monomial in the rates → coefficient
  for (const ex& term : terms) {
    exvector factors;
    if (is_a<mul>(term))
      for (std::size_t j = 0; j < term.nops(); ++j) factors.push_back(term.op(j));
    else
      factors.push_back(term);
    ex mono = 1, coef = 1;
    for (const ex& f : factors) {
      bool is_rate = false;
      for (const auto& r : rates)
        if (f.is_equal(r) || (is_a<GiNaC::power>(f) && f.op(0).is_equal(r))) is_rate = true;
      (is_rate ? mono : coef) *= f;
    }
    by_mono[mono] += coef;
  }
  ex out = 0;
  for (auto& [mono, coef] : by_mono) out += mono * trig_simplify(coef);
  return out;
}


static std::optional<ex> linear_coeff(const ex& arg, const symbol& s) {
  // arg = a s + b with a free of s
  ex d = arg.diff(s);
  if (d.is_zero() || d.has(s)) return std::nullopt;
  return d;
}

std::optional<ex> elementary_antiderivative(const ex& f, const symbol& s);

namespace {

bool is_sin_or_cos(const ex& f) { return is_ex_the_function(f, sin) || is_ex_the_function(f, cos); }

/// The product of two sines or cosines as a sum (product-to-sum):
///   sin A sin B = [cos(A − B) − cos(A + B)]/2,   cos A cos B = [cos(A − B) + cos(A + B)]/2,
///   sin A cos B = [sin(A + B) + sin(A − B)]/2.
ex product_to_sum(const ex& a, const ex& b) {
  const ex A = a.op(0), B = b.op(0);
  const ex d = (A - B).expand(), p = (A + B).expand();
  bool sa = is_ex_the_function(a, sin), sb = is_ex_the_function(b, sin);
  if (sa && sb) return (cos(d) - cos(p)) / 2;
  if (!sa && !sb) return (cos(d) + cos(p)) / 2;
  if (sa) return (sin(p) + sin(d)) / 2;  // sin A cos B
  return (sin(p) - sin(d)) / 2;          // cos A sin B = sin B cos A
}

/// e with every product of sines and cosines (powers included, up to the 16th) written as a sum
/// of single sines and cosines of sums of the arguments: sin θ cos θ → sin 2θ / 2, cos² θ → (1 + cos 2θ)/2.
ex linearize_trig(const ex& e) {
  ex x = e.expand();
  if (is_a<add>(x)) {
    ex out = 0;
    for (const ex& t : x) out += linearize_trig(t);
    return out;
  }
  exvector trig;
  ex rest = 1;
  for (const ex& f : factors_of(x)) {
    if (is_sin_or_cos(f)) {
      trig.push_back(f);
    } else if (is_a<GiNaC::power>(f) && is_sin_or_cos(f.op(0)) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_pos_integer() &&
               ex_to<numeric>(f.op(1)).to_long() <= 16) {
      for (long i = 0; i < ex_to<numeric>(f.op(1)).to_long(); ++i) trig.push_back(f.op(0));
    } else {
      rest *= f;
    }
  }
  if (trig.size() < 2) return x;
  ex others = rest;
  for (std::size_t i = 2; i < trig.size(); ++i) others *= trig[i];
  return linearize_trig(product_to_sum(trig[0], trig[1]) * others);
}

/// How many sines and cosines (counting powers) a product holds.
std::size_t trig_factors(const ex& t) {
  std::size_t n = 0;
  for (const ex& f : factors_of(t)) {
    if (is_sin_or_cos(f)) ++n;
    else if (is_a<GiNaC::power>(f) && is_sin_or_cos(f.op(0)) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_pos_integer())
      n += static_cast<std::size_t>(ex_to<numeric>(f.op(1)).to_long());
  }
  return n;
}

}  // namespace

std::optional<ex> rational_antiderivative(const ex& f, const symbol& s);

std::optional<ex> antiderivative(const ex& f, const symbol& s) {
  if (auto a = elementary_antiderivative(f, s)) return a;
  return rational_antiderivative(f, s);
}

std::optional<ex> elementary_antiderivative(const ex& f, const symbol& s) {
  if (!f.has(s)) return f * s;  // ∫ c ds = c s
  if (f.is_equal(s)) return pow(s, 2) / 2;
  if (is_a<add>(f)) {
    ex r = 0;
    for (std::size_t i = 0; i < f.nops(); ++i) {
      auto a = antiderivative(f.op(i), s);
      if (!a) return std::nullopt;
      r += *a;
    }
    return r;
  }
  if (is_a<mul>(f)) {
    ex c = 1, g = 1;
    int dependent = 0;
    for (std::size_t i = 0; i < f.nops(); ++i) {
      if (f.op(i).has(s)) {
        g *= f.op(i);
        ++dependent;
      } else {
        c *= f.op(i);
      }
    }
    if (dependent == 1) {
      auto a = antiderivative(g, s);
      if (a) return c * *a;
      return std::nullopt;
    }
    // sines and cosines multiplied together: a sum of single ones of multiple angles
    //   ∫ sin θ cos θ dθ = ∫ sin 2θ / 2 dθ = −cos 2θ / 4
    if (trig_factors(g) >= 2) {
      ex l = linearize_trig(g);
      if (!l.is_equal(g)) {
        auto a = antiderivative(l, s);
        if (a) return c * *a;
      }
    }
    // a polynomial times one function with an antiderivative, by parts:
    //   ∫ p(s) g(s) ds = p G − ∫ p′ G ds,  G = ∫ g ds  (the degree of p falls at each step)
    {
      ex p = 1, h = 1;
      int others = 0;
      for (const ex& x : factors_of(g)) {
        if (x.is_polynomial(s)) p *= x;
        else {
          h *= x;
          ++others;
        }
      }
      if (others == 1 && p.has(s) && is_a<function>(h)) {
        auto G = antiderivative(h, s);
        if (G) {
          auto rest = antiderivative((p.diff(s) * *G).expand(), s);
          if (rest) return c * (p * *G - *rest);
        }
      }
    }
    // a product of several factors in s: try its expansion (polynomials, sums)
    ex x = f.expand();
    if (!x.is_equal(f) && is_a<add>(x)) return antiderivative(x, s);
    return std::nullopt;
  }
  if (is_a<GiNaC::power>(f)) {
    const ex& b = f.op(0);
    const ex& n = f.op(1);
    if (n.has(s)) return std::nullopt;
    auto a = linear_coeff(b, s);
    if (a) {
      // ∫ (a s + b)^n ds = (a s + b)^(n+1) / ((n+1) a);  n = −1: log(a s + b)/a
      if (n.is_equal(-1)) return log(b) / *a;
      return pow(b, n + 1) / ((n + 1) * *a);
    }
    if (is_a<numeric>(n) && ex_to<numeric>(n).is_pos_integer()) {
      ex x = f.expand();
      if (!x.is_equal(f)) return antiderivative(x, s);
      // sin² θ = (1 − cos 2θ)/2 and the like
      if (trig_factors(f) >= 2) {
        ex l = linearize_trig(f);
        if (!l.is_equal(f)) return antiderivative(l, s);
      }
    }
    return std::nullopt;
  }
  if (is_a<function>(f) && f.nops() == 1) {
    auto a = linear_coeff(f.op(0), s);
    if (!a) return std::nullopt;
    const ex& u = f.op(0);
    // ∫ sin(a s + b) ds = −cos(a s + b)/a,  ∫ cos = sin/a,  ∫ exp = exp/a, ∫ sinh = cosh/a, ∫ cosh = sinh/a
    if (is_ex_the_function(f, sin)) return -cos(u) / *a;
    if (is_ex_the_function(f, cos)) return sin(u) / *a;
    if (is_ex_the_function(f, exp)) return exp(u) / *a;
    if (is_ex_the_function(f, sinh)) return cosh(u) / *a;
    if (is_ex_the_function(f, cosh)) return sinh(u) / *a;
    return std::nullopt;
  }
  return std::nullopt;
}

/// ∫ P/Q ds for polynomials P, Q in s by partial fractions: the polynomial part, then over the
/// factors of Q (linear L = a s + b and quadratic K = α s² + β s + γ with 4αγ − β² > 0):
///   A/L → (A/a) log L,   A/L^j → A L^(1−j)/((1 − j) a),
///   (B s + C)/K → (B/2α) log K + (C − Bβ/2α) (2/√Δ) atan((2α s + β)/√Δ),  Δ = 4αγ − β².
/// The coefficients A, B, C from the identity P mod Q = Σ (terms) × Q (linear in them). Nothing
/// for an irreducible factor of higher degree, a power of a quadratic, or a Δ of unknown sign.
std::optional<ex> rational_antiderivative(const ex& f, const symbol& s) {
  ex nd;
  try {
    nd = numer_denom(normal(f));
  } catch (const std::exception&) {
    return std::nullopt;
  }
  ex P = nd.op(0).expand(), Q = nd.op(1).expand();
  if (!Q.has(s) || !P.is_polynomial(s) || !Q.is_polynomial(s) || Q.degree(s) > 8) return std::nullopt;
  ex out = 0;
  ex q = quo(P, Q, s), r = rem(P, Q, s);
  if (!q.is_zero()) {
    auto a = elementary_antiderivative(q.expand(), s);
    if (!a) return std::nullopt;
    out += *a;
  }
  if (r.is_zero()) return out;
  ex Qf;
  try {
    Qf = factor(Q);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  // the factors in s with their multiplicities; the rest is a constant
  struct Part {
    ex base;
    int mult;
  };
  std::vector<Part> parts;
  ex lead = 1;
  for (const ex& x : factors_of(Qf)) {
    ex b = x;
    int k = 1;
    if (is_a<GiNaC::power>(x) && is_a<numeric>(x.op(1)) && ex_to<numeric>(x.op(1)).is_pos_integer()) {
      b = x.op(0);
      k = static_cast<int>(ex_to<numeric>(x.op(1)).to_long());
    }
    if (!b.has(s)) {
      lead *= x;
      continue;
    }
    int d = b.degree(s);
    if (d > 2 || (d == 2 && k > 1)) return std::nullopt;
    parts.push_back({b.expand(), k});
  }
  // the ansatz and its coefficients
  lst unknowns, terms_l;
  ex sum = 0;
  std::vector<std::pair<ex, ex>> terms;  // (numerator, denominator) with unknowns
  int n = 0;
  for (auto& pt : parts)
    for (int j = 1; j <= pt.mult; ++j) {
      symbol A("pfA" + std::to_string(n++));
      unknowns.append(A);
      ex num = A;
      if (pt.base.degree(s) == 2) {
        symbol C("pfC" + std::to_string(n++));
        unknowns.append(C);
        num = A * s + C;
      }
      terms.push_back({num, pow(pt.base, j)});
      sum += num * normal(Q / (lead * pow(pt.base, j)));
    }
  // r = lead × Σ num_i × (Q/lead)/den_i, coefficient by coefficient in s
  ex id = (sum * lead - r).expand();
  lst eqs;
  for (int k = 0; k <= id.degree(s); ++k) eqs.append(id.coeff(s, k) == 0);
  ex sol;
  try {
    sol = lsolve(eqs, unknowns);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (!is_a<lst>(sol) || sol.nops() != unknowns.nops()) return std::nullopt;
  for (auto& [num, den] : terms) {
    ex N = num.subs(ex_to<lst>(sol)), base = den, j = 1;
    if (is_a<GiNaC::power>(den)) {
      base = den.op(0);
      j = den.op(1);
    }
    if (N.is_zero()) continue;
    if (base.degree(s) == 1) {
      ex a = base.diff(s);
      out += j.is_equal(1) ? N * log(base) / a : N * pow(base, 1 - j) / ((1 - j) * a);
      continue;
    }
    ex al = base.coeff(s, 2), be = base.coeff(s, 1), ga = base.coeff(s, 0);
    ex D = (4 * al * ga - be * be).expand();
    if (!(D.info(info_flags::positive) || (is_a<numeric>(D) && ex_to<numeric>(D).is_positive()))) return std::nullopt;
    ex B = N.coeff(s, 1), C = N.coeff(s, 0);
    out += B / (2 * al) * log(base) + (C - B * be / (2 * al)) * 2 / sqrt(D) * atan((2 * al * s + be) / sqrt(D));
  }
  return out;
}

}  // namespace kinergy::model
