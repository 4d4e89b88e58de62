// Effects switched on or off at states (issue 13, part 2): over an analysis an effect acts
// throughout, not at all, or in part — then an energy analysis takes its work over its own part,
// a momentum analysis is refused (split it), and the simulator runs each analysis with the
// effects that act over it. Expected forms by hand.
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/confirm/check.hpp"

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
  // a run from state 1 follows the switch: the motor drives until phi = n1 (state 2), then the wheel coasts
  // to rest. By hand: alpha = (M - Mf)/(m k^2) = 25/4.5 rad/s^2, phi = 20 pi at t = sqrt(2 (20 pi)/alpha) =
  // sqrt(36 pi/5) = 4.7559928 s; at rest phi = n1 M/Mf = 60 rev = 120 pi rad, U_motor = M n1 = 600 pi J.
  int st = 0;
  std::string out = kt::run_cli("simulate derivations/energy/flywheel_motor_then_coast.yaml --until 100 --no-native", st);
  INFO(out);
  CHECK(st == 0);
  CHECK(out.find("t = 4.7559928 s: state '2' reached: effect 'motor' switched off") != std::string::npos);
  const auto s0 = kinergy::simulate::state_values(s, 0);
  o.native = false;
  auto r = kinergy::simulate::run_following(s.model, s.branch.sol, kinergy::simulate::simulation_values(s), 0, s0, 100, o, true);
  CHECK(std::fabs(r.end.q[0] - 120 * M_PI) < 1e-7);
  CHECK(r.end.qd[0] == 0);
  REQUIRE(r.work.size() == 2);
  CHECK(std::fabs(r.work[0].second - 600 * M_PI) < 1e-7);
  CHECK(std::fabs(r.drift) < 1e-12);
}

TEST_CASE("a free run switches a brake on at a given time", "[switching][simulate]") {
  // a wheel (m k^2 = 2 kg m^2) spinning at 10 rad/s; a brake couple of 4 N m is applied at t = 3 s (state 2).
  // By hand: phi(3) = 30 rad; then alpha = -2 rad/s^2, rest after 5 s more, at phi = 30 + 10*5/2 = 55 rad.
  const std::string scene =
      "title: brake\nparameters:\n  m: 2 kg\n  k: 1 m\n  w0: 10 rad/s\n  Mb: 4 N*m\npoints:\n  O: [0, 0]\n"
      "coordinates:\n  phi: rad\nbodies:\n  wheel: {mass: m, inertia: {gyration: k}, position: [0, 0], angle: phi}\n"
      "effects:\n  axle: {pin: [O, wheel]}\n  brake: {friction_couple: wheel, M: Mb, direction: positive, on: 2}\n"
      "states:\n  1: {t: 0, phi: 0, phi_dot: w0}\n  2: {t: 3 s}\n  3: {phi_dot: 0}\n"
      "analyses:\n  - momentum: {from: 1, to: 2}\n  - energy: {from: 2, to: 3}\n";
  auto s = kt::solve_text(scene);
  kinergy::simulate::Options o;
  o.native = false;
  auto r = kinergy::simulate::run_following(s.model, s.branch.sol, kinergy::simulate::simulation_values(s), 0,
                                            kinergy::simulate::state_values(s, 0), 20, o, true);
  CHECK(std::fabs(r.end.q[0] - 55) < 1e-8);
  REQUIRE(!r.log.empty());
  CHECK(r.log.front() == "t = 3 s: state '2' reached: effect 'brake' switched on");
  // a switching state that nothing places on the way is refused, naming it
  auto m = kt::model_of(kt::edit(scene.substr(0, scene.find("analyses:")), "  2: {t: 3 s}", "  2: {phi_dot: w0}"));
  const auto params = m.parameter_values();
  CHECK_THROWS_WITH(kinergy::simulate::run_following(m, {}, params, 0, kinergy::simulate::state_values(m, {}, params, 0), 20, o, true),
                    "<test>:18:3: effect 'brake' is switched at state '2', which a run cannot find: nothing given at state '2' places it "
                    "on the way (no time, and no coordinate or rate that changes) \u2014 give the time or a coordinate at state '2'");
}
