// The compiled double evaluator against 50-digit evaluation of the same closed forms.
#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

#include "../support/helpers.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/tape.hpp"
#include "kinergy/problem.hpp"

namespace fs = std::filesystem;
using namespace GiNaC;
using kinergy::numerics::Tape;

TEST_CASE("tape: sin(theta2) and its kin are computed once", "[numeric][tape]") {
  realsymbol th("th"), l("l"), g("g");
  // ω = √(3 g sin θ / l) and a second use of sin θ: one Sin instruction
  ex e = sqrt(3 * g * sin(th) / l) + pow(sin(th), 2);
  Tape t = Tape::compile(e, {th, l, g});
  std::vector<double> x = {0.5235987755982988, 1.2, 9.81};
  double hand = std::sqrt(3 * 9.81 * std::sin(x[0]) / 1.2) + std::sin(x[0]) * std::sin(x[0]);
  CHECK(t(x) == Approx(hand).epsilon(1e-15));
  // sharing: adding sin(θ)² to the form costs the square and the sum only, not a second sine
  // (an absolute count would depend on GiNaC's canonical form, which varies with addresses)
  Tape alone = Tape::compile(sqrt(3 * g * sin(th) / l), {th, l, g});
  CHECK(t.instructions() == alone.instructions() + 2);
}

TEST_CASE("tape: what it cannot evaluate is named", "[numeric][tape]") {
  realsymbol x("x"), y("y");
  CHECK_THROWS_WITH(Tape::compile(x + y, {x}), Catch::Contains("'y' is not an input"));
  CHECK_THROWS_WITH(Tape::compile(zeta(x), {x}), Catch::Contains("zeta"));
}

TEST_CASE("tape: every derivation's closed forms agree with 50-digit values", "[numeric][tape][derivations]") {
  int checked = 0;
  for (auto& f : kt::scene_files("derivations")) {
    kinergy::Solution s = kinergy::solve_file(f);
    auto env = s.model.numeric_environment();
    std::vector<ex> inputs;
    std::vector<double> x;
    for (auto& p : s.model.params)
      if (env.count(p.sym)) {
        inputs.push_back(p.sym);
        x.push_back(kinergy::numerics::evaluate(env[p.sym], {}, 30)->to_double());
      }
    for (auto& r : s.results) {
      if (!r.closed_form || !r.si) continue;
      INFO(fs::path(f).filename().string() << ": " << r.name << " = " << r.closed);
      bool integral = false;
      for (auto it = r.closed.preorder_begin(); it != r.closed.preorder_end(); ++it) integral = integral || kinergy::numerics::is_integral(*it);
      if (integral) {
        // a work integral held as such runs only on balls (tests/numeric/test_proven.cpp)
        CHECK_THROWS_WITH(Tape::compile(r.closed, inputs), Catch::Contains("runs only on balls"));
        continue;
      }
      Tape t = Tape::compile(r.closed, inputs);
      double got = t(x);
      // the reference from the same double inputs, at 50 digits
      exmap at;
      for (std::size_t i = 0; i < inputs.size(); ++i) at[inputs[i]] = numeric(x[i]);
      auto ref = kinergy::numerics::evaluate(r.closed, at, 50);
      REQUIRE(ref);
      double want = ref->to_double();
      double scale = std::max(std::abs(want), 1e-300);
      // at the scenes' own values no form cancels badly: a few ulps through the whole tape
      CHECK(std::abs(got - want) <= 1e-14 * scale + 1e-300);
      ++checked;
    }
  }
  CHECK(checked >= 80);
}

TEST_CASE("tape: an enclosure over a box holds every value in it, and says where the form may be undefined", "[numeric][tape]") {
  realsymbol a("a"), b("b");
  // forms with every kind of step: products, quotients, roots, the periodic functions, powers
  const std::vector<ex> forms = {
      sqrt(3 * 9.81 * sin(a) / b),  a * b - pow(a, 3) / (1 + b * b), cos(a) * exp(-b) + atan(a / b),
      pow(b, numeric(3, 2)) * log(b) - tan(a / 4), atan2(b, a) + asin(a / 4) - sinh(b) / cosh(a),
  };
  Tape t = Tape::compile(forms, {a, b});
  std::vector<kinergy::numerics::Enclosed> box(forms.size());
  std::vector<double> out(forms.size());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int held = 0;
  for (int trial = 0; trial < 200; ++trial) {
    // boxes inside a ∈ (0.1, 3), b ∈ (0.5, 4), from tiny to the whole region
    const double ra = std::pow(10.0, -6 * u(rng)) * 1.4, rb = std::pow(10.0, -6 * u(rng)) * 1.7;
    const double ma = 0.1 + ra + (2.9 - 2 * ra) * u(rng), mb = 0.5 + rb + (3.5 - 2 * rb) * u(rng);
    const double mid[2] = {ma, mb}, rad[2] = {ra, rb};
    t.enclose(mid, rad, box.data());
    for (int s = 0; s < 50; ++s) {
      const double x[2] = {ma + ra * (2 * u(rng) - 1), mb + rb * (2 * u(rng) - 1)};
      t.eval(x, out.data());
      for (std::size_t k = 0; k < forms.size(); ++k) {
        INFO("form " << k << " over [" << ma << " ± " << ra << "] × [" << mb << " ± " << rb << "]");
        // (a wide box may be taken as reaching where a root's argument is negative: an
        // enclosure is conservative; a small one inside the domain never is)
        if (ra < 1e-3 && rb < 1e-3) REQUIRE(!box[k].maybe_undefined);
        if (box[k].maybe_undefined) continue;
        ++held;
        // (the sample's own double carries rounding of 1e-13 relative at most)
        CHECK(std::fabs(out[k] - box[k].value) <= box[k].bound + 1e-13 * std::fabs(out[k]));
      }
    }
  }
  CHECK(held > 200 * 50 * 4);
  // a box that reaches where sin a < 0, a pole of tan, a division by an interval that holds 0
  const double over_pi[2] = {3.0, 1.0}, r1[2] = {0.2, 0.1};
  t.enclose(over_pi, r1, box.data());
  CHECK(box[0].maybe_undefined);
  CHECK(!box[1].maybe_undefined);
  Tape q = Tape::compile(std::vector<ex>{1 / (a - b), tan(a), sqrt(a)}, {a, b});
  std::vector<kinergy::numerics::Enclosed> e(3);
  const double near[2] = {1.0, 1.05}, r2[2] = {0.1, 0.01};
  q.enclose(near, r2, e.data());
  CHECK(e[0].maybe_undefined);
  CHECK(!e[1].maybe_undefined);
  CHECK(!e[2].maybe_undefined);
  const double pole[2] = {1.6, 0.0}, r3[2] = {0.05, 0.0};
  q.enclose(pole, r3, e.data());
  CHECK(e[1].maybe_undefined);
  const double zero[2] = {0.01, 0.0}, r4[2] = {0.02, 0.0};
  q.enclose(zero, r4, e.data());
  CHECK(e[2].maybe_undefined);
}
