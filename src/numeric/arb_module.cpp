// The ball arithmetic module (see arb_api.hpp): the only code that links Arb and FLINT, loaded
// with dlopen by numeric/ball.cpp when proven digits are first asked for. It knows no GiNaC: a
// tape comes in as plain instructions and constants, enclosures go back as integers' digits.
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <acb.h>
#include <acb_calc.h>
#include <arb.h>

#include "arb_api.hpp"

namespace {

using namespace kinergy::numerics::arbapi;

/// The tape's operations, numbered as Tape::Op (numeric/tape.hpp; ball.cpp checks the numbering).
enum class Op : std::uint8_t {
  Const, Input, Add, Mul, Div, Neg, Sq, Cube, Powi, Sqrt, Rsqrt, Pow,
  Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Exp, Log, Abs, Sinh, Cosh, Tanh, Integral
};

enum class Status { Ok, Undefined, Indeterminate };

/// A vector of Arb's real (arb) or complex (acb) balls, freed with it.
template <class Ptr, Ptr (*Init)(slong), void (*Clear)(Ptr, slong)>
class BallVector {
public:
  explicit BallVector(std::size_t n = 0) : n_(n), v_(n ? Init(static_cast<slong>(n)) : nullptr) {}
  ~BallVector() {
    if (v_) Clear(v_, static_cast<slong>(n_));
  }
  BallVector(const BallVector&) = delete;
  BallVector& operator=(const BallVector&) = delete;
  BallVector(BallVector&& o) noexcept : n_(o.n_), v_(o.v_) {
    o.v_ = nullptr;
    o.n_ = 0;
  }
  Ptr operator[](std::size_t i) const { return v_ + i; }
  std::size_t size() const { return n_; }

private:
  std::size_t n_;
  Ptr v_;
};
using Balls = BallVector<arb_ptr, _arb_vec_init, _arb_vec_clear>;
using CBalls = BallVector<acb_ptr, _acb_vec_init, _acb_vec_clear>;

/// A rational p/q at `bits` (exact when it fits, else a ball around it).
void set_rational(arb_t x, const std::string& p, const std::string& q, long bits) {
  fmpq_t r;
  fmpq_init(r);
  fmpz_set_str(fmpq_numref(r), p.c_str(), 10);
  fmpz_set_str(fmpq_denref(r), q.c_str(), 10);
  arb_set_fmpq(x, r, bits);
  fmpq_clear(r);
}

/// A constant at `bits`: a rational rounded (exact when it fits), or π, γ, G; an interval as the
/// ball that holds both its ends.
void set_const(arb_t x, const Const& c, long bits) {
  switch (c.kind) {
    case Const::Pi: arb_const_pi(x, bits); return;
    case Const::Euler: arb_const_euler(x, bits); return;
    case Const::Catalan: arb_const_catalan(x, bits); return;
    case Const::Rational: set_rational(x, c.num, c.den, bits); return;
    case Const::Interval: {
      arb_t hi;
      arb_init(hi);
      set_rational(x, c.num, c.den, bits);
      set_rational(hi, c.num2, c.den2, bits);
      arb_union(x, x, hi, bits);
      arb_clear(hi);
      return;
    }
  }
}

static_assert(FLINT_BITS == 64, "ends() hands over 64-bit limbs");

/// The ball's ends as integers' digits: [a · 2^e, b · 2^e].
Interval ends(const arb_t x) {
  fmpz_t a, b, e;
  fmpz_init(a);
  fmpz_init(b);
  fmpz_init(e);
  arb_get_interval_fmpz_2exp(a, b, e, x);
  Interval out;
  out.e = fmpz_get_si(e);
  if (fmpz_bits(a) <= 128 && fmpz_bits(b) <= 128) {
    out.small = true;
    out.a_negative = fmpz_sgn(a) < 0;
    out.b_negative = fmpz_sgn(b) < 0;
    ulong limbs[2];
    fmpz_abs(a, a);
    fmpz_get_ui_array(limbs, 2, a);
    out.a_limbs[0] = limbs[0];
    out.a_limbs[1] = limbs[1];
    fmpz_abs(b, b);
    fmpz_get_ui_array(limbs, 2, b);
    out.b_limbs[0] = limbs[0];
    out.b_limbs[1] = limbs[1];
  } else {
    char* s = fmpz_get_str(nullptr, 16, a);
    out.a = s;
    flint_free(s);
    s = fmpz_get_str(nullptr, 16, b);
    out.b = s;
    flint_free(s);
  }
  fmpz_clear(a);
  fmpz_clear(b);
  fmpz_clear(e);
  return out;
}

/// Whether every value in x rounds to the same n significant digits (half away from zero, as
/// `round_sig`): ±D · 10^k with 10^(n−1) ≤ D < 10^n. Decided on balls: y = |x| · 10^(n−1−e10)
/// and ⌊y + ½⌋ must be one integer.
/// 10^k as a ball of `prec` bits (an exact integer, or its reciprocal rounded), kept: the same few
/// powers serve every call at a precision.
arb_srcptr power_of_ten(long k, slong prec) {
  struct Power {
    arb_t v;
    Power() { arb_init(v); }
    ~Power() { arb_clear(v); }
    Power(const Power&) = delete;
    Power& operator=(const Power&) = delete;
  };
  thread_local std::map<std::pair<long, slong>, Power> kept;
  if (kept.size() > 512) kept.clear();
  auto [it, made] = kept.try_emplace({k, prec});
  if (made) {
    arb_ui_pow_ui(it->second.v, 10, static_cast<ulong>(k < 0 ? -k : k), prec);
    if (k < 0) arb_inv(it->second.v, it->second.v, prec);
  }
  return it->second.v;
}

/// 10^(n−1) and 10^n as integers, kept per n.
const std::pair<fmpz_t, fmpz_t>& digit_bounds(int n) {
  struct Bounds {
    std::pair<fmpz_t, fmpz_t> b;
    Bounds() {
      fmpz_init(b.first);
      fmpz_init(b.second);
    }
    ~Bounds() {
      fmpz_clear(b.first);
      fmpz_clear(b.second);
    }
    Bounds(const Bounds&) = delete;
    Bounds& operator=(const Bounds&) = delete;
  };
  thread_local std::map<int, Bounds> kept;
  auto [it, made] = kept.try_emplace(n);
  if (made) {
    fmpz_ui_pow_ui(it->second.b.first, 10, static_cast<ulong>(n - 1));
    fmpz_ui_pow_ui(it->second.b.second, 10, static_cast<ulong>(n));
  }
  return it->second.b;
}

bool common_digits(const arb_t x, int n, slong prec) {
  if (arb_contains_zero(x)) return false;
  // |mid| < 2^e2: log₁₀|x| is near e2 · log₁₀2
  const slong e2 = arf_abs_bound_lt_2exp_si(arb_midref(x));
  long e10 = static_cast<long>(std::floor(static_cast<double>(e2) * 0.30102999566398120));
  arb_t y;
  arb_init(y);
  fmpz_t D;
  fmpz_init(D);
  const auto& [lo, hi] = digit_bounds(n);
  bool out = false;
  for (int tries = 0; tries < 6; ++tries) {
    const long shift = n - 1 - e10;
    arb_abs(y, x);
    arb_mul(y, y, power_of_ten(shift, prec + 64), prec + 64);
    arb_mul_2exp_si(y, y, 1);  // y + ½ = (2y + 1)/2, exactly
    arb_add_ui(y, y, 1, prec + 64);
    arb_mul_2exp_si(y, y, -1);
    arb_floor(y, y, prec + 64);
    if (!arb_get_unique_fmpz(D, y)) break;  // the ball holds a rounding boundary
    if (fmpz_cmp(D, hi) >= 0) {
      ++e10;
    } else if (fmpz_cmp(D, lo) < 0) {
      --e10;
    } else {
      out = true;
      break;
    }
  }
  fmpz_clear(D);
  arb_clear(y);
  return out;
}

Status integral(arb_t v, const Program& f, const Balls& x, arb_srcptr a, arb_srcptr b, long bits);

/// Run a program on `x` (one ball per input) at `bits`; every register into `reg`. `consts`: the
/// program's constants at `bits`, when kept (else each is made again from its digits).
Status run(const Program& t, const Balls& x, long bits, Balls& reg, const Balls* consts = nullptr) {
  const slong p = bits;
  for (std::size_t i = 0; i < t.code.size(); ++i) {
    const Ins& in = t.code[i];
    arb_ptr v = reg[i];
    const Op op = static_cast<Op>(in.op);
    const bool leaf = op == Op::Input || op == Op::Const;
    arb_srcptr a = !leaf && in.a >= 0 ? reg[static_cast<std::size_t>(in.a)] : nullptr;
    arb_srcptr b = in.b >= 0 ? reg[static_cast<std::size_t>(in.b)] : nullptr;
    switch (op) {
      case Op::Const:
        if (consts) arb_set(v, (*consts)[static_cast<std::size_t>(in.a)]);
        else set_const(v, t.consts[static_cast<std::size_t>(in.a)], bits);
        break;
      case Op::Input: arb_set(v, x[static_cast<std::size_t>(in.a)]); break;
      case Op::Add: arb_add(v, a, b, p); break;
      case Op::Mul: arb_mul(v, a, b, p); break;
      // a / b: b must be away from 0; an exact 0 is a division by zero
      case Op::Div:
        if (arb_is_zero(b)) return Status::Undefined;
        if (arb_contains_zero(b)) return Status::Indeterminate;
        arb_div(v, a, b, p);
        break;
      case Op::Neg: arb_neg(v, a); break;
      case Op::Sq: arb_sqr(v, a, p); break;
      case Op::Cube: arb_pow_ui(v, a, 3, p); break;
      case Op::Powi: {
        const long n = static_cast<long>(in.c);
        if (n < 0 && arb_is_zero(a)) return Status::Undefined;
        if (n < 0 && arb_contains_zero(a)) return Status::Indeterminate;
        fmpz_t e;
        fmpz_init_set_si(e, n);
        arb_pow_fmpz(v, a, e, p);
        fmpz_clear(e);
        break;
      }
      // √a for a ≥ 0; a ball that is all below 0 is undefined, one across 0 cannot tell
      case Op::Sqrt:
        if (arb_is_zero(a)) {
          arb_zero(v);
        } else if (arb_is_nonnegative(a)) {
          arb_sqrt(v, a, p);
        } else {
          return arb_is_negative(a) ? Status::Undefined : Status::Indeterminate;
        }
        break;
      // 1/√a for a > 0
      case Op::Rsqrt:
        if (arb_is_positive(a)) arb_rsqrt(v, a, p);
        else return arb_is_nonpositive(a) ? Status::Undefined : Status::Indeterminate;
        break;
      case Op::Sin: arb_sin(v, a, p); break;
      case Op::Cos: arb_cos(v, a, p); break;
      case Op::Tan: arb_tan(v, a, p); break;  // a ball across a pole comes out not finite
      // asin, acos for |a| ≤ 1
      case Op::Asin:
      case Op::Acos: {
        arf_t lo;
        arf_init(lo);
        arb_get_abs_lbound_arf(lo, a, p);
        const bool outside = arf_cmp_si(lo, 1) > 0;
        arf_clear(lo);
        if (outside) return Status::Undefined;
        if (op == Op::Asin) arb_asin(v, a, p);
        else arb_acos(v, a, p);
        break;
      }
      case Op::Atan: arb_atan(v, a, p); break;
      // atan2(y = a, x = b): undefined at (0, 0); a ball of y across 0 (not y = 0 itself) with x
      // not positive straddles the cut on the negative x axis, where atan2 jumps from π to −π: no
      // value that is continuous on the ball (a root's sign change must not be a jump)
      case Op::Atan2:
        if (arb_is_zero(a) && arb_is_zero(b)) return Status::Undefined;
        if (arb_contains_zero(a) && !arb_is_zero(a) && !arb_is_positive(b)) return Status::Indeterminate;
        arb_atan2(v, a, b, p);
        break;
      case Op::Exp: arb_exp(v, a, p); break;
      // ln a for a > 0
      case Op::Log:
        if (arb_is_positive(a)) arb_log(v, a, p);
        else return arb_is_nonpositive(a) ? Status::Undefined : Status::Indeterminate;
        break;
      case Op::Abs: arb_abs(v, a); break;
      case Op::Sinh: arb_sinh(v, a, p); break;
      case Op::Cosh: arb_cosh(v, a, p); break;
      case Op::Tanh: arb_tanh(v, a, p); break;
      // a^b = e^(b ln a) for a > 0
      case Op::Pow:
        if (arb_is_positive(a)) arb_pow(v, a, b, p);
        else return arb_is_negative(a) ? Status::Undefined : Status::Indeterminate;
        break;
      case Op::Integral:
        if (const Status st = integral(v, t.integrands.at(static_cast<std::size_t>(in.c)), x, a, b, bits); st != Status::Ok) return st;
        break;
    }
    if (!arb_is_finite(v)) return Status::Indeterminate;
  }
  return Status::Ok;
}

/// Does the ball x hold a point with |x| ≥ 1?
bool reaches_one(const arb_t x) {
  arf_t hi;
  arf_init(hi);
  arb_get_abs_ubound_arf(hi, x, 64);
  const bool out = arf_cmp_si(hi, 1) >= 0;
  arf_clear(hi);
  return out;
}

/// Run an integrand on complex balls (`x`: one per input) at `bits`, as the holomorphic function
/// that equals it on the real line where it is real (the principal branches). With `analytic`,
/// every branch cut (√, ln, a^b on the negative axis; asin, acos beyond ±1; atan beyond ±i; |x| on
/// Re x = 0; atan2 on the negative x axis) that a ball touches makes the value indeterminate, so
/// that Arb's error bounds, which take the function's size on complex neighbourhoods of the path,
/// hold.
Status run_complex(const Program& t, const CBalls& x, long bits, bool analytic, CBalls& reg) {
  const int an = analytic ? 1 : 0;
  const slong p = bits;
  acb_t w;
  acb_init(w);
  Status out = Status::Ok;
  for (std::size_t i = 0; i < t.code.size() && out == Status::Ok; ++i) {
    const Ins& in = t.code[i];
    acb_ptr v = reg[i];
    const Op op = static_cast<Op>(in.op);
    const bool leaf = op == Op::Input || op == Op::Const;
    acb_srcptr a = !leaf && in.a >= 0 ? reg[static_cast<std::size_t>(in.a)] : nullptr;
    acb_srcptr b = in.b >= 0 ? reg[static_cast<std::size_t>(in.b)] : nullptr;
    switch (op) {
      case Op::Const:
        set_const(acb_realref(v), t.consts[static_cast<std::size_t>(in.a)], bits);
        arb_zero(acb_imagref(v));
        break;
      case Op::Input: acb_set(v, x[static_cast<std::size_t>(in.a)]); break;
      case Op::Add: acb_add(v, a, b, p); break;
      case Op::Mul: acb_mul(v, a, b, p); break;
      case Op::Div: acb_div(v, a, b, p); break;  // a divisor that may be 0 gives a value not finite
      case Op::Neg: acb_neg(v, a); break;
      case Op::Sq: acb_sqr(v, a, p); break;
      case Op::Cube: acb_pow_ui(v, a, 3, p); break;
      case Op::Powi: {
        fmpz_t e;
        fmpz_init_set_si(e, static_cast<long>(in.c));
        acb_pow_fmpz(v, a, e, p);
        fmpz_clear(e);
        break;
      }
      case Op::Sqrt: acb_sqrt_analytic(v, a, an, p); break;
      case Op::Rsqrt: acb_rsqrt_analytic(v, a, an, p); break;
      case Op::Log: acb_log_analytic(v, a, an, p); break;
      case Op::Pow: acb_pow_analytic(v, a, b, an, p); break;
      case Op::Abs: acb_real_abs(v, a, an, p); break;
      case Op::Sin: acb_sin(v, a, p); break;
      case Op::Cos: acb_cos(v, a, p); break;
      case Op::Tan: acb_tan(v, a, p); break;  // a pole in the ball: not finite
      case Op::Exp: acb_exp(v, a, p); break;
      case Op::Sinh: acb_sinh(v, a, p); break;
      case Op::Cosh: acb_cosh(v, a, p); break;
      case Op::Tanh: acb_tanh(v, a, p); break;
      // asin, acos: cuts on the real axis beyond ±1
      case Op::Asin:
      case Op::Acos:
        if (analytic && arb_contains_zero(acb_imagref(a)) && reaches_one(acb_realref(a))) out = Status::Indeterminate;
        else if (op == Op::Asin) acb_asin(v, a, p);
        else acb_acos(v, a, p);
        break;
      // atan: cuts on the imaginary axis beyond ±i
      case Op::Atan:
        if (analytic && arb_contains_zero(acb_realref(a)) && reaches_one(acb_imagref(a))) out = Status::Indeterminate;
        else acb_atan(v, a, p);
        break;
      // atan2(y = a, x = b) = atan(y/x) where Re x > 0, π/2 − atan(x/y) where Re y > 0,
      // −π/2 − atan(x/y) where Re y < 0 (each holomorphic there, and equal to atan2 on reals)
      case Op::Atan2: {
        const bool right = arb_is_positive(acb_realref(b)), up = arb_is_positive(acb_realref(a)), down = arb_is_negative(acb_realref(a));
        if (!right && !up && !down) {
          out = Status::Indeterminate;
          break;
        }
        acb_div(w, right ? a : b, right ? b : a, p);
        if (analytic && arb_contains_zero(acb_realref(w)) && reaches_one(acb_imagref(w))) {
          out = Status::Indeterminate;
          break;
        }
        acb_atan(w, w, p);
        if (right) {
          acb_set(v, w);
        } else {
          acb_const_pi(v, p);
          acb_mul_2exp_si(v, v, -1);
          if (down) acb_neg(v, v);
          acb_sub(v, v, w, p);
        }
        break;
      }
      case Op::Integral: out = Status::Indeterminate; break;  // (an integral inside an integrand is not compiled)
    }
    if (out == Status::Ok && !acb_is_finite(v)) out = Status::Indeterminate;
  }
  acb_clear(w);
  return out;
}

/// An integrand bound to the outer program's inputs, as Arb's integration calls it.
struct Integrand {
  const Program& f;
  Balls real_in, real_reg;
  CBalls complex_in, complex_reg;
  bool undefined = false;  ///< f proven undefined at a point of the path
  Integrand(const Program& fn, const Balls& x)
      : f(fn), real_in(x.size() + 1), real_reg(fn.code.size()), complex_in(x.size() + 1), complex_reg(fn.code.size()) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      arb_set(real_in[i + 1], x[i]);
      acb_set_arb(complex_in[i + 1], x[i]);
    }
  }
  /// f on the real ball ξ: the value into v.
  Status real(arb_t v, const arb_t xi, long bits) {
    arb_set(real_in[0], xi);
    const Status st = run(f, real_in, bits, real_reg);
    if (st == Status::Ok) arb_set(v, real_reg[static_cast<std::size_t>(f.outs.at(0))]);
    return st;
  }
};

// f(z) for acb_calc_integrate. On a real ball (order 0: a node, or a piece of the path) the real
// integrand itself, with its domains: one proven outside them (√ of a ball below 0) makes the
// integral undefined, not imaginary. A ball across a domain's edge (√ of [−ε, h] on the piece of
// √x's path next to 0) is enclosed by the principal branches on complex balls, which hold the real
// values where they are defined. On a complex ball the holomorphic extension (order 1 asks that f
// be checked holomorphic there).
int integrand(acb_ptr out, const acb_t z, void* param, slong order, slong prec) {
  auto& q = *static_cast<Integrand*>(param);
  if (order > 1) flint_abort();  // (the integration asks only for values)
  Status st = Status::Indeterminate;
  if (order == 0 && acb_is_real(z)) {
    st = q.real(acb_realref(out), acb_realref(z), prec);
    if (st == Status::Ok) arb_zero(acb_imagref(out));
    if (st == Status::Undefined) q.undefined = true;
  }
  if (st == Status::Indeterminate) {
    acb_set(q.complex_in[0], z);
    st = run_complex(q.f, q.complex_in, prec, order == 1, q.complex_reg);
    if (st == Status::Ok) acb_set(out, q.complex_reg[static_cast<std::size_t>(q.f.outs.at(0))]);
  }
  if (st != Status::Ok) acb_indeterminate(out);
  return 0;
}

// ∫_a^b f(ξ) dξ with ends that are balls a = [a_m ± r_a], b = [b_m ± r_b]:
//   ∫_a^b f dξ = ∫_{a_m}^{b_m} f dξ + ∫_{b_m}^{b} f dξ − ∫_{a_m}^{a} f dξ,
//   |∫_{b_m}^{b} f dξ| ≤ r_b · sup_{ξ ∈ [b]} |f(ξ)|   (f enclosed on the ball [b] itself),
// the middle one by Arb's rigorous integration (Gauss–Legendre on subintervals, the error bounded
// through f on complex ellipses around each, which is why f also runs on complex balls).
Status integral(arb_t v, const Program& f, const Balls& x, arb_srcptr a, arb_srcptr b, long bits) {
  if (arb_is_exact(a) && arb_equal(a, b)) {
    arb_zero(v);  // an empty path
    return Status::Ok;
  }
  Integrand q(f, x);
  acb_t res, am, bm;
  acb_init(res);
  acb_init(am);
  acb_init(bm);
  arb_get_mid_arb(acb_realref(am), a);
  arb_get_mid_arb(acb_realref(bm), b);
  mag_t tol;
  mag_init(tol);
  mag_set_ui_2exp_si(tol, 1, -bits);
  acb_calc_integrate_opt_t opt;
  acb_calc_integrate_opt_init(opt);
  // a bound on the work (Arb's default, 1000 p + p², is hours at thousands of bits for an
  // integral that does not converge); a smooth integrand needs far fewer
  opt->eval_limit = 20 * bits + 4000;
  acb_calc_integrate(res, integrand, &q, am, bm, bits, tol, opt, bits);
  // f real on the path gives a real integral: an imaginary part proven nonzero means it is not.
  // Proven undefined only when the ends are exact: with ball ends Arb integrates between their
  // midpoints, which may reach past the true path (a midpoint of π/2's ball above π/2 under
  // √cos), so there it is only not decided
  const bool exact_ends = mag_is_zero(arb_radref(a)) && mag_is_zero(arb_radref(b));
  const Status off_path = exact_ends ? Status::Undefined : Status::Indeterminate;
  Status st = q.undefined                            ? off_path
              : !acb_is_finite(res)                  ? Status::Indeterminate
              : !arb_contains_zero(acb_imagref(res)) ? off_path
                                                     : Status::Ok;
  if (st == Status::Ok) {
    arb_set(v, acb_realref(res));  // f is real on the path: the integral's real part holds it
    // the ends' radii: r · sup|f| on each end's ball
    arb_t fe, r;
    arb_init(fe);
    arb_init(r);
    for (arb_srcptr end : {a, b}) {
      if (mag_is_zero(arb_radref(end))) continue;
      const Status se = q.real(fe, end, bits);
      if (se != Status::Ok) {
        st = se == Status::Undefined ? Status::Indeterminate : se;  // undefined near the end, not proven at it
        break;
      }
      arb_abs(fe, fe);
      arf_set_mag(arb_midref(r), arb_radref(end));
      mag_zero(arb_radref(r));
      arb_mul(r, r, fe, bits);
      arb_add_error(v, r);
    }
    arb_clear(fe);
    arb_clear(r);
  }
  mag_clear(tol);
  acb_clear(res);
  acb_clear(am);
  acb_clear(bm);
  return st;
}

/// A program bound to its inputs, each enclosed per precision (kept).
struct Bound {
  Program tape;
  std::vector<Program> inputs;
  std::map<long, Balls> at_bits;
  Balls reg;  ///< the tape's registers, kept between calls
  std::map<long, Balls> consts_at_bits;  ///< the tape's constants, per precision

  Bound(const Program& t, const std::vector<Program>& in) : tape(t), inputs(in), reg(t.code.size()) {}

  /// The tape's constants at `bits` (made once).
  const Balls& constants(long bits) {
    auto it = consts_at_bits.find(bits);
    if (it != consts_at_bits.end()) return it->second;
    Balls c(tape.consts.size());
    for (std::size_t i = 0; i < tape.consts.size(); ++i) set_const(c[i], tape.consts[i], bits);
    return consts_at_bits.emplace(bits, std::move(c)).first->second;
  }

  /// The inputs at `bits`: nothing when one of them is not defined there (`st` says whether that
  /// is proven, or not decided at this precision).
  const Balls* enclosed(long bits, Status& st) {
    st = Status::Ok;
    auto it = at_bits.find(bits);
    if (it != at_bits.end()) return &it->second;
    Balls x(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const Program& in = inputs[i];
      // a rational: rounded once; an exact form (π/6, √2): its own program, on balls of a few more bits
      if (in.code.size() == 1 && in.consts.size() == 1) {
        set_const(x[i], in.consts[0], bits);
        continue;
      }
      Balls reg(in.code.size()), none(0);
      if ((st = run(in, none, bits + 16, reg)) != Status::Ok) return nullptr;
      arb_set_round(x[i], reg[static_cast<std::size_t>(in.outs.at(0))], bits);
    }
    return &at_bits.emplace(bits, std::move(x)).first->second;
  }

  /// Run at `bits`; with `first`, input 0 is that ball.
  Status eval(long bits, Balls& reg, arb_srcptr first = nullptr) {
    Status st;
    const Balls* x = enclosed(bits, st);
    if (!x) return st;
    const Balls& c = constants(bits);
    if (!first) return run(tape, *x, bits, reg, &c);
    Balls y(x->size());
    for (std::size_t i = 0; i < x->size(); ++i) arb_set(y[i], (*x)[i]);
    arb_set(y[0], first);
    return run(tape, y, bits, reg, &c);
  }
  arb_srcptr out(const Balls& reg) const { return reg[static_cast<std::size_t>(tape.outs.at(0))]; }
};

// An integral's cost grows fast with the precision, and one that Arb's integration cannot settle at
// several times the bits n digits need will not settle later: its precision stops there.
long integral_cap(const Program& t, int n, long max_bits) {
  return t.integrands.empty() ? max_bits : std::min(max_bits, integral_bits(n));
}

void* create(const Program& tape, const std::vector<Program>& inputs) { return new Bound(tape, inputs); }
void destroy(void* h) { delete static_cast<Bound*>(h); }

// n digits: evaluate at p bits; the digits are proven when every value of the ball rounds to them
// (common_digits). Else p doubles. A ball that keeps holding 0 once the precision is well past what
// n digits need is a zero whose sign is not fixed.
Answer digits(void* h, int n, long max_bits) {
  Bound& b = *static_cast<Bound*>(h);
  n = std::max(1, n);
  const long zero_bits = std::max<long>(1024, 4 * bits_for(n));
  max_bits = integral_cap(b.tape, n, max_bits);
  // a few guard bits over what n digits need, and at least one 64-bit limb
  long bits = std::max<long>(64, bits_for(n) + 12);
  Balls& reg = b.reg;
  Answer a;
  for (;;) {
    const Status st = b.eval(bits, reg);
    if (st == Status::Undefined) {
      a.kind = 3;
      return a;
    }
    if (st == Status::Ok) {
      arb_srcptr x = b.out(reg);
      a.bits = bits;
      if (!arb_contains_zero(x)) {
        if (common_digits(x, n, bits)) {
          a.kind = 1;
          a.at = ends(x);
          return a;
        }
      } else if (arb_is_zero(x)) {
        a.kind = 0;  // an exact zero: the ball is the point 0
        return a;
      } else if (bits >= std::min(zero_bits, max_bits)) {
        a.kind = 2;
        a.at = ends(x);
        return a;
      }
    }
    if (bits >= max_bits) {
      a.kind = 4;
      a.error = "no working precision up to " + std::to_string(max_bits) + " bits fixes " + std::to_string(n) + " digits (" +
                (st == Status::Indeterminate
                     ? std::string("a step of the evaluation cannot be decided: a divisor, a square root's or a logarithm's argument that cannot be told from 0") +
                           (b.tape.integrands.empty() ? "" : ", or an integral whose integrand is singular on its path")
                     : std::string("the digits do not settle")) +
                ")";
      return a;
    }
    bits = std::min(max_bits, 2 * bits);
  }
}

// A root of r(u) = 0 proven: Newton's steps on the balls' midpoints find x; then the ball
// I = [x − δ, x + δ] holds a root when r is defined (so continuous) on all of I and r(x − δ),
// r(x + δ) have proven opposite signs (the intermediate value theorem). The digits are those
// every value of I rounds to.
Answer root(const Program& r, const Program& dr, const std::vector<Program>& inputs, const Const& start, const Const& lo,
            const Const& hi, bool bracket, int n, long max_bits) {
  // n ≤ 0: an enclosure at the precision of |n| digits, whatever digits it fixes (an input to
  // another evaluation on balls, which decides the digits)
  const bool enclose_only = n <= 0;
  n = std::max(1, n < 0 ? -n : n);
  Bound R(r, inputs), D(dr, inputs);
  max_bits = integral_cap(r, n, max_bits);
  long bits = bits_for(n) + 32;
  arb_t x, t, I, a, b, step, blo, bhi;
  for (arb_ptr p : {x, t, I, a, b, step, blo, bhi}) arb_init(p);
  set_const(x, start, 4 * bits);
  arb_get_mid_arb(x, x);
  Balls reg_r(r.code.size()), reg_d(dr.code.size());
  Answer out;
  auto sign = [&](arb_srcptr at, long p) {
    if (R.eval(p, reg_r, at) != Status::Ok) return 0;
    arb_srcptr v = R.out(reg_r);
    return arb_is_positive(v) ? 1 : arb_is_negative(v) ? -1 : 0;
  };
  bool done = false;
  while (!done) {
    // Newton: x ← x − r(x)/r′(x), on midpoints
    arb_zero(step);
    for (int it = 0; it < 200; ++it) {
      if (R.eval(bits, reg_r, x) != Status::Ok || D.eval(bits, reg_d, x) != Status::Ok) break;
      arb_srcptr fr = R.out(reg_r);
      if (arb_is_zero(fr)) {  // r(x) = 0 exactly: x is a root
        out.kind = 0;
        out.at = ends(x);
        out.bits = bits;
        done = true;
        break;
      }
      arb_get_mid_arb(t, fr);
      arb_get_mid_arb(a, D.out(reg_d));
      if (arf_is_zero(arb_midref(a))) break;
      arb_div(step, t, a, bits);
      arb_get_mid_arb(step, step);
      arb_sub(x, x, step, bits);
      arb_get_mid_arb(x, x);
      // |step| ≤ 2^(8 − bits) |x|: the midpoints' noise
      arb_mul_2exp_si(t, x, 8 - bits);
      arb_abs(t, t);
      arb_abs(a, step);
      if (arb_le(a, t) || arf_is_zero(arb_midref(step))) break;
    }
    if (done) break;
    // δ = 4|step| + 2^(8 − bits)|x| + 2^−bits, widened 16-fold while a sign at an end is not
    // decided (an input known only to a ball makes r itself a ball there)
    arb_abs(a, step);
    arb_mul_2exp_si(a, a, 2);
    arb_abs(t, x);
    arb_mul_2exp_si(t, t, 8 - bits);
    arb_add(a, a, t, bits);
    arb_one(t);
    arb_mul_2exp_si(t, t, -bits);
    arb_add(a, a, t, bits);
    arb_get_ubound_arf(arb_midref(step), a, bits);
    mag_zero(arb_radref(step));
    int sa = 0, sb = 0;
    for (int widen = 0; widen < 6; ++widen, arb_mul_2exp_si(step, step, 4)) {
      arb_sub(a, x, step, bits + 16);
      arb_get_mid_arb(a, a);
      arb_add(b, x, step, bits + 16);
      arb_get_mid_arb(b, b);
      sa = sign(a, bits);
      sb = sign(b, bits);
      if (sa != 0 && sb != 0) break;
    }
    arb_union(I, a, b, bits + 16);
    // r defined (so continuous) on I with opposite signs at its ends: a root in I; r′ away from 0
    // on I: only one (r monotone), the one Newton's steps went to
    auto one_root = [&] {
      if (R.eval(bits, reg_r, I) != Status::Ok || D.eval(bits, reg_d, I) != Status::Ok) return false;
      return !arb_contains_zero(D.out(reg_d));
    };
    if (sa != 0 && sb != 0 && sa != sb && one_root()) {
      if (bracket) {
        // inside the bracket the solver found the root in
        set_const(blo, lo, bits + 64);
        set_const(bhi, hi, bits + 64);
        arb_union(t, blo, bhi, bits + 64);
        if (!arb_contains(t, I)) {
          out.error = "the root proven lies outside the bracket it was found in";
          break;
        }
      }
      if (enclose_only || common_digits(I, n, bits)) {
        out.kind = 1;
        out.at = ends(I);
        out.bits = bits;
        break;
      }
    }
    if (bits >= max_bits) {
      out.error = "no working precision up to " + std::to_string(max_bits) + " bits proves the root";
      break;
    }
    bits = std::min(max_bits, 2 * bits);
  }
  for (arb_ptr p : {x, t, I, a, b, step, blo, bhi}) arb_clear(p);
  return out;
}

const Api kApi{kVersion, create, destroy, digits, root};

}  // namespace

extern "C" const kinergy::numerics::arbapi::Api* kinergy_arb_api() { return &kApi; }
