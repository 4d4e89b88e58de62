/// @file tape.hpp  A closed form compiled to a tape of double operations: every distinct
/// subexpression computed once (sin θ, √(…) shared), no GiNaC on the hot path.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace kinergy::numerics {

class Tape {
public:
  /// Compile e; `inputs` are the symbols whose values are given at evaluation, in order.
  /// @throws std::invalid_argument naming a node the tape cannot evaluate, or a free symbol
  /// that is not an input.
  static Tape compile(const GiNaC::ex& e, const std::vector<GiNaC::ex>& inputs);

  /// Value at x[0..inputs-1] (IEEE double arithmetic; NaN where the form is undefined).
  double operator()(const double* x) const;
  double operator()(const std::vector<double>& x) const { return (*this)(x.data()); }

  std::size_t instructions() const { return code_.size(); }  ///< after sharing
  std::size_t inputs() const { return n_inputs_; }

private:
  enum class Op : std::uint8_t {
    Const, Input, Add, Mul, Div, Neg, Sq, Cube, Powi, Sqrt, Rsqrt, Pow,
    Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Exp, Log, Abs, Sinh, Cosh, Tanh
  };
  struct Ins {
    Op op;
    std::int32_t a = -1, b = -1;  ///< operand registers
    double c = 0;                 ///< constant, or an integer exponent
  };
  std::vector<Ins> code_;
  std::size_t n_inputs_ = 0;
  std::int32_t out_ = -1;  ///< the register holding the value
  mutable std::vector<double> reg_;
  friend class TapeBuilder;
};

}  // namespace kinergy::numerics
