// Kinetics at an instant (issue 27): Newton's second law at a state. Expected values by hand
// (the bar: moments about O, I_O alpha = -m g L/2 cos(theta), I_O = m L^2/3; m a_G = R + W), not
// from kinergy's output.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "../support/helpers.hpp"
#include "kinergy/confirm/confirm.hpp"

namespace {

using kt::solve_text;
const auto& value = kt::result_si;
using GiNaC::ex;

std::string bar_scene() {
  std::ifstream f(std::string(KINERGY_SOURCE_DIR) + "/derivations/kinetics/bar_released_pin_reaction.yaml");
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}


}  // namespace

TEST_CASE("kinetics at an instant: a pinned bar at an angle with a rate, its pin's force by hand", "[kinetics]") {
  // theta = 30 deg, theta_dot = 2 rad/s (given): alpha = -(3 g/(2 L)) cos(theta);
  // a_G = (L/2)(-alpha sin - w^2 cos, alpha cos - w^2 sin); R = m a_G - (0, -m g)
  std::string text = kt::edit(bar_scene(), "2: {theta: -pi/2}", "2: {theta: pi/6, theta_dot: 2 rad/s}");
  text = kt::edit(text, "  - energy: {from: 1, to: 2}\n", "");
  text = kt::edit(text, "  omega2: {value: theta_dot@2, root: negative, unit: rad/s}\n", "");
  auto cut = text.find("expect:");
  text = text.substr(0, cut);
  auto s = solve_text(text);
  const double m = 4, L = 0.9, g = 9.81, th = M_PI / 6, w = 2;
  const double alpha = -3 * g / (2 * L) * std::cos(th);
  const double ax = L / 2 * (-alpha * std::sin(th) - w * w * std::cos(th)), ay = L / 2 * (alpha * std::cos(th) - w * w * std::sin(th));
  CHECK(value(s, "alpha2") == Approx(alpha).epsilon(1e-12));
  CHECK(value(s, "Rx2") == Approx(m * ax).epsilon(1e-12));
  CHECK(value(s, "Ry2") == Approx(m * ay + m * g).epsilon(1e-12));
  kinergy::confirm(s);  // the accelerations against the simulator's equations of motion at the state
  REQUIRE(s.confirmed.size() == 2);
  for (auto& c : s.confirmed) CHECK(c.by == kinergy::Confirmed::By::EquationsOfMotion);
}

TEST_CASE("kinetics at an instant: asked without the analysis, it is added at that state", "[kinetics]") {
  std::string text = bar_scene();
  text = kt::edit(text, "  - kinetics: {at: 1}\n", "");
  text = kt::edit(text, "  - kinetics: {at: 2}\n", "");
  auto s = solve_text(text);
  CHECK(s.model.analyses.size() == 3);
  CHECK(value(s, "Ry1") == Approx(4 * 9.81 / 4).epsilon(1e-12));
  CHECK(value(s, "Ry2") == Approx(5 * 4 * 9.81 / 2).epsilon(1e-12));
}

TEST_CASE("kinetics at an instant: what is refused", "[kinetics]") {
  const std::string base = bar_scene().substr(0, bar_scene().find("expect:"));
  SECTION("a force a support does not exert") {
    REQUIRE_THROWS_WITH(solve_text(kt::edit(base, "Rx(pivot)@1", "N(pivot)@1")),
                        Catch::Contains("N(pivot) is not a force 'pivot' exerts: it is a pin") && Catch::Contains("write Rx(pivot), Ry(pivot), R(pivot)"));
    REQUIRE_THROWS_WITH(solve_text(kt::edit(base, "Rx(pivot)@1", "Rx(gravity)@1")), Catch::Contains("it is no support"));
  }
  SECTION("an analysis without its state") {
    REQUIRE_THROWS_WITH(solve_text(kt::edit(base, "kinetics: {at: 1}", "kinetics: {from: 1}")),
                        Catch::Contains("unknown key 'from' in kinetics analysis"));
    REQUIRE_THROWS_WITH(solve_text(kt::edit(base, "kinetics: {at: 1}", "kinetics: {bodies: [bar]}")),
                        Catch::Contains("kinetics analysis has no 'at'") && Catch::Contains("kinetics: {at: 2}"));
  }
  SECTION("a body held to a path by its coordinates with no support declared") {
    // the bar's pin left out: its coordinates still hold O fixed, Newton's law for it cannot hold
    std::string text = kt::edit(base, "  pivot: {pin: [O, bar.O]}\n", "");
    text = kt::edit(text, "  Rx1: {value: Rx(pivot)@1, unit: N}\n  Ry1: {value: Ry(pivot)@1, unit: N}\n", "");
    text = kt::edit(text, "  Rx2: {value: Rx(pivot)@2, unit: N}\n  Ry2: {value: Ry(pivot)@2, unit: N}\n", "");
    REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("does not hold with the supports the scene declares") &&
                                              Catch::Contains("declare that support"));
  }
  SECTION("an effect that switches at the state") {
    std::string text = kt::edit(base, "  gravity: {g: g}\n", "  gravity: {g: g}\n  push: {couple: bar, M: m*g*L, off: 2}\n");
    REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("effect 'push' switches off at state '2'"));
  }
}

TEST_CASE("kinetics at an instant: kinetic friction, where it slides and where nothing does", "[kinetics]") {
  // a block pushed by F0 against kinetic friction mu m g: a = (F0 - mu m g)/m while it slides
  const std::string text = R"Y(title: block with friction
parameters: {m: 2 kg, g: 9.81 m/s^2, mu: 0.3, F0: 10 N}
coordinates: {x: m}
bodies:
  block: {mass: m, inertia: particle, position: [x, 0]}
effects:
  push: {force: block, F: [F0, 0]}
  rub: {friction: block, mu: mu, normal: m*g}
states:
  1: {x: 0, x_dot: 0}
  2: {x: 1 m, x_dot: 2 m/s}
find:
  a2: {value: x_ddot@2, unit: m/s^2}
)Y";
  auto s = solve_text(text);
  CHECK(value(s, "a2") == Approx((10 - 0.3 * 2 * 9.81) / 2).epsilon(1e-12));
  // at rest the friction force is not mu N: refused, not a number
  REQUIRE_THROWS_WITH(solve_text(kt::edit(text, "x_ddot@2", "x_ddot@1")),
                      Catch::Contains("the kinetics at state '1' cannot be taken") && Catch::Contains("is undefined there") &&
                          Catch::Contains("a kinetic friction where nothing slides"));
}

TEST_CASE("kinetics at an instant: a declared analysis must solve for the force asked", "[kinetics]") {
  // a second bar hangs free (its own pin): the kinetics over bar2 alone does not solve for the
  // first bar's pin
  std::string text = bar_scene().substr(0, bar_scene().find("expect:"));
  text = kt::edit(text, "  pivot: {pin: [O, bar.O]}\n", "  pivot: {pin: [O, bar.O]}\n  pivot2: {pin: [O, bar2.O]}\n");
  text = kt::edit(text, "effects:\n", "  bar2:\n    mass: m\n    inertia: {slender_rod: L}\n    position: [L/2*cos(phi), L/2*sin(phi)]\n"
                                      "    angle: phi\n    points: {O: [-L/2, 0]}\neffects:\n");
  text = kt::edit(text, "  theta: rad\n", "  theta: rad\n  phi: rad\n");
  text = kt::edit(text, "1: {theta: 0, theta_dot: 0}", "1: {theta: 0, theta_dot: 0, phi: 0, phi_dot: 0}");
  text = kt::edit(text, "2: {theta: -pi/2}", "2: {theta: -pi/2, phi: 0}");
  text = kt::edit(text, "  - kinetics: {at: 1}\n", "  - kinetics: {at: 1, bodies: [bar2]}\n");
  REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("'Rx1' asks for Rx_pivot@1, which the kinetics analysis at state '1' does not solve for") &&
                                            Catch::Contains("list in that analysis' 'bodies' a body the support holds"));
}

TEST_CASE("a light body (mass 0): energy and kinetics hold, what is not determined is said", "[kinetics]") {
  // a ball on a light rod: omega^2 = 2 g/L at the lowest point (by hand), and a light flap with
  // its own coordinate whose rate nothing determines
  const std::string text = R"Y(title: a light flap
parameters: {m: 2 kg, L: 0.8 m, g: 9.81 m/s^2}
points: {O: [0, 0]}
coordinates: {theta: rad, phi: rad}
bodies:
  ball: {mass: m, inertia: particle, position: [L*cos(theta), L*sin(theta)]}
  flap: {mass: 0, inertia: {slender_rod: L}, position: [L/2*cos(phi), L/2*sin(phi)], angle: phi}
effects:
  gravity: {g: g}
states:
  1: {theta: 0, theta_dot: 0, phi: 0, phi_dot: 1 rad/s}
  2: {theta: -pi/2}
analyses:
  - energy: {from: 1, to: 2}
find:
  w2: {value: theta_dot@2, root: negative, unit: rad/s}
)Y";
  auto s = solve_text(text);
  CHECK(value(s, "w2") == Approx(-std::sqrt(2 * 9.81 / 0.8)).epsilon(1e-12));
  kinergy::confirm(s);  // the flap's coordinate moves no mass: not simulated, said, confirmed by the residuals
  REQUIRE(s.confirmed.size() == 1);
  CHECK(s.confirmed[0].by == kinergy::Confirmed::By::Residuals);
  CHECK_THAT(s.confirmed[0].note, Catch::Contains("M(q) is not positive definite"));
  REQUIRE_THROWS_WITH(solve_text(kt::edit(text, "value: theta_dot@2, root: negative", "value: phi_dot@2")),
                      Catch::Contains("'w2' is not determined: phi_dot@2 is unknown"));
  // a negative mass is still refused
  REQUIRE_THROWS_WITH(solve_text(kt::edit(text, "mass: 0,", "mass: -m,")), Catch::Contains("must be zero or positive"));
}

TEST_CASE("a light body with a coordinate of its own that a load moves: refused, naming what would be needed", "[kinetics]") {
  // two springs in series with a light connector: its place follows from k1 (y1 − y − L) = k2 (−y1 − L)
  // at every instant, which no analysis derives; energy alone would leave it free
  const std::string text = R"Y(title: two springs in series
parameters: {m: 2 kg, k1: 300 N/m, k2: 600 N/m, g: 9.81 m/s^2, L: 0.5 m}
points: {O: [0, 0]}
coordinates: {y: m, y1: m}
bodies:
  block: {mass: m, inertia: particle, position: [0, y]}
  link: {mass: 0, inertia: particle, position: [0, y1]}
effects:
  gravity: {g: g}
  upper: {spring: [O, link], k: k2, free_length: L}
  lower: {spring: [link, block], k: k1, free_length: L}
states:
  1: {y: -2*L, y1: -L, y_dot: 0}
  2: {y_dot: 0}
analyses:
  - energy: {from: 1, to: 2}
find:
  drop: {value: -2*L - y@2, root: positive, unit: m}
)Y";
  REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("coordinate 'y1' moves only bodies without mass (link), and no constraint ties it to the others"));
}

TEST_CASE("simulate --check: kinetics at a state against the equations of motion there", "[kinetics][cli]") {
  int st = 0;
  const std::string out = kt::run_cli("simulate derivations/kinetics/bar_released_pin_reaction.yaml --check", st);
  INFO(out);
  CHECK(st == 0);
  CHECK_THAT(out, Catch::Contains("kinetics at 1: the accelerations against the equations of motion") &&
                      Catch::Contains("kinetics at 2: the accelerations against the equations of motion"));
  CHECK_THAT(out, !Catch::Contains("FAILS") && !Catch::Contains("not checked"));
}

TEST_CASE("kinetics at an instant: a contact lost where its normal force vanishes, by hand", "[kinetics]") {
  // a ball sliding from rest at the top of a smooth dome of radius R: energy v² = 2 g R (1 − cos θ),
  // along the normal m g cos θ − N = m v²/R; N = 0 at cos θ = 2/3, whatever m, R, g
  std::string text = kt::derivation("kinetics/ball_leaves_dome.yaml");
  text = text.substr(0, text.find("expect:"));
  text = kt::edit(text, "  R: 1.5 m", "  R: 2.5 m");
  auto s = solve_text(text);
  CHECK(value(s, "theta2") == Approx(std::acos(2.0 / 3)).epsilon(1e-14));
  CHECK(value(s, "v2") == Approx(std::sqrt(2 * 9.81 * 2.5 / 3)).epsilon(1e-14));
  // the other side of the dome: the same angle, negative
  s = solve_text(kt::edit(text, "root: positive", "root: negative"));
  CHECK(value(s, "theta2") == Approx(-std::acos(2.0 / 3)).epsilon(1e-14));
  // the normal equation solved, m a_x = N sin θ, also holds where sin θ = 0 (the top, the
  // bottom): there Newton's law along y, left out at a general state, does not, so θ = π is no
  // solution and θ = acos(2/3) is the one positive root (else 'root: positive' would be ambiguous)
  s = solve_text(kt::edit(text, "root: positive", "root: {in: [0.1, 3.3]}"));
  CHECK(value(s, "theta2") == Approx(std::acos(2.0 / 3)).epsilon(1e-14));
  // N = 0 asked at the top, at rest: the ball's weight is unbalanced there
  std::string top = kt::edit(text, "2: {where: [\"N(dome) = 0\"]}", "2: {theta: 0, where: [\"N(dome) = 0\"]}");
  top = kt::edit(top, "  theta2: {value: theta@2, root: positive, unit: deg}\n", "");
  REQUIRE_THROWS_WITH(solve_text(top), Catch::Contains("Newton's second law for ball along y at state 2 is off by 3.924"));
}

TEST_CASE("kinetics at an instant: asked where kinetic friction stops sliding, the refusal says so", "[kinetics]") {
  // the bowling ball at the instant it starts to roll: the slip is 0, so μN has no direction there
  std::string text = kt::derivation("momentum/sphere_slide_to_roll.yaml");
  text = text.substr(0, text.find("expect:"));
  text = kt::edit(text, "find:\n", "find:\n  ax2: {value: ax(ball)@2, unit: m/s^2}\n");
  REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("is undefined when") &&
                                            Catch::Contains("a kinetic friction where nothing slides (or a drive at rest) has no force there") &&
                                            Catch::Contains("hold the rolling there with a constraint effect"));
}

TEST_CASE("kinetics at an instant: kinetic friction opposes the slip at the state, whichever way it goes (issue 43, finding 1)", "[kinetics][confirm]") {
  // By hand: a block sliding with rate v on a floor, F = −μ m g sign(v): a = −μ g sign(v). A shoe
  // pressed on a wall by P and sliding down: m a = −m g + μ P. A disk turning clockwise against
  // its bearing's couple Mf: (m r²/2) α = +Mf. The check's equations of motion must take the
  // friction's sense from the state's slip too (they took +x, +y and counter-clockwise, and
  // refused the right answer).
  const std::string block = R"(title: A block sliding on a rough floor, at an instant
parameters:
  m: 4 kg
  mu: 0.25
  g: 9.81 m/s^2
coordinates:
  x: m
bodies:
  block: {mass: m, inertia: particle, position: [x, 0]}
effects:
  rub: {friction: block, mu: mu, normal: m*g}
states:
  1: {x: 0, x_dot: -3 m/s}
analyses:
  - kinetics: {at: 1}
find:
  a: {value: x_ddot@1, unit: m/s^2}
)";
  const std::string shoe = R"(title: A shoe pressed on a wall, sliding down, at an instant
parameters:
  m: 2 kg
  mu: 0.4
  P: 30 N
  g: 9.81 m/s^2
coordinates:
  y: m
bodies:
  shoe: {mass: m, inertia: particle, position: [0, y]}
effects:
  gravity: {g: g}
  rub: {friction: shoe, mu: mu, normal: P}
states:
  1: {y: 0, y_dot: -1.5 m/s}
analyses:
  - kinetics: {at: 1}
find:
  a: {value: y_ddot@1, unit: m/s^2}
)";
  const std::string wheel = R"(title: A wheel turning clockwise against its bearing's couple, at an instant
parameters:
  m: 25 kg
  r: 0.3 m
  Mf: 1.5 N*m
coordinates:
  theta: rad
bodies:
  wheel: {mass: m, inertia: {disk: r}, position: [0, 0], angle: theta}
effects:
  bearing: {friction_couple: wheel, M: Mf}
states:
  1: {theta: 0, theta_dot: -20 rad/s}
analyses:
  - kinetics: {at: 1}
find:
  alpha: {value: theta_ddot@1, unit: rad/s^2}
)";
  auto confirmed = [](kinergy::Solution s) {
    kinergy::confirm(s);  // throws where the equations of motion disagree
    REQUIRE(s.confirmed.size() == 1);
    CHECK(s.confirmed[0].by == kinergy::Confirmed::By::EquationsOfMotion);
    return s;
  };
  CHECK(value(confirmed(solve_text(block)), "a") == Approx(0.25 * 9.81).epsilon(1e-14));
  CHECK(value(confirmed(solve_text(kt::edit(block, "x_dot: -3", "x_dot: 3"))), "a") == Approx(-0.25 * 9.81).epsilon(1e-14));
  CHECK(value(confirmed(solve_text(shoe)), "a") == Approx(-9.81 + 0.4 * 30 / 2).epsilon(1e-14));
  CHECK(value(confirmed(solve_text(kt::edit(shoe, "y_dot: -1.5", "y_dot: 1.5"))), "a") == Approx(-9.81 - 0.4 * 30 / 2).epsilon(1e-14));
  CHECK(value(confirmed(solve_text(wheel)), "alpha") == Approx(2 * 1.5 / (25 * 0.09)).epsilon(1e-14));
  CHECK(value(confirmed(solve_text(kt::edit(wheel, "-20 rad/s", "20 rad/s"))), "alpha") == Approx(-2 * 1.5 / (25 * 0.09)).epsilon(1e-14));
}

TEST_CASE("kinetics just after release against a friction couple: its sense is that of the motion that follows (issue 43, finding 6)", "[kinetics][friction]") {
  // By hand: the derivation's bar (m = 4 kg, L = 0.9 m) pinned at O, released from rest
  // horizontal, now against its bearing's couple Mf = 3 N·m. It falls clockwise, so the couple
  // acts counter-clockwise: (m L²/3) α = −m g L/2 + Mf; the pin's push up Ry = m g + m (L/2) α.
  std::string scene = bar_scene().substr(0, bar_scene().find("expect:"));
  scene = kt::edit(scene, "  g: 9.81 m/s^2\n", "  g: 9.81 m/s^2\n  Mf: 3 N*m\n");
  scene = kt::edit(scene, "  pivot: {pin: [O, bar.O]}\n", "  pivot: {pin: [O, bar.O]}\n  bearing: {friction_couple: bar, M: Mf}\n");
  scene = kt::edit(scene, "  - energy: {from: 1, to: 2}\n  - kinetics: {at: 2}\n", "");
  scene = scene.substr(0, scene.find("  omega2:"));  // (the finds at state 1 only)
  const double m = 4, L = 0.9, Mf = 3, g = 9.81, alpha = (-m * g * L / 2 + Mf) / (m * L * L / 3);
  auto s = solve_text(scene);
  CHECK(value(s, "alpha1") == Approx(alpha).epsilon(1e-14));
  CHECK(value(s, "Ry1") == Approx(m * g + m * L / 2 * alpha).epsilon(1e-14));
  kinergy::confirm(s);  // the simulator's accelerations at the state, its couple against the slip that starts
  REQUIRE(s.confirmed.size() == 1);
  CHECK(s.confirmed[0].by == kinergy::Confirmed::By::EquationsOfMotion);
  // declared the way it goes: the same; declared the other way: refused, naming it
  CHECK(value(solve_text(kt::edit(scene, "M: Mf}", "M: Mf, direction: negative}")), "alpha1") == Approx(alpha).epsilon(1e-14));
  REQUIRE_THROWS_WITH(solve_text(kt::edit(scene, "M: Mf}", "M: Mf, direction: positive}")),
                      Catch::Contains("taken as its 'direction:' says, the body turns against it"));
  // a couple larger than gravity's moment about O (m g L/2 = 17.658 N·m) holds the bar at rest
  REQUIRE_THROWS_WITH(solve_text(kt::edit(scene, "  Mf: 3 N*m", "  Mf: 30 N*m")), Catch::Contains("the couples hold it at rest"));
}
