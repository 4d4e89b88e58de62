#include "kinergy/numeric/evaluate.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

#include <cln/cln.h>

#include "kinergy/common/interrupt.hpp"
#include "kinergy/numeric/digits.hpp"
#include "kinergy/numeric/tape.hpp"
#include "kinergy/numeric/trace.hpp"

namespace kinergy::numerics {

using namespace GiNaC;

// A trigonometric function of x reduces x modulo 2π, and loses x's integer digits doing so: the
// working precision that leaves `digits` digits after that (sin(1e300 deg) at 30 digits is noise).
// 0 when more than 20 000 digits would be needed.
static long covering_digits(const ex& v, long digits) {
  long need = digits;
  for (auto it = v.preorder_begin(); it != v.preorder_end(); ++it) {
    if (!is_a<function>(*it)) continue;
    const std::string name = ex_to<function>(*it).get_name();
    if (name != "sin" && name != "cos" && name != "tan") continue;
    ex a = it->op(0).evalf();
    if (!is_a<GiNaC::numeric>(a) || !ex_to<GiNaC::numeric>(a).is_real() || ex_to<GiNaC::numeric>(a).is_zero()) continue;
    double l = ex_to<GiNaC::numeric>(log(abs(ex_to<GiNaC::numeric>(a)))).to_double() / std::log(10.0);
    if (!(l < 20000)) return 0;
    // as the tape does: only when the integer digits would take a large share of the precision
    const long int_digits = static_cast<long>(std::ceil(l));
    if (int_digits > 0 && int_digits + 10 > digits / 2) need = std::max(need, 2 * (int_digits + 10) + digits);
  }
  return need <= 20000 ? need : 0;
}

std::optional<GiNaC::numeric> evaluate(const ex& e, const exmap& values, int digits) {
  const DigitsScope precision(digits);
  std::optional<GiNaC::numeric> out;
  bool free = false;
  try {
    ex s = e.subs(values);
    free = tracing() && holds_symbol(s);
    long need = covering_digits(s, digits);
    if (need == 0) throw std::domain_error("an angle too large for the working precision");
    precision.set(need);
    ex v = s.evalf();
    if (is_a<GiNaC::numeric>(v) && ex_to<GiNaC::numeric>(v).is_real()) out = ex_to<GiNaC::numeric>(v);
  } catch (const std::exception&) {
    out.reset();  // division by zero, domain errors: no number
  }
  // a choice may read this value: noted for a sweep (numeric/trace.hpp); a form with symbols left
  // has no number at any parameter values, so nothing is chosen by it
  if (tracing() && !free) note(e, out);
  return out;
}

bool beyond_precision(const ex& e, const exmap& values, int digits) {
  const DigitsScope precision(Digits);  // (covering_digits sets it; restored as it was)
  bool beyond = false;
  try {
    beyond = covering_digits(e.subs(values), digits) == 0;
  } catch (const std::exception&) {
    beyond = false;  // not a number at all: some other reason
  }
  return beyond;
}

std::optional<bool> negligible(const ex& e, const exmap& values, int digits) {
  auto v = evaluate(e, values, digits);
  if (!v) return std::nullopt;
  if (v->is_zero()) return true;
  // the largest term of the expanded form sets the scale of what cancels
  numeric scale = abs(*v);
  ex x = e.expand();
  if (is_a<add>(x))
    for (const ex& t : x)
      if (auto tv = evaluate(t, values, digits)) scale = std::max(scale, abs(*tv));
  if (abs(*v) <= scale * pow(numeric(10), 12 - digits)) return true;
  // A value left by rounding alone, where the terms' sizes do not show it (a product of a
  // difference of two forms of one number, sin(acos z) − √(1 − z²)): at twice the digits it
  // shrinks with the working precision, where a value that is really there stays as it is.
  //   noise: |v(2d + 10)| ≤ |v(d)| · 10^(−d/2)
  auto finer = evaluate(e, values, 2 * digits + 10);
  if (!finer) return false;
  return abs(*finer) <= abs(*v) * pow(numeric(10), -(digits / 2));
}

namespace {

// Decimal digits and exponent of v: v = ±0.d1d2d3… × 10^exp10.
struct Decimal {
  bool neg = false;
  std::string digits;
  long exp10 = 0;
};

Decimal decompose(const GiNaC::numeric& v, int n) {
  Decimal d;
  d.neg = v.is_negative();
  cln::cl_R a = cln::abs(cln::the<cln::cl_R>(v.to_cl_N()));
  if (cln::zerop(a)) {
    d.digits = "0";
    return d;
  }
  // a = 0.d1…dn × 10^e:  r = round(a / 10^(e − n)) must have exactly n digits
  GiNaC::numeric l;
  {
    const DigitsScope precision(30);
    l = GiNaC::log(GiNaC::ex_to<GiNaC::numeric>(GiNaC::numeric(a).evalf())) / GiNaC::log(GiNaC::ex_to<GiNaC::numeric>(GiNaC::numeric(10).evalf()));
  }
  long e = static_cast<long>(std::floor(l.to_double())) + 1;
  // (cln::expt_pos needs a positive exponent: 10^0 would never return)
  const cln::cl_I lo = n > 1 ? cln::expt_pos(cln::cl_I(10), n - 1) : cln::cl_I(1);
  const cln::cl_I hi = cln::expt_pos(cln::cl_I(10), n);
  cln::cl_I r;
  for (int guard = 0; guard < 8; ++guard) {
    cln::cl_R scaled = a / cln::expt(cln::cl_RA(10), cln::cl_I(e - n));
    r = cln::floor1(scaled + cln::cl_RA(1) / 2);
    if (r >= hi) ++e;
    else if (r < lo) --e;
    else break;
  }
  if (r >= hi) r = cln::floor1(r, 10);  // rounding carried into a new digit (9.99… → 10.0…)
  std::ostringstream os;
  cln::fprintdecimal(os, r);
  d.digits = os.str();
  d.exp10 = e;
  return d;
}

}  // namespace

GiNaC::numeric round_sig(const GiNaC::numeric& v, int n) {
  Decimal d = decompose(v, n);
  if (d.digits == "0") return 0;
  GiNaC::numeric r(d.digits.c_str());
  r = r * GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(d.exp10 - n));
  return d.neg ? -r : r;
}

namespace {

/// Decimal digits s (value = 0.s × 10^e, trailing zeros dropped) laid out as format() writes them.
std::string layout(bool neg, std::string s, long e) {
  while (s.size() > 1 && s.back() == '0') s.pop_back();  // trailing zeros carry no information here
  std::string out;
  if (e > -5 && e <= 16) {
    if (e <= 0) out = "0." + std::string(static_cast<std::size_t>(-e), '0') + s;
    else if (static_cast<long>(s.size()) <= e) out = s + std::string(static_cast<std::size_t>(e) - s.size(), '0');
    else out = s.substr(0, static_cast<std::size_t>(e)) + "." + s.substr(static_cast<std::size_t>(e));
  } else {
    out = s.substr(0, 1) + (s.size() > 1 ? "." + s.substr(1) : "") + "e" + std::to_string(e - 1);
  }
  return (neg ? "-" : "") + out;
}

/// d's first n significant digits, correctly rounded as the library rounds (ties to even), and its
/// decimal exponent: d = D.DDD… × 10^x.
std::pair<std::string, long> sci(double d, int n, char* buf, std::size_t size) {
  const auto r = std::to_chars(buf, buf + size, d, std::chars_format::scientific, n - 1);
  const std::string t(buf, r.ptr);
  const std::size_t ep = t.find('e');
  std::string digits;
  for (std::size_t i = 0; i < ep; ++i)
    if (std::isdigit(static_cast<unsigned char>(t[i]))) digits += t[i];
  return {digits, std::stol(t.substr(ep + 1))};
}

}  // namespace

std::string g_text(double d, int n) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", n, d);
  return buf;
}

std::string format_double(double d, int n) {
  if (d == 0) return "0";
  const bool neg = d < 0;
  const double a = std::fabs(d);
  char buf[1100];
  auto [digits, x] = sci(a, n, buf, sizeof buf);
  // a tie (the exact value's digits past the n-th are 5 then zeros) rounds away from zero here,
  // to even in the library: every digit of a double's exact value (at most 767) shows which
  auto [all, xa] = sci(a, n + 2, buf, sizeof buf);
  if (all[static_cast<std::size_t>(n)] == '5' && all.find_first_not_of('0', static_cast<std::size_t>(n) + 1) == std::string::npos) {
    auto [exact, xe] = sci(a, 780, buf, sizeof buf);
    const bool tie = exact[static_cast<std::size_t>(n)] == '5' && exact.find_first_not_of('0', static_cast<std::size_t>(n) + 1) == std::string::npos;
    if (tie && xe == xa) {
      // round the n digits up (9.99… → 10.0…)
      std::string up = exact.substr(0, static_cast<std::size_t>(n));
      int i = n - 1;
      while (i >= 0 && up[static_cast<std::size_t>(i)] == '9') up[static_cast<std::size_t>(i--)] = '0';
      if (i >= 0) ++up[static_cast<std::size_t>(i)];
      else up = "1" + up.substr(0, up.size() - 1), ++xe;
      digits = up;
      x = xe;
    }
  }
  return layout(neg, digits, x + 1);
}

std::string format(const GiNaC::numeric& v, int n) {
  Decimal d = decompose(v, n);
  if (d.digits == "0") return "0";
  return layout(d.neg, d.digits, d.exp10);
}


namespace {

/// ∫_a^b f ds in IEEE double, for a few digits (a numeric root's scan asks the sign of a residual
/// that holds the integral, at 6 digits, at 100 points): f compiled once to a tape in s (kept,
/// keyed by f), the same tanh-sinh rule as below, its step halved until two levels agree to 1e-12
/// relative, which is far more than the ≤ 10 digits this is used for. @returns nothing where f
/// does not compile to a tape in s alone (another symbol, a node the tape lacks), a node is not
/// finite, or the levels do not settle: the caller then takes the CLN rule.
std::optional<double> integrate_double(const ex& f, const symbol& s, double a, double b) {
  static thread_local std::map<ex, std::shared_ptr<const Tape>, ex_is_less> tapes;
  std::shared_ptr<const Tape> tape;
  const ex key = lst{f, s};
  if (auto it = tapes.find(key); it != tapes.end()) {
    tape = it->second;
  } else {
    try {
      tape = std::make_shared<const Tape>(Tape::compile(f, {s}));
    } catch (const std::exception&) {
      tape = nullptr;  // (kept too: not compiled again)
    }
    if (tapes.size() > 256) tapes.clear();
    tapes.emplace(key, tape);
  }
  if (!tape || !std::isfinite(a) || !std::isfinite(b)) return std::nullopt;
  // x = c + r tanh(π/2 sinh t),  dx = r (π/2) cosh t / cosh²(π/2 sinh t) dt, |t| ≤ 4 (the weights
  // fall below 1e-40 beyond: nothing a double sum keeps)
  const double c = (a + b) / 2, r = (b - a) / 2, half_pi = 1.5707963267948966;
  auto node = [&](double t, double& sum) {
    const double u = half_pi * std::sinh(t), x = c + r * std::tanh(u), w = r * half_pi * std::cosh(t) / (std::cosh(u) * std::cosh(u));
    if (w == 0 || x == a || x == b) return true;  // beyond the integrand's reach in doubles
    const double v = (*tape)(&x);
    if (!std::isfinite(v)) return false;
    sum += v * w;
    return true;
  };
  double h = 0.5, sum = 0;
  for (double t = -4; t <= 4; t += h)
    if (!node(t, sum)) return std::nullopt;
  double prev = sum * h;
  for (int level = 1; level <= 8; ++level) {
    h /= 2;
    for (double t = -4 + h; t < 4; t += 2 * h)
      if (!node(t, sum)) return std::nullopt;
    const double now = sum * h;
    if (std::fabs(now - prev) <= 1e-12 * std::fabs(now) || (now == 0 && prev == 0)) return now;
    prev = now;
  }
  return std::nullopt;
}

}  // namespace

std::optional<numeric> integrate(const ex& f_in, const symbol& s, const numeric& a_in, const numeric& b_in, const exmap& values,
                                 int digits) {
  if (a_in == b_in) return numeric(0);
  // a few digits (the signs of a numeric root's scan): in doubles, where the integrand compiles
  if (digits <= 10 && values.empty() && a_in.is_real() && b_in.is_real())
    if (auto v = integrate_double(f_in, s, a_in.to_double(), b_in.to_double())) return numeric(*v);
  // a float end (a value evaluated at some precision) is taken as the exact binary fraction it
  // is: the nodes c + r tanh(…) then keep the working precision, where a 17-digit end would cap
  // every node, and so the sums, at 17 digits and the levels would never agree to digits + 2
  auto exact_end = [](const numeric& x) {
    return x.is_rational() || !x.is_real() ? x : numeric(cln::cl_N(cln::rational(cln::the<cln::cl_R>(x.to_cl_N()))));
  };
  const numeric a = exact_end(a_in), b = exact_end(b_in);
  // so is a float in the integrand (GiNaC's evalf makes 40 into 40.0 at its own precision before
  // the integral is taken): a float's precision would cap every value of f, CLN taking the lower
  // precision of two operands
  struct exact_floats : map_function {
    ex operator()(const ex& e) override {
      if (is_a<numeric>(e) && ex_to<numeric>(e).is_real() && !ex_to<numeric>(e).is_rational())
        return numeric(cln::cl_N(cln::rational(cln::the<cln::cl_R>(ex_to<numeric>(e).to_cl_N()))));
      return e.map(*this);
    }
  } to_exact;
  const ex f = to_exact(f_in);
  const int work = digits + 15;
  // x = c + r tanh(π/2 sinh t),  dx = r (π/2) cosh t / cosh²(π/2 sinh t) dt,  c = (a + b)/2, r = (b − a)/2
  const numeric c = (a + b) / 2, r = (b - a) / 2;
  exmap at = values;
  // the nodes on [−1, 1], tanh(π/2 sinh t) and (π/2) cosh t / cosh²(π/2 sinh t), for t a
  // multiple of 2^−12 at this precision: the same for every integrand, kept between calls
  static thread_local std::map<std::pair<int, long>, std::pair<numeric, numeric>> unit_nodes;
  auto unit_node = [&](const numeric& t) -> const std::pair<numeric, numeric>& {
    const long key = (t * 4096).to_long();
    auto it = unit_nodes.find({work, key});
    if (it != unit_nodes.end()) return it->second;
    if (unit_nodes.size() > 200000) unit_nodes.clear();
    numeric un = ex_to<numeric>((Pi / 2 * sinh(ex(t))).evalf());
    numeric th = ex_to<numeric>(tanh(ex(un)).evalf());
    numeric wt = ex_to<numeric>((Pi / 2 * cosh(ex(t)) / pow(cosh(ex(un)), 2)).evalf());
    return unit_nodes.emplace(std::pair<int, long>{work, key}, std::pair<numeric, numeric>{th, wt}).first->second;
  };
  auto node = [&](const numeric& t) -> std::optional<numeric> {
    const auto& [th, wt] = unit_node(t);
    numeric x = ex_to<numeric>((c + r * th).evalf());
    numeric w = ex_to<numeric>((r * wt).evalf());
    if (w.is_zero() || x == a || x == b) return numeric(0);  // underflowed: beyond the integrand's reach
    at[s] = x;
    auto v = evaluate(f, at, work);
    if (!v) return std::nullopt;
    return *v * w;
  };
  const DigitsScope precision(work);
  std::optional<numeric> result;
  try {
    // the nodes reach |t| = T, where the weights fall below 10^-work
    numeric h = 1, T = 0;
    while (true) {
      numeric u = ex_to<numeric>((Pi / 2 * sinh(ex(T))).evalf());
      numeric w = ex_to<numeric>((Pi / 2 * cosh(ex(T)) / pow(cosh(ex(u)), 2)).evalf());
      if (w < pow(numeric(10), -work) || T > 8) break;
      T += numeric(1, 2);
    }
    // level 0: every node k h, |k h| ≤ T
    numeric sum = 0;
    for (numeric t = -T; t <= T; t += h) {
      auto v = node(t);
      if (!v) throw std::domain_error("no value");
      sum += *v;
    }
    numeric prev = sum * h;
    // a few digits (a root search's signs) need few levels; a value that does not settle by then
    // is no value
    const int levels = digits <= 10 ? 7 : 12;
    for (int level = 1; level <= levels; ++level) {
      h /= 2;
      // the new nodes are the odd multiples of h
      for (numeric t = -T + h; t < T; t += 2 * h) {
        poll_interrupt();
        auto v = node(t);
        if (!v) throw std::domain_error("no value");
        sum += *v;
      }
      numeric now = sum * h;
      if (abs(now - prev) <= abs(now) * pow(numeric(10), -(digits + 2)) || (now.is_zero() && prev.is_zero())) {
        result = now;
        break;
      }
      prev = now;
    }
  } catch (const std::exception&) {
    result = std::nullopt;
  }
  return result;
}

// --- integral(f, s, a, b) -------------------------------------------------------------------

namespace {

DECLARE_FUNCTION_4P(integral)

ex integral_evalf(const ex& f, const ex& s, const ex& a, const ex& b) {
  ex av = a.evalf(), bv = b.evalf();
  if (is_a<symbol>(s) && is_a<GiNaC::numeric>(av) && is_a<GiNaC::numeric>(bv) && ex_to<GiNaC::numeric>(av).is_real() &&
      ex_to<GiNaC::numeric>(bv).is_real()) {
    // the same integral at the same precision is asked again and again (every check of an
    // expression that holds it): its value is kept, keyed by the integrand, the ends and the digits
    static thread_local std::map<ex, ex, ex_is_less> kept;
    const ex key = lst{f, s, av, bv, numeric(static_cast<long>(Digits))};
    if (auto it = kept.find(key); it != kept.end()) return it->second;
    if (auto v = integrate(f, ex_to<symbol>(s), ex_to<GiNaC::numeric>(av), ex_to<GiNaC::numeric>(bv), {}, static_cast<int>(Digits))) {
      if (kept.size() > 4096) kept.clear();
      kept.emplace(key, *v);
      return *v;
    }
  }
  return integral(f, s, a, b).hold();
}

// d/da ∫_a^b f ds = −f(a), d/db = f(b); by the integrand's own symbols it has no form here
ex integral_deriv(const ex& f, const ex& s, const ex& a, const ex& b, unsigned i) {
  if (i == 2) return -f.subs(s == a);
  if (i == 3) return f.subs(s == b);
  throw std::logic_error("integral(" + std::to_string(i) + "): only its ends are differentiated");
}

}  // namespace

REGISTER_FUNCTION(integral, evalf_func(integral_evalf).derivative_func(integral_deriv))

ex integral_of(const ex& f, const symbol& s, const ex& a, const ex& b) { return integral(f, s, a, b).hold(); }

bool is_integral(const ex& e) { return is_ex_the_function(e, integral); }

}  // namespace kinergy::numerics
