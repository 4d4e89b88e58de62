// kinergy simulate from the command line: its outputs (summary, CSV, plot, equations, checks)
// and every way a simulation is refused, each with the file, line and a fix.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "../support/helpers.hpp"

namespace fs = std::filesystem;

TEST_CASE("kinergy simulate: summary, CSV and plot of the sliding rod", "[simulate][cli]") {
  fs::path dir = fs::temp_directory_path() / "kinergy-sim-cli";
  fs::create_directories(dir);
  fs::path csv = dir / "rod.csv", svg = dir / "rod.svg";
  int status = 0;
  std::string out = kt::run_cli("simulate derivations/energy/sliding_rod.yaml --until 0.5 --tol 1e-12 --csv " +
                                    kt::shell_quoted(csv.string()) + " --plot " + kt::shell_quoted(svg.string()),
                                status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("method dopri5, tol 1e-12"));
  CHECK_THAT(out, Catch::Contains("end at t = 0.5 s:"));
  CHECK_THAT(out, Catch::Contains("drift |E1 - E0|"));
  std::ifstream c(csv);
  std::string header, row;
  std::getline(c, header);
  std::getline(c, row);
  CHECK(header == "t,theta,theta_dot,T,V,E");
  CHECK(row.rfind("0,", 0) == 0);
  REQUIRE(fs::exists(svg));
  std::ifstream s(svg);
  std::string text((std::istreambuf_iterator<char>(s)), {});
  CHECK_THAT(text, Catch::Contains("<svg"));
  fs::remove_all(dir);
}

TEST_CASE("kinergy simulate --equations and --check", "[simulate][cli]") {
  int status = 0;
  std::string out = kt::run_cli("simulate derivations/energy/atwood_pulley.yaml --equations --check --tol 1e-12", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("M[phi,phi] = M*r^2/2\n"));  // ½ M r², in the plain printer's order
  CHECK_THAT(out, Catch::Contains("M[yA,yA] = mA"));
  CHECK_THAT(out, Catch::Contains("constraints g(q, t) = 0:"));
  CHECK_THAT(out, Catch::Contains("energy 1 -> 2: until yA reaches -1.5"));
  CHECK_THAT(out, Catch::EndsWith(" ok\n"));
  // the bouncing ball from its release: 3 s take in every bounce and the rest on the floor
  out = kt::run_cli("simulate derivations/impact/bouncing_ball.yaml --until 3", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("floor v_n -4.852216 -> 2.426108 m/s, impulse 1.4556648 N*s; energy lost 1.7658 J"));
  CHECK_THAT(out, Catch::Contains("contact 'floor' comes to rest"));
  // a given blow acts at the state the impact analysis starts from, not again after it
  out = kt::run_cli("simulate derivations/impact/rod_struck_by_blow.yaml --until 0.1", status);
  CHECK_THAT(out, Catch::Contains("the given impulse(s) act"));
  CHECK_THAT(out, Catch::Contains("work of given impulses: 34.66666667 J"));
  out = kt::run_cli("simulate derivations/impact/rod_struck_by_blow.yaml --until 0.1 --from after", status);
  CHECK_THAT(out, !Catch::Contains("the given impulse(s) act"));
  CHECK_THAT(out, Catch::Contains("theta_dot = 25 rad/s"));
}

TEST_CASE("kinergy simulate refuses what it cannot do, with the place and a fix", "[simulate][cli][errors]") {
  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"tests/data/simulate/penetrated.yaml --until 1",
       "penetrated.yaml:8:3: contact 'floor' is penetrated at the start (gap -0.1 m) \u2014 start with the parties apart or touching"},
      {"tests/data/simulate/no_rate.yaml --until 1", "no_rate.yaml:9:3: state '1' does not give y_dot as a number"},
      {"tests/data/simulate/unvalued.yaml --until 1", "unvalued.yaml:2:23: parameter 'k' has no value"},
      {"tests/data/simulate/damper_energy.yaml --until 1",
       "damper_energy.yaml:9:3: the work of the damper 'dash' depends on the speeds all along the motion"},
      {"tests/data/simulate/damper_momentum.yaml --until 1", "damper_momentum.yaml:8:3: the damper 'dash' pushes with a force that changes"},
      {"tests/data/simulate/damper_units.yaml --until 1", "damper_units.yaml:8:33: 'c' is in N/m (kg/s^2) but must be in kg/s"},
      {"tests/data/simulate/no_rate.yaml --check", "the scene has no analyses, so no closed form to check"},
      {"derivations/energy/flywheel_power.yaml --until 1",
       "flywheel_power.yaml:25:3: the acceleration is not a number at t = 0 s (power drive 'motor'"},
      {"derivations/energy/sliding_rod.yaml --until 1 --method foo", "no integration method 'foo' \u2014 choose dopri5, rkf78"},
      {"derivations/energy/sliding_rod.yaml", "simulate needs an end time \u2014 add --until T"},
      {"derivations/energy/sliding_rod.yaml --until 1 --from zz", "there is no state 'zz'"},
      {"derivations/energy/sliding_rod.yaml --until 1 --plot out.pdf", "the plot 'out.pdf' is neither .svg nor .png"},
      {"derivations/momentum/spinning_frame.yaml --until 1 --method symplectic",
       "spinning_frame.yaml: the symplectic method needs a conservative scene with separable energy, but its mass matrix depends on s"},
      {"derivations/energy/sliding_rod.yaml --until -1", "the run ends before it starts"},
      // a value beyond the range of doubles once reached the generated C++ as 'inf'
      {"tests/data/simulate/huge_mass.yaml --until 1",
       "huge_mass.yaml:12:3: parameter 'm' is 1e400 in SI units, beyond what a double holds (1e-307 to 1e308), and the "
       "simulation runs in doubles \u2014 give it a value within the range of doubles"},
      {"tests/data/simulate/huge_couple.yaml --until 0.1",
       "huge_couple.yaml: the acceleration is not a number at t = 0 s \u2014 check the parameters and the start state: an "
       "effect or a body's motion is undefined there"},
      {"tests/data/simulate/huge_couple.yaml --until 0.1 --no-native", "huge_couple.yaml: the acceleration is not a number at t = 0 s"},
      {"tests/data/simulate/tiny_pendulum.yaml --until 1",
       "tiny_pendulum.yaml:13:3: the equations of motion cannot be formed in doubles at t = 0 s: the mass matrix entry "
       "M[theta,theta] underflows to 0 \u2014 simulate the scene at a larger scale: its masses and lengths are too small for doubles"},
  };
  for (auto& c : cases) {
    INFO(c.args);
    int status = 0;
    std::string out = kt::run_cli("simulate " + c.args, status);
    CHECK(status == 1);
    CHECK_THAT(out, Catch::Contains(c.message));
    CHECK_THAT(out, !Catch::Contains("internal error"));
  }
}

TEST_CASE("kinergy simulate: options that are not a usable number or file are usage errors (exit 2)",
          "[simulate][cli][errors]") {
  struct Case {
    std::string args, message;
  };
  const std::string rod = "derivations/energy/sliding_rod.yaml ";
  const std::vector<Case> cases = {
      {"--until inf", "--until: 'inf' is not a number: give a finite end time in s\n"},
      {"--until nan", "--until: 'nan' is not a number: give a finite end time in s\n"},
      {"--until ''", "--until: '' is not a number: give a finite end time in s\n"},
      {"--until 1s", "--until: '1s' is not a number: give a finite end time in s\n"},
      {"--until 1 --tol nan", "--tol: 'nan' is not a number: give a tolerance from 1e-15 to 0.1\n"},
      {"--until 1 --tol 0", "--tol: 0 is out of range: give a tolerance from 1e-15 to 0.1\n"},
      {"--until 1 --method rk4 --step 0", "--step: 0 is out of range: give a positive step in s\n"},
      {"--until 1 --method rk4 --step -1e-3", "--step: -1e-3 is out of range: give a positive step in s\n"},
      // checked before the run, not after it
      {"--until 1 --csv /nonexistent-kinergy/x.csv",
       "--csv: the folder '/nonexistent-kinergy' does not exist: create it first, or write elsewhere\n"},
      {"--until 1 --plot /nonexistent-kinergy/x.svg",
       "--plot: the folder '/nonexistent-kinergy' does not exist: create it first, or write elsewhere\n"},
      {"--until 1 --csv /", "--csv: '/' is a folder: name a file\n"},
  };
  for (auto& c : cases) {
    INFO(c.args);
    int status = 0;
    std::string out = kt::run_cli("simulate " + rod + c.args, status);
    CHECK(status == 2);
    CHECK(out.rfind(c.message, 0) == 0);
    CHECK_THAT(out, !Catch::Contains("internal error"));
  }
}

TEST_CASE("kinergy simulate: a fixed step too small for the span is refused before the run", "[simulate][cli][errors]") {
  int status = 0;
  std::string out = kt::run_cli("simulate derivations/energy/sliding_rod.yaml --until 1e6 --method rk4 --step 1e-300", status);
  CHECK(status == 1);
  CHECK(out == "derivations/energy/sliding_rod.yaml: a fixed step of 1e-300 s would take 1e+306 steps to reach t = 1e+06 s, "
               "more than the 100000000 a run may take \u2014 give a larger --step (at least 0.01 s)\n");
}
