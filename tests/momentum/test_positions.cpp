// Positions over a duration (issue 27, item 6): where the pushes on a set are known functions of
// time, its momentum integrates once more, Σ m x̄₂ = Σ m x̄₁ + L₁ Δt + Σ ∫∫F dt' dt. Expected
// values by hand (constant acceleration x = v₁ t + F t²/(2m); a force c t from rest: x = c t³/(6m)),
// not from kinergy's output.
#include <catch2/catch.hpp>

#include <cmath>

#include "../support/helpers.hpp"

namespace {

using kt::solve_text;
const auto& value = kt::result_si;


// A block on a smooth floor, pushed along x by F(t) from x = 0 with speed v1.
std::string pushed_block(const std::string& F, const std::string& v1) {
  return R"(title: pushed block
parameters:
  m: 4 kg
  c: 6 N/s
  P: 10 N
  t2: 2 s
coordinates:
  x: m
bodies:
  block: {mass: m, inertia: particle, position: [x, 0]}
effects:
  push: {force: block, F: [)" + F + R"(, 0]}
states:
  1: {t: 0, x: 0, x_dot: )" + v1 + R"(}
  2: {t: t2}
analyses:
  - momentum: {from: 1, to: 2, along: x}
find:
  x2: {value: x@2, unit: m}
)";
}

}  // namespace

TEST_CASE("positions over a duration: a constant force and a force of t, by hand", "[momentum][positions]") {
  // x₂ = v₁ T + P T²/(2m) = 3·2 + 10·4/8 = 11 m
  auto s = solve_text(pushed_block("P", "3 m/s"));
  CHECK(value(s, "x2") == Approx(11.0).epsilon(1e-14));
  // x₂ = c T³/(6m) = 6·8/24 = 2 m
  s = solve_text(pushed_block("c*t", "0"));
  CHECK(value(s, "x2") == Approx(2.0).epsilon(1e-14));
  // F = P sin(t/T) from rest: ∫₀ᵗ F = P T (1 − cos(t/T)), ∫₀ᵀ that = P T² (1 − sin 1), over m
  s = solve_text(pushed_block("P*sin(t/t2)", "0"));
  CHECK(value(s, "x2") == Approx(10.0 * 4 / 4 * (1 - std::sin(1.0))).epsilon(1e-13));
}

TEST_CASE("positions over a duration: only where a result asks, and not again where energy gives them", "[momentum][positions]") {
  // the bowling ball: x@2 asked, the linear balance integrates; phi@2 not asked: no angle equation
  std::string text = kt::edit(kt::derivation("momentum/sphere_slide_to_roll.yaml"), "find:\n", "find:\n  d2: {value: x@2, unit: m}\n");
  auto s = solve_text(text);
  // x₂ = v0 t₂ − μ g t₂²/2 with t₂ = 2 v0/(7 μ g): 12 v0²/(49 μ g)
  CHECK(value(s, "d2") == Approx(12 * 7.5 * 7.5 / (49 * 0.12 * 9.81)).epsilon(1e-14));
  REQUIRE(s.drawn_on.size() == 1);
  CHECK(s.drawn_on[0].label.find("positions from the linear impulse-momentum along x") == 0);
  // the block on a cart: energy gives both positions; the momentum's second integral is not used
  s = solve_text(kt::derivation("momentum/block_slides_on_cart.yaml"));
  CHECK(s.drawn_on.empty());
}

TEST_CASE("positions over a duration: what is refused, and why", "[momentum][positions]") {
  // a collar sliding out along a turning rod: H = (I + m s²) θ̇ changes with s
  std::string collar = kt::edit(kt::derivation("momentum/collar_on_rod.yaml"), "find:\n", "find:\n  th2: {value: theta@2, unit: rad}\n");
  REQUIRE_THROWS_WITH(solve_text(collar), Catch::Contains("'th2' is not determined: theta@2 is unknown") &&
                                              Catch::Contains("the angular_momentum analysis 1 -> 2 does not give it: the angular momentum about O "
                                                              "changes with the position"));
  // a block hanging from a drum's cord: the cord's impulse is an unknown total, not a force in time
  std::string drum = kt::edit(kt::derivation("momentum/drum_cord_tension.yaml"), "find:\n", "find:\n  y2: {value: y@2, unit: m}\n");
  REQUIRE_THROWS_WITH(solve_text(drum), Catch::Contains("'y2' is not determined") &&
                                            Catch::Contains("the impulse of 'cord' along y is an unknown total, not a force known in time") &&
                                            Catch::Contains("give y@2 at its state"));
}

TEST_CASE("positions over a duration: a chain of analyses, the time to travel a distance, a motion that stops", "[momentum][positions]") {
  // two legs under a constant force from rest: x₃ = F t₃²/(2m) = 4·4/4 = 4 m (x@2 from the first leg)
  std::string chain = kt::edit(pushed_block("P", "0"), "  2: {t: t2}\n", "  2: {t: t2}\n  3: {t: 2*t2}\n");
  chain = kt::edit(chain, "  - momentum: {from: 1, to: 2, along: x}\n",
                   "  - momentum: {from: 1, to: 2, along: x}\n  - momentum: {from: 2, to: 3, along: x}\n");
  chain = kt::edit(chain, "x2: {value: x@2, unit: m}", "x3: {value: x@3, unit: m}");
  CHECK(value(solve_text(chain), "x3") == Approx(10.0 * 16 / 8).epsilon(1e-14));
  // F = c t from rest until x = a: x = c t³/(6m), t = (6 m a/c)^(1/3) = 2 s
  std::string travel = kt::edit(pushed_block("c*t", "0"), "  2: {t: t2}", "  2: {where: [\"x = a\"]}");
  travel = kt::edit(travel, "  t2: 2 s", "  a: 2 m");
  travel = kt::edit(travel, "x2: {value: x@2, unit: m}", "t2: {value: t@2, root: positive, unit: s}");
  CHECK(value(solve_text(travel), "t2") == Approx(std::cbrt(6.0 * 4 * 2 / 6)).epsilon(1e-13));
  // a block that stops inside the interval: kinetic friction would be taken pushing back after
  // it stops (v₂ = v0 − μ g t₂ < 0): refused, saying where to end the analysis
  const std::string stop = R"(title: block stops
parameters: {m: 2 kg, g: 9.81 m/s^2, mu_k: 0.5, v0: 3 m/s, t2: 2 s}
coordinates: {x: m}
bodies:
  block: {mass: m, inertia: particle, position: [x, 0]}
effects:
  rub: {friction: block, mu: mu_k, normal: m*g}
states:
  1: {t: 0, x: 0, x_dot: v0}
  2: {t: t2}
analyses:
  - momentum: {from: 1, to: 2, along: x}
find:
  d: {value: x@2, unit: m}
)";
  REQUIRE_THROWS_WITH(solve_text(stop), Catch::Contains("the sliding under 'rub' is positive at state '1' but the other way at state '2'") &&
                                            Catch::Contains("end the analysis where the sliding stops"));
  // ended where it stops: d = v0²/(2 μ g)
  std::string stops = kt::edit(stop, "  2: {t: t2}", "  2: {where: [\"x_dot = 0\"]}");
  CHECK(value(solve_text(stops), "d") == Approx(9.0 / (2 * 0.5 * 9.81)).epsilon(1e-14));
}
