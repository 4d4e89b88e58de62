/// @file stable.hpp  Forms that do not cancel in floating point.
#pragma once
#include <ginac/ginac.h>

namespace kinergy::numerics {

/// e with the patterns that lose digits to cancellation rewritten into products:
///   A − A cos x        → 2A sin²(x/2)            A + A cos x  → 2A cos²(x/2)
///   A − A sin x        → 2A sin²(π/4 − x/2)      A + A sin x  → 2A cos²(π/4 − x/2)
///   A cos y − A cos x  → −2A sin((y+x)/2) sin((y−x)/2)
///   A sin y − A sin x  → 2A cos((y+x)/2) sin((y−x)/2)
///   A √a − A √b        → A (a − b)/(√a + √b)     (a − b expanded: equal parts cancel exactly)
///   A p² − A q²        → A (p − q)(p + q)        (1 − e² → (1 − e)(1 + e))
/// Equal as functions (identities); which of e and the rewrite to evaluate is decided by an
/// error estimate at the values (see Evaluator).
GiNaC::ex stable_form(const GiNaC::ex& e);

}  // namespace kinergy::numerics
