// The cord_pull effect kind (src/effects/cord_pull.cpp): a cord from a point to a guide, pulled
// with a constant force P. Expected values come from tests/effects/cord_pull_reference.py (sympy).
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "../support/scene_errors.hpp"
#include "kinergy/problem.hpp"

using namespace kt_errors;

namespace {

// derivations/energy/collar_cord_pull.yaml: a collar on a vertical rod, the cord over a pulley D
std::string collar() { return kt::read_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/collar_cord_pull.yaml"); }

}  // namespace

TEST_CASE("cord_pull: V = P L, its generalized force pulls toward the guide", "[effects][cord_pull]") {
  auto m = kt::model_of(collar());
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
  kinergy::Solution s = kinergy::solve_scene(kinergy::scene::load_string(collar(), "collar.yaml"));
  auto env = s.model.numeric_environment();
  auto v = kt::result(s, "v2").value(env, 20);
  REQUIRE(v);
  CHECK(kt::close(*v, GiNaC::numeric("2.7610561760283724598"), kt::tol(18)));
}

TEST_CASE("cord_pull: bad options are refused where they stand", "[effects][cord_pull][errors]") {
  struct Case {
    const char* what;
    std::string from, to, needle, phrase, fix;
  };
  const std::vector<Case> cases = {
      {"one point", "{cord_pull: [collar, D], P: P}", "{cord_pull: collar, P: P}", "collar, P: P",
       "a cord pull runs between two points", "cord_pull: [collar, D]"},
      {"two fixed points", "[collar, D], P: P", "[D, D], P: P", "[D, D]", "runs between two fixed points", "body point"},
      {"no pull", "{cord_pull: [collar, D], P: P}", "{cord_pull: [collar, D]}", "pull: {cord", "has no 'P'", "P: P0"},
      {"a pull that is not a force", "[collar, D], P: P}", "[collar, D], P: m*b}", "m*b}", "'P' is", "N (or lb)"},
      {"a pull that is not positive", "P: 60 N", "P: -60 N", "-60 N", "stands for the pull of the cord", "positive"},
      {"an unknown key", "[collar, D], P: P}", "[collar, D], P: P, k: 3}", "k: 3", "unknown key 'k' in cord_pull effect 'pull'",
       "use: P, cord_pull"},
      // its force turns with the motion, so its impulse over a duration has no closed form
      {"a momentum analysis across it", "- energy: {from: 1, to: 2}", "- momentum: {from: 1, to: 2, along: y}", "pull: {cord",
       "the cord_pull 'pull' pushes with a force that changes with the motion", "energy analysis"},
  };
  for (auto& c : cases) {
    DYNAMIC_SECTION(c.what) {
      auto t = kt_errors::edit(collar(), c.from, c.to);
      expect_error(t, at(t, c.needle), c.phrase, c.fix);
    }
  }
}
