/// @file tape.hpp  A closed form compiled to a tape of operations: every distinct subexpression
/// computed once (sin θ, √(…) shared), no GiNaC on the hot path. The same tape runs in IEEE
/// double (plain, over a batch of points, or with a running error bound) and in CLN at any
/// precision (exact rationals where the operations allow, floats of the asked precision after).
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <cln/real.h>
#include <ginac/ginac.h>

namespace kinergy::numerics {

namespace detail {
struct BallRun;  ///< the tape on Arb balls (ball.cpp)
}

/// A double with a bound on its distance from the exact value of the same form at the same
/// exact inputs: |value − exact| ≤ bound.
struct Bounded {
  double value = 0;
  double bound = 0;
};

/// An output over a box of inputs (Tape::enclose): every exact value of the form in the box
/// lies in [value − bound, value + bound], unless `maybe_undefined`.
struct Enclosed {
  double value = 0;
  double bound = 0;
  bool maybe_undefined = false;
};

/// Thrown by Tape::precise when the working precision cannot cover an argument: a trigonometric
/// function of x needs the digits of x's integer part besides the digits asked (sin(1e80 rad) at 45
/// digits knows nothing of x mod 2π). `digits`: the working precision that would.
struct NeedsPrecision {
  long digits;
};

class Tape {
public:
  /// What a tape takes besides the elementary functions. A work integral held as
  /// integral(f, ξ, a, b) (numeric/evaluate.hpp) compiles only with `Integrals`, and such a tape
  /// runs only on balls (BallEvaluator, root_digits: Arb's rigorous integration); its other
  /// evaluations throw std::logic_error.
  enum class Accept { Elementary, Integrals };

  /// Compile e; `inputs` are the symbols whose values are given at evaluation, in order.
  /// @throws std::invalid_argument naming a node the tape cannot evaluate, or a free symbol
  /// that is not an input.
  static Tape compile(const GiNaC::ex& e, const std::vector<GiNaC::ex>& inputs, Accept accept = Accept::Elementary);
  /// Several outputs from one tape: a subexpression shared between them is computed once
  /// (sin θ for every entry of M(q) and Q). The single-value calls give the first output.
  static Tape compile(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                      Accept accept = Accept::Elementary);

  /// Every output at x: out[k] is output k.
  void eval(const double* x, double* out) const;

  /// Value at x[0..inputs-1] (IEEE double arithmetic; NaN where the form is undefined).
  double operator()(const double* x) const;
  double operator()(const std::vector<double>& x) const { return (*this)(x.data()); }

  /// Values at n points: x holds point i at x[i*inputs() .. i*inputs()+inputs()-1]. Each
  /// instruction runs over the whole batch (the dispatch is paid once per instruction).
  void batch(const double* x, std::size_t n, double* out) const;

  /// Value with a running error bound (Wilkinson's running error analysis, carried through
  /// every instruction): dx[i] bounds the error of input i (0 for an exact input).
  Bounded bounded(const double* x, const double* dx) const;

  /// Every output over a box of inputs: each exact input within radius[i] of mid[i]. out[k]
  /// holds output k's value at mid and a bound on its distance from the exact output at any
  /// point of the box (the running error analysis of bounded(), whose bounds hold for any size
  /// of the inputs' errors), and whether the form may be undefined somewhere in the box.
  void enclose(const double* mid, const double* radius, Enclosed* out) const;

  /// Value in CLN with floats of `digits` decimal digits. With `exact_constants`, the tape's
  /// rational constants stay rationals, and rational inputs with them stay exact through +, −,
  /// ×, ÷ and integer powers (slower: every step reduces a fraction); otherwise the constants
  /// are floats of that precision, as the inputs should then be. @returns nothing where the
  /// form is undefined (division by zero, √ of a negative, log of a non-positive number, …).
  /// @throws NeedsPrecision when `digits` cannot cover an argument.
  std::optional<cln::cl_R> precise(const std::vector<cln::cl_R>& x, long digits, bool exact_constants = true) const;

  /// The tape as straight-line C++: `extern "C" double NAME(const double* x)`, one `const double`
  /// per instruction, constants as exact hexadecimal literals (for NativeFunction).
  std::string cpp(const std::string& name) const;

  /// The same as `extern "C" void NAME(const double* x, double* out)`, writing every output, then
  /// `epilogue` (C++ statements that may read and write `out`: a solve of the outputs' system).
  std::string cpp_vector(const std::string& name, const std::string& epilogue = "") const;

  std::size_t instructions() const { return code_.size(); }  ///< after sharing
  std::size_t outputs() const { return outs_.size(); }
  std::size_t inputs() const { return n_inputs_; }
  /// It holds an integral: it runs only on balls.
  bool has_integrals() const { return !integrands_.empty(); }

private:
  enum class Op : std::uint8_t {
    Const, Input, Add, Mul, Div, Neg, Sq, Cube, Powi, Sqrt, Rsqrt, Pow,
    Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Exp, Log, Abs, Sinh, Cosh, Tanh,
    Integral  ///< ∫_a^b f(ξ) dξ: a, b the ends' registers, c the index of f in integrands_
  };
  struct Ins {
    Op op;
    std::int32_t a = -1, b = -1;  ///< operand registers (Input: the input's index; Const: its exact value's index)
    double c = 0;                 ///< constant, or an integer exponent
  };
  /// Each integral's integrand, a tape of its own: input 0 is ξ, inputs 1… this tape's inputs.
  std::vector<std::shared_ptr<const Tape>> integrands_;
  void elementary_only() const;  ///< @throws std::logic_error when the tape holds an integral
  std::vector<Ins> code_;
  std::vector<GiNaC::ex> exact_;     ///< each constant exactly (a rational, or π, …)
  std::vector<double> const_err_;    ///< |double constant − exact constant|
  std::size_t n_inputs_ = 0;
  std::int32_t out_ = -1;  ///< the register holding the (first) value
  std::vector<std::int32_t> outs_;  ///< the registers holding each output
  std::vector<std::uint32_t> work_;  ///< the instructions that compute (not constants, not inputs)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> inputs_at_;  ///< (register, input index)
  void run(const double* x) const;  ///< every register at x (double)
  void bound_run(const double* x, const double* dx, bool domains) const;  ///< bounded(), enclose()
  static bool outside_domain(const Ins& in, double a, double b, double ea, double eb);
  std::string source(const std::string& name, bool vector, const std::string& epilogue = "") const;
  mutable std::vector<double> reg_;
  mutable std::vector<double> err_;
  mutable std::vector<char> undefined_;  ///< enclose(): the register may be undefined in the box
  mutable std::vector<double> batch_reg_;
  friend class TapeBuilder;
  friend struct detail::BallRun;
};

/// A double's exact value (every finite double is a binary fraction).
GiNaC::numeric exact(double d);
/// The double nearest an exact value (a rational, or an exact form such as π/6).
double to_double(const GiNaC::ex& exact);
/// |d − exact| for the double d of an exact value, as a double (0 when d is exact).
double rounding_error(double d, const GiNaC::ex& exact);
/// An exact value as a CLN real: a rational exactly, anything else (π/6, √2) as a float of
/// `digits` decimal digits. @returns nothing when it is not a real number.
std::optional<cln::cl_R> to_cln(const GiNaC::ex& exact, long digits);

}  // namespace kinergy::numerics
