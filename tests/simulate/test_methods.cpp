// The integration methods against closed forms: a damped oscillator (every adaptive method),
// a pendulum's energy over many periods (symplectic against RK4), and the compiled right-hand
// side against the tape (the same doubles, so the same run).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "../support/helpers.hpp"
#include "kinergy/confirm/check.hpp"

namespace sim = kinergy::simulate;

namespace {

// m ẍ + c ẋ + k x = 0 with m = 1 kg, c = 0.4 N·s/m, k = 25 N/m, x(0) = 0.1 m, ẋ(0) = 0
const char* kOscillator = R"(
title: damped oscillator
parameters: {m: 1 kg, c: 0.4 N*s/m, k: 25 N/m, L: 1 m}
points: {A: [-L, 0]}
coordinates: {x: m}
bodies:
  block: {mass: m, inertia: particle, position: [x, 0]}
effects:
  spring: {spring: [A, block], k: k, free_length: L}
  dash: {damper: [A, block], c: c}
states:
  1: {x: 0.1 m, x_dot: 0 m/s}
)";

// x(t) = e^(−ζω t) (x₀ cos ω_d t + (ζω x₀/ω_d) sin ω_d t)
std::pair<double, double> oscillator(double t) {
  const double w = 5, z = 0.4 / (2 * 5), wd = w * std::sqrt(1 - z * z), x0 = 0.1, s = z * w;
  double e = std::exp(-s * t), C = std::cos(wd * t), S = std::sin(wd * t);
  double x = e * (x0 * C + s * x0 / wd * S);
  double v = e * (-s * (x0 * C + s * x0 / wd * S) + (-x0 * wd * S + s * x0 * C));
  return {x, v};
}

sim::Run go(const kinergy::model::Model& m, sim::Options o, sim::State s0, double until) {
  sim::Simulator S(m, m.parameter_values(), o);
  sim::Stop stop;
  stop.until = until;
  return S.run(s0, stop);
}

}  // namespace

TEST_CASE("damped oscillator: dopri5, rkf78 and Bulirsch-Stoer against the closed form", "[simulate][methods]") {
  auto m = kt::model_of(kOscillator);
  auto [x, v] = oscillator(3);
  for (auto method : {sim::Method::Dopri5, sim::Method::Rkf78, sim::Method::BulirschStoer}) {
    for (double tol : {1e-6, 1e-9, 1e-12}) {
      INFO(sim::method_name(method) << " tol " << tol);
      sim::Options o;
      o.method = method;
      o.tol = tol;
      o.native = false;
      auto r = go(m, o, {0, {0.1}, {0}}, 3);
      CHECK(std::fabs(r.end.q[0] - x) <= 100 * tol * 0.1);
      CHECK(std::fabs(r.end.qd[0] - v) <= 100 * tol * 0.5);
      // the damper's work is the energy the oscillator lost
      REQUIRE(r.work.size() == 1);
      CHECK(r.work[0].first == "dash");
      CHECK(std::fabs(r.drift) <= 100 * tol);
      CHECK(!r.conservative);
    }
  }
}

TEST_CASE("pendulum over 200 periods: the symplectic method keeps the energy, RK4 does not as well",
          "[simulate][methods]") {
  auto m = kt::model_of_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/compound_pendulum.yaml");
  sim::State s0{0, {-M_PI / 2 - 1.0}, {0}};
  sim::Options o;
  o.native = false;
  o.record = false;
  o.step = 0.05;  // about 30 steps a period (T ≈ 1.6 s)
  o.method = sim::Method::Symplectic;
  auto sym = go(m, o, s0, 300);
  o.method = sim::Method::Rk4;
  auto rk4 = go(m, o, s0, 300);
  INFO("symplectic " << sym.drift << ", rk4 " << rk4.drift);
  CHECK(std::fabs(sym.drift) < 1e-4);
  CHECK(std::fabs(rk4.drift) > 10 * std::fabs(sym.drift));
  CHECK(sym.conservative);
}

TEST_CASE("the symplectic method refuses a scene whose energy is not separable", "[simulate][methods][errors]") {
  // the hub's moment of inertia about O grows with the balls' radius: M depends on s
  auto m = kt::model_of_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/momentum/spinning_frame.yaml");
  sim::Options o;
  o.method = sim::Method::Symplectic;
  o.native = false;
  CHECK_THROWS_WITH(sim::Simulator(m, m.parameter_values(), o),
                    Catch::Contains("separable energy") && Catch::Contains("mass matrix depends on"));
  auto d = kt::model_of(kOscillator);
  CHECK_THROWS_WITH(sim::Simulator(d, d.parameter_values(), o), Catch::Contains("'dash' is not conservative"));
}

TEST_CASE("the compiled right-hand side gives the tape's doubles: the same run step for step", "[simulate][native]") {
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/linkage_collar.yaml");
  sim::Options o;
  o.tol = 1e-11;
  sim::State s0 = sim::state_values(s, 0);  // the scene's start, solved (the collar's angle too)
  o.native = false;
  auto tape = go(s.model, o, s0, 0.5);
  o.native = true;
  auto native = go(s.model, o, s0, 0.5);
  REQUIRE(tape.samples.size() == native.samples.size());
  CHECK(tape.steps == native.steps);
  for (std::size_t i = 0; i < s0.q.size(); ++i) {
    CHECK(tape.end.q[i] == native.end.q[i]);
    CHECK(tape.end.qd[i] == native.end.qd[i]);
  }
}

TEST_CASE("the compiled right-hand side solves M q̈ = f itself for a small system without constraints: the tape's values to rounding",
          "[simulate][native]") {
  // the double pendulum (n = 2, no constraint rows): the native kernel carries its own unrolled
  // LDLᵀ; the tape takes the general path (Eigen's LDLᵀ). Both solve the same M q̈ = f.
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/tests/bench/scenes/double_pendulum.yaml");
  sim::Options o;
  o.tol = 1e-10;
  o.native = false;
  sim::Simulator tape(s.model, s.model.parameter_values(), o);
  o.native = true;
  sim::Simulator native(s.model, s.model.parameter_values(), o);
  // states across a swing: angles and rates of both signs, one near the bars in line
  const std::vector<std::array<double, 4>> ys = {
      {1.0471975511965976, 1.7453292519943295, 0, 0}, {-0.3, 2.9, 4.1, -7.5}, {2.5, -2.5, -1, 12}, {0.7, 0.7000001, 3, 3}};
  for (auto& y : ys) {
    std::array<double, 4> a{}, b{};
    tape.rhs(y.data(), 0.0, a.data());
    native.rhs(y.data(), 0.0, b.data());
    for (std::size_t i = 0; i < 4; ++i) CHECK(std::fabs(a[i] - b[i]) <= 1e-13 * (std::fabs(a[i]) + 1));
  }
  // whole runs: the same motion to the tolerance
  sim::State s0 = sim::state_values(s, 0);
  auto rt = go(s.model, [&] { auto p = o; p.native = false; return p; }(), s0, 2.0);
  auto rn = go(s.model, o, s0, 2.0);
  for (std::size_t i = 0; i < s0.q.size(); ++i) {
    CHECK(std::fabs(rt.end.q[i] - rn.end.q[i]) <= 1e-7);
    CHECK(std::fabs(rt.end.qd[i] - rn.end.qd[i]) <= 1e-6);
  }
  // the energy audit's scale, the largest T: the kernel's ½ q̇ᵀ M q̇ at the steps' ends (dopri5's
  // last stage; the next step's first call for the others) against the auxiliary kernel's T
  for (auto method : {sim::Method::Dopri5, sim::Method::Rkf78, sim::Method::BulirschStoer, sim::Method::Rk4}) {
    INFO(static_cast<int>(method));
    auto p = o;
    p.method = method;
    auto n2 = go(s.model, p, s0, 2.0);
    p.native = false;
    auto t2 = go(s.model, p, s0, 2.0);
    CHECK(n2.energy_scale > 0);
    CHECK(std::fabs(t2.energy_scale - n2.energy_scale) <= 1e-6 * t2.energy_scale);
    CHECK(std::fabs(t2.drift - n2.drift) <= 1e-8);
  }
}

TEST_CASE("a simulator's stepper kept between runs gives every run the same steps as a new simulator's first", "[simulate][methods]") {
  // the adaptive steppers (and RK4) are kept between runs and reset at each start (their
  // coefficients and buffers made once): a second and third run must be the first run again,
  // bit for bit, for every method, also after a run of another length in between
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/tests/bench/scenes/double_pendulum.yaml");
  sim::State s0 = sim::state_values(s, 0);
  for (auto method : {sim::Method::Dopri5, sim::Method::Rkf78, sim::Method::BulirschStoer, sim::Method::Rk4}) {
    sim::Options o;
    o.tol = 1e-9;
    o.method = method;
    o.record = false;
    sim::Simulator kept(s.model, s.model.parameter_values(), o);
    sim::Stop stop;
    stop.until = 1.5;
    sim::Stop other;
    other.until = 0.37;
    auto first = kept.run(s0, stop);
    kept.run(s0, other);
    auto again = kept.run(s0, stop);
    auto fresh = go(s.model, o, s0, 1.5);
    INFO(static_cast<int>(method));
    CHECK(first.steps == fresh.steps);
    CHECK(again.steps == fresh.steps);
    CHECK(again.rejected == fresh.rejected);
    for (std::size_t i = 0; i < s0.q.size(); ++i) {
      CHECK(first.end.q[i] == fresh.end.q[i]);
      CHECK(again.end.q[i] == fresh.end.q[i]);
      CHECK(again.end.qd[i] == fresh.end.qd[i]);
    }
  }
}
