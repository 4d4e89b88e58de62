// One-sided springs (issue 13, part 2): a spring that acts only in compression (a bumper met
// part-way, a launcher left behind) or only in tension does work only over the part of the motion
// where it acts; the energy equation takes it as acting at a state where its stretch has the
// acting sign, and the solved states are checked against that. Expected values by hand.
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"

using GiNaC::ex;

using kt::derivation;
using kt::edit;
using kt::solve_text;

TEST_CASE("a one-sided spring works only where it acts", "[effects][spring][one-sided]") {
  SECTION("a bumper: (1/2) m v0^2 = (1/2) k c^2, the root short of the spring dropped") {
    auto s = solve_text(derivation("energy/bumper_max_compression.yaml"));
    ex m = kt::param(s.model, "m"), k = kt::param(s.model, "k"), v0 = kt::param(s.model, "v0");
    CHECK(kt::symbolically_zero(kt::result(s, "c").closed - v0 * sqrt(m / k)));
  }
  SECTION("the same bumper pushing both ways is a spring attached to the package: it pulls it back before contact") {
    auto s = solve_text(edit(derivation("energy/bumper_max_compression.yaml"), ", acts: compression}", "}").substr(0) );
    // v2^2 = v0^2 - k (d/2)^2/m ... with the spring stretched by -d at the start: by hand
    // (1/2) m v0^2 + (1/2) k d^2 = (1/2) m v2^2 + (1/2) k (d/2)^2
    ex m = kt::param(s.model, "m"), k = kt::param(s.model, "k"), v0 = kt::param(s.model, "v0"), d = kt::param(s.model, "d");
    CHECK(kt::symbolically_zero(pow(kt::result(s, "v2").closed, 2) - (v0 * v0 + k * (d * d - d * d / 4) / m)));
  }
  SECTION("a launcher: its energy at the start only") {
    auto s = solve_text(derivation("energy/spring_launcher_height.yaml"));
    ex m = kt::param(s.model, "m"), k = kt::param(s.model, "k"), g = kt::param(s.model, "g"), L0 = kt::param(s.model, "L0"),
       y1 = kt::param(s.model, "y1");
    CHECK(kt::symbolically_zero(kt::result(s, "y2").closed - (y1 + k * pow(L0 - y1, 2) / (2 * m * g))));
  }
}

TEST_CASE("one-sided springs: what is refused", "[effects][spring][one-sided][errors]") {
  auto bumper = derivation("energy/bumper_max_compression.yaml");
  SECTION("'acts' other than compression, tension or both") {
    REQUIRE_THROWS_WITH(solve_text(edit(bumper, "acts: compression", "acts: sideways")),
                        Catch::Contains("'acts' must be compression, tension or both"));
  }
  SECTION("one-sided without a free length") {
    REQUIRE_THROWS_WITH(solve_text(edit(bumper, "free_length: L0, ", "")), Catch::Contains("needs its free length"));
  }
  SECTION("neither state says whether it acts") {
    auto text = edit(bumper, "  1: {x: 0, x_dot: v0}\n", "  1: {x_dot: v0}\n");
    REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("neither state '1' nor '3' tells whether it is"));
  }
  SECTION("both states short of the spring: it does no work") {
    auto text = edit(bumper, "  3: {x_dot: 0}\n", "  3: {x: 0.4 m}\n");
    text = edit(text, "  - energy: {from: 1, to: 3}\n", "  - energy: {from: 2, to: 3}\n");
    text = text.substr(0, text.find("find:\n")) + "find:\n  v3: {value: x_dot@3, root: positive, unit: m/s}\n";
    // both positions known short of the spring: no work, v3 = v0 (by hand)
    auto s = solve_text(text);
    CHECK(kinergy::numerics::format(*kt::result(s, "v3").si, 6) == "3");
  }
  SECTION("a solution that breaks the assumption is refused: a block too heavy to leave the spring") {
    // m = 30 kg: the spring (50 N at the start) cannot lift m g = 294 N; taken as left behind at
    // the top, the energy equation puts the top at y2 = 0.1085 m, where the spring is still
    // compressed (stretch -0.0915 m): no solution of the scene as written
    auto text = edit(derivation("energy/spring_launcher_height.yaml"), "  m: 0.5 kg\n", "  m: 30 kg\n");
    text = text.substr(0, text.find("expect:\n"));
    REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("spring 'launcher' was taken as not compressed at state '2', but the "
                                                          "solution puts its stretch there at -0.0915") &&
                                              Catch::Contains("it does act there"));
  }
}
