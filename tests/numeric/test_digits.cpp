// Values as `kinergy solve` gives them: the compiled double by default, N guaranteed digits with
// --digits N; both against GiNaC's own evaluation of the same closed form at 100 digits (another
// code path), for every derivation.
#include <catch2/catch.hpp>

#include <regex>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"

using namespace GiNaC;
namespace fs = std::filesystem;

TEST_CASE("kinergy solve --digits 50 on the sliding rod: all 50 digits, proven, and the ball in JSON",
          "[numeric][digits][cli]") {
  int status = 0;
  std::string out = kt::run_cli("solve derivations/energy/sliding_rod.yaml --digits 50", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= 3.5017852589786256052372546604589676703245542931001 rad/s"));
  CHECK_THAT(out, Catch::Contains("(proven: ball radius "));
  // JSON: the ball's midpoint and radius; the midpoint agrees with the reference (mpmath, 60
  // digits: sqrt(3 g sin(theta2) / l) = 3.50178525897862560523725466045896767032455429310007178340814…)
  // to the 50 digits (that the reference lies inside the ball: test_proven.cpp)
  out = kt::run_cli("solve derivations/energy/sliding_rod.yaml --digits 50 --json", status);
  CHECK_THAT(out, Catch::Contains("\"proven\": true, \"midpoint\": \"3.501785258978625605237254660458967670324554293100"));
  CHECK(std::regex_search(out, std::regex("\"radius\": \"[0-9.]+e-5[0-9]\"")));  // below 1e-50
  // the default: 15 digits, nothing added to the line
  out = kt::run_cli("solve derivations/energy/sliding_rod.yaml", status);
  CHECK_THAT(out, Catch::Contains("= 3.50178525897863 rad/s\n"));
  // JSON says how each value was obtained
  out = kt::run_cli("solve derivations/impact/centre_of_percussion.yaml --json", status);
  CHECK_THAT(out, Catch::Contains("\"evaluation\": \"double, |error| <= 0\""));
}

TEST_CASE("every derivation: default values and --digits 40 agree with 100-digit GiNaC evaluation",
          "[numeric][digits][derivations]") {
  int doubles = 0, values = 0;
  for (const auto& f : kt::scene_files("derivations")) {
    kinergy::Solution s = kinergy::solve_file(f);
    auto env = s.model.numeric_environment();
    for (auto& r : s.results) {
      if (!r.si) continue;
      INFO(fs::path(f).filename().string() << ": " << r.name << " = " << r.closed);
      auto ref = kinergy::numerics::evaluate(r.closed / r.unit_factor, env, 100);
      REQUIRE(ref);
      auto dflt = r.evaluate(env, 15, true);
      REQUIRE(dflt);
      CHECK(kinergy::numerics::format(dflt->v, 15) == kinergy::numerics::format(*ref, 15));
      if (dflt->how == kinergy::Value::How::Double) ++doubles;
      // a value taken numerically (a numeric root, a work integral) goes to kRootDigits
      auto d40 = r.evaluate(env, r.closed_form ? 40 : kinergy::kRootDigits, false);
      REQUIRE(d40);
      CHECK(d40->how != kinergy::Value::How::Double);
      const int n = r.closed_form ? 40 : kinergy::kRootDigits;
      CHECK(kinergy::numerics::format(d40->v, n) == kinergy::numerics::format(*ref, n));
      ++values;
    }
  }
  CHECK(values >= 100);
  // the compiled double decides most values by itself (the rest fall near a rounding boundary
  // of the 15th digit, where its error bound cannot tell which way to round)
  CHECK(doubles * 2 > values);
}

TEST_CASE("a number found numerically that is not proven is not reported to more digits than it was refined to", "[numeric][digits]") {
  // roots, values solved from them, chains of roots and extremes at numeric stationary points are
  // proven to any number of digits (test_proven.cpp). A value that holds a number found
  // numerically and no expression of proven roots (here one made by hand: its closed form holds a
  // root's number, and it keeps no roots) is refined to kRootDigits: no more are given, and those
  // are not called proven.
  GiNaC::symbol L("L");
  kinergy::Result r;
  r.name = "h";
  r.pos = kinergy::SourcePos{"made.yaml", 7, 3};
  r.closed = L / 2 * sin(GiNaC::numeric("11.926372505758016916010682889800287461137"));
  r.closed_form = false;
  GiNaC::exmap env{{L, 1}};
  auto v = r.evaluate(env, kinergy::kRootDigits, false);
  REQUIRE(v);
  CHECK(!v->proven);
  CHECK_THROWS_WITH(r.evaluate(env, kinergy::kRootDigits + 5, false),
                    Catch::Contains("made.yaml:7:3") && Catch::Contains("'h' has no closed form (it holds a number found numerically") &&
                        Catch::Contains("--digits 35 or fewer"));
}

TEST_CASE("a double that underflows, and an angle beyond the working precision, decide nothing",
          "[numeric][digits][cli]") {
  // references: tests/data/numeric/out_of_range_reference.py (mpmath)
  const std::string scene = "tests/data/numeric/out_of_range.yaml";
  int status = 0;
  std::string out = kt::run_cli("solve " + scene + " --json", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("\"name\": \"tiny\", \"closed_form\": \"-b*exp(-a)\", \"value\": \"-6.59366295617712e-434295\""));
  CHECK_THAT(out, Catch::Contains("\"name\": \"sin_c\", \"closed_form\": \"sin(c)\", \"value\": \"-0.0565899244281819\""));
  CHECK_THAT(out, Catch::Contains("\"name\": \"cos_c\", \"closed_form\": \"cos(c)\", \"value\": \"-0.99839750623347\""));
  CHECK_THAT(out, Catch::Contains("\"name\": \"small\", \"closed_form\": \"s*cos(k)\", \"value\": \"-9.89992496600445e-401\""));
  CHECK_THAT(out, !Catch::Contains("\"evaluation\": \"double"));
  out = kt::run_cli("solve " + scene + " --digits 30", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= -6.59366295617711715793781593822e-434295 m"));
  CHECK_THAT(out, Catch::Contains("= -0.056589924428181880030384130647"));
  CHECK_THAT(out, Catch::Contains("= -0.998397506233470448825399367459"));
  for (int d = 1; d <= 9; ++d) {
    INFO("--digits " << d);
    out = kt::run_cli("solve " + scene + " --digits " + std::to_string(d), status);
    CHECK(status == 0);
  }
}

TEST_CASE("a root chosen with an angle of 1e300 deg", "[numeric][digits][cli]") {
  // reference: tests/data/numeric/out_of_range_reference.py (mpmath)
  int status = 0;
  std::string out = kt::run_cli("solve tests/data/numeric/big_angle.yaml --digits 25", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= 5.198240528322191594483011 rad/s"));
}
