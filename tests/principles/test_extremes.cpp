// Extremes over the motion (issue 13, part 4): the greatest or least value of a result as a
// parameter without a value runs over a range, or where it is reached — from the stationary
// condition with the second-order check, or at an end of the range. Expected values by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"

using kt::derivation;
using kt::edit;
using kt::solve_text;

namespace {

// a particle at rest at x = 0; state 2 at x = p (a parameter without a value); the results are
// expressions of p (the position at state 2)
std::string with(const std::string& finds) {
  return "title: extremes\nparameters:\n  m: 1 kg\n  a: 1 m\n  c: 2 m\n  p: m\ncoordinates:\n  x: m\nbodies:\n"
         "  b: {mass: m, inertia: particle, position: [x, 0]}\nstates:\n  1: {x: 0, x_dot: 0}\n  2: {x: p}\nfind:\n" +
         finds;
}

double si(const kinergy::Solution& s, const std::string& name) { return kt::result(s, name).si->to_double(); }

}  // namespace

TEST_CASE("the greatest and least values over a range, and where they are reached", "[extremes]") {
  SECTION("a minimum inside: (x - 1)^2 + 2 over [0, 3] is least, 2, at x = 1") {
    auto s = solve_text(with("  f: {value: \"(x@2 - a)^2/a + c\", min: p, over: [0, 3 m], unit: m}\n"
                             "  at: {value: \"(x@2 - a)^2/a + c\", at_min: p, over: [0, 3 m], unit: m}\n"));
    CHECK(std::fabs(si(s, "f") - 2) < 1e-30);
    CHECK(std::fabs(si(s, "at") - 1) < 1e-30);
    CHECK(!kt::result(s, "f").closed_form);
    CHECK(kt::result(s, "at").extreme_note.find("second derivative 2 > 0, a minimum") != std::string::npos);
  }
  SECTION("a maximum at an end: x over [0, 2] is greatest, 2, at the end") {
    auto s = solve_text(with("  f: {value: x@2, max: p, over: [0, 2 m], unit: m}\n"));
    CHECK(std::fabs(si(s, "f") - 2) < 1e-30);
    CHECK(kt::result(s, "f").extreme_note.find("nowhere inside the range") != std::string::npos);
    CHECK(kt::result(s, "f").extreme_note.find("an end of the range") != std::string::npos);
  }
  SECTION("x sin(x/1 m) over [0, 3]: greatest where tan(x) = -x, x = 2.0287578381104342") {
    // by hand: d/dx (x sin x) = sin x + x cos x = 0 → tan x = −x; the root in (pi/2, pi), by mpmath's findroot
    auto s = solve_text(with("  at: {value: \"x@2*sin(x@2/a)\", at_max: p, over: [0, 3 m], unit: m}\n"));
    CHECK(std::fabs(si(s, "at") - 2.0287578381104342) < 1e-14);
  }
}

TEST_CASE("extremes: what is refused", "[extremes][errors]") {
  REQUIRE_THROWS_WITH(solve_text(with("  f: {value: x@2, max: m, over: [0, 2 m]}\n")),
                      Catch::Contains("'max' runs over a parameter without a value, and 'm' is given a value"));
  REQUIRE_THROWS_WITH(solve_text(with("  f: {value: x@2, max: q, over: [0, 2 m]}\n")), Catch::Contains("'q' is no parameter"));
  REQUIRE_THROWS_WITH(solve_text(with("  f: {value: x@2, max: p}\n")), Catch::Contains("asks for an extreme without its range"));
  REQUIRE_THROWS_WITH(solve_text(with("  f: {value: x@2, over: [0, 2 m]}\n")), Catch::Contains("'over' gives the range of an extreme"));
  REQUIRE_THROWS_WITH(solve_text(with("  f: {value: x@2, max: p, min: p, over: [0, 2 m]}\n")), Catch::Contains("asks for two extremes"));
  REQUIRE_THROWS_WITH(solve_text(with("  f: {value: x@2, max: p, over: [2 m, 0]}\n")), Catch::Contains("with lo < hi"));
  REQUIRE_THROWS_WITH(solve_text(with("  f: {value: x@2, max: p, over: 2 m}\n")), Catch::Contains("'over' is a range [lo, hi]"));
}
