#include "kinergy/numeric/tape.hpp"

#include "kinergy/expr/canonical.hpp"
#include "kinergy/numeric/digits.hpp"
#include "kinergy/numeric/evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include <cln/cln.h>
#include <stdexcept>

namespace kinergy::numerics {

using namespace GiNaC;

namespace {

// aⁿ by repeated squaring (the same in the tape, its batch and its generated C++)
inline double powi(double a, int n) {
  double p = 1, b = n < 0 ? 1 / a : a;
  for (unsigned k = static_cast<unsigned>(n < 0 ? -n : n); k; k >>= 1, b *= b)
    if (k & 1) p *= b;
  return p;
}

}  // namespace

class TapeBuilder {
public:
  TapeBuilder(Tape& t, const std::vector<ex>& inputs, Tape::Accept accept) : t_(t), inputs_(inputs), accept_(accept) {
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      Tape::Ins in{Tape::Op::Input, static_cast<std::int32_t>(i), -1, 0};
      seen_[inputs[i]] = emit(in);
    }
  }

  // Each distinct subexpression gets one register (hash-consing on GiNaC's canonical form).
  std::int32_t node(const ex& e) {
    auto it = seen_.find(e);
    if (it != seen_.end()) return it->second;
    std::int32_t r = build(e);
    seen_[e] = r;
    return r;
  }

private:
  Tape& t_;
  const std::vector<ex>& inputs_;
  const Tape::Accept accept_;
  std::map<ex, std::int32_t, ex_is_less> seen_;

  std::int32_t emit(const Tape::Ins& in) {
    t_.code_.push_back(in);
    return static_cast<std::int32_t>(t_.code_.size() - 1);
  }
  // a constant: its double, and the exact value kept for the error bound and for CLN
  std::int32_t constant(const ex& exact) {
    double d = to_double(exact);
    t_.exact_.push_back(exact);
    t_.const_err_.push_back(rounding_error(d, exact));
    return emit({Tape::Op::Const, static_cast<std::int32_t>(t_.exact_.size() - 1), -1, d});
  }
  std::int32_t unary(Tape::Op op, const ex& a) { return emit({op, node(a), -1, 0}); }

  std::int32_t build(const ex& e) {
    using Op = Tape::Op;
    if (is_a<numeric>(e)) {
      const numeric& n = ex_to<numeric>(e);
      if (!n.is_real()) throw std::invalid_argument("tape: a complex constant " + to_text(e));
      return constant(e);
    }
    if (is_a<GiNaC::constant>(e)) return constant(e);
    if (is_a<symbol>(e)) throw std::invalid_argument("tape: '" + to_text(e) + "' is not an input");
    if (is_a<add>(e) || is_a<mul>(e)) {
      // a chain of binary operations over the operands, in the order of their keys (GiNaC's own
      // order follows addresses, and the rounding follows the order): plain factors before
      // reciprocals, a number last
      bool sum = is_a<add>(e);
      std::vector<std::pair<std::pair<int, std::string>, ex>> ordered;
      for (std::size_t i = 0; i < e.nops(); ++i) {
        const ex& x = e.op(i);
        int group = is_a<numeric>(x) ? 2 : (!sum && is_a<power>(x) && x.op(1).is_equal(-1)) ? 1 : 0;
        ordered.push_back({{group, expr::key(x).text}, x});
      }
      std::stable_sort(ordered.begin(), ordered.end(), [](auto& a, auto& b) { return a.first < b.first; });
      // a factor −1 is a negation, exact: GiNaC writes a sum that is a factor with the sign its
      // term order asks for, −(b − a) in one run and (a − b) in the next, and the two must round,
      // and be bounded, alike
      bool negate = false;
      if (!sum && ordered.size() > 1 && is_a<numeric>(ordered.back().second) && ordered.back().second.is_equal(-1)) {
        ordered.pop_back();
        negate = true;
      }
      std::int32_t acc = node(ordered[0].second);
      for (std::size_t i = 1; i < ordered.size(); ++i) {
        const ex& x = ordered[i].second;
        // a·x⁻¹ as a division: one rounding instead of two
        if (!sum && is_a<power>(x) && x.op(1).is_equal(-1)) acc = emit({Op::Div, acc, node(x.op(0)), 0});
        else acc = emit({sum ? Op::Add : Op::Mul, acc, node(x), 0});
      }
      return negate ? emit({Op::Neg, acc, -1, 0}) : acc;
    }
    if (is_a<power>(e)) {
      const ex& b = e.op(0);
      const ex& k = e.op(1);
      if (is_a<numeric>(k)) {
        numeric q = ex_to<numeric>(k);
        if (q == 2) return unary(Op::Sq, b);
        if (q == 3) return unary(Op::Cube, b);
        if (q == -1) return emit({Op::Div, constant(1), node(b), 0});
        if (q == numeric(1, 2)) return unary(Op::Sqrt, b);
        if (q == numeric(-1, 2)) return unary(Op::Rsqrt, b);
        if (q.is_integer() && abs(q) < 64) return emit({Op::Powi, node(b), -1, q.to_double()});
      }
      return emit({Op::Pow, node(b), node(k), 0});
    }
    if (is_integral(e)) {
      if (accept_ != Tape::Accept::Integrals || !is_a<symbol>(e.op(1)))
        throw std::invalid_argument("tape: an integral (" + to_text(e) + ") runs only on balls");
      // ∫_a^b f(ξ) dξ: f on a tape of its own, its inputs ξ and then this tape's inputs (an
      // integral inside f is not taken: that compile throws)
      std::vector<ex> in{e.op(1)};
      in.insert(in.end(), inputs_.begin(), inputs_.end());
      t_.integrands_.push_back(std::make_shared<const Tape>(Tape::compile(e.op(0), in)));
      const std::int32_t a = node(e.op(2)), b = node(e.op(3));
      return emit({Op::Integral, a, b, static_cast<double>(t_.integrands_.size() - 1)});
    }
    if (is_a<function>(e)) {
      std::string f = ex_to<function>(e).get_name();
      static const std::map<std::string, Op> ops = {
          {"sin", Op::Sin},   {"cos", Op::Cos},   {"tan", Op::Tan},   {"asin", Op::Asin}, {"acos", Op::Acos},
          {"atan", Op::Atan}, {"exp", Op::Exp},   {"log", Op::Log},   {"abs", Op::Abs},   {"sinh", Op::Sinh},
          {"cosh", Op::Cosh}, {"tanh", Op::Tanh}};
      if (f == "atan2") return emit({Op::Atan2, node(e.op(0)), node(e.op(1)), 0});
      auto it = ops.find(f);
      if (it != ops.end() && e.nops() == 1) return unary(it->second, e.op(0));
      throw std::invalid_argument("tape: the function " + f + " is not supported");
    }
    throw std::invalid_argument("tape: cannot evaluate " + to_text(e));
  }

  static std::string to_text(const ex& e) {
    std::ostringstream os;
    os << e;
    return os.str();
  }
};

Tape Tape::compile(const ex& e, const std::vector<ex>& inputs, Accept accept) {
  return compile(std::vector<ex>{e}, inputs, accept);
}

Tape Tape::compile(const std::vector<ex>& outputs, const std::vector<ex>& inputs, Accept accept) {
  if (outputs.empty()) throw std::invalid_argument("tape: nothing to compute");
  Tape t;
  t.n_inputs_ = inputs.size();
  TapeBuilder b(t, inputs, accept);
  for (auto& e : outputs) t.outs_.push_back(b.node(e));
  t.out_ = t.outs_.front();
  t.reg_.resize(t.code_.size());
  for (std::size_t i = 0; i < t.code_.size(); ++i) {
    const Ins& in = t.code_[i];
    const auto reg = static_cast<std::uint32_t>(i);
    if (in.op == Op::Const) t.reg_[i] = in.c;
    else if (in.op == Op::Input) t.inputs_at_.emplace_back(reg, static_cast<std::uint32_t>(in.a));
    else t.work_.push_back(reg);
  }
  t.err_.resize(t.code_.size());
  return t;
}

void Tape::elementary_only() const {
  if (has_integrals()) throw std::logic_error("tape: a tape with an integral runs only on balls");
}

double Tape::operator()(const double* x) const {
  run(x);
  return out_ < 0 ? 0 : reg_[static_cast<std::size_t>(out_)];
}

void Tape::eval(const double* x, double* out) const {
  run(x);
  for (std::size_t k = 0; k < outs_.size(); ++k) out[k] = reg_[static_cast<std::size_t>(outs_[k])];
}

void Tape::run(const double* x) const {
  elementary_only();
  double* r = reg_.data();  // the constants' registers were filled by compile()
  for (auto [reg, input] : inputs_at_) r[reg] = x[input];
  for (std::uint32_t i : work_) {
    const Ins& in = code_[i];
    const double a = r[in.a], b = in.b >= 0 ? r[in.b] : 0;
    switch (in.op) {
      case Op::Const:
      case Op::Input: break;  // not in work_
      case Op::Add: r[i] = a + b; break;
      case Op::Mul: r[i] = a * b; break;
      case Op::Div: r[i] = a / b; break;
      case Op::Neg: r[i] = -a; break;
      case Op::Sq: r[i] = a * a; break;
      case Op::Cube: r[i] = a * a * a; break;
      case Op::Powi: r[i] = powi(a, static_cast<int>(in.c)); break;
      case Op::Sqrt: r[i] = std::sqrt(a); break;
      case Op::Rsqrt: r[i] = 1 / std::sqrt(a); break;
      case Op::Pow: r[i] = std::pow(a, b); break;
      case Op::Sin: r[i] = std::sin(a); break;
      case Op::Cos: r[i] = std::cos(a); break;
      case Op::Tan: r[i] = std::tan(a); break;
      case Op::Asin: r[i] = std::asin(a); break;
      case Op::Acos: r[i] = std::acos(a); break;
      case Op::Atan: r[i] = std::atan(a); break;
      case Op::Atan2: r[i] = std::atan2(a, b); break;
      case Op::Exp: r[i] = std::exp(a); break;
      case Op::Log: r[i] = std::log(a); break;
      case Op::Abs: r[i] = std::fabs(a); break;
      case Op::Sinh: r[i] = std::sinh(a); break;
      case Op::Cosh: r[i] = std::cosh(a); break;
      case Op::Tanh: r[i] = std::tanh(a); break;
      case Op::Integral: break;  // (elementary_only)
    }
  }
}

void Tape::batch(const double* x, std::size_t n, double* out) const {
  elementary_only();
  // registers laid out instruction-major: register i of point k at R[i*n + k]
  batch_reg_.resize(code_.size() * n);
  double* R = batch_reg_.data();
  const std::size_t m = n_inputs_;
  for (std::size_t i = 0; i < code_.size(); ++i) {
    const Ins& in = code_[i];
    double* r = R + i * n;
    const bool leaf = in.op == Op::Input || in.op == Op::Const;
    const double* a = !leaf && in.a >= 0 ? R + static_cast<std::size_t>(in.a) * n : nullptr;
    const double* b = in.b >= 0 ? R + static_cast<std::size_t>(in.b) * n : nullptr;
    auto each = [&](auto f) {
      for (std::size_t k = 0; k < n; ++k) r[k] = f(k);
    };
    switch (in.op) {
      case Op::Const: each([&](std::size_t) { return in.c; }); break;
      case Op::Input: each([&](std::size_t k) { return x[k * m + static_cast<std::size_t>(in.a)]; }); break;
      case Op::Add: each([&](std::size_t k) { return a[k] + b[k]; }); break;
      case Op::Mul: each([&](std::size_t k) { return a[k] * b[k]; }); break;
      case Op::Div: each([&](std::size_t k) { return a[k] / b[k]; }); break;
      case Op::Neg: each([&](std::size_t k) { return -a[k]; }); break;
      case Op::Sq: each([&](std::size_t k) { return a[k] * a[k]; }); break;
      case Op::Cube: each([&](std::size_t k) { return a[k] * a[k] * a[k]; }); break;
      case Op::Powi: each([&](std::size_t k) { return powi(a[k], static_cast<int>(in.c)); }); break;
      case Op::Sqrt: each([&](std::size_t k) { return std::sqrt(a[k]); }); break;
      case Op::Rsqrt: each([&](std::size_t k) { return 1 / std::sqrt(a[k]); }); break;
      case Op::Pow: each([&](std::size_t k) { return std::pow(a[k], b[k]); }); break;
      case Op::Sin: each([&](std::size_t k) { return std::sin(a[k]); }); break;
      case Op::Cos: each([&](std::size_t k) { return std::cos(a[k]); }); break;
      case Op::Tan: each([&](std::size_t k) { return std::tan(a[k]); }); break;
      case Op::Asin: each([&](std::size_t k) { return std::asin(a[k]); }); break;
      case Op::Acos: each([&](std::size_t k) { return std::acos(a[k]); }); break;
      case Op::Atan: each([&](std::size_t k) { return std::atan(a[k]); }); break;
      case Op::Atan2: each([&](std::size_t k) { return std::atan2(a[k], b[k]); }); break;
      case Op::Exp: each([&](std::size_t k) { return std::exp(a[k]); }); break;
      case Op::Log: each([&](std::size_t k) { return std::log(a[k]); }); break;
      case Op::Abs: each([&](std::size_t k) { return std::fabs(a[k]); }); break;
      case Op::Sinh: each([&](std::size_t k) { return std::sinh(a[k]); }); break;
      case Op::Cosh: each([&](std::size_t k) { return std::cosh(a[k]); }); break;
      case Op::Tanh: each([&](std::size_t k) { return std::tanh(a[k]); }); break;
      case Op::Integral: break;  // (elementary_only)
    }
  }
  if (out_ < 0) {
    std::fill(out, out + n, 0.0);
    return;
  }
  const double* r = R + static_cast<std::size_t>(out_) * n;
  std::copy(r, r + n, out);
}

// Running error analysis. With u = 2⁻⁵³ the unit roundoff, every register carries r̂ and a
// bound e with |r̂ − r| ≤ e, where r is the exact value of the same operation on exact operands.
// For r = f(a, b) computed as fl(f(â, b̂)):
//   |r̂ − r| ≤ |f(â, b̂) − f(a, b)| + |fl(f(â, b̂)) − f(â, b̂)|
// the first part bounded through f on the interval [â − e_a, â + e_a] (× same for b), the second
// by u|r̂| for correctly rounded +, −, ×, ÷, √ and by 2u|r̂| for the library functions (glibc's
// sin, cos, exp, log, pow are within one ulp).
Bounded Tape::bounded(const double* x, const double* dx) const {
  bound_run(x, dx, false);
  if (out_ < 0) return {0, 0};
  return {reg_[static_cast<std::size_t>(out_)], err_[static_cast<std::size_t>(out_)]};
}

void Tape::enclose(const double* mid, const double* radius, Enclosed* out) const {
  bound_run(mid, radius, true);
  for (std::size_t k = 0; k < outs_.size(); ++k) {
    const auto r = static_cast<std::size_t>(outs_[k]);
    out[k] = {reg_[r], err_[r], undefined_[r] != 0};
  }
}

// May an operand within a ± e_a (b ± e_b) leave instruction `in` undefined?
bool Tape::outside_domain(const Ins& in, double a, double b, double ea, double eb) {
  switch (in.op) {
    case Op::Div: return !(std::fabs(b) > eb);
    case Op::Sqrt: return !(a - ea >= 0);
    case Op::Rsqrt:
    case Op::Log:
    case Op::Pow: return !(a - ea > 0);
    case Op::Powi: return in.c < 0 && !(std::fabs(a) > ea);
    case Op::Asin:
    case Op::Acos: return !(std::fabs(a) + ea <= 1);
    // |cos| is 1-Lipschitz: a pole p within [a ± e_a] gives |cos a| = |cos a − cos p| ≤ e_a
    case Op::Tan: return !(std::fabs(std::cos(a)) > ea);
    case Op::Atan2: return !(std::hypot(a, b) > ea + eb);
    default: return false;
  }
}

// Every register's value and bound (bounded() above). With `domains`, undefined_[i] also says
// whether some operands within the bounds leave instruction i (or one it takes) undefined: a
// division by an interval that holds 0, √ or log of one that reaches below 0, asin of one past ±1,
// tan of one that holds a pole.
void Tape::bound_run(const double* x, const double* dx, bool domains) const {
  elementary_only();
  constexpr double u = 0x1p-53;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double* r = reg_.data();
  double* E = err_.data();
  if (domains) undefined_.assign(code_.size(), 0);
  for (std::size_t i = 0; i < code_.size(); ++i) {
    const Ins& in = code_[i];
    const bool leaf = in.op == Op::Input || in.op == Op::Const;
    const double a = !leaf && in.a >= 0 ? r[in.a] : 0, b = in.b >= 0 ? r[in.b] : 0;
    const double ea = !leaf && in.a >= 0 ? E[in.a] : 0, eb = in.b >= 0 ? E[in.b] : 0;
    const double A = std::fabs(a), B = std::fabs(b);
    double v = 0, e = 0;
    if (domains && !leaf)
      undefined_[i] = (in.a >= 0 && undefined_[static_cast<std::size_t>(in.a)]) || (in.b >= 0 && undefined_[static_cast<std::size_t>(in.b)]) ||
                      outside_domain(in, a, b, ea, eb);
    switch (in.op) {
      case Op::Const: v = in.c; e = const_err_[static_cast<std::size_t>(in.a)]; break;
      case Op::Input: v = x[in.a]; e = dx ? dx[in.a] : 0; break;
      // (a+δa) + (b+δb) − (a+b) = δa + δb
      case Op::Add: v = a + b; e = ea + eb + u * std::fabs(v); break;
      // (a+δa)(b+δb) − ab = a δb + b δa + δa δb
      case Op::Mul: v = a * b; e = A * eb + B * ea + ea * eb + u * std::fabs(v); break;
      // (a+δa)/(b+δb) − a/b = (δa − (a/b) δb)/(b + δb)
      case Op::Div:
        v = a / b;
        e = B > eb ? (ea + std::fabs(v) * eb) / (B - eb) + u * std::fabs(v) : inf;
        break;
      case Op::Neg: v = -a; e = ea; break;
      // (a+δ)² − a² = 2aδ + δ²
      case Op::Sq: v = a * a; e = 2 * A * ea + ea * ea + u * v; break;
      // (a+δ)³ − a³ = 3a²δ + 3aδ² + δ³ ; two roundings
      case Op::Cube: v = a * a * a; e = 3 * A * A * ea + 3 * A * ea * ea + ea * ea * ea + 2 * u * std::fabs(v); break;
      // |(a+δ)ⁿ − aⁿ| ≤ |n| max(|a|±|δ|)^(n−1) |δ|
      case Op::Powi: {
        v = powi(a, static_cast<int>(in.c));
        const double n = std::fabs(in.c);
        const double far = in.c > 0 ? A + ea : A - ea;  // where |x^(n−1)| is largest on the interval
        e = far > 0 ? n * std::pow(far, in.c - 1) * ea : inf;
        e += (2 * std::log2(n) + 2) * u * std::fabs(v);  // repeated squaring: ≤ 2 log₂|n| + 1 roundings
        break;
      }
      // |√(a+δ) − √a| = |δ|/(√(a+δ) + √a) ≤ |δ|/(√(a−|δ|) + √a), and ≤ √|δ| always
      case Op::Sqrt:
        v = std::sqrt(a);
        e = (a > ea ? std::min(ea / (std::sqrt(a - ea) + v), std::sqrt(ea)) : std::sqrt(a + ea) + v) + u * v;
        break;
      // |1/√(a+δ) − 1/√a| ≤ |δ| / (2 (a−|δ|)^(3/2))
      case Op::Rsqrt:
        v = 1 / std::sqrt(a);
        e = a > ea ? ea / (2 * (a - ea) * std::sqrt(a - ea)) + 2 * u * v : inf;
        break;
      // |f(a+δ) − f(a)| ≤ |f'(a)||δ| + ½ max|f''| δ² for sin and cos (|f''| ≤ 1)
      case Op::Sin: v = std::sin(a); e = std::min(2.0, std::fabs(std::cos(a)) * ea + ea * ea / 2) + 2 * u * std::fabs(v); break;
      case Op::Cos: v = std::cos(a); e = std::min(2.0, std::fabs(std::sin(a)) * ea + ea * ea / 2) + 2 * u * std::fabs(v); break;
      // tan' = 1 + tan², bounded on the interval when it holds no pole
      case Op::Tan: {
        v = std::tan(a);
        const double c = std::cos(a);
        e = std::fabs(c) > ea ? ea / ((std::fabs(c) - ea) * (std::fabs(c) - ea)) + 2 * u * std::fabs(v) : inf;
        break;
      }
      // asin' = acos' = 1/√(1 − a²)
      case Op::Asin:
      case Op::Acos: {
        v = in.op == Op::Asin ? std::asin(a) : std::acos(a);
        const double far = A + ea;
        // near ±1: |asin x − asin y| ≤ (π/√2) √|x − y|
        e = far < 1 ? ea / std::sqrt(1 - far * far) : 2.2214414690791831 * std::sqrt(ea);
        e += 2 * u * std::fabs(v);
        break;
      }
      case Op::Atan: v = std::atan(a); e = ea + 2 * u * std::fabs(v); break;
      // |∇atan2(y, x)| = 1/√(x² + y²)
      case Op::Atan2: {
        v = std::atan2(a, b);
        const double rho = std::hypot(a, b) - ea - eb;
        // (near the origin: any two angles in [−π, π] are at most 2π apart)
        e = rho > 0 ? std::min((ea + eb) / rho + 2 * u * std::fabs(v), 6.2831853071795872) : 6.2831853071795872;
        break;
      }
      // e^(a+δ) − e^a = e^a (e^δ − 1)
      case Op::Exp: v = std::exp(a); e = v * std::expm1(ea) + 2 * u * v; break;
      // |ln(a+δ) − ln a| ≤ |δ|/(a − |δ|)
      case Op::Log: v = std::log(a); e = a > ea ? ea / (a - ea) + 2 * u * std::fabs(v) : inf; break;
      case Op::Abs: v = A; e = ea; break;
      case Op::Sinh:
      case Op::Cosh:
        v = in.op == Op::Sinh ? std::sinh(a) : std::cosh(a);
        e = std::cosh(A + ea) * ea + 2 * u * std::fabs(v);
        break;
      case Op::Tanh: v = std::tanh(a); e = ea + 2 * u * std::fabs(v); break;
      // a^b = e^(b ln a): relative change ≤ e^(|b| δa/(a−δa) + |ln a| δb + …) − 1
      case Op::Pow: {
        v = std::pow(a, b);
        if (a > ea) {
          const double rel = (B + eb) * ea / (a - ea) + std::fabs(std::log(a)) * eb + ea * eb / (a - ea);
          e = std::fabs(v) * std::expm1(rel) + 2 * u * std::fabs(v);
        } else {
          e = inf;
        }
        break;
      }
      case Op::Integral: break;  // (elementary_only)
    }
    r[i] = v;
    E[i] = std::isnan(v) ? inf : e;
    if (domains && std::isnan(v)) undefined_[i] = 1;
  }
}

namespace {

using cln::cl_R;

bool is_rational(const cl_R& x) { return cln::instanceof(x, cln::cl_RA_ring); }

cln::cl_F as_float(const cl_R& x, const cln::float_format_t& f) { return cln::cl_float(x, f); }

}  // namespace

// Rationals stay rationals through +, −, ×, ÷, integer powers, and √ of a perfect square; the
// first inexact step makes a float of the asked format, and CLN carries that format on.
// A periodic function of x reduces x modulo 2π: x's integer digits are lost to the reduction, so
// the working precision must hold them besides `digits` digits of the result.
static void cover_argument(const cl_R& x, long digits) {
  if (cln::zerop(x)) return;
  const long int_digits = static_cast<long>(std::ceil(static_cast<double>(cln::float_exponent(cln::cl_float(x))) * 0.30103));
  if (int_digits > 0 && int_digits + 10 > digits / 2) throw NeedsPrecision{2 * (int_digits + 10) + digits};
}

std::optional<cl_R> Tape::precise(const std::vector<cl_R>& x, long digits, bool exact_constants) const {
  elementary_only();
  const cln::float_format_t f = cln::float_format(digits);
  std::vector<cl_R> r(code_.size());
  for (std::size_t i = 0; i < code_.size(); ++i) {
    const Ins& in = code_[i];
    const bool leaf = in.op == Op::Input || in.op == Op::Const;
    const cl_R a = !leaf && in.a >= 0 ? r[static_cast<std::size_t>(in.a)] : cl_R(0);
    const cl_R b = in.b >= 0 ? r[static_cast<std::size_t>(in.b)] : cl_R(0);
    cl_R v;
    switch (in.op) {
      case Op::Const: {
        auto c = to_cln(exact_[static_cast<std::size_t>(in.a)], digits);
        if (!c) return std::nullopt;
        v = exact_constants || !is_rational(*c) ? *c : cl_R(as_float(*c, f));
        break;
      }
      case Op::Input: v = x.at(static_cast<std::size_t>(in.a)); break;
      case Op::Add: v = a + b; break;
      case Op::Mul: v = a * b; break;
      case Op::Div:
        if (cln::zerop(b)) return std::nullopt;
        v = a / b;
        break;
      case Op::Neg: v = -a; break;
      case Op::Sq: v = a * a; break;
      case Op::Cube: v = a * a * a; break;
      case Op::Powi: {
        const long n = static_cast<long>(in.c);
        if (n < 0 && cln::zerop(a)) return std::nullopt;
        v = cln::expt(a, n);
        break;
      }
      case Op::Sqrt:
      case Op::Rsqrt: {
        if (cln::minusp(a)) return std::nullopt;
        cl_R s;
        cln::cl_RA q, root;
        if (is_rational(a) && cln::sqrtp(q = cln::the<cln::cl_RA>(a), &root)) s = root;
        else s = cln::sqrt(as_float(a, f));
        if (in.op == Op::Sqrt) {
          v = s;
        } else {
          if (cln::zerop(s)) return std::nullopt;
          v = 1 / s;
        }
        break;
      }
      case Op::Sin:
        cover_argument(a, digits);
        v = cln::zerop(a) ? cl_R(0) : cl_R(cln::sin(as_float(a, f)));
        break;
      case Op::Cos:
        cover_argument(a, digits);
        v = cln::zerop(a) ? cl_R(1) : cl_R(cln::cos(as_float(a, f)));
        break;
      case Op::Tan: {
        cover_argument(a, digits);
        if (cln::zerop(a)) {
          v = 0;
          break;
        }
        cln::cl_F c = cln::cos(as_float(a, f));
        if (cln::zerop(c)) return std::nullopt;
        v = cln::sin(as_float(a, f)) / c;
        break;
      }
      case Op::Asin:
      case Op::Acos: {
        if (cln::abs(a) > 1) return std::nullopt;
        if (in.op == Op::Asin && cln::zerop(a)) {
          v = 0;
          break;
        }
        // asin a = atan2(a, √(1 − a²)), acos a = atan2(√(1 − a²), a)
        cln::cl_F s = cln::sqrt(as_float(1 - a * a, f));
        v = in.op == Op::Asin ? cln::atan(s, as_float(a, f)) : cln::atan(as_float(a, f), s);
        break;
      }
      case Op::Atan: v = cln::zerop(a) ? cl_R(0) : cl_R(cln::atan(as_float(a, f))); break;
      case Op::Atan2:  // atan2(y = a, x = b); cln::atan(x, y) is the angle of the point (x, y)
        if (cln::zerop(a) && cln::zerop(b)) return std::nullopt;
        v = cln::atan(as_float(b, f), as_float(a, f));
        break;
      case Op::Exp: v = cln::zerop(a) ? cl_R(1) : cl_R(cln::exp(as_float(a, f))); break;
      case Op::Log:
        if (!cln::plusp(a)) return std::nullopt;
        v = a == 1 ? cl_R(0) : cl_R(cln::ln(as_float(a, f)));
        break;
      case Op::Abs: v = cln::abs(a); break;
      case Op::Sinh: v = cln::zerop(a) ? cl_R(0) : cl_R(cln::sinh(as_float(a, f))); break;
      case Op::Cosh: v = cln::zerop(a) ? cl_R(1) : cl_R(cln::cosh(as_float(a, f))); break;
      case Op::Tanh: v = cln::zerop(a) ? cl_R(0) : cl_R(cln::tanh(as_float(a, f))); break;
      case Op::Pow:
        // a^b = e^(b ln a) for a > 0; 0^b = 0 for b > 0
        if (cln::zerop(a)) {
          if (!cln::plusp(b)) return std::nullopt;
          v = 0;
        } else if (cln::minusp(a)) {
          return std::nullopt;
        } else {
          v = cln::exp(as_float(b, f) * cln::ln(as_float(a, f)));
        }
        break;
      case Op::Integral: break;  // (elementary_only)
    }
    r[i] = v;
  }
  if (out_ < 0) return cl_R(0);
  return r[static_cast<std::size_t>(out_)];
}

std::string Tape::cpp(const std::string& name) const { return source(name, false); }

std::string Tape::cpp_vector(const std::string& name, const std::string& epilogue) const { return source(name, true, epilogue); }

std::string Tape::source(const std::string& name, bool vector, const std::string& epilogue) const {
  elementary_only();
  std::ostringstream os;
  auto r = [](std::int32_t i) { return "r" + std::to_string(i); };
  os << "#include <cmath>\n"
     << "static inline double kinergy_powi(double a, int n) {\n"
     << "  double p = 1, b = n < 0 ? 1 / a : a;\n"
     << "  for (unsigned k = static_cast<unsigned>(n < 0 ? -n : n); k; k >>= 1, b *= b) if (k & 1) p *= b;\n"
     << "  return p;\n}\n"
     << "extern \"C\" " << (vector ? "void " : "double ") << name
     << (vector ? "(const double* x, double* out) {\n" : "(const double* x) {\n");
  for (std::size_t i = 0; i < code_.size(); ++i) {
    const Ins& in = code_[i];
    const std::string a = in.a >= 0 ? r(in.a) : "", b = in.b >= 0 ? r(in.b) : "";
    std::string v;
    char hex[64];
    switch (in.op) {
      case Op::Const:
        // "%a" writes an infinity as "inf" and a NaN as "nan", which C++ does not know: the same
        // doubles from <cmath> (a constant beyond the range of doubles reaches here only so)
        if (std::isnan(in.c)) v = "NAN";
        else if (std::isinf(in.c)) v = in.c > 0 ? "HUGE_VAL" : "(-HUGE_VAL)";
        else {
          std::snprintf(hex, sizeof hex, "%a", in.c);
          v = hex;
        }
        break;
      case Op::Input: v = "x[" + std::to_string(in.a) + "]"; break;
      case Op::Add: v = a + " + " + b; break;
      case Op::Mul: v = a + " * " + b; break;
      case Op::Div: v = a + " / " + b; break;
      case Op::Neg: v = "-" + a; break;
      case Op::Sq: v = a + " * " + a; break;
      case Op::Cube: v = a + " * " + a + " * " + a; break;
      case Op::Powi: v = "kinergy_powi(" + a + ", " + std::to_string(static_cast<int>(in.c)) + ")"; break;
      case Op::Sqrt: v = "std::sqrt(" + a + ")"; break;
      case Op::Rsqrt: v = "1 / std::sqrt(" + a + ")"; break;
      case Op::Pow: v = "std::pow(" + a + ", " + b + ")"; break;
      case Op::Sin: v = "std::sin(" + a + ")"; break;
      case Op::Cos: v = "std::cos(" + a + ")"; break;
      case Op::Tan: v = "std::tan(" + a + ")"; break;
      case Op::Asin: v = "std::asin(" + a + ")"; break;
      case Op::Acos: v = "std::acos(" + a + ")"; break;
      case Op::Atan: v = "std::atan(" + a + ")"; break;
      case Op::Atan2: v = "std::atan2(" + a + ", " + b + ")"; break;
      case Op::Exp: v = "std::exp(" + a + ")"; break;
      case Op::Log: v = "std::log(" + a + ")"; break;
      case Op::Abs: v = "std::fabs(" + a + ")"; break;
      case Op::Sinh: v = "std::sinh(" + a + ")"; break;
      case Op::Cosh: v = "std::cosh(" + a + ")"; break;
      case Op::Tanh: v = "std::tanh(" + a + ")"; break;
      case Op::Integral: break;  // (elementary_only)
    }
    os << "  const double " << r(static_cast<std::int32_t>(i)) << " = " << v << ";\n";
  }
  if (vector) {
    for (std::size_t k = 0; k < outs_.size(); ++k) os << "  out[" << k << "] = " << r(outs_[k]) << ";\n";
    os << epilogue;
  } else
    os << "  return " << (out_ < 0 ? std::string("0") : r(out_)) << ";\n";
  os << "}\n";
  return os.str();
}

numeric exact(double d) { return numeric(cln::cl_N(cln::rational(cln::cl_DF(d)))); }

double to_double(const ex& exact) {
  if (is_a<numeric>(exact) && ex_to<numeric>(exact).is_real()) return ex_to<numeric>(exact).to_double();
  auto v = to_cln(exact, 40);
  return v ? cln::double_approx(*v) : std::numeric_limits<double>::quiet_NaN();
}

double rounding_error(double d, const ex& exact) {
  if (!std::isfinite(d)) return std::numeric_limits<double>::infinity();
  auto v = to_cln(exact, 60);
  if (!v) return std::numeric_limits<double>::infinity();
  cl_R diff = cln::the<cl_R>(numerics::exact(d).to_cl_N()) - *v;  // the double is an exact binary fraction
  // rounded up to stay a bound
  double e = cln::double_approx(cln::abs(diff));
  return e == 0 ? 0 : std::nextafter(e, std::numeric_limits<double>::infinity());
}

std::optional<cl_R> to_cln(const ex& exact, long digits) {
  if (is_a<numeric>(exact)) {
    const numeric& n = ex_to<numeric>(exact);
    if (!n.is_real()) return std::nullopt;
    cln::cl_N c = n.to_cl_N();
    cl_R r = cln::the<cl_R>(c);
    if (is_rational(r)) return r;
    return cl_R(cln::cl_float(r, cln::float_format(digits)));  // a float given as a constant
  }
  if (exact.is_equal(Pi)) return cl_R(cln::pi(cln::float_format(digits)));
  // any other exact form (π/6, √2, e^…): GiNaC's evaluation with guard digits
  const DigitsScope precision(digits + 10);
  std::optional<cl_R> out;
  try {
    ex v = exact.evalf();
    if (is_a<numeric>(v) && ex_to<numeric>(v).is_real())
      out = cl_R(cln::cl_float(cln::the<cl_R>(ex_to<numeric>(v).to_cl_N()), cln::float_format(digits)));
  } catch (const std::exception&) {
    out.reset();
  }
  return out;
}

}  // namespace kinergy::numerics
