// A root in a bracket: bracketed_root, and staged_root (a cheap first stage at a few digits,
// then the dear function from a narrow bracket). The reference roots, cos x = x (the Dottie
// number) and x² = 2, were printed by mpmath at 110 digits:
//   python3 -c "from mpmath import *; mp.dps=110; print(findroot(lambda x: cos(x)-x, 0.74)); print(sqrt(2))"
#include <catch2/catch.hpp>

#include "kinergy/numeric/digits.hpp"
#include "kinergy/numeric/roots.hpp"

using namespace GiNaC;
using kinergy::numerics::tenth;

namespace {

const char* kDottie = "0.73908513321516064165531208767387340401341175890075746496568063577328465488354759459937610693176653";

/// cos x − x at `digits` digits, counting the calls.
kinergy::numerics::Scalar dottie(int digits, int& calls) {
  return [digits, &calls](const numeric& x) -> std::optional<numeric> {
    ++calls;
    const kinergy::numerics::DigitsScope precision(digits);
    return ex_to<numeric>((cos(ex(x)) - x).evalf());
  };
}

bool agrees(const numeric& x, const char* ref, int digits) {
  const kinergy::numerics::DigitsScope precision(110);
  const numeric r = ex_to<numeric>(parser()(ref).evalf());
  return abs(x - r) <= tenth(digits) * abs(r);
}

}  // namespace

TEST_CASE("staged_root: the dear function's root to its tolerance, in fewer of its calls", "[numeric][roots]") {
  int coarse_calls = 0, fine_calls = 0, plain_calls = 0;
  const auto coarse = dottie(10, coarse_calls), fine = dottie(60, fine_calls), plain = dottie(60, plain_calls);
  const numeric a = 0, b = 1, fa = *fine(a), fb = *fine(b);
  fine_calls = 0;
  auto staged = kinergy::numerics::staged_root(coarse, fine, a, b, fa, fb, tenth(50), tenth(300), 60);
  auto direct = kinergy::numerics::bracketed_root(plain, a, b, fa, fb, tenth(50), tenth(300), 60);
  REQUIRE(staged);
  REQUIRE(direct);
  CHECK(agrees(*staged, kDottie, 49));
  CHECK(agrees(*direct, kDottie, 49));
  CHECK(fine_calls < plain_calls);
}

TEST_CASE("staged_root: a coarse stage that misleads costs calls, never the root", "[numeric][roots]") {
  // the coarse function's root is 0.75, off the true one by 0.011: the narrow bracket about it
  // does not hold the true root, and the fine stage starts again from [0, 1]
  int fine_calls = 0;
  const auto fine = dottie(60, fine_calls);
  const kinergy::numerics::Scalar misleading = [](const numeric& x) -> std::optional<numeric> { return numeric(3, 4) - x; };
  auto staged = kinergy::numerics::staged_root(misleading, fine, 0, 1, *fine(0), *fine(1), tenth(50), tenth(300), 60);
  REQUIRE(staged);
  CHECK(agrees(*staged, kDottie, 49));
  // a coarse function with no value at the ends: the fine stage alone
  const kinergy::numerics::Scalar undefined = [](const numeric&) -> std::optional<numeric> { return std::nullopt; };
  auto alone = kinergy::numerics::staged_root(undefined, fine, 0, 1, *fine(0), *fine(1), tenth(50), tenth(300), 60);
  REQUIRE(alone);
  CHECK(agrees(*alone, kDottie, 49));
}

TEST_CASE("staged_root: the root keeps the fine stage's digits (a float bracket end does not cap them)", "[numeric][roots]") {
  // x² − 2 on [1, 2]: √2 to 80 digits, though the coarse stage's floats have 20
  const kinergy::numerics::Scalar coarse = [](const numeric& x) -> std::optional<numeric> {
    const kinergy::numerics::DigitsScope precision(10);
    return ex_to<numeric>((x * x - 2).evalf());
  };
  const kinergy::numerics::Scalar fine = [](const numeric& x) -> std::optional<numeric> {
    const kinergy::numerics::DigitsScope precision(90);
    return ex_to<numeric>((x * x - 2).evalf());
  };
  auto r = kinergy::numerics::staged_root(coarse, fine, 1, 2, -1, 2, tenth(80), tenth(300), 90);
  REQUIRE(r);
  CHECK(agrees(*r, "1.4142135623730950488016887242096980785696718753769480731766797379907324784621070388503875343276415727", 79));
  // no bracket: nothing
  CHECK_FALSE(kinergy::numerics::staged_root(coarse, fine, 2, 3, 2, 7, tenth(80), tenth(300), 90));
}
