// A body that leaves a surface that can only push goes on free of it (issue 42): the simulator
// integrates the scene with a gap coordinate for the surface, closed while the surface pushes and
// open after. The instants, angles and states after the release asserted here are derived
// independently of kinergy by tests/contact/sympy_flight.py (energy and Newton–Euler up to the
// release, a projectile or Lagrange's equations in sympy, integrated by mpmath, after it).
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace {

namespace sim = kinergy::simulate;

std::string contact(const std::string& name) { return kt::read_file(std::filesystem::path(KINERGY_SOURCE_DIR) / "tests/data/contact" / name); }

/// The coordinate named `name` of the run's model, its index.
std::size_t coordinate(const sim::Run& r, const std::string& name) {
  REQUIRE(r.model);
  for (std::size_t i = 0; i < r.model->coords.size(); ++i)
    if (r.model->coords[i].name == name) return i;
  FAIL("no coordinate " << name);
  return 0;
}

sim::Run run(const std::string& text, double until) {
  const kinergy::model::Model m = kt::model_of(text);
  sim::Options o;
  o.native = false;
  o.record = false;
  sim::Simulator s(m, m.parameter_values(), o);
  return s.run(sim::state_values(m, {}, m.parameter_values(), 0), {until, std::nullopt, true});
}

}  // namespace

TEST_CASE("flight: the ball leaves the dome where its push falls to zero and falls free of it", "[simulate][release]") {
  // released at rest at 0.2 rad: leaves at t = 0.843453923349726 s, 49.2032458521461 deg; 0.25 s later
  // at polar angle 1.51806416518665 rad, 0.144318779909857 m off the dome (sympy_flight.py, case 1)
  const sim::Run r = run(contact("dome_flight.yaml"), 0.843453923349726 + 0.25);
  REQUIRE(r.switches.size() == 1);
  CHECK(r.switches[0].kind == "leaves");
  CHECK(r.switches[0].effect == "dome");
  CHECK(std::fabs(r.switches[0].t - 0.843453923349726) < 1e-8);
  CHECK_THAT(r.switches[0].text, Catch::Contains("ball leaves 'dome' at theta = 0.858759 rad (49.2032 deg)"));
  CHECK(r.model->coords.size() == 2);
  CHECK(std::fabs(r.end.q[0] - 1.51806416518665) < 1e-8);
  CHECK(std::fabs(r.end.q[coordinate(r, "dome_gap")] - 0.144318779909857) < 1e-8);
  CHECK(std::fabs(r.drift) < 1e-9);  // the dome does no work, on it or off it
}

TEST_CASE("flight: the ladder goes on with its top free of the wall, its foot on the floor", "[simulate][release]") {
  // from theta0 = 20 deg with vA0 = 0.5 m/s: B leaves the wall at t = 0.635987033526879 s, 51.0531254544615
  // deg; 0.2 s later theta = 1.31472706779781 rad, theta_dot = 2.47935197384411 rad/s, B 0.0466367038593675 m
  // from the wall (sympy_flight.py, case 2)
  const sim::Run r = run(kt::derivation("kinetics/rod_leaves_wall.yaml"), 0.635987033526879 + 0.2);
  REQUIRE(r.switches.size() == 1);
  CHECK(r.switches[0].effect == "wall");
  CHECK(std::fabs(r.switches[0].t - 0.635987033526879) < 1e-8);
  CHECK(std::fabs(r.end.q[0] - 1.31472706779781) < 1e-8);
  CHECK(std::fabs(r.end.qd[0] - 2.47935197384411) < 1e-8);
  CHECK(std::fabs(r.end.q[coordinate(r, "wall_gap")] - 0.0466367038593675) < 1e-8);
  CHECK(std::fabs(r.end.q[coordinate(r, "floor_gap")]) < 1e-12);  // the floor still pushes
}

TEST_CASE("flight: a ball lifted off its floor leaves it at once, strikes it again and rebounds with the track's e", "[simulate][release]") {
  // leaves at t = 0; strikes at 0.261803398874989 s at v_n = -1.09679134296365 m/s, again at
  // 0.373606797749979 s (sympy_flight.py, case 5)
  const sim::Run r = run(contact("ball_thrown_off_floor.yaml"), 0.3);
  REQUIRE(r.switches.size() == 2);
  CHECK(r.switches[0].kind == "leaves");
  CHECK(r.switches[0].t == 0);
  CHECK(r.switches[1].kind == "strikes");
  REQUIRE(r.impacts.size() == 1);
  CHECK(std::fabs(r.impacts[0].t - 0.261803398874989) < 1e-9);
  CHECK(std::fabs(r.impacts[0].vn_before[0] - -1.09679134296365) < 1e-8);
  CHECK(std::fabs(r.impacts[0].vn_after[0] - 1.09679134296365 / 2) < 1e-8);
  const sim::Run r2 = run(contact("ball_thrown_off_floor.yaml"), 0.38);
  REQUIRE(r2.impacts.size() == 2);
  CHECK(std::fabs(r2.impacts[1].t - 0.373606797749979) < 1e-8);  // (the event located to the integration's tolerance)
}

TEST_CASE("flight: a disk set sliding without spin slides until its slip stops, then rolls", "[simulate][release][friction]") {
  // rolls from t = 0.509683995922528 s, at x = 2.25484199796126 m at t = 1 s (sympy_flight.py, case 6)
  const sim::Run r = run(contact("disk_thrown_sliding.yaml"), 1.0);
  REQUIRE(r.switches.size() == 1);
  CHECK(r.switches[0].kind == "sticks");
  CHECK(std::fabs(r.switches[0].t - 0.509683995922528) < 1e-9);
  CHECK(std::fabs(r.end.q[0] - 2.25484199796126) < 1e-9);
  CHECK(std::fabs(r.end.qd[0] - 2) < 1e-9);
  CHECK(std::fabs(r.drift) < 1e-9);
}

TEST_CASE("flight: a body that strikes its surface again needs the track's e", "[simulate][release][errors]") {
  // the ball lifted off its floor comes down on it: without e the run says so
  const std::string ball = kt::edit(contact("ball_thrown_off_floor.yaml"), "pushes: up, e: 0.5}", "pushes: up}");
  REQUIRE_THROWS_WITH(run(ball, 2.0), Catch::Contains("ball strikes 'floor' again at t = 0.261803 s") && Catch::Contains("does not say how it rebounds"));
  // with e = 0 it lands and slides on
  const sim::Run r = run(kt::edit(ball, "pushes: up}", "pushes: up, e: 0}"), 2.0);
  REQUIRE(r.switches.size() == 2);
  CHECK(r.switches[0].kind == "leaves");
  CHECK(r.switches[1].kind == "strikes");
  CHECK(std::fabs(r.end.qd[0] - 1) < 1e-9);  // smooth: its sliding speed is kept
}

TEST_CASE("flight: a cord whirled too slowly goes slack, the bob flies, and the cord snaps taut", "[simulate][release]") {
  // v0 = 6 m/s at the bottom, l = 1.2 m: slack at t = 0.527529055311618 s, 110.652629518225 deg; taut again
  // (e = 0) at t = 1.30497995964184 s, theta = 0.489427173932131 rad, approaching at v_n = -4.71070275247336
  // m/s, T = 2.76131703586534 J after (sympy_flight.py, case 3)
  const sim::Run r = run(kt::derivation("kinetics/bob_cord_slack.yaml"), 1.5);
  REQUIRE(r.switches.size() == 2);
  CHECK(r.switches[0].kind == "slack");
  CHECK(std::fabs(r.switches[0].t - 0.527529055311618) < 1e-8);
  CHECK_THAT(r.switches[0].text, Catch::Contains("cord 'string' goes slack at theta = 1.93125 rad (110.653 deg)"));
  CHECK(r.switches[1].kind == "taut");
  REQUIRE(r.impacts.size() == 1);
  const sim::Impact& im = r.impacts[0];
  CHECK(std::fabs(im.t - 1.30497995964184) < 1e-8);
  CHECK(std::fabs(im.vn_before[0] - -4.71070275247336) < 1e-7);
  CHECK(std::fabs(im.vn_after[0]) < 1e-9);  // e = 0: it stays taut
  CHECK(std::fabs(im.T_after - 2.76131703586534) < 1e-7);
  CHECK_THAT(r.switches[1].text, Catch::Contains("theta = 0.489427 rad"));
}

TEST_CASE("flight: simulate --json lists each switch at its instant, the same bytes on every run", "[simulate][release][cli]") {
  int status = 0;
  const std::string cmd = "simulate derivations/kinetics/bob_cord_slack.yaml --until 1.5 --json --no-native";
  const std::string out = kt::run_cli(cmd, status);
  REQUIRE(status == 0);
  CHECK_THAT(out, Catch::Contains("\"switches\": [\n    {\"t\": 0.5275290") && Catch::Contains("\"effect\": \"string\", \"kind\": \"slack\"") &&
                      Catch::Contains("\"kind\": \"taut\"") && Catch::Contains("\"string_gap\": ") && Catch::Contains("\"impacts\": [\n    {\"t\": 1.304979959"));
  int again_status = 0;
  CHECK(kt::run_cli(cmd, again_status) == out);
}

TEST_CASE("flight: a rolling disk pushed past its static friction slips and slides on", "[simulate][release][friction]") {
  // slips at t = 0.333325313335315 s, x = 0.400641364134971 m; 0.3 s later x = 1.17380263935945 m,
  // x_dot = 3.75192520196304 m/s, phi_dot = -16.6895879706387 rad/s (sympy_flight.py, case 4)
  const std::string text = contact("disk_pushed_slips.yaml");
  const sim::Run r = run(text, 0.333325313335315 + 0.3);
  REQUIRE(r.switches.size() == 1);
  CHECK(r.switches[0].kind == "slips");
  CHECK(r.switches[0].effect == "rolling");
  CHECK(std::fabs(r.switches[0].t - 0.333325313335315) < 1e-8);
  CHECK_THAT(r.switches[0].text, Catch::Contains("'rolling' slips at x = 0.400641 m"));
  CHECK(std::fabs(r.end.q[0] - 1.17380263935945) < 1e-8);
  CHECK(std::fabs(r.end.qd[0] - 3.75192520196304) < 1e-8);
  CHECK(std::fabs(r.end.qd[1] - -16.6895879706387) < 1e-7);
  CHECK(std::fabs(r.drift) < 1e-9);  // the sliding friction's work in the audit
  // without mu_k the run cannot say how it slides: it stops at the slip, asking for it
  try {
    run(kt::edit(text, ", mu_k: muk}", "}"), 1.0);
    FAIL("the run went past the slip");
  } catch (const sim::SlipError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("'rolling' slips at t = 0.333325 s, x = 0.400641 m"));
    CHECK_THAT(e.fix(), Catch::Contains("give 'rolling' its kinetic friction, 'mu_k: 0.25'"));
  }
}

TEST_CASE("flight: a track the coordinates do not keep is refused by the simulation, not passed through", "[simulate][errors]") {
  REQUIRE_THROWS_WITH(run(contact("track_not_kept.yaml"), 0.5), Catch::Contains("track 'floor': the coordinates do not keep disk on it"));
}

TEST_CASE("flight: a wheel that struck a step's edge pivots over it and lets go on the far side", "[simulate][release][impact]") {
  // plastic and rough: it pivots about E, over the top, and down the far side until the edge's push
  // falls to zero at G - E = (0.238531494859549, 0.181941545448171) m (sympy_step.py, x_leave, y_leave)
  const sim::Run r = run(kt::derivation("impact/wheel_over_step.yaml"), 1.0);
  REQUIRE(r.impacts.size() == 1);
  CHECK(std::fabs(r.impacts[0].impulse[0] - 9.5405567039991) < 1e-8);  // Jn (sympy_step.py)
  REQUIRE(r.switches.size() == 1);
  CHECK(r.switches[0].kind == "lets go");
  CHECK_THAT(r.switches[0].text, Catch::Contains("wheel lets go of 'edge' at x = 0.238531 m, y = 0.181942 m"));
}
