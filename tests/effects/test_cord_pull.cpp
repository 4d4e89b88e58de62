// The cord_pull effect kind (src/effects/cord_pull.cpp): a cord from a point to a guide, pulled
// with a constant force P. Expected values come from tests/effects/cord_pull_reference.py (sympy).
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "../support/scene_errors.hpp"
#include "kinergy/problem.hpp"

using namespace kt_errors;

namespace {

// the collar of derivations/energy/collar_cord_pull.yaml
const std::string kCollar = R"(title: collar pulled over a pulley
parameters: {m: 3 kg, P: 60 N, b: 0.4 m, h: 0.9 m, d: 0.6 m, g: 9.81 m/s^2}
points: {D: [b, h]}
coordinates: {y: m}
bodies:
  collar: {mass: m, inertia: particle, position: [0, y]}
effects:
  gravity: {g: g}
  pull: {cord_pull: [collar, D], P: P}
states:
  1: {y: 0, y_dot: 0}
  2: {y: d}
analyses:
  - energy: {from: 1, to: 2}
find:
  v2: {value: y_dot@2, root: positive}
)";

}  // namespace

TEST_CASE("cord_pull: V = P L, its generalized force pulls toward the guide", "[effects][cord_pull]") {
  auto m = kt::model_of(kCollar);
  const auto& e = kt::effect(m, "pull");
  CHECK(e.conservative());
  GiNaC::exmap at = m.parameter_values();
  at[kt::coord(m, "y").q] = GiNaC::numeric(3, 10);
  // Q_y(y = 0.3 m) = P (h − y)/L = 49.923017660270620982 N (sympy)
  GiNaC::numeric Q = kt::value(e.generalized_force(m, 0), at, 30);
  CHECK(kt::close(Q, GiNaC::numeric("49.923017660270620982"), kt::tol(17)));
  // V = P L: at y = 0.3, L = sqrt(0.16 + 0.36) = sqrt(0.52)
  GiNaC::numeric V = kt::value(e.potential(m), at, 30);
  CHECK(kt::close(V, kt::value(60 * GiNaC::sqrt(GiNaC::ex(GiNaC::numeric(52, 100))), {}, 30), kt::tol(25)));
  // its power is −dV/dt = Q_y ẏ
  auto yd = kt::coord(m, "y").qd;
  CHECK(kt::symbolically_zero(e.power(m) - e.generalized_force(m, 0) * yd));
}

TEST_CASE("cord_pull: the work-energy result matches the reference", "[effects][cord_pull]") {
  kinergy::Solution s = kinergy::solve_scene(kinergy::scene::load_string(kCollar, "collar.yaml"));
  auto env = s.model.numeric_environment();
  auto v = kt::result(s, "v2").value(env, 20);
  REQUIRE(v);
  CHECK(kt::close(*v, GiNaC::numeric("2.7610561760283724598"), kt::tol(18)));
}

TEST_CASE("cord_pull: bad options are refused where they stand", "[effects][cord_pull][errors]") {
  SECTION("one point") {
    auto t = kt_errors::edit(kCollar, "{cord_pull: [collar, D], P: P}", "{cord_pull: collar, P: P}");
    expect_error(t, at(t, "collar, P: P", 0), "a cord pull runs between two points", "cord_pull: [collar, D]");
  }
  SECTION("two fixed points") {
    auto t = kt_errors::edit(kCollar, "points: {D: [b, h]}", "points: {D: [b, h], E: [0, 0]}");
    t = kt_errors::edit(t, "[collar, D], P: P", "[E, D], P: P");
    expect_error(t, at(t, "[E, D]"), "runs between two fixed points", "body point");
  }
  SECTION("no pull") {
    auto t = kt_errors::edit(kCollar, "{cord_pull: [collar, D], P: P}", "{cord_pull: [collar, D]}");
    expect_error(t, at(t, "pull: {"), "has no 'P'", "P: P0");
  }
  SECTION("a pull that is not a force") {
    auto t = kt_errors::edit(kCollar, "[collar, D], P: P}", "[collar, D], P: m*b}");
    expect_error(t, at(t, "m*b}"), "'P' is", "N (or lb)");
  }
  SECTION("a pull that is not positive") {
    auto t = kt_errors::edit(kCollar, "P: 60 N", "P: -60 N");
    expect_error(t, at(t, "-60 N"), "stands for the pull of the cord", "positive");
  }
  SECTION("an unknown key") {
    auto t = kt_errors::edit(kCollar, "[collar, D], P: P}", "[collar, D], P: P, k: 3}");
    expect_error(t, at(t, "k: 3"), "unknown key 'k' in cord_pull effect 'pull'", "use: P, cord_pull");
  }
  SECTION("its impulse over a duration has no closed form") {
    auto t = kt_errors::edit(kCollar, "  - energy: {from: 1, to: 2}", "  - momentum: {from: 1, to: 2, along: y}");
    t = kt_errors::edit(t, "  1: {y: 0, y_dot: 0}", "  1: {y: 0, y_dot: 0, t: 0}");
    expect_error(t, at(t, "pull: {", 0), "the cord_pull 'pull' pushes with a force that changes with the motion", "energy analysis");
  }
}
