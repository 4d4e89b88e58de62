// Static friction in rolling (issue 27, "whether mu suffices"): `mu_s` and `normal` on a constraint
// effect, |F| <= mu_s |N| checked at the states of every analysis it acts in, along the simulated
// motion where the friction it needs changes, and by the simulator. Expected values from
// tests/kinetics/sympy_static_friction.py (Newton-Euler by hand), not from kinergy's output.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "../support/helpers.hpp"

namespace {

using kt::solve_text;

std::string incline() { return kt::read_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/kinetics/disk_rolls_incline_friction.yaml"); }
std::string pushed() { return kt::read_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/disk_pushed_static_friction.yaml"); }

std::string written(const std::string& name, const std::string& text) { return kt::written("kinergy-static-friction-test", name, text); }

const char* kRolling = "  rolling: {constraint: \"x + r*phi = 0\", between: [disk, O], at: [x*cos(beta), -x*sin(beta)], mu_s: mus, normal: incline}\n";

/// A sphere (m = 2 kg, r = 0.1 m) rolling on a circle of radius R about the origin, theta from
/// the bottom inside a bowl (its centre at R - r) or from the top on a dome (at R + r), with its
/// rolling 'rolling' held by mu_s on the track named `track`; state 1 and what follows it.
std::string ball_on_circle(bool inside, const std::string& R, const std::string& w0, const std::string& mus, const std::string& state1,
                           const std::string& rest) {
  const std::string rho = inside ? "(R - r)" : "(R + r)", y = inside ? "-" : "", track = inside ? "bowl" : "dome";
  return std::string("title: Ball rolling on a circle\nparameters:\n  m: 2 kg\n  r: 0.1 m\n  R: ") + R + "\n  g: 9.81 m/s^2\n  w0: " + w0 +
         "\n  mus: " + mus + "\npoints:\n  O: [0, 0]\ncoordinates:\n  theta: rad\n  phi: rad\nbodies:\n  ball:\n    mass: m\n"
         "    inertia: {sphere: r}\n    position: [" + rho + "*sin(theta), " + y + rho + "*cos(theta)]\n    angle: phi\neffects:\n"
         "  gravity: {g: g}\n  " + track + ": {track: ball, circle: {centre: [0, 0], radius: R}, offset: " + (inside ? "-r" : "r") + "}\n"
         "  rolling: {constraint: \"" + rho + "*theta + r*phi = 0\", between: [ball, O], at: [R*sin(theta), " + y + "R*cos(theta)], mu_s: mus, normal: " +
         track + "}\nstates:\n  1: " + state1 + "\n" + rest;
}

}  // namespace

TEST_CASE("static friction: a rolling disk with enough mu_s solves, and the derivation says it was checked", "[kinetics][friction]") {
  auto s = solve_text(incline());
  REQUIRE(s.friction_limits.size() == 1);
  CHECK(s.valid_where.empty());
  int st = 0;
  std::string out = kt::run_cli("derive derivations/kinetics/disk_rolls_incline_friction.yaml", st);
  CHECK(st == 0);
  std::replace(out.begin(), out.end(), '\n', ' ');  // (the text is wrapped)
  // tan(20 deg)/3 = 0.1213 (sympy_static_friction.py, case 2)
  CHECK_THAT(out, Catch::Contains("'rolling' holds without slipping where |F| <= mu_s |N(incline)|") &&
                      Catch::Contains("|F|/|N| = 0.1213 at state 1."));
}

TEST_CASE("static friction: too little mu_s is an error at its line, with both numbers", "[kinetics][friction]") {
  // needs tan(20 deg)/3 = 0.121323; mu_s = 0.1 leaves F - mu_s N = 1.57254 N (case 3a)
  const std::string text = kt::edit(incline(), "  mus: 0.3\n", "  mus: 0.1\n");
  REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("'rolling' slips at state '1'") && Catch::Contains("|F|/|N| = 0.121323 of the normal force of 'incline'") &&
                                            Catch::Contains("mu_s = mus = 0.1") && Catch::Contains("short by 1.57254 N") &&
                                            Catch::Contains("abs(F(rolling)@1/N(incline)@1)"));
  // over an energy analysis too (the disk rolls 3 m): F and N from Newton-Euler over its motion
  std::string energy = kt::edit(text, "  1: {x: 0, x_dot: 0, phi: 0}\n", "  1: {x: 0, x_dot: 0, phi: 0}\n  2: {x: 3 m}\n");
  energy = kt::edit(energy, "  - kinetics: {at: 1}\n", "  - energy: {from: 1, to: 2}\n");
  energy = energy.substr(0, energy.find("find:")) + "find:\n  v2: {value: x_dot@2, root: positive, unit: m/s}\n";
  REQUIRE_THROWS_WITH(solve_text(energy), Catch::Contains("'rolling' slips at state '1'") && Catch::Contains("short by 1.57254 N"));
  // the same energy analysis with mu_s = 0.3 solves: 3.66345 m/s = sqrt(4 g d sin(beta)/3)
  auto ok = solve_text(kt::edit(energy, "  mus: 0.1\n", "  mus: 0.3\n"));
  CHECK(kt::result_si(ok, "v2") == Approx(std::sqrt(4 * 9.81 * 3 * std::sin(M_PI / 9) / 3)).epsilon(1e-12));
}

TEST_CASE("static friction: with mu_s without a value, the solution is valid only where it holds", "[kinetics][friction]") {
  auto s = solve_text(kt::edit(incline(), "  mus: 0.3\n", "  mus: number\n"));
  REQUIRE(s.valid_where.size() == 1);
  CHECK_THAT(s.valid_where[0].assumed, Catch::Contains("'rolling' holds without slipping at state '1'"));
  // mus |m g cos(beta)| - |m g sin(beta)/3| >= 0 at mus = tan(beta)/3 exactly
  GiNaC::exmap at{{kt::param(s.model, "mus"), GiNaC::tan(GiNaC::Pi / 9) / 3}, {kt::param(s.model, "m"), 8}, {kt::param(s.model, "g"), GiNaC::numeric(981, 100)},
                  {kt::param(s.model, "beta"), GiNaC::Pi / 9}};
  CHECK(std::fabs(kt::to_double(s.valid_where[0].e, at)) < 1e-12);
}

TEST_CASE("static friction: where the friction needed changes along an energy analysis, the simulation checks the way", "[kinetics][friction][cli]") {
  int st = 0;
  std::string out = kt::run_cli("derive derivations/energy/disk_pushed_static_friction.yaml", st);
  CHECK(st == 0);
  std::replace(out.begin(), out.end(), '\n', ' ');  // (the text is wrapped)
  // F/N = P/(3 m g): 0 at x = 0 and x = d, 0.1699 at d/2 (sympy_static_friction.py, case 1)
  CHECK_THAT(out, Catch::Contains("|F|/|N| = 0 at state 1, 0 at state 2, 0.1699 at state 3.") &&
                      Catch::Contains("Between states 1 and 2 that share changes with the motion: the simulation that confirms the energy "
                                      "analysis checks it along the way, and it holds."));
  // P0 = 60 N: both ends need no friction (P = 0 there), but F/N = P/(3 m g) reaches 0.2 at
  // x = 0.5745 m, t = 0.449859 s, F = 15.696 N (case 3b)
  std::string push60 = kt::edit(pushed(), "  P0: 40 N\n", "  P0: 60 N\n");
  push60 = kt::edit(push60, "  3: {x: d/2}\n", "");
  push60 = kt::edit(push60, "  - energy: {from: 1, to: 3}\n  - kinetics: {at: 3}\n", "");
  push60 = push60.substr(0, push60.find("find:")) + "find:\n  v2: {value: x_dot@2, root: positive, unit: m/s}\n";
  const std::string path = written("push60", push60);
  out = kt::run_cli("solve " + path, st);
  CHECK(st != 0);
  CHECK_THAT(out, Catch::Contains("the energy analysis from state '1' to '2' takes the contact as rolling, but the simulated motion slips") &&
                      Catch::Contains("'rolling' slips at t = 0.449859 s") && Catch::Contains("15.696 N, 0.2 times the normal force of 'floor'"));
  // without a value of P0, the way between is simulated at sampled values of it (issue 43), and
  // the output says the friction was checked there only
  std::string sym = kt::edit(push60, "  P0: 60 N\n", "  P0: N\n");
  sym = sym.substr(0, sym.find("find:")) + "find:\n  v2: {value: x_dot@2, root: positive}\n";
  out = kt::run_cli("solve " + written("pushsym", sym), st);
  INFO(out);
  CHECK(st == 0);
  std::replace(out.begin(), out.end(), '\n', ' ');
  CHECK_THAT(out, Catch::Contains("energy 1 -> 2: by simulation at 3 sampled values of P0") &&
                      Catch::Contains("the static friction of the rolling along the way holds at these values; at others it is not checked"));
}

TEST_CASE("static friction: the simulator stops where a rolling body slips", "[kinetics][friction][simulate]") {
  // a sphere launched up the inside of a bowl at 6 rad/s, mu_s = 0.5: F/N reaches 0.5 at
  // theta = 1.35547, t = 0.279195 s, F = 5.47626 N, N = 10.9525 N (case 3c)
  const std::string bowl = ball_on_circle(true, "0.5 m", "6 rad/s", "0.5", "{theta: 0, theta_dot: w0, phi: 0, phi_dot: -(R - r)*w0/r}", "");
  int st = 0;
  std::string out = kt::run_cli("simulate " + written("bowl", bowl) + " --until 2", st);
  CHECK(st != 0);
  CHECK_THAT(out, Catch::Contains("'rolling' slips at t = 0.279195 s") && Catch::Contains("5.47626 N, 0.5 times the normal force of 'bowl' (10.9525 N)") &&
                      Catch::Contains("bowl.yaml:23:"));
  // launched at 4 rad/s it turns at theta = 0.996 rad, where F/N = (2/7) tan(theta) = 0.44 is
  // its greatest: it rolls up and back
  out = kt::run_cli("simulate " + written("bowl2", ball_on_circle(true, "0.5 m", "4 rad/s", "0.5", "{theta: 0, theta_dot: w0, phi: 0, phi_dot: -(R - r)*w0/r}", "")) + " --until 1.5", st);
  INFO(out);
  CHECK(st == 0);
}

TEST_CASE("static friction: what is refused, naming what would be needed", "[kinetics][friction][errors]") {
  const std::string base = incline();
  auto with = [&](const std::string& rolling) {
    return solve_text(kt::edit(base, kRolling, "  rolling: {constraint: \"x + r*phi = 0\", between: [disk, O], at: [x*cos(beta), -x*sin(beta)]" + rolling + "}\n"));
  };
  REQUIRE_THROWS_WITH(with(", mu_s: mus"), Catch::Contains("'mu_s' and 'normal' go together") && Catch::Contains("mu_s: 0.3, normal: floor"));
  REQUIRE_THROWS_WITH(with(", normal: incline"), Catch::Contains("'mu_s' and 'normal' go together"));
  REQUIRE_THROWS_WITH(with(", mu_s: 0, normal: incline"), Catch::Contains("mu_s = 0 holds no friction"));
  REQUIRE_THROWS_WITH(with(", mu_s: -0.2, normal: incline"), Catch::Contains("coefficient of static friction"));
  REQUIRE_THROWS_WITH(with(", mu_s: r, normal: incline"), Catch::Contains("a friction coefficient is a pure number"));
  REQUIRE_THROWS_WITH(with(", mu_s: mus, normal: gravity"), Catch::Contains("'normal: gravity' is not a track") && Catch::Contains("normal: floor"));
  REQUIRE_THROWS_WITH(with(", mu_s: mus, normal: floor"), Catch::Contains("'normal: floor' names no effect"));
  REQUIRE_THROWS_WITH(with(", mu_s: mus, normal: [incline]"), Catch::Contains("'normal' names a track effect"));
  SECTION("a track that holds another body") {
    std::string two = kt::edit(base, "bodies:\n", "bodies:\n  block:\n    mass: m\n    inertia: particle\n    position: [x + r, 2*r]\n");
    two = kt::edit(two, "  incline: {", "  rail: {track: block, line: {through: [0, 2*r], along: [1, 0]}, pushes: up}\n  incline: {");
    two = kt::edit(two, "normal: incline}", "normal: rail}");
    REQUIRE_THROWS_WITH(solve_text(two), Catch::Contains("track 'rail' holds block, which is not a party of 'rolling'"));
  }
  SECTION("an impact the rolling acts in") {
    std::string hit = kt::edit(base, "  1: {x: 0, x_dot: 0, phi: 0}\n", "  1: {x: 0, x_dot: 0, phi: 0}\n  2: {x: 0}\n");
    hit = kt::edit(hit, "  incline: {", "  blow: {impulse: disk, J: [J0, 0]}\n  incline: {");
    hit = kt::edit(hit, "  mus: 0.3\n", "  mus: 0.3\n  J0: 2 N*s\n");
    hit = kt::edit(hit, "  - kinetics: {at: 1}\n", "  - impact: {from: 1, to: 2}\n");
    hit = hit.substr(0, hit.find("find:")) + "find:\n  v2: {value: x_dot@2, unit: m/s}\n";
    REQUIRE_THROWS_WITH(solve_text(hit), Catch::Contains("acts in the impact from state '1' to '2', where kinergy does not check static friction") &&
                                             Catch::Contains("'off:'"));
  }
}

namespace {

const char* kKinetics = "analyses:\n  - kinetics: {at: 1}\nfind:\n  F1: {value: F(rolling)@1, unit: N}\n  N1: {value: N(dome)@1, unit: N}\n";

}  // namespace

TEST_CASE("static friction: a surface that would have to pull, and a friction force with no normal force", "[kinetics][friction][errors]") {
  // by hand: m (R + r) theta_dot^2 = m g cos(theta) - N and F = (2/7) m g sin(theta) (tangential
  // Newton with (7/5) m (R + r) theta_ddot = m g sin(theta)). At theta = 1, theta_dot = 2.4623727572:
  // N = 2 (9.81 cos 1 - 1.1 * 2.4623727572^2) = -2.73848 N
  REQUIRE_THROWS_WITH(solve_text(ball_on_circle(false, "1 m", "5 rad/s", "2", "{theta: 1 rad, theta_dot: 2.4623727572 rad/s}", kKinetics)),
                      Catch::Contains("at state '1' the surface of 'dome' would have to pull on ball (2.73848 N)") &&
                          Catch::Contains("ball leaves it before that state, and a surface can only push"));
  // theta_dot^2 = g cos(1)/(R + r): N = 0, F = (2/7)(2)(9.81) sin 1 = 4.71705 N
  const std::string at_zero = ball_on_circle(false, "1 m", "5 rad/s", "2", "{theta: 1 rad, theta_dot: sqrt(g*cos(1)/(R + r))}", kKinetics);
  std::string err;
  try {
    solve_text(at_zero);
  } catch (const kinergy::SceneError& e) {
    err = e.what();
  }
  CHECK_THAT(err, Catch::Contains("'rolling' slips at state '1': holding it takes |F|/|N| = infinite (no normal force)") &&
                      Catch::Contains("short by 4.71705 N"));
  CHECK(err.find("internal error") == std::string::npos);
}

TEST_CASE("static friction: the simulator lets the ball go where the surface would have to pull", "[kinetics][friction][simulate]") {
  // at the top with theta_dot = 5 rad/s: N = m g - m (R + r) theta_dot^2 = 19.62 - 55 < 0, F = 0: the
  // ball leaves at once and flies, its rolling relation gone with the surface (its spin kept)
  int st = 0;
  const std::string path = written("dome_top", ball_on_circle(false, "1 m", "5 rad/s", "2", "{theta: 0, theta_dot: w0, phi: 0, phi_dot: -(R + r)*w0/r}", ""));
  const std::string out = kt::run_cli("simulate " + path + " --until 1", st);
  INFO(out);
  CHECK(st == 0);
  CHECK_THAT(out, Catch::Contains("t = 0 s: ball leaves 'dome' at theta = 0 rad (0 deg)") && Catch::Contains("phi_dot = -55 rad/s"));
}

TEST_CASE("static friction: mu_s without a value in a kinetics analysis is confirmed by the equations of motion", "[kinetics][friction][cli]") {
  int st = 0;
  const std::string out = kt::run_cli("solve " + written("incline_sym", kt::edit(incline(), "  mus: 0.3\n", "  mus: number\n")), st);
  INFO(out);
  CHECK(st == 0);
  CHECK_THAT(out, Catch::Contains("Valid only where") && Catch::Contains("kinetics at 1: by the equations of motion"));
}

TEST_CASE("static friction: --no-confirm says the way between the states was not checked", "[kinetics][friction][cli]") {
  int st = 0;
  const std::string out = kt::run_cli("solve --no-confirm derivations/energy/disk_pushed_static_friction.yaml", st);
  CHECK(st == 0);
  CHECK_THAT(out, Catch::Contains("Not checked: the static friction of the rolling between the states of the energy 1 -> 2 analysis"));
}
