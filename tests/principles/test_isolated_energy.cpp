// Work–energy of a body set isolated from the rest (issue 13, part 1): the set's own kinetic
// energy, the effects acting only on it whole, those acting only outside not at all, and those
// that cross its boundary by their work on it — a weight by the set's own, a constraint by its
// unknown average force times the distance its point moves along it. Every expected form here
// is worked by hand in the comments (the numbers of the derivations are re-derived by
// tests/momentum/isolated_bodies_reference.py).
#include <catch2/catch.hpp>

#include <map>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"

using GiNaC::ex;

using kt::derivation;
using kt::edit;
using kt::solve_text;

namespace {

ex P(const kinergy::Solution& s, const std::string& name) { return kt::param(s.model, name); }
ex closed(const kinergy::Solution& s, const std::string& name) { return kt::result(s, name).closed; }

// A block of mass m hangs from a cord wound on a drum (a disk of mass M, radius R, on a fixed
// axle), released from rest; at state 2 it has dropped d. All symbolic.
const std::string drum = R"Y(title: block on a cord from a drum
parameters:
  m: kg
  M: kg
  R: m
  a: m
  d: m
  g: m/s^2
points:
  O: [0, 0]
coordinates:
  phi: rad
  y: m
bodies:
  drum: {mass: M, inertia: {disk: R}, position: [0, 0], angle: phi}
  block: {mass: m, inertia: particle, position: [R, y]}
effects:
  gravity: {g: g}
  axle: {pin: [O, drum]}
  cord: {constraint: "y = R*phi - a", between: [block, drum], at: [[R, y], [R, 0]]}
states:
  1: {phi: 0, phi_dot: 0}
  2: {y: -a - d}
analyses:
  - energy: {from: 1, to: 2}
  - ISOLATED
find:
  v2: {value: y_dot@2, root: negative}
  T: "force(cord, 1, 2)"
)Y";

}  // namespace

TEST_CASE("the cord's tension from the work-energy of the block alone, and of the drum alone", "[energy][isolated]") {
  // By hand: the system, m g d = (1/2)(m + M/2) v^2, so v^2 = 4 m g d/(2m + M). The block alone:
  // (1/2) m v^2 = m g d - T d, so T = m g - m v^2/(2d) = m g M/(2m + M). The drum alone:
  // (1/2)(M R^2/2)(v/R)^2 = T d gives the same T.
  for (const char* set : {"[block]", "[drum]"}) {
    DYNAMIC_SECTION("bodies: " << set) {
      auto s = solve_text(edit(drum, "ISOLATED", std::string("energy: {from: 1, to: 2, bodies: ") + set + "}"));
      ex m = P(s, "m"), M = P(s, "M"), g = P(s, "g"), d = P(s, "d");
      CHECK(kt::symbolically_zero(GiNaC::pow(closed(s, "v2"), 2) - 4 * m * g * d / (2 * m + M)));
      CHECK(kt::symbolically_zero(closed(s, "T") - m * g * M / (2 * m + M)));
    }
  }
}

TEST_CASE("an effect acting inside and outside an isolated set without a known work is refused", "[energy][isolated]") {
  // a spring between the block and the drum's rim, instead of the cord's constraint effect
  auto text = edit(drum, "  cord: {constraint: \"y = R*phi - a\", between: [block, drum], at: [[R, y], [R, 0]]}\n",
                   "  cord: {constraint: \"y = R*phi - a\", between: [block, drum], at: [[R, y], [R, 0]]}\n"
                   "  tie: {spring: [block, drum], k: m*g/d, free_length: d}\n");
  text = edit(text, "ISOLATED", "energy: {from: 1, to: 2, bodies: [block]}");
  REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("effect 'tie' (spring) acts on bodies inside this energy analysis' set and outside it") &&
                                            Catch::Contains("list in 'bodies' every body it acts on (block, drum)"));
}

TEST_CASE("force() names an energy analysis that isolates one of its parties", "[energy][isolated]") {
  auto text = edit(drum, "  - ISOLATED\n", "");
  REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("no energy analysis from state '1' to '2' isolates bodies that 'cord' joins to the rest"));
  text = edit(drum, "ISOLATED", "energy: {from: 1, to: 2, bodies: [block]}");
  text = edit(text, "force(cord, 1, 2)", "force(nothing, 1, 2)");
  REQUIRE_THROWS_WITH(solve_text(text), Catch::Contains("no effect named 'nothing'"));
}

TEST_CASE("an isolated set sees its own weight, and the work of the interaction on it", "[energy][isolated]") {
  // The block alone: its weight does U = -m g (y2 - y1); the cord's force on it, average T̄ along
  // û (on the block), does T̄ (y2 - y1) (the block moves along y). The drum alone: no work of
  // gravity (its centre is fixed), the cord's force on it (−T̄ û at (R, 0)) does -T̄ R (phi2 - phi1).
  auto s = solve_text(edit(drum, "ISOLATED", "energy: {from: 1, to: 2, bodies: [block]}"));
  REQUIRE(s.balances_of<kinergy::principles::EnergyBalance>().size() == 2);
  const auto& m = s.model;
  ex y1 = kt::at(m, "y", "1"), y2 = kt::at(m, "y", "2");
  std::map<std::string, ex> U;
  for (auto& w : s.balances_of<kinergy::principles::EnergyBalance>()[1]->works) U[w.effect] = w.U;
  REQUIRE(U.count("gravity"));
  REQUIRE(U.count("cord"));
  CHECK(kt::symbolically_zero(U["gravity"] + P(s, "m") * P(s, "g") * (y2 - y1)));
  ex F = m.analyses[1].reactions.at("cord")[0];
  CHECK(kt::symbolically_zero(U["cord"] - F * (y2 - y1)));
  CHECK(U.size() == 2);  // the axle and the drum's weight act outside the set

  auto d = solve_text(edit(drum, "ISOLATED", "energy: {from: 1, to: 2, bodies: [drum]}"));
  std::map<std::string, ex> Ud;
  for (auto& w : d.balances_of<kinergy::principles::EnergyBalance>()[1]->works) Ud[w.effect] = w.U;
  CHECK(!Ud.count("gravity"));
  REQUIRE(Ud.count("cord"));
  ex Fd = d.model.analyses[1].reactions.at("cord")[0];
  CHECK(kt::symbolically_zero(Ud["cord"] + Fd * P(d, "R") * (kt::at(d.model, "phi", "2") - kt::at(d.model, "phi", "1"))));
}
