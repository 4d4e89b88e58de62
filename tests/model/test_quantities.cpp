// Power, velocity and angular momentum, each checked against a second computation written in
// the test: F·v and M ω by hand, v_P = v̄ + ω k × (r_P − r_G), H_O = I_O ω.
#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

#include "../support/helpers.hpp"

using namespace GiNaC;
using kinergy::model::Model;

namespace {

/// Random exact values for the parameters without a value, every coordinate, rate and t; the
/// parameters with a value keep it.
exmap random_state(const Model& m, std::mt19937& rng) {
  exmap v = m.parameter_values();
  for (auto& p : m.params)
    if (!p.value) v[p.sym] = kt::random_rational(rng, 1, 3);
  for (auto& c : m.coords) {
    v[c.q] = kt::random_rational(rng, -3, 3);
    v[c.qd] = kt::random_rational(rng, -3, 3);
  }
  v[m.t] = kt::random_rational(rng, 0, 3);
  return v;
}

/// Equal symbolically, and at a few random points to 40 digits.
void check_same(const Model& m, const ex& a, const ex& b, std::mt19937& rng) {
  INFO("library: " << a);
  INFO("by hand: " << b);
  CHECK(kt::symbolically_zero(a - b));
  for (int i = 0; i < 4; ++i) {
    exmap at = random_state(m, rng);
    CHECK(kt::close(kt::value(a, at, 45), kt::value(b, at, 45), kt::tol(40)));
  }
}

const char* kBar = R"(title: bar pinned at O with loads
parameters:
  m: kg
  L: m
  g: m/s^2
  P: N
  Q: N
  M0: N*m
  c: N*m
  k: N/m
  L0: m
  Mf: N*m
  W: W
points:
  O: [0, 0]
  C: [0, 2*L]
coordinates:
  theta: rad
bodies:
  bar:
    mass: m
    inertia: {slender_rod: L}
    position: [L/2*cos(theta), L/2*sin(theta)]
    angle: theta
    points: {O: [-L/2, 0], B: [L/2, 0]}
effects:
  gravity: {g: g}
  pivot: {pin: [O, bar.O]}
  push: {force: bar.B, F: [P, Q]}
  drive: {couple: bar, M: M0}
  winder: {couple: bar, M: c*theta}
  spring_BC: {spring: [bar.B, C], k: k, free_length: L0}
  brake: {friction_couple: bar, M: Mf}
  motor: {power: bar, P: W}
)";

}  // namespace

TEST_CASE("power of each effect on a pinned bar equals F.v and M omega by hand", "[model][power][two-ways]") {
  Model m = kt::model_of(kBar);
  std::mt19937 rng(99);
  ex mm = kt::param(m, "m"), L = kt::param(m, "L"), g = kt::param(m, "g"), P = kt::param(m, "P"),
     Q = kt::param(m, "Q"), M0 = kt::param(m, "M0"), c = kt::param(m, "c"), k = kt::param(m, "k"),
     L0 = kt::param(m, "L0"), Mf = kt::param(m, "Mf"), W = kt::param(m, "W");
  ex th = kt::coord(m, "theta").q, w = kt::coord(m, "theta").qd;
  // end B: r_B = L (cos θ, sin θ), v_B = L ω (−sin θ, cos θ)
  ex vBx = -L * w * sin(th), vBy = L * w * cos(th);

  SECTION("force at a body point: P = F . v_B") {
    check_same(m, m.power(kt::effect(m, "push")), P * vBx + Q * vBy, rng);
  }
  SECTION("constant couple: P = M omega") {
    check_same(m, m.power(kt::effect(m, "drive")), M0 * w, rng);
  }
  SECTION("couple depending on the angle: P = c theta omega") {
    check_same(m, m.power(kt::effect(m, "winder")), c * th * w, rng);
  }
  SECTION("gravity: P = (0, -m g) . v_G") {
    check_same(m, m.power(kt::effect(m, "gravity")), -mm * g * (L / 2 * w * cos(th)), rng);
  }
  SECTION("friction couple: P = -Mf |omega|") {
    Model const& mc = m;
    ex p = mc.power(kt::effect(m, "brake"));
    for (int i = 0; i < 6; ++i) {
      exmap at = random_state(m, rng);
      CHECK(kt::close(kt::value(p, at), kt::value(-Mf * abs(w), at), kt::tol(40)));
    }
  }
  SECTION("power drive: P = W") {
    CHECK(kt::symbolically_zero(m.power(kt::effect(m, "motor")) - W));
  }
  SECTION("spring: P = F . v_B with F = k (|BC| - L0) (C - B)/|BC|") {
    // by hand, numerically: C = (0, 2L)
    ex dx = 0 - L * cos(th), dy = 2 * L - L * sin(th);
    ex len = sqrt(dx * dx + dy * dy);
    ex F = k * (len - L0);  // tension pulls B towards C
    ex hand = F * (dx * vBx + dy * vBy) / len;
    ex lib = m.power(kt::effect(m, "spring_BC"));
    for (int i = 0; i < 6; ++i) {
      exmap at = random_state(m, rng);
      CHECK(kt::close(kt::value(lib, at), kt::value(hand, at), kt::tol(40)));
    }
  }
  SECTION("the built-in power(effect) of an expression is the same quantity") {
    ex parsed = m.parse("power(push)", {"<test>", 1, 1}, false);
    CHECK(kt::symbolically_zero(parsed - (P * vBx + Q * vBy)));
  }
}

TEST_CASE("power of a force applied at a world place (cord leaving a drum)", "[model][power][two-ways]") {
  // drum of radius r turning about its centre O; a cord leaves it at (r, 0) and pulls down with W
  Model m = kt::model_of(R"(title: drum and cord
parameters:
  m: kg
  r: m
  W: N
points:
  O: [0, 0]
coordinates:
  phi: rad
bodies:
  drum:
    mass: m
    inertia: {disk: r}
    position: [0, 0]
    angle: phi
effects:
  axle: {pin: [O, drum]}
  cord: {force: drum, at: [r, 0], F: [0, -W]}
)");
  std::mt19937 rng(5);
  ex r = kt::param(m, "r"), W = kt::param(m, "W"), w = kt::coord(m, "phi").qd;
  // the material point at (r, 0) moves with ω k × (r, 0) = (0, r ω): P = −W r ω
  check_same(m, m.power(kt::effect(m, "cord")), -W * r * w, rng);
  // its generalized force is the moment of the cord about O
  check_same(m, m.generalized_force(kt::effect(m, "cord"), 0), -W * r, rng);
}

TEST_CASE("friction power is -mu N |v| along an incline", "[model][power]") {
  Model m = kt::model_of(R"(title: block on incline
parameters:
  m: kg
  beta: rad
  mu: 0.3
  N0: N
coordinates:
  x: m
bodies:
  block:
    mass: m
    inertia: particle
    position: [x*cos(beta), x*sin(beta)]
effects:
  rub: {friction: block, mu: mu, normal: N0}
)");
  std::mt19937 rng(11);
  ex mu = kt::param(m, "mu"), N0 = kt::param(m, "N0"), xd = kt::coord(m, "x").qd;
  ex p = m.power(kt::effect(m, "rub"));
  int negative_rates = 0;
  for (int i = 0; i < 10; ++i) {
    exmap at = random_state(m, rng);
    negative_rates += kt::value(xd, at).is_negative();
    CHECK(kt::close(kt::value(p, at), kt::value(-mu * N0 * abs(xd), at), kt::tol(40)));
    CHECK(kt::value(p, at) <= 0);  // friction never feeds energy in
  }
  CHECK(negative_rates > 0);  // both senses of sliding were tried
}

TEST_CASE("power of every non-friction effect equals sum Q_i qdot_i (two routes)", "[model][power][two-ways]") {
  // power() uses F·v (velocity by differentiation); generalized_force() uses F·∂r/∂q
  std::mt19937 rng(3);
  for (auto& f : kt::derivation_scenes()) {
    DYNAMIC_SECTION(std::filesystem::path(f).filename().string()) {
      Model m = kt::model_of_file(f);
      for (auto& e : m.effects) {
        if (e.kind == "friction" || e.kind == "friction_couple" || e.kind == "power") continue;
        ex sum = 0;
        for (std::size_t i = 0; i < m.coords.size(); ++i) sum += m.generalized_force(e, i) * m.coords[i].qd;
        ex p = m.power(e);
        INFO(e.name << " (" << e.kind << "): power = " << p << ", sum Q qdot = " << sum);
        for (int t = 0; t < 3; ++t) {
          exmap at = random_state(m, rng);
          auto a = kinergy::numerics::evaluate(p, at, 45), b = kinergy::numerics::evaluate(sum, at, 45);
          if (!a || !b) continue;  // a spring length sqrt() may be complex off the real path
          CHECK(kt::close(*a, *b, kt::tol(38)));
        }
      }
    }
  }
}

TEST_CASE("velocity of body points: derivative of position equals v_G + omega k x (r_P - r_G)",
          "[model][kinematics][two-ways]") {
  std::mt19937 rng(17);
  for (auto& f : kt::derivation_scenes()) {
    DYNAMIC_SECTION(std::filesystem::path(f).filename().string()) {
      Model m = kt::model_of_file(f);
      for (std::size_t b = 0; b < m.bodies.size(); ++b) {
        const auto& body = m.bodies[b];
        ex w = m.omega(static_cast<int>(b));
        ex vgx = m.rate(body.x), vgy = m.rate(body.y);
        for (auto& [name, p] : body.points) {
          auto ref = m.point(body.name + "." + name);
          auto [px, py] = m.position(ref);
          auto [vx, vy] = m.velocity(ref);
          // rigid body: v_P = v_G + ω k × (r_P − r_G) = (vGx − ω (yP − yG), vGy + ω (xP − xG))
          ex hx = vgx - w * (py - body.y), hy = vgy + w * (px - body.x);
          INFO(body.name << "." << name);
          CHECK(kt::symbolically_zero(vx - hx));
          CHECK(kt::symbolically_zero(vy - hy));
          // and |r_P − r_G| is the body-frame distance (the point is fixed in the body)
          CHECK(kt::symbolically_zero(pow(px - body.x, 2) + pow(py - body.y, 2) - p.first * p.first -
                                      p.second * p.second));
          // speed(P) is |v_P|
          ex speed = m.parse("speed(" + body.name + "." + name + ")", {"<test>", 1, 1}, false);
          exmap at = random_state(m, rng);
          CHECK(kt::close(kt::value(speed, at), kt::value(sqrt(hx * hx + hy * hy), at), kt::tol(40)));
        }
      }
    }
  }
}

TEST_CASE("angular momentum about a fixed point", "[model][momentum][two-ways]") {
  SECTION("pendulum bar about its pin: H_O = I_O omega = m L^2/3 omega") {
    Model m = kt::model_of(kBar);
    ex mm = kt::param(m, "m"), L = kt::param(m, "L"), w = kt::coord(m, "theta").qd;
    CHECK(kt::symbolically_zero(m.angular_momentum(m.point("O")) - mm * L * L / 3 * w));
    // about the mass centre only the spin part remains: H_G = Ī ω
    CHECK(kt::symbolically_zero(m.angular_momentum(m.point("bar")) - mm * L * L / 12 * w));
    // the same through the expression language
    CHECK(kt::symbolically_zero(m.parse("H(O)", {"<test>", 1, 1}, false) - mm * L * L / 3 * w));
  }
  SECTION("disk rolling on the floor, about a fixed point of the floor: H = (Ibar + m r^2) omega") {
    Model m = kt::model_of(R"(title: rolling disk
parameters:
  m: kg
  r: m
  s: m
points:
  F: [s, 0]
coordinates:
  x: m
bodies:
  disk:
    mass: m
    inertia: {disk: r}
    position: [x, r]
    angle: -x/r
)");
    ex mm = kt::param(m, "m"), r = kt::param(m, "r"), xd = kt::coord(m, "x").qd;
    ex w = -xd / r;
    CHECK(kt::symbolically_zero(m.omega(0) - w));
    CHECK(kt::symbolically_zero(m.angular_momentum(m.point("F")) - (mm * r * r / 2 + mm * r * r) * w));
  }
  SECTION("particle in circular motion about O: H = m R^2 omega, independent of the angle") {
    Model m = kt::model_of(R"(title: particle on a circle
parameters:
  m: kg
  R: m
points:
  O: [0, 0]
coordinates:
  theta: rad
bodies:
  p:
    mass: m
    inertia: particle
    position: [R*cos(theta), R*sin(theta)]
)");
    ex mm = kt::param(m, "m"), R = kt::param(m, "R"), w = kt::coord(m, "theta").qd;
    CHECK(kt::symbolically_zero(m.angular_momentum(m.point("O")) - mm * R * R * w));
  }
}

TEST_CASE("rate() differentiates along the motion, including explicit time", "[model][kinematics]") {
  Model m = kt::model_of(R"(title: rate
parameters:
  a: m
  w0: rad/s
  mp: 1 kg
coordinates:
  x: m
  theta: rad
bodies:
  p:
    mass: mp
    inertia: particle
    position: [x, 0]
)");
  ex x = kt::coord(m, "x").q, xd = kt::coord(m, "x").qd;
  ex th = kt::coord(m, "theta").q, thd = kt::coord(m, "theta").qd;
  ex a = kt::param(m, "a"), w0 = kt::param(m, "w0");
  ex e = x * x * sin(th) + a * cos(w0 * m.t);
  ex hand = 2 * x * xd * sin(th) + x * x * cos(th) * thd - a * w0 * sin(w0 * m.t);
  CHECK(kt::symbolically_zero(m.rate(e) - hand));
}

TEST_CASE("the moment of inertia and the radius of gyration as results: I(body), I(body, P), k(body) (issue 44, item 5)", "[model][inertia]") {
  // By hand: a slender rod of mass m = 3 kg, length L = 1.2 m, pinned at its end O, swinging from
  // theta = 0: Ī = m L²/12 = 0.36 kg·m², about its end m L²/3 = 1.44 kg·m² (parallel axis:
  // Ī + m (L/2)²), k = L/√12 = 0.34641 m, about O k_O = L/√3 = 0.69282 m; a disk of mass 2 kg,
  // radius 0.25 m: Ī = m r²/2 = 0.0625, about a rim point 3 m r²/2 = 0.1875 kg·m²; H_O = I_O ω.
  const std::string scene = R"Y(title: inertia results
parameters:
  m: 3 kg
  L: 1.2 m
  md: 2 kg
  r: 0.25 m
  g: 9.81 m/s^2
points:
  O: [0, 0]
coordinates:
  theta: rad
bodies:
  rod: {mass: m, inertia: {slender_rod: L}, position: [L/2*sin(theta), -L/2*cos(theta)], angle: theta - pi/2, points: {O: [-L/2, 0]}}
  wheel: {mass: md, inertia: {disk: r}, position: [3*L, 0], points: {E: [r, 0]}}
effects:
  gravity: {g: g}
  pivot: {pin: [O, rod.O]}
states:
  1: {theta: 0, theta_dot: 5 rad/s}
  2: {theta: 1}
analyses:
  - energy: {from: 1, to: 2}
find:
  I_G: {value: I(rod), unit: kg*m^2}
  I_end: {value: "I(rod, rod.O)", unit: kg*m^2}
  I_O: {value: "I(rod, O)@2", unit: kg*m^2}
  k_G: {value: k(rod), unit: m}
  k_O: {value: "k(rod, O)@1", unit: m}
  I_rim: {value: "I(wheel, wheel.E)", unit: kg*m^2}
  H_ratio: {value: "H(O, rod)@1/theta_dot@1", unit: kg*m^2}
)Y";
  auto s = kt::solve_text(scene);
  auto v = [&](const char* n) { return kt::result(s, n).si->to_double(); };
  CHECK(v("I_G") == Approx(3 * 1.44 / 12).epsilon(1e-14));
  CHECK(v("I_end") == Approx(3 * 1.44 / 3).epsilon(1e-14));
  CHECK(v("I_O") == Approx(3 * 1.44 / 3).epsilon(1e-14));
  CHECK(v("k_G") == Approx(1.2 / std::sqrt(12.0)).epsilon(1e-14));
  CHECK(v("k_O") == Approx(1.2 / std::sqrt(3.0)).epsilon(1e-14));
  CHECK(v("I_rim") == Approx(1.5 * 2 * 0.0625).epsilon(1e-14));
  CHECK(v("H_ratio") == Approx(v("I_O")).epsilon(1e-14));
  CHECK(kt::symbolically_zero(kt::result(s, "I_end").closed - kt::param(s.model, "m") * GiNaC::pow(kt::param(s.model, "L"), 2) / 3));
  // what is refused: no body, three arguments, a light body's radius of gyration
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "value: I(rod), unit", "value: I(bar), unit")), Catch::Contains("no body named 'bar'"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "value: I(rod), unit", "value: \"I(rod, O, O)\", unit")),
                    Catch::Contains("I takes a body and, optionally, a point, not 3 arguments"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(kt::edit(scene, "md: 2 kg", "md: 0 kg"), "  I_rim: {value: \"I(wheel, wheel.E)\", unit: kg*m^2}\n",
                                            "  k_w: {value: k(wheel), unit: m}\n")),
                    Catch::Contains("'wheel' is a light body (no mass): it has no radius of gyration"));
}
