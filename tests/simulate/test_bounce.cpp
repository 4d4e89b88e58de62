// A ball dropped on a floor with e = 0.5: every impact located, each losing exactly what the
// closed form predicts, the bounces ending in rest on the floor with all energy accounted for.
#include <catch2/catch.hpp>

#include <cmath>

#include "../support/helpers.hpp"
#include "kinergy/confirm/check.hpp"

namespace sim = kinergy::simulate;

TEST_CASE("bouncing ball, e = 0.5: impact times and energy losses against the closed forms",
          "[simulate][impact]") {
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/impact/bouncing_ball.yaml");
  const double m = 0.2, r = 0.03, h = 1.2, e = 0.5, g = 9.81;
  const double v1 = std::sqrt(2 * g * h);
  for (auto method : {sim::Method::Dopri5, sim::Method::Rkf78, sim::Method::BulirschStoer}) {
    INFO(sim::method_name(method));
    sim::Options o;
    o.tol = 1e-12;
    o.method = method;
    o.native = false;
    sim::Simulator S(s.model, sim::simulation_values(s), o);
    sim::Stop stop;
    stop.until = 3;
    sim::Run run = S.run(sim::state_values(s, 0), stop);
    REQUIRE(run.impacts.size() >= 15);
    double t = std::sqrt(2 * h / g);  // the first impact
    for (std::size_t k = 0; k < run.impacts.size(); ++k) {
      const auto& im = run.impacts[k];
      INFO("impact " << k + 1 << " at t = " << im.t);
      if (im.comes_to_rest) {
        // the bounces too small to resolve end with the contact at rest: the rest of the
        // normal kinetic energy (what the remaining geometric series of bounces would lose)
        CHECK(k + 1 == run.impacts.size());
        CHECK(im.loss >= 0);
        CHECK(im.loss < 1e-10 * m * g * h);
        break;
      }
      // v before impact k is e^(k−1) v1; it loses ½ m v² (1 − e²); the flight after it lasts 2 e^k v1 / g
      double vk = v1 * std::pow(e, static_cast<double>(k));
      double loss = 0.5 * m * vk * vk * (1 - e * e);
      // each time to 1e-12 relative; the tiny last bounces (1e-6 s flights, 1e-13 m high) are
      // located to the rounding of the height over their speed, about 1e-11 s each
      CHECK(im.t == Approx(t).epsilon(1e-12).margin(2e-10));
      // velocities to 1e-12 of the first impact's speed (an absolute error, the same for every bounce)
      CHECK(im.vn_before[0] == Approx(-vk).margin(1e-12 * v1));
      CHECK(im.vn_after[0] == Approx(e * vk).margin(1e-12 * v1));
      // the loss from the impulse (no difference of large numbers), to the digits of v
      CHECK(im.loss == Approx(loss).epsilon(1e-10).margin(1e-12 * m * g * h));
      CHECK(im.loss >= 0);  // never an energy gain
      t += 2 * e * vk / g;
    }
    // at rest on the floor: y = r, y_dot = 0, and E₀ − E₁ = Σ losses = m g h exactly
    CHECK(run.end.q[0] == Approx(r).epsilon(1e-12));
    CHECK(std::fabs(run.end.qd[0]) < 1e-12);
    CHECK(run.impact_loss == Approx(m * g * h).epsilon(1e-12));
    CHECK(std::fabs(run.drift) < 1e-12);
  }
}

TEST_CASE("a plastic impact (e = 0) leaves the contact resting, and a resting contact lets go when it would pull",
          "[simulate][impact]") {
  // a ball on a floor pulled upward by a force that grows with time: rests, then lifts off at m g = F
  auto m = kt::model_of(R"(
title: ball lifted off a floor
parameters: {m: 2 kg, g: 9.81 m/s^2, k: 4 N/s}
coordinates: {y: m}
bodies:
  ball: {mass: m, inertia: particle, position: [0, y]}
effects:
  gravity: {g: g}
  lift: {force: ball, F: [0, k*t]}
  floor: {contact: [ground, ball], normal: [0, 1], e: 0}
states:
  1: {t: 0 s, y: 0 m, y_dot: -1 m/s}
)");
  sim::Options o;
  o.tol = 1e-12;
  o.native = false;
  sim::Simulator S(m, m.parameter_values(), o);
  sim::Stop stop;
  stop.until = 6;
  sim::Run run = S.run({0, {0}, {-1}}, stop);
  REQUIRE(run.impacts.size() == 1);  // the plastic impact at the start
  CHECK(run.impacts[0].loss == Approx(0.5 * 2 * 1 * 1).epsilon(1e-14));
  // lift-off at t = m g / k = 4.905 s; after it y = k (t − t₀)³ / (6 m)
  bool let_go = false;
  for (auto& l : run.log) let_go = let_go || l.find("lets go") != std::string::npos;
  CHECK(let_go);
  const double t0 = 2 * 9.81 / 4, dt = 6 - t0;
  CHECK(run.end.q[0] == Approx(4 * dt * dt * dt / (6 * 2)).epsilon(1e-9));
}

TEST_CASE("a contact touched and left inside one step is not stepped over", "[simulate][impact]") {
  // a ball thrown up to 1e-4 of its rise above a ceiling at H: a parabola, which dopri5 integrates
  // exactly, so its steps grow far longer than the 2 ms the ball spends above the ceiling
  auto m = kt::model_of(R"(
title: ball grazing a ceiling
parameters: {m: 1 kg, g: 9.81 m/s^2, H: 2 m}
points: {C: [0, H]}
coordinates: {y: m}
bodies:
  ball: {mass: m, inertia: particle, position: [0, y]}
effects:
  gravity: {g: g}
  ceiling: {contact: [ball, C], normal: [0, 1], e: 1}
states:
  1: {y: 0 m, y_dot: 1 m/s}
)");
  const double g = 9.81, H = 2, v0 = std::sqrt(2 * g * H * (1 + 1e-4));
  sim::Options o;
  o.tol = 1e-6;
  o.native = false;
  sim::Simulator S(m, m.parameter_values(), o);
  sim::Stop stop;
  stop.until = 1.5;
  sim::Run run = S.run({0, {0}, {v0}}, stop);
  REQUIRE(run.impacts.size() == 1);
  // y = v0 t − g t²/2 = H at t* = (v0 − √(v0² − 2 g H))/g
  const double ts = (v0 - std::sqrt(v0 * v0 - 2 * g * H)) / g;
  CHECK(run.impacts[0].t == Approx(ts).epsilon(1e-9));
  CHECK(run.impacts[0].vn_before[0] == Approx(-std::sqrt(v0 * v0 - 2 * g * H)).epsilon(1e-6));
  CHECK(run.impacts[0].loss == Approx(0).margin(1e-15));  // e = 1: nothing lost
}
