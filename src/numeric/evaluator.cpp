#include "kinergy/numeric/evaluator.hpp"

#include "kinergy/expr/canonical.hpp"

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <stdexcept>
#include <limits>
#include <map>

#include <cln/cln.h>

#include "kinergy/common/interrupt.hpp"
#include "kinergy/numeric/ball.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/stable.hpp"

namespace kinergy::numerics {

using namespace GiNaC;

namespace {

/// Rational in the inputs: numbers, input symbols and π combined by +, −, ×, ÷ and integer powers.
bool rational_in(const ex& e, const exmap& values) {
  if (is_a<numeric>(e)) return ex_to<numeric>(e).is_real();
  if (is_a<symbol>(e)) return values.count(e) > 0;
  if (is_a<constant>(e)) return true;
  if (is_a<add>(e) || is_a<mul>(e)) {
    for (const ex& x : e)
      if (!rational_in(x, values)) return false;
    return true;
  }
  if (is_a<power>(e)) return is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_integer() && rational_in(e.op(0), values);
  return false;
}

/// The largest subexpressions of e that are rational in the inputs (and not a single symbol or
/// number), replaced by new symbols; `parts` receives symbol → subexpression. In a sum or a
/// product that is not rational as a whole, its rational terms (factors) make one part.
struct Promote : map_function {
  const exmap& values;
  std::map<ex, ex, ex_is_less> seen;
  std::vector<std::pair<ex, ex>> parts;
  explicit Promote(const exmap& v) : values(v) {}
  ex part(const ex& e) {
    if (is_a<symbol>(e) || is_a<numeric>(e) || is_a<constant>(e)) return e;
    auto it = seen.find(e);
    if (it != seen.end()) return it->second;
    symbol s("exact" + std::to_string(parts.size()));
    seen[e] = s;
    parts.emplace_back(s, e);
    return s;
  }
  ex operator()(const ex& e) override {
    if (is_a<symbol>(e) || is_a<numeric>(e) || is_a<constant>(e)) return e;
    if (rational_in(e, values)) return part(e);
    if (is_a<add>(e) || is_a<mul>(e)) {
      const bool sum = is_a<add>(e);
      ex exact = sum ? 0 : 1, rest = sum ? 0 : 1;
      int n_exact = 0;
      // the operands in the order of their keys, so that the parts are numbered alike in every run
      std::vector<std::pair<std::string, ex>> ordered;
      for (const ex& x : e) ordered.push_back({expr::key(x).text, x});
      std::stable_sort(ordered.begin(), ordered.end(), [](auto& a, auto& b) { return a.first < b.first; });
      for (const auto& [k, x] : ordered) {
        if (rational_in(x, values)) {
          exact = sum ? exact + x : exact * x;
          ++n_exact;
        } else {
          ex y = (*this)(x);
          rest = sum ? rest + y : rest * y;
        }
      }
      if (n_exact >= 2) return sum ? part(exact) + rest : part(exact) * rest;
      return sum ? (*this)(exact) + rest : (*this)(exact) * rest;
    }
    return e.map(*this);
  }
};

/// √a √b / √c → √(ab/c) in each product, where every radicand is positive at the values
/// (so the identity holds there): one root, one rounding, instead of three.
struct MergeRoots : map_function {
  const exmap& values;
  explicit MergeRoots(const exmap& v) : values(v) {}
  bool positive(const ex& b) const {
    auto v = evaluate(b, values, 30);
    return v && v->is_positive();
  }
  ex operator()(const ex& e) override {
    ex m = e.map(*this);
    if (!is_a<mul>(m)) return m;
    ex inside = 1, rest = 1;
    int roots = 0;
    for (const ex& x : m) {
      if (is_a<power>(x) && (x.op(1).is_equal(numeric(1, 2)) || x.op(1).is_equal(numeric(-1, 2))) && positive(x.op(0))) {
        inside *= x.op(1).is_equal(numeric(1, 2)) ? x.op(0) : 1 / x.op(0);
        ++roots;
      } else {
        rest *= x;
      }
    }
    return roots >= 2 ? rest * sqrt(inside) : m;
  }
};

/// An exact value as a double, with a bound on its distance from the exact value; NaN (with an
/// infinite bound) when no double holds it: a value that is not zero and rounds to 0, to a
/// subnormal or to infinity (1e-400, 1e400) decides nothing through the double path.
std::pair<double, double> rounded(const ex& exact) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN(), kInf = std::numeric_limits<double>::infinity();
  if (is_a<numeric>(exact) && ex_to<numeric>(exact).is_rational()) {
    if (ex_to<numeric>(exact).is_zero()) return {0, 0};
    double d = to_double(exact);
    if (!std::isnormal(d)) return {kNaN, kInf};
    return {d, rounding_error(d, exact)};
  }
  // π/6, √2 …: two precisions; their difference bounds the error of the lower one
  auto lo = to_cln(exact, 40), hi = to_cln(exact, 80);
  if (!lo || !hi) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()};
  if (cln::zerop(*hi)) return {0, cln::double_approx(cln::abs(*lo))};
  double d = cln::double_approx(*hi);
  if (!std::isnormal(d)) return {kNaN, kInf};
  double e = cln::double_approx(cln::abs(*hi - *lo)) + rounding_error(d, numeric(cln::cl_N(*hi)));
  return {d, e};
}

}  // namespace

Evaluator::Evaluator(const ex& e, const exmap& values) : e_(e) {
  stable_ = stable_form(e);
  for (auto& [s, v] : values)
    if (e.has(s)) {
      syms_.push_back(s);
      exact_.push_back(v);
    }
  try {
    // (a work integral compiles too: that tape runs only on balls)
    precise_tape_ = Tape::compile(stable_, syms_, Tape::Accept::Integrals);
  } catch (const std::invalid_argument&) {
    precise_tape_.reset();
  }
  // rational inputs, kept as CLN rationals: the tape in exact arithmetic tells a rational value
  if (!exact_.empty() && std::all_of(exact_.begin(), exact_.end(), [](const ex& v) { return is_a<numeric>(v) && ex_to<numeric>(v).is_rational(); }))
    for (auto& v : exact_) rational_inputs_.push_back(cln::the<cln::cl_R>(ex_to<numeric>(v).to_cl_N()));
  for (std::size_t i = 0; i < syms_.size(); ++i) {
    values_[syms_[i]] = exact_[i];
    auto [d, err] = rounded(exact_[i]);  // the inputs as doubles, once for every candidate
    x_.push_back(d);
    dx_.push_back(err);
  }
  // the candidates for double evaluation, each with its exact parts
  double best = std::numeric_limits<double>::infinity();
  MergeRoots merge(values_);
  for (const ex& form : {stable_, merge(stable_), e_}) {
    Promote p(values_);
    ex f = p(form);
    std::vector<ex> in = syms_;
    std::vector<double> x = x_, dx = dx_;
    try {
      for (auto& [s, part] : p.parts) {
        in.push_back(s);
        auto [d, err] = rounded(part.subs(values_));  // GiNaC's exact arithmetic: 2L − 3d = 0 exactly
        x.push_back(d);
        dx.push_back(err);
      }
      Tape t = Tape::compile(f, in);
      Bounded b = t.bounded(x.data(), dx.data());
      // the error estimate decides; the stable form (tried first) wins a tie
      double rel = b.value != 0 ? b.bound / std::fabs(b.value) : b.bound;
      if (!(rel >= best) && !std::isnan(rel)) {
        best = rel;
        fast_tape_ = std::move(t);
        fast_x_ = x;
        fast_dx_ = dx;
        exmap back;
        for (auto& [s, part] : p.parts) back[s] = part;
        fast_form_ = f.subs(back);
      }
    } catch (const std::exception&) {
      // a function the tape has no instruction for, or a part undefined at the values
      // (a division by zero): not this candidate
    }
  }
}

std::optional<Bounded> Evaluator::fast() const {
  if (!fast_tape_) return std::nullopt;
  // a double that overflows, underflows (to a subnormal or to 0) or is invalid anywhere on the
  // way decides nothing: its value and its error bound are no longer what they claim
  constexpr int kOut = FE_OVERFLOW | FE_UNDERFLOW | FE_INVALID | FE_DIVBYZERO;
  std::feclearexcept(kOut);
  Bounded b = fast_tape_->bounded(fast_x_.data(), fast_dx_.data());
  if (std::fetestexcept(kOut) || !std::isfinite(b.value) || !std::isfinite(b.bound) ||
      (b.value != 0 && !std::isnormal(b.value)))
    return std::nullopt;
  return b;
}

std::optional<Bounded> Evaluator::naive() const {
  try {
    Tape t = Tape::compile(e_, syms_);
    return t.bounded(x_.data(), dx_.data());
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

std::optional<numeric> Evaluator::at(long working) const {
  if (!precise_tape_ || precise_tape_->has_integrals()) {
    // no tape for this form in CLN: GiNaC's own evaluation at that precision (an integral by
    // tanh–sinh quadrature)
    return evaluate(e_, values_, static_cast<int>(working));
  }
  // the inputs as floats of this precision, converted once (exact values are the business of
  // digits(), which asks GiNaC's exact arithmetic first)
  auto it = inputs_.find(working);
  if (it == inputs_.end()) {
    std::vector<cln::cl_R> x;
    for (auto& v : exact_) {
      auto c = to_cln(v, working);
      if (!c) return std::nullopt;
      x.push_back(cln::cl_float(*c, cln::float_format(working)));
    }
    it = inputs_.emplace(working, std::move(x)).first;
  }
  auto r = precise_tape_->precise(it->second, working, false);
  if (!r) return std::nullopt;
  return numeric(cln::cl_N(*r));
}

// An exact value first: the tape in exact arithmetic (rationals stay rationals through +, −, ×, ÷,
// integer powers and √ of a square: a few rational operations), then GiNaC's exact arithmetic
// (sin(π) = 0, 2L − 3d = 0). That the value is not rational at these values is kept once GiNaC has
// said so (a property of the form and its values, as its tape is): later calls go straight to the
// balls. A rational value is computed again at each call.
std::optional<numeric> Evaluator::exact_value(bool& undefined) const {
  undefined = false;
  if (irrational_) return std::nullopt;
  if (precise_tape_ && !precise_tape_->has_integrals() && !rational_inputs_.empty()) {
    try {
      if (auto r = precise_tape_->precise(rational_inputs_, 20, true); r && cln::instanceof(*r, cln::cl_RA_ring))
        return numeric(cln::cl_N(*r));
    } catch (const NeedsPrecision&) {
      // a trigonometric function of a large angle: not rational here; GiNaC decides below
    }
  }
  try {
    ex v = e_.subs(values_);
    if (is_a<numeric>(v) && ex_to<numeric>(v).is_rational()) return ex_to<numeric>(v);
    irrational_ = true;
  } catch (const std::exception&) {
    undefined = true;  // a division by zero at the exact values
  }
  return std::nullopt;
}

// N digits proven: the tape on balls from the exact inputs (ball.hpp).
std::optional<Precise> Evaluator::digits(int n) const {
  bool undefined = false;
  if (auto q = exact_value(undefined)) return Precise{*q, 0, true, false, 0, true, *q, *q};
  if (undefined) return std::nullopt;
  if (!precise_tape_) return settled(n);
  if (!balls_) balls_ = std::make_shared<BallEvaluator>(*precise_tape_, exact_);
  if (balls_->from_float()) return settled(n);
  // the same limit as CLN's: 20000 digits, or 8 per digit asked
  const long max_bits = bits_for(static_cast<int>(std::max<long>(20000, 8L * n)));
  auto p = balls_->digits(n, max_bits);
  if (!p) return std::nullopt;
  const long working = digits_in(p->bits);
  switch (p->kind) {
    case Proven::Kind::Exact: return Precise{p->value, 0, true, false, 0, true, p->value, p->value};
    // the midpoint: it rounds to the proven digits (it lies inside the ball, whose every value
    // rounds to them), and carries more digits for a caller that rounds again
    case Proven::Kind::Digits: return Precise{p->value, working, false, false, 0, true, p->at.lo, p->at.hi};
    case Proven::Kind::Unsigned: {
      numeric m = std::max(abs(p->at.lo), abs(p->at.hi));
      return Precise{0, working, false, true, round_up2(m).to_double(), true, p->at.lo, p->at.hi};
    }
  }
  return std::nullopt;
}

// N digits: evaluate at p and at a higher precision until both round to the same N digits.
std::optional<Precise> Evaluator::settled(int n) const {
  bool undefined = false;
  if (auto q = exact_value(undefined)) return Precise{*q, 0, true, false, 0, false, {}, {}};
  if (undefined) return std::nullopt;
  const long limit = std::max<long>(20000, 8L * n);
  // at(w), with w raised to what the arguments need (a trigonometric function of 1e80 rad)
  auto covering = [&](long& w) -> std::optional<numeric> {
    for (;;) {
      try {
        return at(w);
      } catch (const NeedsPrecision& np) {
        if (np.digits > limit)
          throw std::domain_error("an argument of a trigonometric function is too large for " + std::to_string(limit) +
                                  " digits of working precision (reducing it modulo 2*pi would need " +
                                  std::to_string(np.digits) + ")");
        w = std::max(w + 1, np.digits);
      }
    }
  };
  // at least 20 digits: below about 17, CLN's floats are machine floats whose exponents
  // overflow and underflow like a double's (exp(-1e6) at 11 digits is an underflow exception)
  long p = std::max<long>(n + 10, 20);
  auto prev = covering(p);
  if (!prev) return std::nullopt;
  if (prev->is_rational()) return Precise{*prev, 0, true, false, 0, false, {}, {}};
  int shrinking = 0;
  while (p < limit) {
    poll_interrupt();
    long q = std::min(limit, p + std::max(20L, p / 2));
    auto cur = covering(q);
    if (!cur) return std::nullopt;
    if (!prev->is_zero() && !cur->is_zero() && round_sig(*prev, n) == round_sig(*cur, n)) return Precise{*cur, q, false, false, 0, false, {}, {}};
    if (prev->is_zero() && cur->is_zero()) return Precise{*cur, q, false, false, 0, false, {}, {}};
    // a value that is zero in exact arithmetic comes out as noise of the working precision,
    // and the noise falls as the precision rises
    double lp = std::log10(std::fabs(prev->to_double()) + 1e-300), lc = std::log10(std::fabs(cur->to_double()) + 1e-300);
    if (cur->is_zero() || lc < lp - 0.5 * static_cast<double>(q - p)) ++shrinking;
    else shrinking = 0;
    if (shrinking >= 3 || (cur->is_zero() && shrinking >= 1))
      return Precise{0, q, false, true, std::max(std::fabs(cur->to_double()), std::pow(10.0, -static_cast<double>(std::min(q, 300L)))), false, {}, {}};
    prev = cur;
    p = q;
  }
  return std::nullopt;
}

}  // namespace kinergy::numerics
