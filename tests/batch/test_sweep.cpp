// kinergy sweep (issue 16, part 3): a scene solved over a grid. Expected values by hand: the sliding
// rod's omega2 = sqrt(3 g sin(theta2) / l) (its description), g = 9.81 m/s^2.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "../support/helpers.hpp"
#include "kinergy/batch/sweep.hpp"
#include "kinergy/common/error.hpp"

namespace {

const std::string kRod = std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/sliding_rod.yaml";

double omega(double l, double deg) { return std::sqrt(3 * 9.81 * std::sin(deg * 3.14159265358979323846 / 180) / l); }

}  // namespace

TEST_CASE("sweep: every point of the grid solved, the last range fastest, a point without solution says why", "[batch][sweep]") {
  const auto def = kinergy::scene::load_file(kRod);
  std::vector<kinergy::batch::Range> ranges{kinergy::batch::parse_range("l=0.5..2:4", def), kinergy::batch::parse_range("theta2=0..90:3", def)};
  CHECK(ranges[0].unit == "m");
  CHECK(ranges[1].unit == "deg");
  const auto s = kinergy::batch::sweep(def, ranges);
  REQUIRE(s.rows.size() == 12);
  CHECK(s.parameters == std::vector<std::string>{"l (m)", "theta2 (deg)"});
  CHECK(s.results == std::vector<std::string>{"omega2 (rad/s)"});
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    const double l = 0.5 + 0.5 * static_cast<double>(k / 3), deg = 45.0 * static_cast<double>(k % 3);
    INFO(k);
    CHECK(s.rows[k].at == std::vector<double>{l, deg});
    if (deg == 0) {
      // at rest at 0°: no positive omega2, as the scene asks
      CHECK(std::isnan(s.rows[k].values[0]));
      CHECK(s.rows[k].error == "no solution has 'omega2' with the root asked for");
    } else {
      CHECK(std::fabs(s.rows[k].values[0] - omega(l, deg)) < 1e-12 * omega(l, deg));
      CHECK(s.rows[k].error.empty());
    }
  }
  const std::string table = kinergy::batch::csv(s);
  CHECK(table.rfind("\"l (m)\",\"theta2 (deg)\",\"omega2 (rad/s)\",\"error\"\n0.5,0,,\"no solution has 'omega2' with the root asked for\"\n0.5,45,", 0) == 0);
  const std::string j = kinergy::batch::json(s);
  CHECK(j.find("{\"at\": [0.5, 0], \"values\": [null], \"error\": \"no solution has 'omega2' with the root asked for\"}") != std::string::npos);
}

TEST_CASE("sweep: a range is refused with what is wrong", "[batch][sweep][errors]") {
  const auto def = kinergy::scene::load_file(kRod);
  const std::string form = "write NAME=LO..HI:COUNT, e.g. --set l=0.5..2:16 (in the unit the scene writes the parameter in)";
  struct Case {
    std::string text, message, fix;
  };
  const std::vector<Case> cases = {
      {"l", "'l' is not a range of a parameter", form},
      {"l=0.5:3", "'l=0.5:3' is not a range of a parameter", form},
      {"l=a..2:3", "the start of 'l=a..2:3' is not a number", form},
      {"l=1..2x:3", "the end of 'l=1..2x:3' is not a number", form},
      {"l=1..2:1", "the count of 'l=1..2:1' is not a whole number from 2 to 100000", form},
      {"l=1..2:2.5", "the count of 'l=1..2:2.5' is not a whole number from 2 to 100000", form},
      {"l=1..inf:3", "the end of 'l=1..inf:3' is not a number", form},
      {"q=1..2:3", "the scene has no parameter 'q'", "sweep one of its parameters: m, l, g, theta2"},
  };
  for (auto& c : cases) {
    INFO(c.text);
    try {
      kinergy::batch::parse_range(c.text, def);
      FAIL("accepted");
    } catch (const kinergy::InputError& e) {
      CHECK(std::string(e.what()) == c.message);
      CHECK(e.fix() == c.fix);
    }
  }
}

TEST_CASE("kinergy sweep: CSV on standard output, JSON and a plot to files", "[batch][sweep][cli]") {
  const auto dir = std::filesystem::temp_directory_path() / "kinergy-sweep-test";
  std::filesystem::create_directories(dir);
  int st = 0;
  std::string out = kt::run_cli("sweep derivations/energy/sliding_rod.yaml --set l=1..2:3", st);
  CHECK(st == 0);
  CHECK(out.find("\"l (m)\",\"omega2 (rad/s)\",\"error\"\n1,") != std::string::npos);
  CHECK(out.find("kinergy sweep: 3 points, 0 without a solution") != std::string::npos);
  out = kt::run_cli("sweep derivations/energy/sliding_rod.yaml --set l=1..2:3 --json " + (dir / "s.json").string() + " --plot " +
                        (dir / "s.svg").string(),
                    st);
  INFO(out);
  CHECK(st == 0);
  CHECK(kt::read_file(dir / "s.json").rfind("{\"parameters\": [\"l (m)\"]", 0) == 0);
  CHECK(kt::read_file(dir / "s.svg").find("<svg") != std::string::npos);
  out = kt::run_cli("sweep derivations/energy/sliding_rod.yaml --set l=1..2:3 --plot " + (dir / "s.gif").string(), st);
  CHECK(st != 0);
  CHECK(out.find("the plot '" + (dir / "s.gif").string() + "' is neither .svg nor .png") != std::string::npos);
  out = kt::run_cli("sweep derivations/energy/sliding_rod.yaml --set zz=1..2:3", st);
  CHECK(st != 0);
  CHECK(out.find("the scene has no parameter 'zz'") != std::string::npos);
}
