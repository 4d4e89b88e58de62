// Square roots of results (issue 13, part 5): a perfect square comes out of its root when the
// sign of what is squared is known — a positive symbol, or an expression of parameters whose
// given values fix its sign — so a result that does not depend on a parameter without a value
// gets its number. Expected forms by hand.
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/problem.hpp"

using GiNaC::ex;

namespace {

kinergy::Solution with_find(const std::string& params, const std::string& find) {
  std::string text = "title: roots\nparameters:\n" + params +
                     "  m: 1 kg\ncoordinates:\n  x: m\nbodies:\n  b: {mass: m, inertia: particle, position: [x, 0]}\n"
                     "states:\n  1: {x: 0, x_dot: 0}\nfind:\n  d: " + find + "\n";
  INFO(text);
  return kinergy::solve_scene(kinergy::scene::load_string(text, "test.yaml"));
}

}  // namespace

TEST_CASE("a perfect square under a root comes out when its sign is known", "[model][roots]") {
  SECTION("sqrt(L s0 + L^2/4 + s0^2) - s0 = L/2 with s0 without a value: a number") {
    auto s = with_find("  L: 2 m\n  s0: m\n", "{value: \"sqrt(L*s0 + L^2/4 + s0^2) - s0\", unit: m}");
    CHECK(kt::symbolically_zero(kt::result(s, "d").closed - kt::param(s.model, "L") / 2));
    REQUIRE(kt::result(s, "d").si);
    CHECK(kinergy::numerics::format(*kt::result(s, "d").si, 6) == "1");
  }
  SECTION("sqrt(sin(beta)^2) = sin(beta) for beta = 20 deg, -sin(beta) for beta = 200 deg") {
    auto s = with_find("  beta: 20 deg\n", "\"sqrt(sin(beta)^2)\"");
    ex beta = kt::param(s.model, "beta");
    CHECK(kt::symbolically_zero(kt::result(s, "d").closed - sin(beta)));
    auto t = with_find("  beta: 200 deg\n", "\"sqrt(sin(beta)^2)\"");
    CHECK(kt::symbolically_zero(kt::result(t, "d").closed + sin(kt::param(t.model, "beta"))));
  }
  SECTION("a square whose sign no value fixes stays under its root") {
    // s0 - L/2 may have either sign for an s0 without a value
    auto s = with_find("  L: 2 m\n  s0: m\n", "\"sqrt(s0^2 - L*s0 + L^2/4)\"");
    CHECK(kt::result(s, "d").closed.has(kt::param(s.model, "s0")));
    bool rooted = false;
    for (auto it = kt::result(s, "d").closed.preorder_begin(); it != kt::result(s, "d").closed.preorder_end(); ++it)
      rooted = rooted || (GiNaC::is_a<GiNaC::power>(*it) && it->op(1).is_equal(GiNaC::numeric(1, 2)));
    CHECK(rooted);
  }
}
