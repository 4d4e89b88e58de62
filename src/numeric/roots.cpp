#include "kinergy/numeric/roots.hpp"

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

}  // namespace kinergy::numerics
