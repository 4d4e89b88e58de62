#include "kinergy/numeric/ball.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include <arb.h>
#include <cln/cln.h>

#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::numerics {

using namespace GiNaC;

namespace {

/// A vector of Arb balls, freed with it.
class Balls {
public:
  explicit Balls(std::size_t n = 0) : n_(n), v_(n ? _arb_vec_init(static_cast<slong>(n)) : nullptr) {}
  ~Balls() {
    if (v_) _arb_vec_clear(v_, static_cast<slong>(n_));
  }
  Balls(const Balls&) = delete;
  Balls& operator=(const Balls&) = delete;
  Balls(Balls&& o) noexcept : n_(o.n_), v_(o.v_) {
    o.v_ = nullptr;
    o.n_ = 0;
  }
  arb_ptr operator[](std::size_t i) const { return v_ + i; }
  std::size_t size() const { return n_; }

private:
  std::size_t n_;
  arb_ptr v_;
};

/// A CLN integer into FLINT's, 64 bits at a time.
void set_fmpz(fmpz_t z, const cln::cl_I& n) {
  if (cln::integer_length(n) < 62) {
    fmpz_set_si(z, cln::cl_I_to_long(n));
    return;
  }
  const cln::cl_I a = cln::abs(n);
  const std::size_t limbs = (cln::integer_length(a) + 63) / 64;
  std::vector<ulong> w(limbs);
  for (std::size_t i = 0; i < limbs; ++i) w[i] = cln::cl_I_to_UQ(cln::ldb(a, cln::cl_byte(64, 64 * i)));
  fmpz_set_ui_array(z, w.data(), static_cast<slong>(limbs));
  if (cln::minusp(n)) fmpz_neg(z, z);
}

/// FLINT's integer into CLN's, 64 bits at a time.
cln::cl_I to_cl_I(const fmpz_t z) {
  if (fmpz_fits_si(z)) return cln::cl_I(static_cast<long>(fmpz_get_si(z)));
  fmpz_t a;
  fmpz_init(a);
  fmpz_abs(a, z);
  const slong limbs = static_cast<slong>(fmpz_size(a));
  std::vector<ulong> w(static_cast<std::size_t>(limbs));
  fmpz_get_ui_array(w.data(), limbs, a);
  fmpz_clear(a);
  cln::cl_I r = 0;
  for (slong i = limbs - 1; i >= 0; --i) r = cln::logior(cln::ash(r, 64), cln::cl_I(static_cast<unsigned long>(w[static_cast<std::size_t>(i)])));
  return fmpz_sgn(z) < 0 ? cln::cl_I(-r) : r;
}

/// An exact rational into a ball of `bits` (exact when it fits).
void set_rational(arb_t x, const cln::cl_RA& q, long bits) {
  fmpq_t f;
  fmpq_init(f);
  set_fmpz(fmpq_numref(f), cln::numerator(q));
  set_fmpz(fmpq_denref(f), cln::denominator(q));
  arb_set_fmpq(x, f, bits);
  fmpq_clear(f);
}

/// A CLN float is an exact binary fraction: m · 2^e.
void set_float(arb_t x, const cln::cl_F& f) {
  cln::cl_RA q = cln::rational(f);
  fmpq_t r;
  fmpq_init(r);
  set_fmpz(fmpq_numref(r), cln::numerator(q));
  set_fmpz(fmpq_denref(r), cln::denominator(q));
  arb_set_fmpq(x, r, cln::float_digits(f) + 64);  // exact: a binary fraction of that many bits
  fmpq_clear(r);
}

/// m · 2^e exactly, as a CLN float with as many bits as m (a rational would cost a gcd, and a
/// rational of 2^400000 would make every later step slow).
numeric scaled(const cln::cl_I& m, long e) {
  if (cln::zerop(m)) return 0;
  const long bits = std::max<long>(static_cast<long>(cln::integer_length(m)) + 2, 64);
  const cln::cl_F f = cln::cl_float(m, cln::float_format(static_cast<long>(static_cast<double>(bits) * 0.30103) + 2));
  return numeric(cln::cl_N(cln::scale_float(f, e)));
}

/// The ball's ends, exactly.
Enclosure ends(const arb_t x) {
  fmpz_t a, b, e;
  fmpz_init(a);
  fmpz_init(b);
  fmpz_init(e);
  arb_get_interval_fmpz_2exp(a, b, e, x);
  const cln::cl_I A = to_cl_I(a), B = to_cl_I(b);
  const long ex = fmpz_get_si(e);
  fmpz_clear(a);
  fmpz_clear(b);
  fmpz_clear(e);
  return {scaled(A, ex), scaled(B, ex)};
}

/// Whether every value in x rounds to the same n significant digits (half away from zero, as
/// `round_sig`): ±D · 10^k with 10^(n−1) ≤ D < 10^n. Decided on balls: y = |x| · 10^(n−1−e10)
/// and ⌊y + ½⌋ must be one integer.
bool common_digits(const arb_t x, int n, slong prec) {
  if (arb_contains_zero(x)) return false;
  // |mid| < 2^e2: log₁₀|x| is near e2 · log₁₀2
  const slong e2 = arf_abs_bound_lt_2exp_si(arb_midref(x));
  long e10 = static_cast<long>(std::floor(static_cast<double>(e2) * 0.30102999566398120));
  arb_t y, t;
  arb_init(y);
  arb_init(t);
  fmpz_t D, k, lo, hi;
  fmpz_init(D);
  fmpz_init(k);
  fmpz_init(lo);
  fmpz_init(hi);
  fmpz_ui_pow_ui(lo, 10, static_cast<ulong>(n - 1));
  fmpz_ui_pow_ui(hi, 10, static_cast<ulong>(n));
  bool out = false;
  for (int tries = 0; tries < 6; ++tries) {
    const long shift = n - 1 - e10;
    arb_set_ui(t, 10);
    fmpz_set_si(k, shift);
    arb_pow_fmpz(t, t, k, prec + 64);
    arb_abs(y, x);
    arb_mul(y, y, t, prec + 64);
    arb_set_d(t, 0.5);
    arb_add(y, y, t, prec + 64);
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
  fmpz_clear(k);
  fmpz_clear(lo);
  fmpz_clear(hi);
  arb_clear(y);
  arb_clear(t);
  return out;
}

bool is_float(const ex& e) { return is_a<numeric>(e) && ex_to<numeric>(e).is_real() && !ex_to<numeric>(e).is_rational(); }

}  // namespace

/// The tape's instructions on balls (a friend of Tape: it reads the instructions).
struct detail::BallRun {
  using Status = BallValue::Status;
  /// Run the tape on `x` (one ball per input) at `bits`; every output's ball into `out`.
  static Status run(const Tape& t, const Balls& x, long bits, Balls& reg, std::vector<std::size_t>& outs) {
    using Op = Tape::Op;
    const slong p = bits;
    for (std::size_t i = 0; i < t.code_.size(); ++i) {
      const Tape::Ins& in = t.code_[i];
      arb_ptr v = reg[i];
      const bool leaf = in.op == Op::Input || in.op == Op::Const;
      arb_srcptr a = !leaf && in.a >= 0 ? reg[static_cast<std::size_t>(in.a)] : nullptr;
      arb_srcptr b = in.b >= 0 ? reg[static_cast<std::size_t>(in.b)] : nullptr;
      switch (in.op) {
        case Op::Const: {
          const ex& c = t.exact_[static_cast<std::size_t>(in.a)];
          if (is_a<numeric>(c) && ex_to<numeric>(c).is_rational()) {
            set_rational(v, cln::the<cln::cl_RA>(ex_to<numeric>(c).to_cl_N()), bits);
          } else if (c.is_equal(Pi)) {
            arb_const_pi(v, p);
          } else if (c.is_equal(Euler)) {
            arb_const_euler(v, p);
          } else if (c.is_equal(Catalan)) {
            arb_const_catalan(v, p);
          } else if (is_float(c)) {
            set_float(v, cln::the<cln::cl_F>(ex_to<numeric>(c).to_cl_N()));
          } else {
            return Status::Undefined;  // the tape keeps no other kind of constant
          }
          break;
        }
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
          if (in.op == Op::Asin) arb_asin(v, a, p);
          else arb_acos(v, a, p);
          break;
        }
        case Op::Atan: arb_atan(v, a, p); break;
        // atan2(y = a, x = b): undefined at (0, 0)
        case Op::Atan2:
          if (arb_is_zero(a) && arb_is_zero(b)) return Status::Undefined;
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
      }
      if (!arb_is_finite(v)) return Status::Indeterminate;
    }
    outs.clear();
    for (auto o : t.outs_) outs.push_back(static_cast<std::size_t>(o));
    return Status::Ok;
  }
  /// A float among the tape's constants (a number found numerically, written into the form).
  static bool has_float(const Tape& t) {
    for (auto& c : t.exact_)
      if (is_float(c)) return true;
    return false;
  }
};

struct BallEvaluator::Impl {
  /// Run at `bits`: the status, and the registers (the outputs among them). With `first`, input 0
  /// is that ball instead of its exact value.
  BallValue::Status run(long bits, Balls& reg, std::vector<std::size_t>& outs, arb_srcptr first = nullptr) const {
    const Balls* x = enclosed(bits);
    if (!x) return BallValue::Status::Undefined;
    if (!first) return detail::BallRun::run(tape, *x, bits, reg, outs);
    Balls y(x->size());
    for (std::size_t i = 0; i < x->size(); ++i) arb_set(y[i], (*x)[i]);
    arb_set(y[0], first);
    return detail::BallRun::run(tape, y, bits, reg, outs);
  }
  Tape tape;
  std::vector<ex> inputs;
  mutable std::map<long, Balls> at_bits;  ///< the inputs enclosed, per precision

  /// The inputs at `bits`: nothing when one of them is undefined or not real.
  const Balls* enclosed(long bits) const {
    auto it = at_bits.find(bits);
    if (it != at_bits.end()) return &it->second;
    Balls x(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const ex& v = inputs[i];
      if (is_a<numeric>(v) && ex_to<numeric>(v).is_rational()) {
        set_rational(x[i], cln::the<cln::cl_RA>(ex_to<numeric>(v).to_cl_N()), bits);
      } else if (is_float(v)) {
        set_float(x[i], cln::the<cln::cl_F>(ex_to<numeric>(v).to_cl_N()));
      } else {
        // an exact form (π/6, √2): its own tape, on balls of a few more bits
        Tape t;
        try {
          t = Tape::compile(v, {});
        } catch (const std::invalid_argument&) {
          return nullptr;
        }
        Balls reg(t.instructions());
        std::vector<std::size_t> outs;
        if (detail::BallRun::run(t, Balls(0), bits + 16, reg, outs) != BallValue::Status::Ok) return nullptr;
        arb_set_round(x[i], reg[outs.front()], bits);
      }
    }
    return &at_bits.emplace(bits, std::move(x)).first->second;
  }
};

BallEvaluator::BallEvaluator(const Tape& t, const std::vector<ex>& inputs) : impl_(std::make_unique<Impl>(Impl{t, inputs, {}})) {
  from_float_ = detail::BallRun::has_float(t);
  for (auto& v : inputs)
    for (auto it = v.preorder_begin(); it != v.preorder_end(); ++it) from_float_ = from_float_ || is_float(*it);
}
BallEvaluator::~BallEvaluator() = default;
BallEvaluator::BallEvaluator(BallEvaluator&&) noexcept = default;
BallEvaluator& BallEvaluator::operator=(BallEvaluator&&) noexcept = default;

std::vector<BallValue> BallEvaluator::at_all(long bits) const {
  std::vector<BallValue> out(impl_->tape.outputs());
  Balls reg(impl_->tape.instructions());
  std::vector<std::size_t> outs;
  auto st = impl_->run(bits, reg, outs);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].status = st;
    if (st == BallValue::Status::Ok) out[k].at = ends(reg[outs[k]]);
  }
  return out;
}

// n digits: evaluate at p bits; the digits are proven when both ends of the ball round to them
// (rounding is monotone: every value between the ends rounds alike). Else double p.
std::optional<Proven> BallEvaluator::digits(int n, long max_bits) const {
  // a ball that keeps holding 0 is a zero whose sign this precision cannot fix: it is called so
  // once the precision is well past what n digits need
  const long zero_bits = std::max<long>(1024, 4 * bits_for(n));
  long bits = bits_for(n) + 32;
  Balls reg(impl_->tape.instructions());
  std::vector<std::size_t> outs;
  for (;;) {
    BallValue v;
    v.status = impl_->run(bits, reg, outs);
    if (v.status == BallValue::Status::Undefined) return std::nullopt;
    if (v.status == BallValue::Status::Ok) {
      arb_srcptr x = reg[outs.front()];
      if (!arb_contains_zero(x)) {
        if (common_digits(x, n, bits)) {
          Enclosure e = ends(x);
          return Proven{Proven::Kind::Digits, e.mid(), e, bits};
        }
      } else if (arb_is_zero(x)) {
        return Proven{Proven::Kind::Exact, 0, {0, 0}, bits};  // an exact zero: the ball is the point 0
      } else if (bits >= std::min(zero_bits, max_bits)) {
        return Proven{Proven::Kind::Unsigned, 0, ends(x), bits};
      }
    }
    if (bits >= max_bits)
      throw std::domain_error("no working precision up to " + std::to_string(max_bits) + " bits fixes " + std::to_string(n) +
                              " digits (" +
                              (v.status == BallValue::Status::Indeterminate
                                   ? std::string("a step of the evaluation cannot be decided: a divisor, a square root's or a logarithm's argument that cannot be told from 0")
                                   : std::string("the digits do not settle")) +
                              ")");
    bits = std::min(max_bits, 2 * bits);
  }
}

// A root of r(u) = 0 proven: Newton's steps on the balls' midpoints find x; then the ball
// I = [x − δ, x + δ] holds a root when r is defined (so continuous) on all of I and r(x − δ),
// r(x + δ) have proven opposite signs (the intermediate value theorem). r′ on I away from 0
// makes it the only root in I. The digits are those every value of I rounds to.
std::optional<Proven> root_digits(const ex& r, const symbol& u, const numeric& x0, const numeric& lo, const numeric& hi,
                                  const exmap& values, int n, long max_bits) {
  // the start as the exact binary fraction a float is: it is only where Newton begins
  const numeric start = x0.is_rational() ? x0 : numeric(cln::cl_N(cln::rational(cln::the<cln::cl_R>(x0.to_cl_N()))));
  std::vector<ex> in{u}, vals{start};
  for (auto& [s, v] : values)
    if (r.has(s) && !s.is_equal(u)) {
      in.push_back(s);
      vals.push_back(v);
    }
  Tape tr, td;
  try {
    tr = Tape::compile(r, in);
    td = Tape::compile(r.diff(u), in);
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a function the tape has no instruction for (a work integral)
  }
  BallEvaluator R(tr, vals), D(td, vals);
  if (R.from_float() || D.from_float()) return std::nullopt;
  long bits = bits_for(n) + 32;
  arb_t x, t, I, a, b, step;
  arb_init(x);
  arb_init(t);
  arb_init(I);
  arb_init(a);
  arb_init(b);
  arb_init(step);
  set_rational(x, cln::the<cln::cl_RA>(start.to_cl_N()), 4 * bits);
  arb_get_mid_arb(x, x);
  Balls reg_r(tr.instructions()), reg_d(td.instructions());
  std::vector<std::size_t> outs_r, outs_d;
  std::optional<Proven> out;
  using St = BallValue::Status;
  auto sign = [&](arb_srcptr at, long p) {
    if (R.impl_->run(p, reg_r, outs_r, at) != St::Ok) return 0;
    arb_srcptr v = reg_r[outs_r[0]];
    return arb_is_positive(v) ? 1 : arb_is_negative(v) ? -1 : 0;
  };
  while (!out) {
    // Newton: x ← x − r(x)/r′(x), on midpoints
    for (int it = 0; it < 200; ++it) {
      if (R.impl_->run(bits, reg_r, outs_r, x) != St::Ok || D.impl_->run(bits, reg_d, outs_d, x) != St::Ok) break;
      arb_srcptr fr = reg_r[outs_r[0]];
      if (arb_is_zero(fr)) {  // r(x) = 0 exactly: x is a root
        out = Proven{Proven::Kind::Exact, 0, ends(x), bits};
        out->value = out->at.lo;
        break;
      }
      arb_get_mid_arb(t, fr);
      arb_get_mid_arb(a, reg_d[outs_d[0]]);
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
    if (out) break;
    // δ = 4|step| + 2^(8 − bits)|x| + 2^−bits
    arb_abs(a, step);
    arb_mul_2exp_si(a, a, 2);
    arb_abs(t, x);
    arb_mul_2exp_si(t, t, 8 - bits);
    arb_add(a, a, t, bits);
    arb_one(t);
    arb_mul_2exp_si(t, t, -bits);
    arb_add(a, a, t, bits);
    arb_get_ubound_arf(arb_midref(t), a, bits);
    mag_zero(arb_radref(t));
    arb_sub(a, x, t, bits + 16);
    arb_get_mid_arb(a, a);
    arb_add(b, x, t, bits + 16);
    arb_get_mid_arb(b, b);
    arb_union(I, a, b, bits + 16);
    const int sa = sign(a, bits), sb = sign(b, bits);
    if (sa != 0 && sb != 0 && sa != sb && R.impl_->run(bits, reg_r, outs_r, I) == St::Ok) {
      Enclosure e = ends(I);
      if (lo < hi && (e.lo < lo || e.hi > hi)) break;  // not the root of the solver's bracket
      if (common_digits(I, n, bits)) {
        out = Proven{Proven::Kind::Digits, e.mid(), e, bits};
        break;
      }
    }
    if (bits >= max_bits) break;
    bits = std::min(max_bits, 2 * bits);
  }
  for (arb_ptr p : {x, t, I, a, b, step}) arb_clear(p);
  return out;
}

std::optional<Enclosure> enclose(const ex& exact, long bits) {
  Tape t;
  try {
    t = Tape::compile(exact, {});
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
  BallEvaluator b(t, {});
  BallValue v = b.at(bits);
  if (v.status != BallValue::Status::Ok) return std::nullopt;
  return v.at;
}

long bits_for(int n) { return static_cast<long>(std::ceil(n * 3.3219280948873623)); }

numeric round_up2(const numeric& x) {
  if (!x.is_positive()) return 0;
  if (!x.is_rational()) {
    // a float (beyond 2^±4096): its decimal exponent from its binary one, the quotient taken in
    // floats and raised by a relative 2^−40 so that rounding cannot take it below x
    const cln::cl_F f = cln::the<cln::cl_F>(x.to_cl_N());
    const long e2 = cln::float_exponent(f);
    long k = static_cast<long>(std::floor(static_cast<double>(e2) * 0.30102999566398120)) - 2;
    auto up = [&](long kk) {
      const cln::cl_F q = f / cln::expt(cln::cl_float(10, cln::float_format(40)), cln::cl_I(kk));
      return cln::ceiling1(q * cln::cl_float(1 + cln::expt(cln::cl_RA(2), -40), cln::float_format(40)));
    };
    cln::cl_I d = up(k);
    while (d > 100) d = up(++k);
    while (d <= 10) d = up(--k);
    return numeric(cln::cl_N(cln::cl_float(d, cln::float_format(20)) * cln::expt(cln::cl_float(10, cln::float_format(40)), cln::cl_I(k))));
  }
  // x ≤ d · 10^k with d of two digits, d = ⌈x / 10^k⌉, k chosen so that 10 < d ≤ 100
  const cln::cl_RA q = cln::the<cln::cl_RA>(x.to_cl_N());
  const long l2 = static_cast<long>(cln::integer_length(cln::numerator(q))) - static_cast<long>(cln::integer_length(cln::denominator(q)));
  long k = static_cast<long>(std::floor(static_cast<double>(l2) * 0.30102999566398120)) - 2;  // log₁₀ x within 1
  auto up = [&](long kk) { return cln::ceiling1(q / cln::expt(cln::cl_RA(10), kk)); };
  cln::cl_I d = up(k);
  while (d > 100) d = up(++k);
  while (d <= 10) {
    cln::cl_I e = up(k - 1);
    if (e > 100) break;
    d = e;
    --k;
  }
  return numeric(cln::cl_N(d * cln::expt(cln::cl_RA(10), k)));
}

}  // namespace kinergy::numerics
