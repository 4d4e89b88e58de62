// Composite bodies (issue 27, item 3): one body of several parts welded together, its mass, mass
// centre and Ī by composition and the parallel-axis theorem. Expected values by hand, not from
// kinergy's output.
#include <catch2/catch.hpp>

#include <cmath>

#include "../support/helpers.hpp"
#include "../support/scene_errors.hpp"
#include "kinergy/draw/figure.hpp"

namespace {

using kt::solve_text;
const auto& value = kt::result_si;
using namespace kt_errors;

double num(const kinergy::model::Model& m, const GiNaC::ex& e) {
  return GiNaC::ex_to<GiNaC::numeric>(e.subs(m.parameter_values()).evalf()).to_double();
}


// A wheel: a ring (m1, radius R) with two diametral rods (m2 each, length 2R, one turned 90°),
// rolling without slipping down an incline of angle beta from rest through a distance s.
const std::string kWheel = R"(title: ring with two diametral rods rolls down an incline
parameters:
  m1: 2 kg
  m2: 0.5 kg
  R: 0.3 m
  beta: 30 deg
  s: 2 m
  g: 9.81 m/s^2
coordinates:
  x: m
  phi: rad
constraints:
  - x + R*phi = 0
bodies:
  wheel:
    parts:
      ring: {mass: m1, inertia: {ring: R}, at: [0, 0]}
      rod1: {mass: m2, inertia: {slender_rod: 2*R}, at: [0, 0]}
      rod2: {mass: m2, inertia: {slender_rod: 2*R}, at: [0, 0], angle: pi/2}
    position: [x*cos(beta) + R*sin(beta), -x*sin(beta) + R*cos(beta)]
    angle: phi
effects:
  gravity: {g: g}
states:
  1: {x: 0, x_dot: 0}
  2: {x: s}
analyses:
  - energy: {from: 1, to: 2}
find:
  v2: {value: x_dot@2, root: positive, unit: m/s}
)";

// A rod (m1, L) with a particle (m2) at its end B, pinned at its other end O.
const std::string kRodBall = R"(title: rod with a ball at its end
parameters:
  m1: 2 kg
  m2: 1 kg
  L: 0.9 m
  g: 9.81 m/s^2
points:
  O: [0, 0]
coordinates:
  theta: rad
bodies:
  arm:
    parts:
      rod: {mass: m1, inertia: {slender_rod: L}, at: [L/2, 0]}
      ball: {mass: m2, inertia: particle, at: [L, 0]}
    position: [0, 0]
    angle: theta
    points: {O: [0, 0], B: [L, 0]}
effects:
  gravity: {g: g}
  pivot: {pin: [O, arm.O]}
states:
  1: {theta: 0, theta_dot: 0}
  2: {theta: -pi/2}
analyses:
  - energy: {from: 1, to: 2}
find:
  omega2: {value: theta_dot@2, root: negative, unit: rad/s}
)";

}  // namespace

TEST_CASE("composite body: mass, mass centre and I by composition, points from the reference point, by hand", "[composite]") {
  auto s = solve_text(kRodBall);
  const auto& m = s.model;
  const auto& b = m.bodies.at(0);
  const double m1 = 2, m2 = 1, L = 0.9;
  // m = m1 + m2; c = (m1 L/2 + m2 L)/m; Ī = m1 L²/12 + m1 (L/2 − c)² + m2 (L − c)²
  const double c = (m1 * L / 2 + m2 * L) / (m1 + m2);
  const double I = m1 * L * L / 12 + m1 * (L / 2 - c) * (L / 2 - c) + m2 * (L - c) * (L - c);
  CHECK(num(m, b.mass) == Approx(3.0).epsilon(1e-15));
  CHECK(num(m, b.inertia) == Approx(I).epsilon(1e-14));
  // its mass centre at c along the arm (theta = 0: on x); the points measured from O, not from G
  GiNaC::exmap at0{{m.coords[0].q, 0}};
  CHECK(num(m, b.x.subs(at0)) == Approx(c).epsilon(1e-14));
  CHECK(num(m, b.y.subs(at0)) == Approx(0.0).margin(1e-15));
  CHECK(num(m, b.points.at("O").first) == Approx(-c).epsilon(1e-14));
  CHECK(num(m, b.points.at("B").first) == Approx(L - c).epsilon(1e-14));
  // energy: I_O ω² / 2 = g (m1 L/2 + m2 L) with I_O = m1 L²/3 + m2 L²
  const double IO = m1 * L * L / 3 + m2 * L * L;
  CHECK(value(s, "omega2") == Approx(-std::sqrt(2 * 9.81 * (m1 * L / 2 + m2 * L) / IO)).epsilon(1e-13));
}

TEST_CASE("composite body: a ring with two diametral rods rolls down an incline, by hand", "[composite]") {
  auto s = solve_text(kWheel);
  // Ī = m1 R² + 2 m2 (2R)²/12, M = m1 + 2 m2; M g s sin β = (M + Ī/R²) v²/2
  const double m1 = 2, m2 = 0.5, R = 0.3, M = m1 + 2 * m2, I = m1 * R * R + 2 * m2 * 4 * R * R / 12;
  CHECK(num(s.model, s.model.bodies[0].inertia) == Approx(I).epsilon(1e-14));
  const double v = std::sqrt(2 * M * 9.81 * 2 * 0.5 / (M + I / (R * R)));
  CHECK(value(s, "v2") == Approx(v).epsilon(1e-13));
  // drawn: every part's outline, a circle (the ring) and two bars of length 2R across it, the
  // second turned 90° (the wheel at phi = 0: one along the incline, one across it)
  const auto f = kinergy::draw::scene_at(s.model, s.branch.sol, kinergy::parameter_values(s), 0);
  int circles = 0;
  std::vector<double> lengths, dirs;
  for (auto& sh : f.shapes()) {
    if (sh.ink != kinergy::draw::Ink::Body) continue;
    if (sh.kind == kinergy::draw::Figure::Shape::Circle) {
      ++circles;
      CHECK(sh.r == Approx(R).epsilon(1e-12));
    }
    if (sh.kind == kinergy::draw::Figure::Shape::Line) {
      const double dx = sh.pts[1].first - sh.pts[0].first, dy = sh.pts[1].second - sh.pts[0].second;
      lengths.push_back(std::hypot(dx, dy));
      dirs.push_back(std::atan2(dy, dx));
    }
  }
  CHECK(circles == 1);
  REQUIRE(lengths.size() == 2);
  CHECK(lengths[0] == Approx(2 * R).epsilon(1e-12));
  CHECK(lengths[1] == Approx(2 * R).epsilon(1e-12));
  CHECK(std::fabs(std::cos(dirs[0] - dirs[1])) < 1e-12);  // at right angles
}

TEST_CASE("composite body: what is refused", "[composite][errors]") {
  // mass or inertia beside parts
  std::string t = edit(kRodBall, "  arm:\n    parts:", "  arm:\n    mass: m1\n    parts:");
  expect_error(t, at(t, "m1\n    parts"), "has 'parts', so its mass is theirs", "remove 'mass'");
  // a part without its place
  t = edit(kRodBall, "ball: {mass: m2, inertia: particle, at: [L, 0]}", "ball: {mass: m2, inertia: particle}");
  expect_error(t, at(t, "ball:"), "part 'ball' of body 'arm' has no 'at'", "at: [x, y]");
  // an unknown key in a part
  t = edit(kRodBall, "at: [L, 0]}", "at: [L, 0], radius: 1}");
  expect_error(t, at(t, "radius"), "unknown key 'radius'");
  // parts of no mass together
  t = edit(edit(kRodBall, "  m1: 2 kg", "  m1: 0 kg"), "  m2: 1 kg", "  m2: 0 kg");
  expect_error(t, at(t, "rod: {"), "have no mass together", "give a part its mass");
  // a part's place that moves with the coordinates
  t = edit(kRodBall, "at: [L, 0]}", "at: [L*cos(theta), 0]}");
  expect_error(t, at(t, "theta), 0]"), "only parameters may stand here");
  // no parts
  t = edit(kRodBall, "    parts:\n      rod: {mass: m1, inertia: {slender_rod: L}, at: [L/2, 0]}\n      ball: {mass: m2, inertia: particle, at: [L, 0]}\n",
           "    parts: {}\n");
  expect_error(t, at(t, "parts: {}", 7), "has no parts");
}
