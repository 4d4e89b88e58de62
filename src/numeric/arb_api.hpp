/// @file arb_api.hpp  (private) The ball arithmetic module's interface: a tape in plain numbers
/// and the answers in integers' digits, so that the module (src/numeric/arb_module.cpp, the only
/// code that links Arb and FLINT) is loaded with dlopen when `--digits` first needs it. Loading
/// Arb, FLINT and NTL costs every process about 5 ms of dynamic linking: a process that never
/// asks for proven digits does not pay it.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace kinergy::numerics::arbapi {

/// A constant of a tape: a rational p/q (decimal digits), or π, Euler's γ, Catalan's G; or an
/// interval [p/q, p2/q2] (an input known only to lie there: a root proven to some digits).
struct Const {
  enum Kind : std::uint8_t { Rational, Pi, Euler, Catalan, Interval } kind = Rational;
  std::string num = "0", den = "1";
  std::string num2 = "0", den2 = "1";  ///< Interval: the upper end
};

/// One instruction, as Tape keeps it (op: Tape::Op's value; a, b: registers, or for Input the
/// input's index and for Const the constant's index; c: an integer exponent).
struct Ins {
  std::uint8_t op;
  std::int32_t a, b;
  double c;
};

/// A tape in plain numbers. An Integral instruction (op 25: a, b the ends' registers, c an index
/// into `integrands`) takes ∫_a^b f(ξ) dξ of a program f whose input 0 is ξ and whose inputs 1…
/// are this program's inputs.
struct Program {
  std::vector<Ins> code;
  std::vector<Const> consts;
  std::vector<std::int32_t> outs;
  std::size_t inputs = 0;
  std::vector<Program> integrands;
};

/// An enclosure [lo, hi] = [a · 2^e, b · 2^e] (a, b: signed hexadecimal digits; or, when `small`,
/// |a| and |b| as two 64-bit limbs each, low limb first, with their signs: what a working
/// precision of a limb or two gives, without text).
struct Interval {
  std::string a = "0", b = "0";
  long e = 0;
  bool small = false;
  std::uint64_t a_limbs[2] = {0, 0}, b_limbs[2] = {0, 0};
  bool a_negative = false, b_negative = false;
};

/// What a proof gives back. kind: 0 exact (the point `at`), 1 digits (every value of `at` rounds
/// to the n digits asked), 2 unsigned (`at` keeps holding 0), 3 undefined (proven), 4 not proven
/// (`error` says why; for a root: no precision up to the limit proved it).
struct Answer {
  int kind = 4;
  Interval at;
  long bits = 0;
  std::string error;
};

/// The module's functions (kinergy_arb_api() returns them).
struct Api {
  int version;
  /// A tape bound to its inputs (each input a program without inputs of its own: a rational,
  /// π/6, √2, …). Returns a handle for the calls below.
  void* (*create)(const Program& tape, const std::vector<Program>& inputs);
  void (*destroy)(void* handle);
  /// n digits of output 0, the precision doubled from what n needs up to max_bits.
  Answer (*digits)(void* handle, int n, long max_bits);
  /// A root of output 0 of `r` (input 0 its unknown) near `start`, proven to n digits with `dr`
  /// (r's derivative) steering Newton's steps; inside [lo, hi] when `bracket`.
  Answer (*root)(const Program& r, const Program& dr, const std::vector<Program>& inputs, const Const& start,
                 const Const& lo, const Const& hi, bool bracket, int n, long max_bits);
};

constexpr int kVersion = 3;

/// Bits for n decimal digits (n·log₂10), rounded up: the module and numeric/ball.cpp alike.
inline long bits_for(int n) { return static_cast<long>(std::ceil(n * 3.3219280948873623)); }

/// The most bits an evaluation with an integral in it goes to for n digits: Arb's integration
/// costs more and more as the precision rises, and an integral it cannot settle at several times
/// the bits n digits need will not settle later.
inline long integral_bits(int n) { return std::max<long>(1024, 4 * bits_for(n)); }

}  // namespace kinergy::numerics::arbapi

extern "C" {
/// The entry point of the module (looked up with dlsym).
const kinergy::numerics::arbapi::Api* kinergy_arb_api();
}
