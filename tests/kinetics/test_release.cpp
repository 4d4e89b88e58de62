// Surfaces that only push (issue 42): a body leaves a one-sided track where its normal force falls
// to zero. Every angle and speed asserted here is derived independently, from Newton–Euler and
// energy in sympy/mpmath, by tests/contact/sympy_release.py (which reads the same scene files):
// the dome's release at 48.1897 deg (cos = 2/3), the rod against the wall at 51.0531 deg (with its
// starting speed) and 52.8283 deg (from rest, cos = 2 cos(theta0)/3), the block over the quarter
// circle at 45.1791 deg, the ball in the loop at 123.819 deg.
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/confirm/confirm.hpp"
#include "kinergy/emit/emit.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace {

std::string contact(const std::string& name) { return kt::read_file(std::filesystem::path(KINERGY_SOURCE_DIR) / "tests/data/contact" / name); }

/// The result's SI value in degrees, to 6 significant figures.
std::string degrees(const kinergy::Solution& s, const std::string& name) {
  return kinergy::numerics::format(*kt::result(s, name).si * 180 / GiNaC::ex_to<GiNaC::numeric>(GiNaC::Pi.evalf()), 6);
}

}  // namespace

TEST_CASE("release: a state past the place a body leaves its surface is refused, naming the place", "[kinetics][release]") {
  REQUIRE_THROWS_WITH(kt::solve_text(contact("dome_past_release.yaml")),
                      Catch::Contains("ball leaves 'dome' at theta = 0.841069 rad (48.1897 deg), before state '2'") &&
                          Catch::Contains("ask for the state where it leaves, where: [\"N(dome) = 0\"]"));
  // the rod asked at 70 deg from the vertical, past where its top leaves the wall
  auto rod = kt::derivation("kinetics/rod_leaves_wall.yaml");
  auto at70 = kt::edit(kt::edit(rod, "  2: {where: [\"N(wall) = 0\"]}", "  2: {theta: 70 deg}"), "  - kinetics: {at: 2}\n", "");
  REQUIRE_THROWS_WITH(kt::solve_text(at70), Catch::Contains("rod leaves 'wall' at theta = 0.891045 rad (51.0531 deg), before state '2'"));
  // and the root beyond the first crossing (theta = 180 deg, where N(wall) = 0 too) asked for: the
  // rod hangs straight down from its end on the floor there, through the floor (issue 47)
  auto beyond = kt::edit(rod, "theta2: {value: theta@2, unit: deg}", "theta2: {value: theta@2, unit: deg, root: {in: [90 deg, 200 deg]}}");
  REQUIRE_THROWS_WITH(kt::solve_text(beyond), Catch::Contains("the root asked for gives a solution the scene's supports do not allow: track 'floor' "
                                                              "only pushes, and at state '2' rod reaches 3 m through it (at [0, -3])"));
}

TEST_CASE("release: a state defined by N = 0 is the first along the motion", "[kinetics][release]") {
  // N(wall) = 0 also at theta = 0 and 180 deg (a factor sin(theta)): the motion from 20 deg meets 51.05 deg first
  auto s = kt::solve_text(kt::derivation("kinetics/rod_leaves_wall.yaml"));
  CHECK(degrees(s, "theta2") == "51.0531");
  CHECK(degrees(kt::solve_text(contact("rod_leaves_wall_rest.yaml")), "theta2") == "52.8283");
  CHECK(degrees(kt::solve_text(kt::derivation("kinetics/block_leaves_quarter_circle.yaml")), "theta2") == "45.1791");
  // the rolling sphere: theta = -r phi/(R + r) puts sin(r phi/(R + r)) in the equations, solved in closed form
  auto sphere = kt::solve_text(kt::derivation("kinetics/sphere_rolls_off_sphere.yaml"));
  const GiNaC::ex theta2 = kt::result(sphere, "theta2").closed;
  INFO("theta2 = " << theta2 << " = " << kt::value(theta2, sphere.model.numeric_environment(), 40));
  CHECK(kt::close(kt::value(theta2, sphere.model.numeric_environment(), 40), kt::value(GiNaC::acos(GiNaC::ex(GiNaC::numeric(10, 17))), {}, 40), kt::tol(35)));
}

TEST_CASE("release: the confirming simulation follows the push between the states", "[kinetics][release][simulate]") {
  // two coordinates with no constraint between them: the closed form does not follow N along the
  // way; it is positive at both states, and the simulation finds where it falls to zero
  const std::string loop = contact("loop_two_bodies.yaml");
  auto s = kt::solve_text(loop);  // solved: the states alone do not show it
  REQUIRE_THROWS_WITH(kinergy::confirm(s), Catch::Contains("keeps ball on 'loop', but in the simulated motion it leaves before state '2'") &&
                                               Catch::Contains("theta = 2.16105 rad (123.819 deg)"));
}

TEST_CASE("release: a run told not to follow the body stops where it leaves, the instant and place reported", "[simulate][release]") {
  auto s = kt::solve_text(kt::derivation("kinetics/block_leaves_quarter_circle.yaml"));
  kinergy::simulate::Options o;
  o.native = false;
  o.follow_releases = false;  // as the check of an analysis that keeps the block on the surface runs
  kinergy::simulate::Simulator sim(s.model, kinergy::parameter_values(s), o);
  kinergy::simulate::State s0{0, {0}, {1.5 / 2}};  // theta = 0, theta_dot = v0/R
  try {
    sim.run(s0, {2.0, std::nullopt, true});
    FAIL("the run went past the release");
  } catch (const kinergy::simulate::ReleaseError& e) {
    CHECK(e.effect() == "surface");
    CHECK_THAT(std::string(e.what()), Catch::Contains("block leaves 'surface' at t = ") && Catch::Contains("theta = 0.788524 rad (45.1791 deg)"));
  }
}

TEST_CASE("release: a cord that only pulls goes slack where its tension falls to zero", "[kinetics][release]") {
  // v0 = 6 m/s < sqrt(5 g l): the tension m v^2/l + m g cos(theta) falls to zero at cos(theta) =
  // -(v0^2 - 2 g l)/(3 g l), 110.653 deg (sympy_flight.py, case 3)
  auto s = kt::solve_text(kt::derivation("kinetics/bob_cord_slack.yaml"));
  CHECK(degrees(s, "theta2") == "110.653");
  REQUIRE_THROWS_WITH(kt::solve_text(contact("bob_whirled_past_slack.yaml")),
                      Catch::Contains("cord 'string' goes slack at theta = 1.93125 rad (110.653 deg), before state '2'") &&
                          Catch::Contains("a cord can only pull") && Catch::Contains("where: [\"T(string) = 0\"]"));
}

TEST_CASE("release: a cord runs from a fixed point to a body's point, with a length", "[kinetics][release][errors]") {
  const std::string bob = kt::derivation("kinetics/bob_cord_slack.yaml");
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(bob, "string: {cord: [O, bob], length: l, e: 0}", "string: {cord: [bob, O], length: l}")),
                      Catch::Contains("write the fixed point first"));
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(bob, "string: {cord: [O, bob], length: l, e: 0}", "string: {cord: [O, bob]}")),
                      Catch::Contains("length"));
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(bob, "length: l, e: 0}", "length: l, e: 2}")), Catch::Contains("not from 0 to 1"));
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(bob, "length: l, e: 0}", "length: l, pushes: up}")), Catch::Contains("pushes"));
  // a track's e: a restitution from 0 to 1, and only where it can only push
  const std::string dome = kt::derivation("kinetics/ball_leaves_dome.yaml");
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(dome, "pushes: outward}", "pushes: outward, e: 1.5}")),
                      Catch::Contains("coefficient of restitution of track 'dome' is 1.5, not from 0 to 1"));
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(dome, "pushes: outward}", "holds: both, e: 0.5}")), Catch::Contains("'e' has no use here"));
}

TEST_CASE("release: a push Newton's law does not determine is said not checked, and the run does not free the body", "[kinetics][release][simulate]") {
  // two floors under one block: N1 + N2 = m g, each undetermined (statically indeterminate)
  const std::string text = contact("two_floors.yaml");
  auto s = kt::solve_text(text);
  CHECK_THAT(kinergy::emit::text(s, {}), Catch::Contains("Not checked: the push of 'floor1' during the energy analysis from state '1' to '2'") &&
                                             Catch::Contains("statically indeterminate"));
  // the simulator cannot give the block a gap for each (two along one line): it slides on, held
  const kinergy::model::Model m = kt::model_of(text);
  kinergy::simulate::Options o;
  o.native = false;
  kinergy::simulate::Simulator sim(m, m.parameter_values(), o);
  CHECK(sim.model().coords.size() == 1);
  const auto r = sim.run({0, {0}, {2}}, {0.5, std::nullopt, true});
  CHECK(std::fabs(r.end.q[0] - 1) < 1e-12);
}

TEST_CASE("release: a rolling body is not freed: the run stops where it leaves, saying why", "[simulate][release]") {
  // the sphere rolling off the sphere: its rolling relation holds it (free of the surface, the
  // relation would still tie its turning to its place)
  auto s = kt::solve_text(kt::derivation("kinetics/sphere_rolls_off_sphere.yaml"));
  kinergy::simulate::Options o;
  o.native = false;
  kinergy::simulate::Simulator sim(s.model, kinergy::parameter_values(s), o);
  const auto s0 = kinergy::simulate::state_values(s, 0);
  auto nudged = s0;
  nudged.qd[0] = 1e-3;  // (from rest at the top: an equilibrium)
  try {
    sim.run(nudged, {20.0, std::nullopt, true});
    FAIL("the run went past the release");
  } catch (const kinergy::simulate::ReleaseError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("leaves '"));
    CHECK_THAT(e.fix(), Catch::Contains("cannot go on with") && Catch::Contains("a relation between the coordinates holds"));
  }
}

TEST_CASE("release: a surface that would pull at the state the motion starts from is refused as such", "[kinetics][release][errors]") {
  // the wheel about the step edge at omega2 = 5.18519 rad/s: N = m (g sin(psi2) - r omega2^2) = -12.2067 N
  // (by hand, in the scene's description): it leaves at once, not "before" the state
  REQUIRE_THROWS_WITH(kt::solve_text(contact("wheel_pivots_too_fast.yaml")),
                      Catch::Contains("at state '2', where the motion starts, the surface of 'edge' would have to pull on wheel (12.2067 N)") &&
                          Catch::Contains("leaves it at once"));
}

TEST_CASE("release: two points that meet at the origin strike there (no false gap from rounding)", "[momentum][impact]") {
  // the wheel's point C and the edge E both at (0, 0) at 'before', each computed with rounding of
  // 1e-21 m: against the wheel's size they touch. omega2 = v1 (2 h - 3 r)/(3 r^2) by angular momentum
  // about E, m v1 (r - h) + (m r^2/2)(v1/r) = (3/2) m r^2 omega2 (clockwise)
  auto s = kt::solve_text(contact("wheel_strikes_edge.yaml"));
  const double v1 = 2, r = 0.3, h = 0.1;
  CHECK(std::fabs(GiNaC::ex_to<GiNaC::numeric>(*kt::result(s, "omega2").si).to_double() - v1 * (2 * h - 3 * r) / (3 * r * r)) < 1e-12);
}

// A plastic, rough contact stays closed after its impact (issue 42): a wheel and a sphere that
// strike a step's edge pivot about it, the edge's push checked >= 0. Expected values from
// tests/contact/sympy_step.py (angular momentum about E, Newton-Euler and energy in sympy).
TEST_CASE("closed contact: a wheel over a step pivots about the edge it struck, its push from Newton-Euler", "[kinetics][release][impact]") {
  // (the push just after the impact asked too: kinetics at 'after')
  const auto wheel = kt::edit(kt::edit(kt::derivation("impact/wheel_over_step.yaml"), "  - energy: {from: after, to: top}\n",
                                       "  - kinetics: {at: after}\n  - energy: {from: after, to: top}\n"),
                              "  omega_top: {value", "  N2: {value: N(edge)@after, unit: N}\n  F2: {value: F(edge)@after, unit: N}\n  omega_top: {value");
  const kinergy::Solution s = kt::solve_text(wheel);
  CHECK(std::fabs(kt::result(s, "omega2").si->to_double() - -4.14814814814815) < 1e-12);
  CHECK(std::fabs(kt::result(s, "N2").si->to_double() - 11.0228806584362) < 1e-10);
  CHECK(std::fabs(kt::result(s, "F2").si->to_double() - -19.4985127637982) < 1e-10);
  CHECK(std::fabs(kt::result(s, "omega_top").si->to_double() - -1.63517574763436) < 1e-12);
  CHECK(std::fabs(kt::result(s, "N_top").si->to_double() - 72.0628806584362) < 1e-10);
  const kinergy::Solution sp = kt::solve_text(kt::derivation("impact/sphere_onto_step.yaml"));
  CHECK(std::fabs(kt::result(sp, "omega_top").si->to_double() - -5.61084954824679) < 1e-12);
  CHECK(std::fabs(kt::result(sp, "N_top").si->to_double() - 13.3236734693878) < 1e-10);
  // the angle the wheel has turned at the top, from the constraints, not given: -acos((r - h)/r)
  auto free_top = kt::edit(kt::derivation("impact/wheel_over_step.yaml"), "  top: {x: 0, y: r, phi: -acos((r - h)/r)}", "  top: {x: 0, y: r}");
  free_top = kt::edit(kt::edit(free_top, "  - kinetics: {at: top}\n", ""), "  N_top: {value: N(edge)@top, unit: N}\n", "");
  free_top = kt::edit(free_top, "  N_top: {form: m*(g - v1^2*(3*r - 2*h)^2/(9*r^3) + 4*g*h/(3*r)), value: 72.06 N}\n", "");
  const kinergy::Solution f = kt::solve_text(free_top);
  CHECK(std::fabs(kt::result(f, "omega_top").si->to_double() - -1.63517574763436) < 1e-12);
}

TEST_CASE("closed contact: a wheel that strikes the edge too fast leaves it at once", "[kinetics][release][impact]") {
  // v1 = 2 m/s: the edge would have to pull 12.2067489711934 N just after the impact (sympy_step.py)
  auto fast = kt::edit(kt::derivation("impact/wheel_over_step.yaml"), "  v1: 1.6 m/s", "  v1: 2 m/s");
  REQUIRE_THROWS_WITH(kt::solve_text(fast), Catch::Contains("at state 'after', where the motion starts, the surface of 'edge' would have to pull on wheel (12.2067 N)") &&
                                                Catch::Contains("wheel leaves it at once"));
}

TEST_CASE("closed contact: what the format refuses about it, at its line", "[kinetics][release][impact][errors]") {
  const std::string w = kt::derivation("impact/wheel_over_step.yaml");
  // 'surface' on a contact that rebounds: nothing stays closed, so whose surface it is says nothing
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(w, "e: 0, tangential: stick, surface: wheel", "e: 0.3, tangential: stick, surface: wheel")),
                      Catch::Contains("'surface' says whose surface the normal is") && Catch::Contains("rebounds"));
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(w, "e: 0, tangential: stick, surface: wheel", "e: 0, surface: wheel")),
                      Catch::Contains("is smooth"));
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(w, "surface: wheel}", "surface: floor}")),
                      Catch::Contains("'surface: floor' is not a party's: the surface is ground's or wheel's"));
  // a momentum analysis over the pivoting: the edge's force is not one of its unknowns
  auto mom = kt::edit(w, "  - energy: {from: after, to: top}\n", "  - energy: {from: after, to: top}\n  - angular_momentum: {from: after, to: top, about: E}\n");
  REQUIRE_THROWS_WITH(kt::solve_text(mom), Catch::Contains("contact 'edge' holds wheel.C at E from state 'after' on") &&
                                               Catch::Contains("use an energy analysis"));
}
