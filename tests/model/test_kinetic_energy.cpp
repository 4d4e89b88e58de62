// Kinetic energy computed two independent ways, and the inertias it is built from.
//
//  1. For every worked scene: T from the body sum (½ m v̄² + ½ Ī ω²) equals ½ q̇ᵀ M(q) q̇ from the
//     mass matrix, symbolically and at random exact points (50 digits).
//  2. A body pinned at distance d from its mass centre: T = ½ (Ī + m d²) ω² with Ī written here
//     from the textbook table (parallel-axis theorem), for every inertia shape.
#include <catch2/catch.hpp>

#include <filesystem>
#include <functional>
#include <random>
#include <cmath>

#include "../support/helpers.hpp"
#include "kinergy/confirm/confirm.hpp"

using namespace GiNaC;
using kinergy::model::Model;

namespace {

/// ½ q̇ᵀ M q̇ from the mass matrix.
ex quadratic_form(const Model& m) {
  matrix M = m.mass_matrix();
  ex T = 0;
  for (std::size_t i = 0; i < m.coords.size(); ++i)
    for (std::size_t j = 0; j < m.coords.size(); ++j) T += M(i, j) * m.coords[i].qd * m.coords[j].qd;
  return T / 2;
}

/// Random exact values for every parameter (positive), coordinate, rate and t.
exmap random_point(const Model& m, std::mt19937& rng) {
  exmap v;
  for (auto& p : m.params) v[p.sym] = kt::random_rational(rng, 1, 3);
  for (auto& c : m.coords) {
    v[c.q] = kt::random_rational(rng, -3, 3);
    v[c.qd] = kt::random_rational(rng, -3, 3);
  }
  v[m.t] = kt::random_rational(rng, 0, 3);
  return v;
}

}  // namespace

TEST_CASE("T from the body sum equals 1/2 qdot^T M(q) qdot for every derivation scene",
          "[model][kinetic][two-ways]") {
  auto files = kt::derivation_scenes();
  REQUIRE(files.size() >= 12);
  std::mt19937 rng(20240611);
  for (auto& f : files) {
    DYNAMIC_SECTION(std::filesystem::path(f).filename().string()) {
      Model m = kt::model_of_file(f);
      REQUIRE(!m.coords.empty());
      ex T = m.kinetic_energy();
      ex Tq = quadratic_form(m);
      INFO("T          = " << T);
      INFO("½ q̇ᵀMq̇     = " << Tq);
      // a scene in which nothing moves would make the comparison empty
      CHECK(!T.is_zero());

      // symbolically: the difference vanishes after expansion and sin² + cos² = 1
      CHECK(kt::symbolically_zero(T - Tq));

      // the mass matrix is symmetric
      matrix M = m.mass_matrix();
      for (std::size_t i = 0; i < m.coords.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) CHECK(kt::symbolically_zero(M(i, j) - M(j, i)));

      // T is the sum of the bodies' kinetic energies
      ex sum = 0;
      for (std::size_t b = 0; b < m.bodies.size(); ++b) sum += m.kinetic_energy(static_cast<int>(b));

      // numerically, at random exact points, to 50 digits
      for (int trial = 0; trial < 6; ++trial) {
        exmap at = random_point(m, rng);
        numeric a = kt::value(T, at, 50), b = kt::value(Tq, at, 50), c = kt::value(sum, at, 50);
        INFO("trial " << trial << ": T = " << a << ", quadratic form = " << b);
        CHECK(kt::close(a, b, kt::tol(45)));
        CHECK(kt::close(a, c, kt::tol(45)));
        // kinetic energy is a positive semi-definite quadratic form
        CHECK(a >= numeric(-1, 1000000000));
      }
    }
  }
}

TEST_CASE("T of the rolling disk is (3/4) m v^2 once the rolling constraint holds", "[model][kinetic]") {
  Model m = kt::model_of_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/rolling_disk_incline.yaml");
  ex mm = kt::param(m, "m"), r = kt::param(m, "r");
  const auto& x = kt::coord(m, "x");
  const auto& phi = kt::coord(m, "phi");
  // x_dot + r phi_dot = 0  →  phi_dot = −x_dot / r
  ex T = m.kinetic_energy().subs(phi.qd == -x.qd / r);
  CHECK(kt::symbolically_zero(T - numeric(3, 4) * mm * pow(x.qd, 2)));
}

// ------------------------------------------------------------------------------------------
// I_O = Ī + m d²

namespace {

struct Shape {
  const char* yaml;   ///< the inertia entry
  const char* name;
  /// Ī written from the table in the test: m, size symbols looked up by name
  std::function<ex(const Model&)> ibar;
};

std::string pinned_scene(const std::string& inertia) {
  // G at distance d from the fixed pin O, on the body x axis: r_G = d (cos θ, sin θ), angle θ.
  return R"(title: body pinned off its centre
parameters:
  m: kg
  d: m
  l: m
  r: m
  a: m
  b: m
  k: m
  I0: kg*m^2
points:
  O: [0, 0]
coordinates:
  theta: rad
bodies:
  body:
    mass: m
    inertia: )" + inertia + R"(
    position: [d*cos(theta), d*sin(theta)]
    angle: theta
    points: {P: [-d, 0]}
effects:
  pivot: {pin: [O, body.P]}
)";
}

}  // namespace

TEST_CASE("a body pinned at distance d from G: T = 1/2 (Ibar + m d^2) omega^2 for every shape",
          "[model][kinetic][inertia][two-ways]") {
  auto P = [](const Model& m, const char* n) { return kt::param(m, n); };
  std::vector<Shape> shapes = {
      {"{slender_rod: l}", "slender rod", [&](const Model& m) { return P(m, "m") * pow(P(m, "l"), 2) / 12; }},
      {"{disk: r}", "disk", [&](const Model& m) { return P(m, "m") * pow(P(m, "r"), 2) / 2; }},
      {"{cylinder: r}", "cylinder", [&](const Model& m) { return P(m, "m") * pow(P(m, "r"), 2) / 2; }},
      {"{ring: r}", "ring", [&](const Model& m) { return P(m, "m") * pow(P(m, "r"), 2); }},
      {"{hoop: r}", "hoop", [&](const Model& m) { return P(m, "m") * pow(P(m, "r"), 2); }},
      {"{plate: [a, b]}", "plate",
       [&](const Model& m) { return P(m, "m") * (pow(P(m, "a"), 2) + pow(P(m, "b"), 2)) / 12; }},
      {"{plate_edge_on: b}", "plate edge-on", [&](const Model& m) { return P(m, "m") * pow(P(m, "b"), 2) / 12; }},
      {"{disk_edge_on: r}", "circular plate edge-on", [&](const Model& m) { return P(m, "m") * pow(P(m, "r"), 2) / 4; }},
      {"{sphere: r}", "sphere", [&](const Model& m) { return 2 * P(m, "m") * pow(P(m, "r"), 2) / 5; }},
      {"{spherical_shell: r}", "spherical shell",
       [&](const Model& m) { return 2 * P(m, "m") * pow(P(m, "r"), 2) / 3; }},
      {"{gyration: k}", "gyration", [&](const Model& m) { return P(m, "m") * pow(P(m, "k"), 2); }},
      {"{centroidal: I0}", "centroidal", [&](const Model& m) { return P(m, "I0"); }},
      {"particle", "particle", [&](const Model&) { return ex(0); }},
  };
  for (auto& s : shapes) {
    DYNAMIC_SECTION(s.name) {
      Model m = kt::model_of(pinned_scene(s.yaml));
      REQUIRE(m.bodies.size() == 1);
      ex Ibar = s.ibar(m);
      // the centroidal inertia of the shape table
      CHECK(kt::symbolically_zero(m.bodies[0].inertia - Ibar));
      // T about the pin: parallel-axis theorem
      ex mm = kt::param(m, "m"), d = kt::param(m, "d");
      ex w = kt::coord(m, "theta").qd;
      ex expected = (Ibar + mm * d * d) * w * w / 2;
      INFO("T = " << m.kinetic_energy() << ", expected " << expected);
      CHECK(kt::symbolically_zero(m.kinetic_energy() - expected));
      // and the 1×1 mass matrix is I_O itself
      CHECK(kt::symbolically_zero(m.mass_matrix()(0, 0) - (Ibar + mm * d * d)));
    }
  }
}

TEST_CASE("plate pinned at a corner and disk pinned at its rim: textbook I_O", "[model][kinetic][inertia]") {
  SECTION("rectangular plate a x b about a corner: I_O = m (a^2 + b^2) / 3") {
    Model m = kt::model_of(R"(title: plate about a corner
parameters:
  m: kg
  a: m
  b: m
points:
  O: [0, 0]
coordinates:
  theta: rad
bodies:
  plate:
    mass: m
    inertia: {plate: [a, b]}
    position: [a/2*cos(theta) - b/2*sin(theta), a/2*sin(theta) + b/2*cos(theta)]
    angle: theta
    points: {C: [-a/2, -b/2]}
effects:
  hinge: {pin: [O, plate.C]}
)");
    ex mm = kt::param(m, "m"), a = kt::param(m, "a"), b = kt::param(m, "b");
    ex w = kt::coord(m, "theta").qd;
    CHECK(kt::symbolically_zero(m.kinetic_energy() - mm * (a * a + b * b) / 3 * w * w / 2));
  }
  SECTION("disk about a point of its rim: I_O = 3/2 m r^2 (numbers: m = 4 kg, r = 0.3 m)") {
    Model m = kt::model_of(R"(title: disk about its rim
parameters:
  m: 4 kg
  r: 0.3 m
points:
  O: [0, 0]
coordinates:
  theta: rad
bodies:
  disk:
    mass: m
    inertia: {disk: r}
    position: [r*cos(theta), r*sin(theta)]
    angle: theta
    points: {A: [-r, 0]}
effects:
  pin: {pin: [O, disk.A]}
states:
  1: {theta: 0.7, theta_dot: 5 rad/s}
)");
    // T = ½ (3/2 · 4 · 0.09) 25 = 6.75 J exactly
    ex T1 = m.bind(m.kinetic_energy(), 0).subs(m.states[0].given).subs(m.parameter_values());
    CHECK(kt::symbolically_zero(T1 - numeric(675, 100)));
  }
  SECTION("a misplaced pin is refused (the geometry is really checked)") {
    CHECK_THROWS_AS(kt::model_of(R"(title: disk with a wrong pin
parameters:
  m: 4 kg
  r: 0.3 m
points:
  O: [0, 0]
coordinates:
  theta: rad
bodies:
  disk:
    mass: m
    inertia: {disk: r}
    position: [r*cos(theta), r*sin(theta)]
    angle: theta
    points: {A: [r, 0]}
effects:
  pin: {pin: [O, disk.A]}
)"),
                    kinergy::SceneError);
  }
}

TEST_CASE("free body, T = 1/2 m (xd^2 + yd^2) + 1/2 Ibar w^2 (diagonal mass matrix)",
          "[model][kinetic]") {
  // three coordinates, no coupling: the mass matrix is diag(m, m, Ī)
  Model m = kt::model_of(R"(title: free body
parameters:
  m: kg
  r: m
coordinates:
  x: m
  y: m
  phi: rad
bodies:
  disk:
    mass: m
    inertia: {disk: r}
    position: [x, y]
    angle: phi
)");
  ex mm = kt::param(m, "m"), r = kt::param(m, "r");
  matrix M = m.mass_matrix();
  REQUIRE(M.rows() == 3);
  CHECK(kt::symbolically_zero(M(0, 0) - mm));
  CHECK(kt::symbolically_zero(M(1, 1) - mm));
  CHECK(kt::symbolically_zero(M(2, 2) - mm * r * r / 2));
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j)
      if (i != j) CHECK(M(i, j).is_zero());
}

TEST_CASE("a plate turning about an axis in its plane, hinged at an edge: plate_edge_on, disk_edge_on (issue 44, item 4)", "[model][kinetic][inertia]") {
  // By hand: a trapdoor (width b across its hinge) falls from theta0 = 80 deg to flat:
  // m g (b/2) sin(theta0) = (1/2)(m b^2/12 + m b^2/4) w^2, w = sqrt(3 g sin(theta0)/b); a circular
  // plate hinged on a tangent at its rim: I = m r^2/4 + m r^2 = 5 m r^2/4, w = sqrt(8 g sin(theta0)/(5 r))
  const std::string door = R"(title: A trapdoor falls shut
parameters:
  m: 12 kg
  b: 0.8 m
  g: 9.81 m/s^2
points:
  O: [0, 0]
coordinates:
  theta: rad
bodies:
  door:
    mass: m
    inertia: {plate_edge_on: b}
    position: [b/2*cos(theta), b/2*sin(theta)]
    angle: theta
    points: {O: [-b/2, 0]}
effects:
  gravity: {g: g}
  hinge: {pin: [O, door.O]}
states:
  open: {theta: 80 deg, theta_dot: 0}
  shut: {theta: 0}
analyses:
  - energy: {from: open, to: shut}
find:
  w: {value: theta_dot@shut, root: negative, unit: rad/s}
)";
  const double s80 = std::sin(80 * M_PI / 180);
  auto s = kt::solve_text(door);
  kinergy::confirm(s);
  CHECK(kt::result(s, "w").si->to_double() == Approx(-std::sqrt(3 * 9.81 * s80 / 0.8)).epsilon(1e-13));
  CHECK(s.confirmed[0].by == kinergy::Confirmed::By::Simulation);
  auto c = kt::solve_text(kt::edit(kt::edit(kt::edit(door, "{plate_edge_on: b}", "{disk_edge_on: b}"), "b/2*cos(theta), b/2*sin(theta)", "b*cos(theta), b*sin(theta)"),
                                   "points: {O: [-b/2, 0]}", "points: {O: [-b, 0]}"));
  CHECK(kt::result(c, "w").si->to_double() == Approx(-std::sqrt(8 * 9.81 * s80 / (5 * 0.8))).epsilon(1e-13));
}
