// Work integrals with no elementary antiderivative, taken numerically (issue 13, part 3):
// tanh–sinh quadrature against mpmath's quad at 50 digits (the reference numbers were printed by
//   python3 -c "from mpmath import *; mp.dps=50; print(quad(lambda x: exp(-x**2), [0,1]))"
// and the like, kept here), and a scene whose work is an error function (by mpmath).
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/problem.hpp"

using namespace GiNaC;

namespace {
bool agree(const numeric& got, const char* ref, int digits) {
  const long saved = Digits;
  Digits = 70;  // the reference as written, not rounded to the default 17 digits
  numeric r = ex_to<numeric>(parser()(ref).evalf());
  bool ok = abs(got - r) <= abs(r) * pow(numeric(10), -digits);
  Digits = saved;
  return ok;
}
numeric dec(const char* s) { return ex_to<numeric>(parser()(s)); }
}  // namespace

TEST_CASE("numeric integrals to 40 digits against mpmath", "[numeric][integrate]") {
  symbol x("x");
  auto I = kinergy::numerics::integrate(exp(-pow(x, 2)), x, 0, 1, {}, 40);
  REQUIRE(I);
  CHECK(agree(*I, "0.74682413281242702539946743613185300535449968681261", 40));
  // sin(x)/x: an integrand that is 0/0 at an end (the nodes never reach the end itself)
  // (the end to 60 digits: the quadrature is as precise as its ends)
  const long saved = Digits;
  Digits = 60;
  const numeric pi60 = ex_to<numeric>(Pi.evalf());
  Digits = saved;
  I = kinergy::numerics::integrate(sin(x) / x, x, 0, pi60, {}, 30);
  REQUIRE(I);
  CHECK(agree(*I, "1.8519370519824661703610533701579913633458097289812", 25));
  // a parameter from `values`
  symbol c("c");
  I = kinergy::numerics::integrate(c / (1 + pow(x, 4)), x, 0, 2, {{c, 3}}, 40);
  REQUIRE(I);
  CHECK(agree(*I / 3, "1.070127689136688147727121362581770723727754630116", 40));
  // backwards: the negative
  I = kinergy::numerics::integrate(exp(-pow(x, 2)), x, 1, 0, {}, 40);
  REQUIRE(I);
  CHECK(agree(-*I, "0.74682413281242702539946743613185300535449968681261", 40));
  // no real value inside: nothing (not a wrong number)
  CHECK(!kinergy::numerics::integrate(log(x), x, dec("-1"), 1, {}, 20));
  // a symbol without a value: nothing
  symbol d("d");
  CHECK(!kinergy::numerics::integrate(d * x, x, 0, 1, {}, 20));
}

TEST_CASE("a few digits of an integral are taken in doubles, to those digits, against mpmath", "[numeric][integrate]") {
  // (digits <= 10: the signs a numeric root's scan asks at 100 points; the integrand compiled once)
  symbol x("x");
  for (int digits : {6, 10}) {
    INFO(digits);
    auto I = kinergy::numerics::integrate(exp(-pow(x, 2)), x, 0, 1, {}, digits);
    REQUIRE(I);
    CHECK(agree(*I, "0.74682413281242702539946743613185300535449968681261", 12));
    I = kinergy::numerics::integrate(sin(x) / x, x, 0, dec("3.14159265358979323846264338327950288419716939937510"), {}, digits);
    REQUIRE(I);
    CHECK(agree(*I, "1.8519370519824661703610533701579913633458097289812", 12));
    I = kinergy::numerics::integrate(exp(-pow(x, 2)), x, 1, 0, {}, digits);
    REQUIRE(I);
    CHECK(agree(-*I, "0.74682413281242702539946743613185300535449968681261", 12));
    // no real value inside, a symbol without a value: nothing, as at any precision
    CHECK(!kinergy::numerics::integrate(log(x), x, dec("-1"), 1, {}, digits));
    symbol d("d");
    CHECK(!kinergy::numerics::integrate(d * x, x, 0, 1, {}, digits));
  }
}

TEST_CASE("a work with no closed form is taken numerically, or refused naming what is missing", "[numeric][integrate][work]") {
  auto text = kt::read_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/wheel_cam_couple_numeric.yaml");
  auto s = kinergy::solve_scene(kinergy::scene::load_string(text, "cam.yaml"));
  const kinergy::Result& r = s.results.at(0);
  // held as the integral (as erf would be): a closed form in the parameters, its value by quadrature
  CHECK(r.closed_form);
  bool held = false;
  for (auto it = r.closed.preorder_begin(); it != r.closed.preorder_end(); ++it) held = held || kinergy::numerics::is_integral(*it);
  CHECK(held);
  auto v = r.value(s.model.numeric_environment(), 30);
  REQUIRE(v);
  // by mpmath: sqrt(2 M0 phi0 (sqrt(pi)/2) erf(phi2/phi0)/(m k^2))
  CHECK(agree(*v, "6.709051266990077198931405617897785", 29));
  // the end is unknown: a braking cam M = -M0 exp(-(phi/phi0)^2) stops the wheel from w0 = 6 rad/s where its
  // work reaches -(1/2) m k^2 w0^2 = -22.5 J: at phi0 erfinv(22.5/(M0 phi0 sqrt(pi)/2)), by mpmath
  // 0.7144304417732017885921246356422574 (the derivation wheel_cam_couple_angle reaches 6 rad/s there)
  auto brake = kt::edit(kt::edit(kt::edit(text, "  2: {phi: phi2}\n", "  2: {phi_dot: 0}\n"), "M: M0*exp(", "M: -M0*exp("),
                        "  1: {phi: 0, phi_dot: 0}", "  1: {phi: 0, phi_dot: w0}");
  brake = kt::edit(brake.substr(0, brake.find("find:\n")) + "find:\n  phi2s: phi@2\n", "  phi2: 1.5 rad\n", "  w0: 6 rad/s\n");
  auto b = kinergy::solve_scene(kinergy::scene::load_string(brake, "cam.yaml"));
  CHECK(!b.results.at(0).closed_form);
  CHECK(agree(*b.results.at(0).value(b.model.numeric_environment(), 30), "0.7144304417732017885921246356422574", 30));
  // from 8 rad/s (40 J) the brake's whole work, M0 phi0 sqrt(pi)/2 = 28.36 J, does not stop it: no root
  REQUIRE_THROWS_WITH(kinergy::solve_scene(kinergy::scene::load_string(kt::edit(brake, "w0: 6 rad/s", "w0: 8 rad/s"), "cam.yaml")),
                      Catch::Contains("has no closed form for phi@2 and no root was found"));
}
