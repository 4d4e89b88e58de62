// kinergy sweep (issue 16, part 3): a scene solved over a grid. Expected values by hand: the sliding
// rod's omega2 = sqrt(3 g sin(theta2) / l) (its description), g = 9.81 m/s^2.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "../support/helpers.hpp"
#include "kinergy/batch/sweep.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/units/units.hpp"

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
  CHECK(table.rfind("\"l (m)\",\"theta2 (deg)\",\"omega2 (rad/s)\",\"how\",\"error\"\n0.5,0,,\"solved\",\"no solution has 'omega2' with the root asked for\"\n0.5,45,", 0) == 0);
  const std::string j = kinergy::batch::json(s);
  CHECK(j.find("{\"at\": [0.5, 0], \"values\": [null], \"how\": \"solved\", \"error\": \"no solution has 'omega2' with the root asked for\"}") != std::string::npos);
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
  // a parameter the scene gives a range: a sweep that leaves it is refused (inside it, taken)
  {
    auto ranged = def;
    for (auto& p : ranged.parameters)
      if (p.name == "theta2") p.in = std::make_pair(kinergy::scene::Text{"10 deg", {}}, kinergy::scene::Text{"80 deg", {}});
    CHECK_NOTHROW(kinergy::batch::parse_range("theta2=10..80:8", ranged));
    try {
      kinergy::batch::parse_range("theta2=5..60:8", ranged);
      FAIL("accepted");
    } catch (const kinergy::InputError& e) {
      CHECK(std::string(e.what()) == "'theta2=5..60:8' leaves the range the scene gives 'theta2', in: [10 deg, 80 deg]");
      CHECK(e.fix() == "sweep 'theta2' inside that range, or widen it in the scene");
    }
  }
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
  CHECK(out.find("\"l (m)\",\"omega2 (rad/s)\",\"how\",\"error\"\n1,") != std::string::npos);
  CHECK(out.find("kinergy sweep: 3 points, 0 without a solution") != std::string::npos);
  out = kt::run_cli("sweep derivations/energy/sliding_rod.yaml --set l=1..2:3 --json " + (dir / "s.json").string() + " --plot " +
                        (dir / "s.svg").string(),
                    st);
  INFO(out);
  CHECK(st == 0);
  CHECK(kt::read_file(dir / "s.json").rfind("{\"parameters\": [\"l (m)\"]", 0) == 0);
  CHECK(kt::read_file(dir / "s.svg").find("<svg") != std::string::npos);
  // over 12 values of the second parameter: a map with contours, not 20 curves
  out = kt::run_cli("sweep derivations/energy/sliding_rod.yaml --set l=1..2:30 --set theta2=30..270:20 --csv " + (dir / "m.csv").string() +
                        " --plot " + (dir / "m.svg").string(),
                    st);
  INFO(out);
  CHECK(st == 0);
  CHECK(out.find("kinergy sweep: 600 points, ") != std::string::npos);
  const std::string map = kt::read_file(dir / "m.svg");
  CHECK(map.find("<svg") != std::string::npos);
  CHECK(map.find("omega2 (rad/s) (blank: no solution)") != std::string::npos);
  CHECK(map.find("theta2 (deg) = ") == std::string::npos);
  out = kt::run_cli("sweep derivations/energy/sliding_rod.yaml --set l=1..2:3 --plot " + (dir / "s.gif").string(), st);
  CHECK(st != 0);
  CHECK(out.find("the plot '" + (dir / "s.gif").string() + "' is neither .svg nor .png") != std::string::npos);
  out = kt::run_cli("sweep derivations/energy/sliding_rod.yaml --set zz=1..2:3", st);
  CHECK(st != 0);
  CHECK(out.find("the scene has no parameter 'zz'") != std::string::npos);
}

namespace {

/// The same sweep solved at every point: the rows a carried closed form must equal.
void same_rows(const kinergy::batch::Sweep& fast, const kinergy::batch::Sweep& slow) {
  REQUIRE(fast.rows.size() == slow.rows.size());
  for (std::size_t k = 0; k < fast.rows.size(); ++k) {
    const auto &a = fast.rows[k], &b = slow.rows[k];
    INFO("row " << k << ": " << a.how << " / " << a.error << " | " << b.error);
    REQUIRE(a.at == b.at);
    CHECK(a.error.empty() == b.error.empty());
    for (std::size_t r = 0; r < a.values.size(); ++r) {
      CHECK(std::isnan(a.values[r]) == std::isnan(b.values[r]));
      if (!std::isnan(b.values[r])) CHECK(std::fabs(a.values[r] - b.values[r]) <= 1e-12 * std::fabs(b.values[r]));
    }
  }
}

}  // namespace

TEST_CASE("sweep: the closed form carried wherever every choice falls the same way, and past where the motion reaches, why",
          "[batch][sweep]") {
  const auto def = kinergy::scene::load_file(kRod);
  // theta2 past 180°: sin θ2 < 0, the rod cannot get there from rest (ω² < 0)
  const std::vector<kinergy::batch::Range> ranges{kinergy::batch::parse_range("l=0.5..2:25", def),
                                                  kinergy::batch::parse_range("theta2=30..270:25", def)};
  const auto fast = kinergy::batch::sweep(def, ranges);
  kinergy::batch::SweepOptions each;
  each.per_point = true;
  const auto slow = kinergy::batch::sweep(def, ranges, each);
  same_rows(fast, slow);
  std::size_t closed = 0, past = 0;
  for (const auto& row : fast.rows) {
    const double l = row.at[0], deg = row.at[1];
    INFO(l << " m, " << deg << " deg: " << row.error);
    closed += row.how == "closed form" ? 1 : 0;
    if (deg < 180) {
      // by hand: ω2 = √(3 g sin θ2 / l)
      CHECK(row.error.empty());
      CHECK(std::fabs(row.values[0] - omega(l, deg)) <= 1e-12 * omega(l, deg));
    } else if (deg == 180) {
      // at rest there (ω2 = 0): no positive ω2, each such point solved (a choice reads a zero)
      CHECK(row.error == "no solution has 'omega2' with the root asked for");
      CHECK(row.how == "solved");
    } else {
      ++past;
      CHECK(std::isnan(row.values[0]));
      CHECK(row.error.find("no real solution for theta_dot@2") != std::string::npos);
      if (row.how != "solved") CHECK(row.error.rfind("as solved at l = ", 0) == 0);
    }
  }
  CHECK(past == 25 * 9);
  // every row below 180° is carried; past it, the first is solved and its failure carried on
  CHECK(closed == 25 * 15);
  CHECK(fast.summary.solved == 25 + 1);
  CHECK(fast.summary.confirmed == 8);
  CHECK(fast.summary.difference <= 1e-12);
  CHECK(fast.summary.note.empty());
  CHECK(slow.summary.solved == slow.rows.size());
}

TEST_CASE("sweep: every derivation over a grid of two of its parameters, the closed forms carried equal solves at each point",
          "[batch][sweep][slow]") {
  std::size_t rows = 0, closed = 0, scenes = 0;
  for (const auto& path : kt::scene_files("derivations")) {
    const auto def = kinergy::scene::load_file(path);
    std::vector<kinergy::batch::Range> ranges;
    for (const auto& p : def.parameters) {
      if (ranges.size() == 2) break;
      kinergy::units::Quantity q;
      try {
        q = kinergy::units::parse_quantity(p.value.s);
      } catch (const kinergy::InputError&) {
        continue;
      }
      if (!q.has_number || q.number.is_zero()) continue;
      const double v = q.number.to_double(), a = 0.8 * v, b = 1.2 * v;
      std::ostringstream text;
      text << std::setprecision(17) << p.name << "=" << std::min(a, b) << ".." << std::max(a, b) << ":" << (ranges.empty() ? 3 : 2);
      ranges.push_back(kinergy::batch::parse_range(text.str(), def));
    }
    if (ranges.empty()) continue;
    INFO(path);
    kinergy::batch::SweepOptions quick, each;
    quick.samples = 2;
    each.per_point = true;
    const auto fast = kinergy::batch::sweep(def, ranges, quick);
    same_rows(fast, kinergy::batch::sweep(def, ranges, each));
    ++scenes;
    rows += fast.rows.size();
    for (const auto& row : fast.rows) closed += row.how == "closed form" ? 1 : 0;
  }
  CHECK(scenes >= 70);
  // (so that the test cannot pass with nothing carried: most scenes' closed forms hold around their values)
  CHECK(closed * 2 >= rows);
}

TEST_CASE("sweep: through zero, a solution found at a positive value is not carried to negative ones", "[batch][sweep]") {
  // theta2 is a positive symbol where the scene gives 30°: its simplifications hold for θ2 > 0
  // only, so the sign of θ2 is one of the choices; below 0 the rod does not get there from rest
  const auto def = kinergy::scene::load_file(kRod);
  const std::vector<kinergy::batch::Range> ranges{kinergy::batch::parse_range("theta2=-60..60:13", def)};
  const auto fast = kinergy::batch::sweep(def, ranges);
  kinergy::batch::SweepOptions each;
  each.per_point = true;
  same_rows(fast, kinergy::batch::sweep(def, ranges, each));
  for (const auto& row : fast.rows) {
    INFO(row.at[0] << " deg: " << row.how << " " << row.error);
    if (row.at[0] > 0) CHECK(row.how == "closed form");
    else CHECK(row.how != "closed form");
  }
}

TEST_CASE("sweep: points without a closed form solved in worker processes, the rows those of one process", "[batch][sweep]") {
  // the wheel's angle is a numeric root (a work integral): every point is solved, here in two
  // processes, and the CSV is the same bytes as solved in one
  const auto wheel = kinergy::scene::load_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/wheel_cam_couple_angle.yaml");
  const std::vector<kinergy::batch::Range> ranges{kinergy::batch::parse_range("m=15..25:3", wheel),
                                                  kinergy::batch::parse_range("w2=5..6:2", wheel)};
  kinergy::batch::SweepOptions one, two;
  two.jobs = 2;
  const auto a = kinergy::batch::sweep(wheel, ranges, one), b = kinergy::batch::sweep(wheel, ranges, two);
  CHECK(kinergy::batch::csv(a) == kinergy::batch::csv(b));
  CHECK(a.summary.solved == 6);
  CHECK(b.summary.solved == 6);
  CHECK(b.summary.note.find("every point solved: a choice depends on a numeric root") == 0);
  // --per-point in two processes: the rod's hand values, and the rows of one process
  const auto rod = kinergy::scene::load_file(kRod);
  const std::vector<kinergy::batch::Range> grid{kinergy::batch::parse_range("l=0.5..2:4", rod), kinergy::batch::parse_range("theta2=30..90:5", rod)};
  kinergy::batch::SweepOptions each;
  each.per_point = true;
  each.jobs = 2;
  const auto p = kinergy::batch::sweep(rod, grid, each);
  REQUIRE(p.rows.size() == 20);
  for (const auto& row : p.rows) {
    INFO(row.at[0] << " m, " << row.at[1] << " deg");
    CHECK(row.how == "solved");
    CHECK(std::fabs(row.values[0] - omega(row.at[0], row.at[1])) < 1e-12 * omega(row.at[0], row.at[1]));
  }
  each.jobs = 1;
  CHECK(kinergy::batch::csv(kinergy::batch::sweep(rod, grid, each)) == kinergy::batch::csv(p));
}
