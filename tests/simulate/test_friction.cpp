// Coulomb friction in a simulation: a block on an incline holds, slides, stops and sticks,
// against the closed forms of uniformly accelerated motion.
#include <catch2/catch.hpp>

#include <cmath>

#include "../support/helpers.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace sim = kinergy::simulate;

namespace {

kinergy::model::Model incline(const std::string& mu, const std::string& v0) {
  return kt::model_of(R"(
title: block on an incline
parameters: {m: 5 kg, beta: 30 deg, mu: )" + mu + R"(, g: 9.81 m/s^2}
coordinates: {x: m}
bodies:
  block: {mass: m, inertia: particle, position: [x*cos(beta), x*sin(beta)]}
effects:
  gravity: {g: g}
  rub: {friction: block, mu: mu, normal: m*g*cos(beta)}
states:
  1: {x: 0 m, x_dot: )" + v0 + R"( m/s}
)");
}

sim::Run run(const kinergy::model::Model& m, double v0, double until) {
  sim::Options o;
  o.tol = 1e-12;
  o.native = false;
  sim::Simulator S(m, m.parameter_values(), o);
  sim::Stop stop;
  stop.until = until;
  return S.run({0, {0}, {v0}}, stop);
}

bool logged(const sim::Run& r, const std::string& what) {
  for (auto& l : r.log)
    if (l.find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("friction holds a block at rest when mu > tan(beta)", "[simulate][friction]") {
  auto r = run(incline("0.7", "0"), 0, 2);
  // held by a constraint solved in doubles: still to the rounding of g
  CHECK(std::fabs(r.end.q[0]) < 1e-14);
  CHECK(std::fabs(r.end.qd[0]) < 1e-14);
}

TEST_CASE("friction too weak: the block slides down with a = g (sin b - mu cos b)", "[simulate][friction]") {
  auto r = run(incline("0.3", "0"), 0, 2);
  const double b = M_PI / 6, a = -9.81 * (std::sin(b) - 0.3 * std::cos(b));
  CHECK(r.end.q[0] == Approx(0.5 * a * 4).epsilon(1e-11));
  CHECK(r.end.qd[0] == Approx(a * 2).epsilon(1e-11));
  // its work: −μ N times the distance
  REQUIRE(r.work.size() == 1);
  CHECK(r.work[0].second == Approx(-0.3 * 5 * 9.81 * std::cos(b) * std::fabs(0.5 * a * 4)).epsilon(1e-11));
}

TEST_CASE("a block sent up a rough incline stops, and sticks when mu > tan(beta)", "[simulate][friction]") {
  auto r = run(incline("0.7", "3"), 3, 2);
  const double b = M_PI / 6, a = -9.81 * (std::sin(b) + 0.7 * std::cos(b));
  const double t_stop = -3 / a, d = -9 / (2 * a);
  CHECK(logged(r, "sticks"));
  CHECK(r.end.q[0] == Approx(d).epsilon(1e-11));
  CHECK(std::fabs(r.end.qd[0]) < 1e-14);
  CHECK(r.log.front().find("t = " + std::to_string(t_stop).substr(0, 5)) == 0);
  // its work takes all the kinetic energy not stored as height
  CHECK(std::fabs(r.drift) < 1e-12);
}

TEST_CASE("a block sent up a rough incline with mu < tan(beta) stops and slides back", "[simulate][friction]") {
  auto r = run(incline("0.25", "6"), 6, 3);
  CHECK(logged(r, "reverses"));
  const double b = M_PI / 6, up = 9.81 * (std::sin(b) + 0.25 * std::cos(b)), down = 9.81 * (std::sin(b) - 0.25 * std::cos(b));
  const double t1 = 6 / up, d = 36 / (2 * up), t2 = 3 - t1;
  CHECK(r.end.q[0] == Approx(d - 0.5 * down * t2 * t2).epsilon(1e-11));
  CHECK(r.end.qd[0] == Approx(-down * t2).epsilon(1e-11));
}
