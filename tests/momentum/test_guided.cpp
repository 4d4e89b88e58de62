// Moments of a system whose supports cancel (issue 27, item 5): a body the coordinates hold to a
// fixed line without turning (a block on a table) is balanced across its line by its support, so
// about a point P only the components of its loads along the line count, at its mass centre; and
// moments about a place that moves parallel to the mass centre (the point of a cable a drum
// climbs). Expected values by hand (each body isolated, Newton-Euler; the derivations' own are
// re-derived by tests/momentum/sympy_supports.py), not from kinergy's output.
#include <catch2/catch.hpp>

#include <cmath>

#include "../support/helpers.hpp"
#include "kinergy/emit/derive.hpp"

namespace {

using kt::solve_text;
const auto& value = kt::result_si;

// derivations/momentum/drum_blocks_on_table.yaml with its friction as FRICTION and B's cord as CORD
std::string drum_and_blocks(const std::string& friction, const std::string& cord, const std::string& b_at = "[xB, r]") {
  return R"(title: drum, hanging block, block on a table
parameters:
  M: 8 kg
  r: 0.25 m
  mA: 5 kg
  mB: 4 kg
  mu: 0.2
  a: 1 m
  b: 1 m
  t1: 2 s
  g: 9.81 m/s^2
points:
  O: [0, 0]
coordinates:
  phi: rad
  yA: m
  xB: m
bodies:
  drum: {mass: M, inertia: {disk: r}, position: [0, 0], angle: phi}
  blockA: {mass: mA, inertia: particle, position: [r, yA]}
  blockB: {mass: mB, inertia: particle, position: )" + b_at + R"(}
constraints:
  - yA = r*phi - a
  - )" + cord + R"(
effects:
  gravity: {g: g}
  axle: {pin: [O, drum]}
)" + friction + R"(
states:
  1: {t: 0, phi: 0, phi_dot: 0}
  2: {t: t1}
analyses:
  - angular_momentum: {from: 1, to: 2, about: O}
find:
  omega2: {value: phi_dot@2, unit: rad/s}
)";
}

// derivations/momentum/drum_climbs_cable.yaml, moments about ABOUT, with the couple MC
std::string climbing_drum(const std::string& about, const std::string& Mc = "80 N*m") {
  return R"(title: drum climbs its cable
parameters:
  m: 20 kg
  r: 0.3 m
  k: 0.25 m
  Mc: )" + Mc + R"(
  t1: 3 s
  g: 9.81 m/s^2
coordinates:
  y: m
  phi: rad
bodies:
  drum: {mass: m, inertia: {gyration: k}, position: [0, y], angle: phi}
effects:
  gravity: {g: g}
  motor: {couple: drum, M: Mc}
  cable: {constraint: "y = r*phi", between: [drum, ground], at: [-r, y]}
states:
  1: {t: 0, y: 0, phi: 0, phi_dot: 0}
  2: {t: t1}
analyses:
  - angular_momentum: {from: 1, to: 2, about: )" + about + R"(}
find:
  omega2: {value: phi_dot@2, unit: rad/s}
)";
}

}  // namespace

TEST_CASE("moments about an axle with a block on a level table: its weight and the table's normal force cancel",
          "[momentum][supports][guided]") {
  const double M = 8, r = 0.25, mA = 5, mB = 4, mu = 0.2, t1 = 2, g = 9.81;
  SECTION("with kinetic friction under B") {
    // drum: I φ̈ = −r T_A + r T_B; A: m_A r φ̈ = T_A − m_A g; B: −m_B r φ̈ = T_B − μ m_B g
    //   ⇒ φ̈ = −(m_A − μ m_B) g / (r (M/2 + m_A + m_B))
    auto s = solve_text(drum_and_blocks("  table: {friction: blockB, mu: mu, normal: mB*g, direction: positive}", "xB = -r*phi - b"));
    CHECK(value(s, "omega2") == Approx(-(mA - mu * mB) * g * t1 / (r * (M / 2 + mA + mB))).epsilon(1e-12));
  }
  SECTION("on a smooth table") {
    auto s = solve_text(drum_and_blocks("", "xB = -r*phi - b"));
    CHECK(value(s, "omega2") == Approx(-mA * g * t1 / (r * (M / 2 + mA + mB))).epsilon(1e-12));
  }
  SECTION("the derivation says how the table was taken") {
    const std::string text = kinergy::emit::text(kinergy::emit::derive(solve_text(drum_and_blocks("", "xB = -r*phi - b"))));
    CHECK_THAT(text, Catch::Contains("blockB keeps to a fixed straight line without turning"));
  }
}

TEST_CASE("moments with a block on a table: what the support's answer cannot be known for is refused",
          "[momentum][supports][guided][errors]") {
  SECTION("a cord to B that is not parallel to the table (its pull turns with the motion)") {
    // B on the floor (y = 0), the cord from the drum's top at height r runs down to it
    auto text = drum_and_blocks("", "sqrt(xB^2 + r^2) = -r*phi + b", "[xB, 0]");
    REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("pulls on 'blockB' in a direction that changes with the motion"));
  }
  SECTION("friction between a block and a cart it rides on, their mass centres at different heights") {
    const std::string cart = R"(title: block on a cart
parameters:
  m: 2 kg
  mc: 6 kg
  mu: 0.3
  h: 0.4 m
  g: 9.81 m/s^2
  v0: 3 m/s
points:
  O: [0, 0]
coordinates:
  x: m
  xc: m
bodies:
  block: {mass: m, inertia: particle, position: [x, h]}
  cart: {mass: mc, inertia: particle, position: [xc, 0]}
effects:
  gravity: {g: g}
  rub: {friction: block, against: cart, at: [x, h], mu: mu, normal: m*g}
states:
  1: {t: 0, x: 0, xc: 0, x_dot: v0, xc_dot: 0}
  2: {t: 0.2 s}
analyses:
  - angular_momentum: {from: 1, to: 2, about: O}
find:
  v2: {value: xc_dot@2, unit: m/s}
)";
    REQUIRE_THROWS_WITH(solve_text(cart), Catch::Contains("effect 'rub' pushes on 'cart' across its line (or with a moment about its mass centre)"));
  }
}

TEST_CASE("angular momentum about a place that moves parallel to the mass centre", "[momentum][supports][about]") {
  const double m = 20, r = 0.3, k = 0.25, t1 = 3, g = 9.81;
  SECTION("the point of the cable a drum climbs") {
    // m ÿ = T − m g, m k² φ̈ = M_c − r T, ÿ = r φ̈  ⇒  φ̈ = (M_c − m g r)/(m (k² + r²))
    auto s = solve_text(climbing_drum("{C: [-r, y]}"));
    CHECK(value(s, "omega2") == Approx(t1 * (80 - m * g * r) / (m * (k * k + r * r))).epsilon(1e-12));
  }
  SECTION("with no couple the drum unwinds and falls") {
    auto s = solve_text(climbing_drum("{C: [-r, y]}", "0 N*m"));
    CHECK(value(s, "omega2") == Approx(-t1 * g * r / (k * k + r * r)).epsilon(1e-12));
  }
  SECTION("a place that moves across the mass centre's velocity: refused") {
    REQUIRE_THROWS_WITH(solve_text(climbing_drum("{C: [y, 0]}")),
                        Catch::Contains("does not hold: it moves, and not parallel to the mass centre"));
  }
  SECTION("a place named like a body: refused") {
    REQUIRE_THROWS_WITH(solve_text(climbing_drum("{drum: [-r, y]}")), Catch::Contains("'drum' already names a body"));
  }
  SECTION("a place of one coordinate: refused, with the form to write") {
    REQUIRE_THROWS_WITH(solve_text(climbing_drum("{C: [-r]}")), Catch::Contains("write e.g. about: {C: [-r, y]}"));
  }
  SECTION("two places: refused") {
    REQUIRE_THROWS_WITH(solve_text(climbing_drum("{C: [-r, y], D: [0, 0]}")),
                        Catch::Contains("'about' as a place names one point and where it is"));
  }
}

TEST_CASE("a condition on a parameter without a value is stated with the closed form, not judged at sample values",
          "[momentum][conditions]") {
  // the friction under B is declared to oppose B sliding the positive way; with mA and mu
  // without values, that holds where vB2 = 2 g t1 (mA − mu mB)/(M + 2 mA + 2 mB) ≥ 0 — once
  // judged at the sample values standing in for mA and mu, and refused
  auto text = kt::edit(kt::edit(drum_and_blocks("  table: {friction: blockB, mu: mu, normal: mB*g, direction: positive}", "xB = -r*phi - b"),
                                "  mA: 5 kg\n", "  mA: kg\n"),
                       "  mu: 0.2\n", "  mu: number\n");
  text = kt::edit(text, "omega2: {value: phi_dot@2, unit: rad/s}", "omega2: phi_dot@2");
  auto s = solve_text(text);
  REQUIRE(s.valid_where.size() == 1);
  const auto& m = s.model;
  const GiNaC::ex g = kt::param(m, "g"), t1 = kt::param(m, "t1"), mA = kt::param(m, "mA"), mB = kt::param(m, "mB"),
                  mu = kt::param(m, "mu"), M = kt::param(m, "M");
  const GiNaC::ex want = 2 * g * t1 * (mA - mu * mB) / (M + 2 * mA + 2 * mB);
  CHECK(kt::symbolically_zero(s.valid_where[0].e - want));
  CHECK_THAT(s.valid_where[0].assumed, Catch::Contains("the sliding under 'table' goes the declared way (positive) at state '2'"));
  CHECK_THAT(kinergy::emit::text(kinergy::emit::derive(s)), Catch::Contains("Valid only where"));
}

namespace {

// a gear (M, r) on a fixed axle turned by a couple M0 drives a rack (mR) whose mass centre is e
// below the pitch line; the rack slides on a smooth guide
std::string rack_and_gear(const std::string& e) {
  return R"(title: rack and gear
parameters:
  M: 10 kg
  r: 0.2 m
  mR: 6 kg
  e: )" + e + R"(
  M0: 12 N*m
  t1: 2 s
  g: 9.81 m/s^2
points:
  O: [0, 0]
coordinates:
  phi: rad
  x: m
bodies:
  gear: {mass: M, inertia: {disk: r}, position: [0, 0], angle: phi}
  rack: {mass: mR, inertia: particle, position: [x, -r - e]}
constraints:
  - x = r*phi
effects:
  gravity: {g: g}
  motor: {couple: gear, M: M0}
  axle: {pin: [O, gear]}
states:
  1: {t: 0, phi: 0, phi_dot: 0}
  2: {t: t1}
analyses:
  - angular_momentum: {from: 1, to: 2, about: O}
find:
  omega2: {value: phi_dot@2, unit: rad/s}
)";
}

}  // namespace

TEST_CASE("moments with a guided body: a cord or a mesh to it must keep its length as the set turns about P",
          "[momentum][supports][guided]") {
  SECTION("a block on an incline held by a cord along the incline from a drum: the cord's pull is along its line") {
    // drum (M, r) on a fixed axle; the block (m) below it on a smooth 30° incline, the cord
    // leaving the drum at (−r sin β, −r cos β) along (cos β, −sin β):
    //   m s̈ = m g sin β − T,  (M r²/2) φ̈ = r T,  s̈ = r φ̈  ⇒  φ̈ = 2 m g sin β/(r (M + 2 m))
    const std::string text = R"(title: block on incline held by a cord from a drum
parameters:
  M: 10 kg
  r: 0.3 m
  m: 8 kg
  beta: 30 deg
  s0: 1 m
  t1: 1.5 s
  g: 9.81 m/s^2
points:
  O: [0, 0]
coordinates:
  phi: rad
  s: m
bodies:
  drum: {mass: M, inertia: {disk: r}, position: [0, 0], angle: phi}
  block: {mass: m, inertia: particle, position: [-r*sin(beta) + s*cos(beta), -r*cos(beta) - s*sin(beta)]}
constraints:
  - s = s0 + r*phi
effects:
  gravity: {g: g}
  axle: {pin: [O, drum]}
states:
  1: {t: 0, phi: 0, phi_dot: 0}
  2: {t: t1}
analyses:
  - angular_momentum: {from: 1, to: 2, about: O}
find:
  omega2: {value: phi_dot@2, unit: rad/s}
)";
    const double M = 10, r = 0.3, m = 8, beta = M_PI / 6, t1 = 1.5, g = 9.81;
    CHECK(value(solve_text(text), "omega2") == Approx(2 * m * g * std::sin(beta) * t1 / (r * (M + 2 * m))).epsilon(1e-12));
  }
  SECTION("a rack on its pitch line: right; a rack whose mass centre is off the pitch line: refused") {
    // (M r²/2) φ̈ = M0 − r F, mR r φ̈ = F  ⇒  φ̈ = 2 M0/(r² (M + 2 mR))
    const double M = 10, r = 0.2, mR = 6, M0 = 12, t1 = 2;
    CHECK(value(solve_text(rack_and_gear("0 m")), "omega2") == Approx(2 * M0 * t1 / (r * r * (M + 2 * mR))).epsilon(1e-12));
    // the tooth force acts on the pitch line, e off the rack's mass centre: the guide answers
    // with a couple of unknown size (it was once taken as 2 M0 t1/(r (2 e mR + 2 mR r + M r)))
    REQUIRE_THROWS_WITH(solve_text(rack_and_gear("0.05 m")), Catch::Contains("cannot turn freely about O"));
  }
  SECTION("a block on a table whose mass centre is below the cord: refused") {
    REQUIRE_THROWS_WITH(solve_text(drum_and_blocks("", "xB = -r*phi - b", "[xB, r/2]")), Catch::Contains("cannot turn freely about O"));
  }
  SECTION("a named cord whose two places are not on one line along its pull: refused") {
    auto text = kt::edit(drum_and_blocks("  cordB: {constraint: \"xB = -r*phi - b\", between: [drum, blockB], at: [[0, r], [xB, r/2]]}",
                                         "yA = r*phi - a", "[xB, r/2]"),
                         "  - yA = r*phi - a\n  - yA = r*phi - a\n", "  - yA = r*phi - a\n");
    REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("which are not on one line along it"));
  }
}

TEST_CASE("moments about a point: what the balance cannot know is refused, also with symbols", "[momentum][supports][errors]") {
  SECTION("a relation between the bodies that turning them together breaks (a reversing gear train: its housing takes a moment)") {
    // two disks on one axle, p2 = −p1 through gears in a fixed carrier: about O the carrier's
    // moment is unknown (it was once taken as zero: 2 M0 t1/(I1r² m1 − m2 r2²), not
    // 2 M0 t1/(I1r² m1 + m2 r2²) as Lagrange gives)
    const std::string text = R"(title: reversing gearbox
parameters: {I1r: m, m1: kg, m2: kg, r2: m, M0: N*m, t1: s, g: 9.81 m/s^2}
points: {O: [0, 0]}
coordinates: {p1: rad, p2: rad}
bodies:
  d1: {mass: m1, inertia: {disk: I1r}, position: [0, 0], angle: p1}
  d2: {mass: m2, inertia: {disk: r2}, position: [0, 0], angle: p2}
constraints:
  - p2 = -p1
effects:
  gravity: {g: g}
  motor: {couple: d1, M: M0}
states:
  1: {t: 0, p1: 0, p1_dot: 0}
  2: {t: t1}
analyses:
  - angular_momentum: {from: 1, to: 2, about: O}
find:
  w: p1_dot@2
)";
    REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("or a relation between them (a cord, a gear train) does not hold as they turn together"));
  }
  SECTION("a pin's reaction about a place that moves in time: its moment changes over the interval") {
    const std::string text = R"(title: flywheel about a moving place
parameters: {M: 8 kg, r: 0.25 m, M0: 3 N*m, v0: 2 m/s, t1: s, g: 9.81 m/s^2}
points: {O: [0, 0]}
coordinates: {phi: rad}
bodies:
  drum: {mass: M, inertia: {disk: r}, position: [0, 0], angle: phi}
effects:
  gravity: {g: g}
  axle: {pin: [O, drum]}
  motor: {couple: drum, M: M0}
states:
  1: {t: 0, phi: 0, phi_dot: 0}
  2: {t: t1}
analyses:
  - angular_momentum: {from: 1, to: 2, about: {C: [v0*t, 0]}}
find:
  w: phi_dot@2
)";
    REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("the reaction of 'axle' has a moment about C that changes with the motion (or in time)"));
  }
  SECTION("an unknown parameter in the geometry: the block below its cord is still refused") {
    auto text = kt::edit(drum_and_blocks("", "xB = -r*phi - b", "[xB, r/2]"), "  r: 0.25 m\n", "  r: unknown m\n");
    text = kt::edit(kt::edit(text, "  2: {t: t1}", "  2: {t: t1, phi_dot: -20 rad/s}"), "omega2: {value: phi_dot@2, unit: rad/s}", "radius: {value: r, unit: m}");
    REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("cannot turn freely about O"));
  }
}

TEST_CASE("the check that a set moves freely finds positions where a small geometry is defined", "[momentum][supports]") {
  // a ball in a circular groove of radius R = 2 mm in a cart on a smooth floor, from u1 = 1.5 mm
  // at rest to the bottom: momentum along x is conserved (nothing pushes along x) and energy
  //   m g (R − √(R² − u1²)) = ½ M V² + ½ m (V + v)²,  M V + m (V + v) = 0
  //   ⇒ V = m √(2 g (M + m)(R − √(R² − u1²))/M)/(M + m)
  // (its positions are defined only for |u| ≤ R: once refused, as no random place in (−2, 2) had one)
  const std::string text = R"(title: ball in a small groove of a cart
parameters: {M: 3 kg, m: 0.5 kg, R: 0.002 m, u1: 0.0015 m, g: 9.81 m/s^2}
coordinates: {x: m, u: m}
bodies:
  cart: {mass: M, inertia: particle, position: [x, 0]}
  ball: {mass: m, inertia: particle, position: [x + u, R - sqrt(R^2 - u^2)]}
effects:
  gravity: {g: g}
states:
  1: {x: 0, x_dot: 0, u: u1, u_dot: 0}
  2: {u: 0}
analyses:
  - momentum: {from: 1, to: 2, along: x, conserved: true}
  - energy: {from: 1, to: 2}
find:
  V: {value: x_dot@2, unit: m/s}
  vu: {value: u_dot@2, root: negative, unit: m/s}
)";
  const double M = 3, m = 0.5, R = 0.002, u1 = 0.0015, g = 9.81;
  const double V = m * std::sqrt(2 * g * (M + m) * (R - std::sqrt(R * R - u1 * u1)) / M) / (M + m);
  CHECK(value(solve_text(text), "V") == Approx(V).epsilon(1e-12));
}
