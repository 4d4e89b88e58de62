// Effects switched on or off at states (issue 13, part 2): over an analysis an effect acts
// throughout, not at all, or in part — then an energy analysis takes its work over its own part,
// a momentum analysis is refused (split it), and the simulator runs each analysis with the
// effects that act over it. Expected forms by hand.
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/simulate/check.hpp"

using GiNaC::ex;

using kt::derivation;
using kt::edit;
using kt::solve_text;

namespace {

// a wheel (I = m k^2) on an axle from rest; a couple M switched by ON_OFF, a brake couple Mb
// switched by BRAKE; states 1 (rest, phi = 0), 2 (phi = a), 3 (phi = a + b); the forms are
// compared symbolically (the values only keep the kinetic energy positive)
const std::string wheel = R"Y(title: a switched wheel
parameters:
  m: 50 kg
  k: 0.3 m
  M: 30 N*m
  Mb: 5 N*m
  a: 10 rev
  b: 4 rev
points:
  O: [0, 0]
coordinates:
  phi: rad
bodies:
  wheel: {mass: m, inertia: {gyration: k}, position: [0, 0], angle: phi}
effects:
  axle: {pin: [O, wheel]}
  motor: {couple: wheel, M: MOTOR}
  brake: {couple: wheel, M: BRAKE}
states:
  1: {phi: 0, phi_dot: 0}
  2: {phi: a}
  3: {phi: a + b}
analyses:
  - energy: {from: 1, to: 3}
find:
  w3sq: phi_dot@3^2
)Y";

std::string with(const std::string& motor, const std::string& brake) {
  std::string s = wheel;
  s.replace(s.find("MOTOR"), 5, motor);
  s.replace(s.find("BRAKE"), 5, brake);
  return s;
}

}  // namespace

TEST_CASE("an energy analysis takes a switched effect's work over the part where it acts", "[energy][switching]") {
  // I w3^2/2 = work of the motor + work of the brake over their parts of [0, a + b]
  auto check = [&](const std::string& motor, const std::string& brake, const std::function<ex(ex, ex, ex, ex)>& U) {
    auto s = solve_text(with(motor, brake));
    ex m = kt::param(s.model, "m"), k = kt::param(s.model, "k"), M = kt::param(s.model, "M"), Mb = kt::param(s.model, "Mb");
    ex a = kt::param(s.model, "a"), b = kt::param(s.model, "b");
    CHECK(kt::symbolically_zero(kt::result(s, "w3sq").closed - 2 * U(M, Mb, a, b) / (m * k * k)));
  };
  SECTION("throughout") { check("M", "-Mb", [](ex M, ex Mb, ex a, ex b) { return (M - Mb) * (a + b); }); }
  SECTION("the motor disconnected at 2") { check("M, off: 2", "-Mb", [](ex M, ex Mb, ex a, ex b) { return M * a - Mb * (a + b); }); }
  SECTION("the brake applied from 2 on") { check("M", "-Mb, on: 2", [](ex M, ex Mb, ex a, ex b) { return M * (a + b) - Mb * b; }); }
  SECTION("both: motor to 2, brake from 2") {
    check("M, off: 2", "-Mb, on: 2", [](ex M, ex Mb, ex a, ex b) { return M * a - Mb * b; });
  }
  SECTION("switched off at the first state: it never acts") {
    check("M", "-Mb, off: 1", [](ex M, ex, ex a, ex b) { return M * (a + b); });
  }
}

TEST_CASE("the simulator runs each analysis with the effects that act over it", "[energy][switching][simulate]") {
  auto s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/flywheel_motor_then_coast.yaml");
  auto legs = kinergy::simulate::legs(s);
  REQUIRE(legs.size() == 3);
  kinergy::simulate::Options o;
  // 1 -> 2 with the motor, 2 -> 3 without it: both agree with the closed form
  for (int i : {0, 1}) {
    REQUIRE(legs[static_cast<std::size_t>(i)].why_not.empty());
    auto c = kinergy::simulate::check_leg(s, legs[static_cast<std::size_t>(i)], o, 1e-8);
    INFO(c.worst_what);
    CHECK(c.ok);
  }
  // 1 -> 3 has the switch inside: not one run
  CHECK(legs[2].why_not.find("effect 'motor' is switched inside it (at state '2')") != std::string::npos);
  // a run from one state cannot follow the switch: refused
  int st = 0;
  std::string out = kt::run_cli("simulate derivations/energy/flywheel_motor_then_coast.yaml --until 10", st);
  INFO(out);
  CHECK(st == 1);
  CHECK(out.find("effect 'motor' is switched on or off at a state, which a run from one state does not follow") != std::string::npos);
}
