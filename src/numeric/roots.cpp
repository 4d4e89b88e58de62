#include "kinergy/numeric/roots.hpp"

#include <algorithm>

#include <cln/rational.h>
#include <cln/real.h>

#include "kinergy/numeric/digits.hpp"

namespace kinergy::numerics {

using GiNaC::numeric;

numeric tenth(int n) { return GiNaC::ex_to<numeric>(GiNaC::pow(numeric(10), -n)); }

std::optional<numeric> bracketed_root(const Scalar& f, numeric a, numeric b, numeric fa, numeric fb, const numeric& rtol,
                                      const numeric& atol, int digits, int max_steps) {
  if (fa.is_zero()) return a;
  if (fb.is_zero()) return b;
  if (fa.is_negative() == fb.is_negative()) return std::nullopt;
  int side = 0;
  numeric c = a;
  for (int it = 0; it < max_steps; ++it) {
    // the secant through (a, fa), (b, fb): c = (a fb − b fa)/(fb − fa)
    c = (a * fb - b * fa) / (fb - fa);
    if (!(c > std::min(a, b) && c < std::max(a, b)) || it % 8 == 7) c = (a + b) / 2;
    auto fc = f(c);
    if (!fc) return std::nullopt;
    if (fc->is_zero() || GiNaC::abs(b - a) <= rtol * GiNaC::abs(c) + atol) return c;
    if (fc->is_negative() == fa.is_negative()) {
      a = c;
      fa = *fc;
      if (side == -1) fb = fb / 2;  // Illinois: the end kept twice has its value halved
      side = -1;
    } else {
      b = c;
      fb = *fc;
      if (side == 1) fa = fa / 2;
      side = 1;
    }
    // keep the working numbers floats of fixed size (rationals would grow with every step)
    const DigitsScope precision(digits);
    c = GiNaC::ex_to<numeric>(c.evalf());
    a = GiNaC::ex_to<numeric>(a.evalf());
    b = GiNaC::ex_to<numeric>(b.evalf());
  }
  return c;
}

std::optional<numeric> staged_root(const Scalar& coarse, const Scalar& f, const numeric& a, const numeric& b, const numeric& fa,
                                   const numeric& fb, const numeric& rtol, const numeric& atol, int digits) {
  // a float's own precision would cap every later step's (CLN takes the lower of two operands'):
  // the narrow bracket's ends are the exact binary fractions the coarse floats are
  auto exact = [](const numeric& x) { return x.is_rational() ? x : numeric(cln::cl_N(cln::rational(cln::the<cln::cl_R>(x.to_cl_N())))); };
  auto ca = coarse(a), cb = coarse(b);
  if (ca && cb)
    if (auto x = bracketed_root(coarse, a, b, *ca, *cb, tenth(9), atol, 20)) {
      // the coarse root is good to about nine digits where the coarse values are good to ten:
      // a bracket of 10^-7 about it, inside [a, b]
      const numeric lo = std::max(std::min(a, b), exact(*x - tenth(7) * (abs(*x) + abs(b - a))));
      const numeric hi = std::min(std::max(a, b), exact(*x + tenth(7) * (abs(*x) + abs(b - a))));
      auto fl = f(lo), fh = f(hi);
      if (fl && fh && (fl->is_zero() || fh->is_zero() || fl->is_negative() != fh->is_negative()))
        return bracketed_root(f, lo, hi, *fl, *fh, rtol, atol, digits);
    }
  return bracketed_root(f, a, b, fa, fb, rtol, atol, digits);
}

}  // namespace kinergy::numerics
