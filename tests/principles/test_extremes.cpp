// Extremes over the motion (issue 13, part 4): the greatest or least value of a result as a
// parameter without a value runs over a range, or where it is reached — from the stationary
// condition with the second-order check, or at an end of the range. Expected values by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/simulate/simulate.hpp"

#include <sstream>

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
    // the stationary condition 2 (x - a)/a = 0 solved in closed form: x = a, f = c
    CHECK(kt::result(s, "f").closed_form);
    CHECK(kt::symbolically_zero(kt::result(s, "f").closed - kt::param(s.model, "c")));
    CHECK(kt::symbolically_zero(kt::result(s, "at").closed - kt::param(s.model, "a")));
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
    CHECK(!kt::result(s, "at").closed_form);  // tan x = -x: no closed form
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

namespace {

// a block sliding on a rough floor from x = 0 with speed v (friction mu m g): state 2 at x = d
std::string sliding(const std::string& params, const std::string& state2, const std::string& finds) {
  return "title: reach\nparameters:\n  m: 2 kg\n  g: 9.81 m/s^2\n" + params +
         "coordinates:\n  x: m\nbodies:\n  b: {mass: m, inertia: particle, position: [x, 0]}\n"
         "effects:\n  rubbing: {friction: b, mu: mu, normal: m*g}\n"
         "states:\n  1: {x: 0, x_dot: v}\n  2: " + state2 + "\nanalyses:\n  - energy: {from: 1, to: 2}\nfind:\n" + finds;
}

}  // namespace

TEST_CASE("the least or greatest value of a parameter for which a state is reached", "[extremes][reach]") {
  SECTION("greatest friction coefficient: (1/2) m v^2 = mu m g d, mu = v^2/(2 g d) = 16/39.24") {
    auto s = solve_text(sliding("  v: 4 m/s\n  d: 2 m\n  mu: number\n", "{x: d}", "  mu_max: {greatest: mu, reaches: 2}\n"));
    const auto& r = kt::result(s, "mu_max");
    CHECK(r.closed_form);
    CHECK(kt::symbolically_zero(r.closed - GiNaC::pow(kt::param(s.model, "v"), 2) / (2 * kt::param(s.model, "g") * kt::param(s.model, "d"))));
    CHECK(std::fabs(si(s, "mu_max") - 16.0 / 39.24) < 1e-15);
    CHECK(r.extreme_note.find("for mu below") != std::string::npos);
  }
  SECTION("least speed, the state at the end only: v = sqrt(2 mu g d)") {
    auto s = solve_text(sliding("  mu: 0.25\n  d: 2 m\n  v: m/s\n", "{x: d}", "  v_min: {least: v, reaches: 2, unit: m/s}\n"));
    CHECK(std::fabs(si(s, "v_min") - std::sqrt(2 * 0.25 * 9.81 * 2)) < 1e-14);
    CHECK(kt::result(s, "v_min").extreme_note.find("taken at the state itself") != std::string::npos);
  }
  SECTION("a hump inside the path whose top is not a simple number: no closed form, the number by hand") {
    // a particle on a smooth floor pushed by F = -k (2 x - x^2/a), the force of the potential
    // V = k (x^2 - x^3/(3 a)), from x = 0 to s in [0, 2.7 a]: V is greatest inside, at x = 2 a (V' = 0,
    // V'' = -2 k < 0), V(2 a) = 4 k a^2/3 (the far end has V(2.7 a) < V(2 a)). Least v: (1/2) m v^2 =
    // 4 k a^2/3, v = sqrt(8 k a^2/(3 m)); with a = 1.3 m the top, 2.6 m, is found exactly (a rational).
    std::string scene =
        "title: hump\nparameters:\n  m: 2 kg\n  k: 5 N/m\n  a: 1.3 m\n  v: m/s\n  s: m\ncoordinates:\n  x: m\nbodies:\n"
        "  b: {mass: m, inertia: particle, position: [x, 0]}\neffects:\n  push: {force: b, F: [\"-k*(2*x - x^2/a)\", 0]}\n"
        "states:\n  1: {x: 0, x_dot: v}\n  2: {x: s}\nanalyses:\n  - energy: {from: 1, to: 2}\nfind:\n"
        "  v_min: {least: v, reaches: 2, along: s, over: [0, 2.7*a], unit: m/s}\n";
    auto s = solve_text(scene);
    CHECK(std::fabs(si(s, "v_min") - std::sqrt(8 * 5 * 1.69 / 6.0)) < 1e-14);
    CHECK(kt::result(s, "v_min").closed_form);
    CHECK(kt::result(s, "v_min").extreme_note.find("where its derivative along the path is zero") != std::string::npos);
    // the top moved to an irrational place (x = sqrt(2) a): V = k (x^2/2)... F = -k (x - x^3/(2 a^2)),
    // V = k (x^2/2 - x^4/(8 a^2)), greatest at x = sqrt(2) a: V = k a^2/2; v = sqrt(k a^2/m) = 1.3 sqrt(2.5)
    auto s2 = solve_text(edit(edit(scene, "\"-k*(2*x - x^2/a)\"", "\"-k*(x - x^3/(2*a^2))\""), "over: [0, 2.7*a]", "over: [0, 1.9*a]"));
    CHECK(std::fabs(si(s2, "v_min") - 1.3 * std::sqrt(2.5)) < 1e-14);
  }
}

TEST_CASE("least and greatest parameter values: what is refused", "[extremes][reach][errors]") {
  const std::string p = "  mu: 0.25\n  d: 2 m\n  v: m/s\n";
  auto refused = [&](const std::string& params, const std::string& s2, const std::string& find, const std::string& msg) {
    REQUIRE_THROWS_WITH(solve_text(sliding(params, s2, find)), Catch::Contains(msg));
  };
  refused(p, "{x: d}", "  f: {least: v}\n", "without the state to reach");
  refused(p, "{x: d}", "  f: {least: v, greatest: v, reaches: 2}\n", "both the least and the greatest");
  refused(p, "{x: d}", "  f: {least: v, reaches: 2, value: x@2}\n", "which has no 'value'");
  refused(p, "{x: d}", "  f: {value: x@2, reaches: 2}\n", "'reaches' names the state of a least or greatest parameter value");
  refused(p, "{x: d}", "  f: {least: v, reaches: 3}\n", "'reaches' names state '3', which the scene does not have");
  refused(p, "{x: d}", "  f: {least: mu, reaches: 2}\n", "'least' asks for the value of a parameter without a value, and 'mu' is given a value");
  refused(p, "{x: d}", "  f: {least: v, reaches: 2, along: d}\n", "'along' needs the range of the path");
  refused(p, "{x: d}", "  f: {least: v, reaches: 2, over: [0, 1 m]}\n", "'over' gives the range of the parameter named by 'along'");
  refused(p, "{x: d}", "  f: {least: v, reaches: 2, along: v, over: [0, 1 m]}\n", "names the parameter whose least value is asked");
  // another parameter without a value: the bound in closed form, (1/2) m v^2 = mu m g s
  {
    auto s = solve_text(sliding("  mu: 0.25\n  s: m\n  v: m/s\n", "{x: s}", "  f: {least: v, reaches: 2}\n"));
    const auto& r = kt::result(s, "f");
    REQUIRE(r.closed_form);
    const GiNaC::ex sv = kt::param(s.model, "s");
    for (int d : {1, 2, 7}) {
      GiNaC::exmap at = s.model.parameter_values();
      at[sv] = d;
      CHECK(kt::value(r.closed, at).to_double() == Approx(std::sqrt(0.5 * 9.81 * d)).epsilon(1e-14));
    }
  }
  // ... and where the bound has no closed form (the top of a hump where cos(x/a) = x/(2 a), a
  // transcendental place): neither a form nor a number, refused
  const std::string hump =
      "title: hump\nparameters:\n  m: 2 kg\n  k: 5 N/m\n  a: m\n  v: m/s\n  s: m\ncoordinates:\n  x: m\nbodies:\n"
      "  b: {mass: m, inertia: particle, position: [x, 0]}\neffects:\n  push: {force: b, F: [\"k*(x/2 - a*cos(x/a))\", 0]}\n"
      "states:\n  1: {x: 0, x_dot: v}\n  2: {x: s}\nanalyses:\n  - energy: {from: 1, to: 2}\nfind:\n"
      "  f: {least: v, reaches: 2, along: s, over: [0, 3*a]}\n";
  REQUIRE_THROWS_WITH(solve_text(hump), Catch::Contains("'f' has no closed form (its bound is found numerically, by a scan and bisection), and parameter '") &&
                                            Catch::Contains("neither a form nor a number"));
  // (with a number for a, the bound is found: the scene itself is good)
  CHECK_NOTHROW(solve_text(edit(hump, "  a: m\n", "  a: 1.3 m\n")));
  // the kinetic energy at 2 does not depend on the parameter
  refused("  mu: 0.25\n  d: 2 m\n  v: 4 m/s\n  w: m/s\n", "{x: d}", "  f: {least: w, reaches: 2}\n", "does not depend on 'w'");
  // never reached: a greatest speed (the energy only grows with v) / always reached
  refused(p, "{x: d}", "  f: {greatest: v, reaches: 2}\n", "state '2' is reached for every value of 'v' up to 2^40");
  refused("  mu: 0\n  d: 2 m\n  v: m/s\n", "{x: d}", "  f: {least: v, reaches: 2}\n", "state '2' is reached for every value of 'v' down to 2^-20");
  refused("  mu: 1e30\n  d: 2 m\n  v: m/s\n", "{x: d}", "  f: {least: v, reaches: 2}\n", "state '2' is not reached for any value of 'v'");
}

TEST_CASE("the least angular velocity for a full revolution, against a simulation", "[extremes][reach][simulate]") {
  // closed form against simulation: given 0.1 % more than w0_min the rod goes over the top (theta passes pi);
  // given 0.1 % less it swings back before it
  std::string text = kt::derivation("energy/rod_full_revolution_least_speed.yaml");
  auto s = solve_text(text);
  const double w0 = si(s, "w0_min");
  for (double f : {1.001, 0.999}) {
    std::ostringstream given;
    given.precision(17);
    given << "w0: " << f * w0 << " rad/s";
    auto m = kt::model_of(edit(text.substr(0, text.find("find:")), "w0: rad/s", given.str()));
    kinergy::simulate::Options o;
    o.native = false;
    kinergy::simulate::Simulator sim(m, m.parameter_values(), o);
    kinergy::simulate::State s0;
    s0.q = {0};
    s0.qd = {f * w0};
    auto run = sim.run(s0, {3.0, {}, true});
    double top = 0;
    for (auto& x : run.samples) top = std::max(top, x.q[0]);
    INFO("factor " << f << ": highest theta " << top);
    CHECK((f > 1 ? top > M_PI : top < M_PI));
  }
}
