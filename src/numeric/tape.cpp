#include "kinergy/numeric/tape.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace kinergy::numerics {

using namespace GiNaC;

class TapeBuilder {
public:
  TapeBuilder(Tape& t, const std::vector<ex>& inputs) : t_(t) {
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
  std::map<ex, std::int32_t, ex_is_less> seen_;

  std::int32_t emit(const Tape::Ins& in) {
    t_.code_.push_back(in);
    return static_cast<std::int32_t>(t_.code_.size() - 1);
  }
  std::int32_t constant(double v) { return emit({Tape::Op::Const, -1, -1, v}); }
  std::int32_t unary(Tape::Op op, const ex& a) { return emit({op, node(a), -1, 0}); }

  std::int32_t build(const ex& e) {
    using Op = Tape::Op;
    if (is_a<numeric>(e)) {
      const numeric& n = ex_to<numeric>(e);
      if (!n.is_real()) throw std::invalid_argument("tape: a complex constant " + to_text(e));
      return constant(n.to_double());
    }
    if (is_a<GiNaC::constant>(e)) return constant(ex_to<numeric>(e.evalf()).to_double());
    if (is_a<symbol>(e)) throw std::invalid_argument("tape: '" + to_text(e) + "' is not an input");
    if (is_a<add>(e) || is_a<mul>(e)) {
      // a chain of binary operations over the operands (a numeric coefficient last in GiNaC)
      bool sum = is_a<add>(e);
      std::int32_t acc = node(e.op(0));
      for (std::size_t i = 1; i < e.nops(); ++i) {
        const ex& x = e.op(i);
        // a·x⁻¹ as a division: one rounding instead of two
        if (!sum && is_a<power>(x) && x.op(1).is_equal(-1)) acc = emit({Op::Div, acc, node(x.op(0)), 0});
        else acc = emit({sum ? Op::Add : Op::Mul, acc, node(x), 0});
      }
      return acc;
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

Tape Tape::compile(const ex& e, const std::vector<ex>& inputs) {
  Tape t;
  t.n_inputs_ = inputs.size();
  TapeBuilder b(t, inputs);
  t.out_ = b.node(e);
  t.reg_.resize(t.code_.size());
  return t;
}

double Tape::operator()(const double* x) const {
  double* r = reg_.data();
  for (std::size_t i = 0; i < code_.size(); ++i) {
    const Ins& in = code_[i];
    const double a = in.a >= 0 && in.op != Op::Input ? r[in.a] : 0, b = in.b >= 0 ? r[in.b] : 0;
    switch (in.op) {
      case Op::Const: r[i] = in.c; break;
      case Op::Input: r[i] = x[in.a]; break;
      case Op::Add: r[i] = a + b; break;
      case Op::Mul: r[i] = a * b; break;
      case Op::Div: r[i] = a / b; break;
      case Op::Neg: r[i] = -a; break;
      case Op::Sq: r[i] = a * a; break;
      case Op::Cube: r[i] = a * a * a; break;
      case Op::Powi: r[i] = std::pow(a, in.c); break;
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
    }
  }
  return out_ < 0 ? 0 : r[out_];
}

}  // namespace kinergy::numerics
