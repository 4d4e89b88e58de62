// Tracks (issue 13, part 6): a point declared on a line or a circle is checked for every value of
// the coordinates (no constraints) or at every solved state (constraints), and its normal
// reaction is an unknown of momentum analyses. Expected values by hand in the comments.
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"

using GiNaC::ex;

using kt::derivation;
using kt::edit;
using kt::solve_text;

TEST_CASE("tracks that hold: the sliding rod's slots, the bowl's circle", "[effects][track]") {
  // A = (l cos theta, 0) and B = (0, -l sin theta) for every theta: on y = 0 and x = 0
  auto rod = edit(derivation("energy/sliding_rod.yaml"), "effects:\n",
                  "effects:\n  slotA: {track: rod.A, line: {through: [0, 0], along: [1, 0]}, holds: both}\n"
                  "  slotB: {track: rod.B, line: {through: [0, 0], along: [0, 1]}, holds: both}\n");
  auto s = solve_text(rod);
  CHECK(kinergy::numerics::format(*kt::result(s, "omega2").si, 4) == "3.502");
  // the sphere's centre is on the circle of radius R - r about O; checked at the states (a constraint).
  // The derivation declares the bowl itself with offset -r (the sphere touches it); the same circle
  // without the offset:
  auto bowl = edit(derivation("energy/sphere_in_bowl.yaml"), "bowl: {track: ball, circle: {centre: [0, 0], radius: R}, offset: -r, pushes: inward}",
                   "bowl: {track: ball, circle: {centre: [0, 0], radius: R - r}, pushes: inward}");
  CHECK_NOTHROW(solve_text(bowl));
  REQUIRE_THROWS_WITH(solve_text(edit(bowl, "radius: R - r}", "radius: R}")),
                      Catch::Contains("track 'bowl': ball is 0.1 m off the circle of centre [0, 0] and radius R at state '1'"));
  // a wheel on an incline, its centre at distance r on the normal's side: the other side is 2 r off
  auto wheel = derivation("energy/rolling_disk_incline.yaml");
  CHECK_NOTHROW(solve_text(wheel));
  REQUIRE_THROWS_WITH(solve_text(edit(wheel, "offset: r, pushes: [sin(beta), cos(beta)]}", "offset: -r}")),
                      Catch::Contains("track 'incline': disk is 0.3 m off the line through [0, 0] along [cos(beta), -sin(beta)] at distance -r"));
}

TEST_CASE("a track's normal reaction in momentum: a block on a smooth incline", "[effects][track][momentum]") {
  // along x: m v cos(beta) = N sin(beta) t2; along y: -m v sin(beta) = N cos(beta) t2 - m g t2
  // so v = g sin(beta) t2 and N = m g cos(beta) (symbolic)
  auto text = derivation("momentum/block_incline_normal_force.yaml");
  for (const char* p : {"  m: 2 kg\n", "  g: 9.81 m/s^2\n", "  beta: 30 deg\n", "  t2: 1.5 s\n"}) {
    std::string line(p), name = line.substr(2, line.find(':') - 2);
    std::string unit = name == "m" ? "kg" : name == "g" ? "m/s^2" : name == "beta" ? "rad" : "s";
    text = edit(text, line, "  " + name + ": " + unit + "\n");
  }
  text = text.substr(0, text.find("expect:\n"));
  text = edit(text, "  v2: {value: s_dot@2, unit: m/s}\n  N: {value: \"impulse(incline, 1, 2)/(t@2 - t@1)\", unit: N}\n",
              "  v2: s_dot@2\n  Nx: \"impulse_x(incline, 1, 2)/(t@2 - t@1)\"\n");
  auto s = solve_text(text);
  ex m = kt::param(s.model, "m"), g = kt::param(s.model, "g"), b = kt::param(s.model, "beta"), t2 = kt::param(s.model, "t2");
  CHECK(kt::symbolically_zero(kt::result(s, "v2").closed - g * sin(b) * t2));
  // N n = m g cos(beta) (sin(beta), cos(beta)): its x component
  CHECK(kt::symbolically_zero(kt::result(s, "Nx").closed - m * g * cos(b) * sin(b)));
}

TEST_CASE("a track is written with one shape, a point and a direction or a centre and a radius", "[effects][track][errors]") {
  auto rod = derivation("energy/sliding_rod.yaml");
  auto with = [&](const std::string& track) { return edit(rod, "effects:\n", "effects:\n  slot: " + track + "\n"); };
  REQUIRE_THROWS_WITH(solve_text(with("{track: rod.A}")), Catch::Contains("needs one shape: 'line' or 'circle'"));
  REQUIRE_THROWS_WITH(solve_text(with("{track: rod.A, line: {through: [0, 0], along: [1, 0]}, circle: {centre: [0, 0], radius: l}}")),
                      Catch::Contains("needs one shape"));
  REQUIRE_THROWS_WITH(solve_text(with("{track: rod.A, line: [[0, 0], [1, 0]]}")), Catch::Contains("'line' is given by a point and a direction"));
  REQUIRE_THROWS_WITH(solve_text(with("{track: rod.A, line: {through: [0, 0], along: [0, 0]}}")),
                      Catch::Contains("the direction of the line of track 'slot' is zero"));
  REQUIRE_THROWS_WITH(solve_text(with("{track: rod.A, circle: {centre: [0, 0]}}")),
                      Catch::Contains("'circle' is given by its centre and radius"));
  REQUIRE_THROWS_WITH(solve_text(with("{track: rod.A, circle: {centre: [0, 0], radius: -l}}")), Catch::Contains("radius"));
  auto fixed = edit(rod, "coordinates:\n", "points:\n  O: [0, 0]\ncoordinates:\n");
  REQUIRE_THROWS_WITH(solve_text(edit(fixed, "effects:\n", "effects:\n  slot: {track: O, line: {through: [0, 0], along: [1, 0]}, holds: both}\n")),
                      Catch::Contains("a track holds a point of a body, but 'O' is a fixed point"));
}

TEST_CASE("a circular track's impulse has no fixed components, and its moment about the centre is none", "[effects][track][errors]") {
  // a bead on a smooth horizontal ring of radius R about O, at speed v0 at (R, 0): the ring's
  // force is radial, so about O: m R v0 = m R v at (0, R), where x_dot = -v0
  const std::string ring = R"Y(title: bead on a ring
parameters:
  m: kg
  R: m
  v0: m/s
points: {O: [0, 0]}
coordinates:
  th: rad
bodies:
  bead: {mass: m, inertia: particle, position: [R*cos(th), R*sin(th)]}
effects:
  ring: {track: bead, circle: {centre: [0, 0], radius: R}, holds: both}
states:
  1: {th: 0, th_dot: v0/R, t: 0}
  2: {th: pi/2, t: 1 s}
analyses:
  - angular_momentum: {from: 1, to: 2, about: O}
find:
  w2: th_dot@2
)Y";
  auto s = solve_text(ring);
  CHECK(kt::symbolically_zero(kt::result(s, "w2").closed - kt::param(s.model, "v0") / kt::param(s.model, "R")));
  REQUIRE_THROWS_WITH(solve_text(ring + "  J: \"impulse_x(ring, 1, 2)\"\n"),
                      Catch::Contains("the normal of track 'ring' turns with the motion"));
}

TEST_CASE("a track says whether it can only push or holds both ways", "[effects][track][errors]") {
  // the sliding rod's end A on y = 0 (normal k x t = +y) and the dome of ball_leaves_dome
  auto rod = derivation("energy/sliding_rod.yaml");
  auto with = [&](const std::string& track) { return edit(rod, "effects:\n", "effects:\n  slot: " + track + "\n"); };
  const std::string line = "{track: rod.A, line: {through: [0, 0], along: [1, 0]}";
  REQUIRE_THROWS_WITH(solve_text(with(line + "}")), Catch::Contains("track 'slot' does not say whether it can only push (a surface) or holds both ways") &&
                                                         Catch::Contains("'pushes: up'") && Catch::Contains("'holds: both'"));
  REQUIRE_THROWS_WITH(solve_text(with(line + ", pushes: up, holds: both}")), Catch::Contains("says both 'pushes' and 'holds'"));
  REQUIRE_THROWS_WITH(solve_text(with(line + ", holds: one}")), Catch::Contains("'holds' of track 'slot' is 'both'"));
  REQUIRE_THROWS_WITH(solve_text(with(line + ", pushes: sideways}")), Catch::Contains("is up, down, left, right or a direction [nx, ny], not 'sideways'"));
  REQUIRE_THROWS_WITH(solve_text(with(line + ", pushes: left}")), Catch::Contains("is not across the line through [0, 0] along [1, 0]"));
  REQUIRE_THROWS_WITH(solve_text(with(line + ", pushes: [1, 1]}")), Catch::Contains("this direction is not across"));
  REQUIRE_THROWS_WITH(solve_text(with(line + ", pushes: outward}")), Catch::Contains("not 'outward'"));
  CHECK_NOTHROW(solve_text(with(line + ", pushes: [0, -3]}")));
  CHECK_NOTHROW(solve_text(with(line + ", pushes: down}")));
  // (the sliding rod hangs below its end A: a surface there that pushes up would have it through it)
  REQUIRE_THROWS_WITH(solve_text(with(line + ", pushes: [0, 3]}")), Catch::Contains("track 'slot' only pushes, and at state '2' rod reaches"));
  auto dome = derivation("kinetics/ball_leaves_dome.yaml");
  REQUIRE_THROWS_WITH(solve_text(edit(dome, "pushes: outward}", "pushes: up}")), Catch::Contains("a circular track pushes 'outward'"));
  REQUIRE_THROWS_WITH(solve_text(edit(dome, "pushes: outward}", "pushes: [0, 1]}")), Catch::Contains("not a direction"));
  // a round body at an offset is on its side of the surface: pushed away from it
  auto wheel = derivation("energy/rolling_disk_incline.yaml");
  REQUIRE_THROWS_WITH(solve_text(edit(wheel, "pushes: [sin(beta), cos(beta)]", "pushes: [-sin(beta), -cos(beta)]")),
                      Catch::Contains("pushes the round body toward the surface"));
  CHECK_NOTHROW(solve_text(edit(wheel, ", pushes: [sin(beta), cos(beta)]", "")));  // the offset says it
}

TEST_CASE("a one-sided track's N is positive when it pushes, a guide's up whichever way its line is written (issue 44, item 7)",
          "[effects][track][kinetics]") {
  // the bar of bar_slides_on_floor with its floor written as pushing up, and as a guide along
  // [1, 0] or [-1, 0] (its normal k x t up, or down): N = m g/(1 + 3 cos^2(theta0)) = 4 m g/7 by
  // hand, positive up in each (the sign rule: a force across a horizontal line is counted up)
  auto bar = derivation("kinetics/bar_slides_on_floor.yaml");
  auto N = [&](const std::string& text) { return *kt::result(solve_text(text), "N1").si; };
  const GiNaC::numeric up = N(bar);
  CHECK(kinergy::numerics::format(up, 4) == "28.03");
  CHECK(N(edit(bar, "along: [1, 0]}, pushes: up}", "along: [-1, 0]}, holds: both}")) == up);
  CHECK(N(edit(bar, "along: [1, 0]}, pushes: up}", "along: [1, 0]}, holds: both}")) == up);
  CHECK(N(edit(bar, "along: [1, 0]}, pushes: up}", "along: [-1, 0]}, pushes: up}")) == up);
}

TEST_CASE("a pose that puts a body through a surface that only pushes is refused at the state (issue 47)", "[effects][track][pose]") {
  // By hand: the rod's end A on the floor, B = (0, L cos(theta)); at theta = 120 deg B is
  // L/2 = 1.5 m below the floor. At 60 deg it is above it, and the scene solves.
  const std::string text = kt::read_file(std::string(KINERGY_SOURCE_DIR) + "/tests/data/bad/rod_below_floor.yaml");
  REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("track 'floor' only pushes, and at state '2' rod reaches 1.5 m through it (at [0, -1.5])") &&
                                            Catch::Contains("a body rests on a surface, it does not pass through it"));
  CHECK_NOTHROW(solve_text(edit(text, "2: {theta: 120 deg}", "2: {theta: 60 deg}")));
}
