/// @file simplify.hpp  Trigonometric simplification without normal() on big trig expressions.
#pragma once
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include <ginac/ginac.h>

namespace kinergy::model {

/// Expand and remove sin²+cos² pairs: cos(a)^n → cos(a)^(n mod 2)·(1 − sin(a)²)^(n div 2),
/// and the same with sin and cos swapped; returns the shorter result.
GiNaC::ex trig_simplify(const GiNaC::ex& e);

/// sin(x + nπ/2) → ±sin x or ±cos x (likewise cos), sin(−x) → −sin x, cos(−x) → cos x.
GiNaC::ex unshift_trig(const GiNaC::ex& e);

/// The sign a factor keeps (+1, −1; 0 when it is not fixed), for root_simplify.
using SignOf = std::function<int(const GiNaC::ex&)>;

/// Take squares of positive factors out of square roots: √(r²·X) → r·√X; with `sign`, also the
/// even powers of factors whose sign it fixes: √(sin(β)²·X) → sin(β)·√X where sin β > 0.
GiNaC::ex root_simplify(const GiNaC::ex& e, const SignOf& sign = nullptr);

/// Collect a quadratic form in `rates` and trig-simplify each coefficient.
GiNaC::ex collect_simplify(const GiNaC::ex& e, const GiNaC::lst& rates);

/// Antiderivative of f in s when an elementary rule applies (sums, constant factors,
/// powers and sin/cos/exp/sinh/cosh of a linear argument); nothing otherwise.
std::optional<GiNaC::ex> antiderivative(const GiNaC::ex& f, const GiNaC::symbol& s);

/// A closed form made tidy: trigonometric simplification, then the rational normal form when
/// the expression is small enough for that to stay cheap (and it does not grow).
GiNaC::ex tidy(const GiNaC::ex& e);
/// tidy(), and for a result that stays large (over 1500 nodes), normalised once with its functions
/// and roots as symbols, kept when shorter.
GiNaC::ex tidy_result(const GiNaC::ex& e);

/// factor() of any expression: non-polynomial parts (functions, roots) stand in as symbols.
GiNaC::ex factor_any(const GiNaC::ex& e);

/// Numerator and denominator factored, when that gives a shorter form.
GiNaC::ex factored(const GiNaC::ex& e);

/// tidy() and factored() applied inside every function's arguments (acos(…), sin(…)).
GiNaC::ex tidy_function_arguments(const GiNaC::ex& e);

/// The factors of a product (the expression itself when it is not a product).
GiNaC::exvector factors_of(const GiNaC::ex& e);

/// GiNaC's default text of an expression (for messages).
std::string text(const GiNaC::ex& e);

/// What GiNaC's complaint about a value means, in words ("a division by zero", "log(0)", …).
std::string math_fault(const std::exception& err);

/// Number of nodes in an expression tree (a size measure), the same for a form and its twin
/// with sums written the other way round (a −1 coefficient is not counted).
std::size_t ex_size(const GiNaC::ex& e);

}  // namespace kinergy::model
