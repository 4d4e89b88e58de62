/// @file parser.hpp  Expressions of a scene: exact decimals, names, `X@S`, built-in quantities.
///
/// Grammar (precedence low to high):
///   expr    := term (('+' | '-') term)*
///   term    := unary (('*' | '/') unary)*
///   unary   := ('-' | '+') unary | power
///   power   := postfix (('^' | '**') unary)?          right-associative, -x^2 = -(x^2)
///   postfix := primary ('@' STATE)?
///   primary := NUMBER | NAME | NAME '(' args ')' | '(' expr ')'
/// NAME may be dotted (`rod.A`). A NUMBER is read exactly (9.81 → 981/100).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

namespace kinergy::expr {

/// What names mean: given by the model. Every method may throw InputError.
class Context {
public:
  virtual ~Context() = default;
  /// A plain name (parameter, coordinate, rate, t, built-in quantity without arguments).
  virtual GiNaC::ex name(const std::string& id) = 0;
  /// A built-in quantity with arguments (`speed(rod.A)`, `T(rod)`); args are raw texts.
  virtual GiNaC::ex quantity(const std::string& f, const std::vector<std::string>& args) = 0;
  /// `X@S`: X evaluated at state S.
  virtual GiNaC::ex at_state(const GiNaC::ex& e, const std::string& state) = 0;
};

/// The largest exponent an exact power may have: b^n costs time and memory in proportion to n
/// (0.5^1000000000 has a billion-bit denominator, and GiNaC expands (2x)^n into 2^n x^n), and no
/// physical quantity needs more. Refused where it is written, and again where a parameter's value
/// makes it (model/context.hpp).
constexpr long kMaxExponent = 100000;

/// Parse one expression. @throws InputError with the 1-based column of the fault.
GiNaC::ex parse(const std::string& text, Context& ctx);

/// Parse "lhs = rhs" (or a bare expression meaning "= 0"). @returns lhs − rhs.
GiNaC::ex parse_equation(const std::string& text, Context& ctx);

/// True when `name` is a mathematical function the parser knows (sin, cos, sqrt, …).
bool is_math_function(const std::string& name);

}  // namespace kinergy::expr
