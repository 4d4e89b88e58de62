// Friction over a duration opposes the motion during the interval: from rest, the direction
// comes from the second state's velocity, or from `direction:`; otherwise a clear error.
#include <catch2/catch.hpp>

#include "../support/scene_errors.hpp"
#include "kinergy/numeric/evaluate.hpp"

using namespace kt_errors;

namespace {
const std::string kSpin = R"Y(title: Flywheel from rest against bearing friction
parameters: {m: 40 kg, k: 0.3 m, M: 30 N*m, Mf: 6 N*m, t2: 5 s, w2: 20 rad/s}
points: {O: [0, 0]}
coordinates: {phi: rad}
bodies:
  wheel: {mass: m, inertia: {gyration: k}, position: [0, 0], angle: phi}
effects:
  motor: {couple: wheel, M: M}
  bearing: {friction_couple: wheel, M: Mf, direction: positive}
states:
  1: {t: 0, phi: 0, phi_dot: 0}
  2: {t: t2}
analyses:
  - angular_momentum: {from: 1, to: 2, about: O}
find:
  omega2: {value: phi_dot@2, unit: rad/s}
)Y";

double value_of(const std::string& text, const std::string& name) {
  auto s = kinergy::solve_scene(kinergy::scene::load_string(text, "spin.yaml"));
  for (auto& r : s.results)
    if (r.name == name) return r.si->to_double();
  FAIL("no result " << name);
  return 0;
}
}  // namespace

TEST_CASE("friction couple from rest: the declared direction", "[momentum][friction]") {
  // m k² ω₂ = (M − Mf) t₂ = 24·5 / 3.6
  CHECK(value_of(kSpin, "omega2") == Approx(120.0 / 3.6).epsilon(1e-14));
  // declared the other way, the bearing would help the motor ((M + Mf) t₂ / (m k²)): friction
  // cannot drive the motion, so the declaration is checked on the solution and refused
  auto wrong = edit(kSpin, "direction: positive", "direction: negative");
  expect_error(wrong, at(wrong, "bearing:"), "declares 'direction: negative', but the solution has the rotation at state '2' the other way",
               "give 'direction: positive' on 'bearing'");
}

TEST_CASE("friction couple from rest: the direction from the second state", "[momentum][friction]") {
  // the speed reached is given and the time asked: the rotation at state 2 tells the direction
  auto t = edit(edit(kSpin, ", direction: positive", ""), "  2: {t: t2}\n", "  2: {phi_dot: w2}\n");
  t = edit(t, "  omega2: {value: phi_dot@2, unit: rad/s}\n", "  t2_needed: {value: t@2, unit: s}\n");
  CHECK(value_of(t, "t2_needed") == Approx(20 * 3.6 / 24).epsilon(1e-14));
}

TEST_CASE("friction couple from rest with nothing to tell the direction", "[momentum][friction][errors]") {
  auto t = edit(kSpin, ", direction: positive", "");
  expect_error(t, at(t, "bearing:"), "the direction of rotation under 'bearing' between states 1 and 2 is not known",
               "direction: positive|negative");
  auto bad = edit(kSpin, "direction: positive", "direction: up");
  expect_error(bad, at(bad, "up}"), "'direction' must be positive or negative", "direction: positive");
}
