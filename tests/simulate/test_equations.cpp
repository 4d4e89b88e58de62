// Equations of motion: M(q) from Σ Jᵀ m J checked against the kinetic energy (½ q̇ᵀ M q̇ = T,
// another code path), velocity products against a rotating frame by hand, and only the
// effects a scene lists in Q.
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/simulate/equations.hpp"

using namespace GiNaC;
namespace fs = std::filesystem;
namespace sim = kinergy::simulate;

TEST_CASE("every derivation: 1/2 q_dot^T M q_dot equals the kinetic energy", "[simulate][equations]") {
  int n = 0;
  for (const auto& f : kt::scene_files("derivations")) {
    auto m = kt::model_of_file(f);
    bool timed = false;
    for (auto& b : m.bodies) timed = timed || b.x.has(m.t) || b.y.has(m.t) || b.angle.has(m.t);
    if (timed) continue;  // a moving support: T has terms linear in the rates too
    auto eq = sim::equations_of_motion(m);
    ex quad = 0;
    for (std::size_t i = 0; i < eq.q.size(); ++i)
      for (std::size_t j = 0; j < eq.q.size(); ++j) quad += eq.qd[i] * eq.M(i, j) * eq.qd[j] / 2;
    INFO(fs::path(f).filename().string());
    CHECK(kinergy::model::trig_simplify((quad - eq.T).expand()).is_zero());
    // M is symmetric
    for (std::size_t i = 0; i < eq.q.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) CHECK((eq.M(i, j) - eq.M(j, i)).expand().is_zero());
    ++n;
  }
  CHECK(n >= 40);
}

TEST_CASE("velocity products of a rotating frame: Coriolis and centrifugal terms", "[simulate][equations]") {
  auto m = kt::model_of_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/momentum/spinning_frame.yaml");
  auto eq = sim::equations_of_motion(m);
  ex mb = kt::param(m, "m_b");
  ex th = kt::coord(m, "theta").q, thd = kt::coord(m, "theta").qd, s = kt::coord(m, "s").q, sd = kt::coord(m, "s").qd;
  (void)th;
  // two balls at ±s on the spinning guide: c_θ = 4 m s ṡ θ̇ (Coriolis), c_s = −2 m θ̇² s (centrifugal)
  CHECK((eq.c[0] - 4 * mb * s * sd * thd).expand().is_zero());
  CHECK((eq.c[1] + 2 * mb * thd * thd * s).expand().is_zero());
}

TEST_CASE("only the effects a scene lists appear: no friction symbol without friction", "[simulate][equations]") {
  auto rod = kt::model_of_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/sliding_rod.yaml");
  auto eq = sim::equations_of_motion(rod);
  std::string text = eq.text(rod);
  CHECK_THAT(text, !Catch::Contains("friction"));
  CHECK_THAT(text, !Catch::Contains("mu"));
  CHECK_THAT(text, !Catch::Contains("contact"));
  CHECK(eq.friction.empty());
  CHECK(eq.contacts.empty());
  // one force term per listed effect (gravity), none for the pins the coordinates already imply
  CHECK(eq.forces.size() == 1);

  auto block = kt::model_of_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/block_incline_friction.yaml");
  auto eqb = sim::equations_of_motion(block);
  CHECK(eqb.friction.size() == 1);
  CHECK_THAT(eqb.text(block), Catch::Contains("mu_k"));
}

TEST_CASE("a damper along its line: Q = -c (d . d_dot)(d . dd/dq)/|d|^2, and its power", "[simulate][equations]") {
  auto m = kt::model_of(R"(
title: damped slider
parameters: {m: 1 kg, c: 3 N*s/m, k: 50 N/m, a: 0.5 m}
points: {A: [0, a]}
coordinates: {x: m}
bodies:
  block: {mass: m, inertia: particle, position: [x, 0]}
effects:
  spring: {spring: [A, block], k: k, free_length: a}
  dash: {damper: [A, block], c: c}
states:
  1: {x: 0.1 m, x_dot: 0 m/s}
)");
  auto eq = sim::equations_of_motion(m);
  REQUIRE(eq.forces.size() == 2);
  ex x = kt::coord(m, "x").q, xd = kt::coord(m, "x").qd, c = kt::param(m, "c"), a = kt::param(m, "a");
  // d = (x, −a): the damper's rate of length is x ẋ/|d|, its force along d
  ex want = -c * x * xd * x / (x * x + a * a);
  CHECK((eq.forces[1].Q[0] - want).normal().is_zero());
  CHECK((eq.forces[1].power - want * xd).normal().is_zero());
  CHECK(!eq.forces[1].conservative);
  CHECK((m.power(kt::effect(m, "dash")) - want * xd).normal().is_zero());
}
