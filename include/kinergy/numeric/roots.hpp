/// @file roots.hpp  A root of a function of one variable inside a bracket, in CLN numbers.
#pragma once
#include <functional>
#include <optional>

#include <ginac/ginac.h>

namespace kinergy::numerics {

/// f at x; nothing where f has no real value.
using Scalar = std::function<std::optional<GiNaC::numeric>(const GiNaC::numeric&)>;

/// 10^−n exactly: a tolerance of n decimal digits.
GiNaC::numeric tenth(int n);

/// A root of f in the bracket [a, b] (f(a), f(b) of opposite signs, or one of them zero):
/// regula falsi with the Illinois modification (the end kept twice has its value halved), a
/// bisection step every eighth step and wherever the secant leaves the bracket, until
/// |b − a| ≤ rtol·|x| + atol or f is exactly zero there. The trial points are kept as floats of
/// `digits` decimal digits (rationals would grow with every step). The solver's numeric roots, an
/// extreme's stationary points and a least parameter value all use it.
/// @returns nothing when f has no value at a trial point or the ends do not bracket a root.
std::optional<GiNaC::numeric> bracketed_root(const Scalar& f, GiNaC::numeric a, GiNaC::numeric b, GiNaC::numeric fa,
                                             GiNaC::numeric fb, const GiNaC::numeric& rtol, const GiNaC::numeric& atol,
                                             int digits, int max_steps = 400);

/// The same root, found in two stages where f is dear (a residual that holds a quadrature):
/// first with `coarse` (f at a few digits) to about nine digits, then with f from a narrow
/// bracket about that, whose ends are checked with f to bracket a root; where they do not (the
/// coarse values too coarse there), with f from [a, b] as bracketed_root. Either way the root is
/// f's, to rtol and atol: the coarse stage only saves f's steps.
std::optional<GiNaC::numeric> staged_root(const Scalar& coarse, const Scalar& f, const GiNaC::numeric& a, const GiNaC::numeric& b,
                                          const GiNaC::numeric& fa, const GiNaC::numeric& fb, const GiNaC::numeric& rtol,
                                          const GiNaC::numeric& atol, int digits);

}  // namespace kinergy::numerics
