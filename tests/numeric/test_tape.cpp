// The compiled double evaluator against 50-digit evaluation of the same closed forms.
#include <catch2/catch.hpp>

#include <filesystem>

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
