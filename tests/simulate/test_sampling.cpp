// Samples at regular times from the integrator's steps (issue 14, item 4): a bouncing ball's
// flights are parabolas between the impacts, and each impact is sampled before and after.
// Expected values by hand: from rest at y0 = h + r = 1.23 m, y(t) = y0 - g t^2/2 until the
// ball's bottom meets the floor (y = r) at t1 = sqrt(2 h/g); it leaves with e sqrt(2 g h) and
// flies the parabola y = r + e v1 (t - t1) - g (t - t1)^2/2 until t2 = t1 + 2 e v1/g.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "../support/helpers.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace sim = kinergy::simulate;

TEST_CASE("regular samples: the bouncing ball's flights are parabolas, the impacts sampled exactly", "[simulate][sampling]") {
  auto s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/impact/bouncing_ball.yaml");
  sim::Options o;
  o.native = false;
  o.tol = 1e-12;
  o.sample_dt = 0.002;
  sim::Simulator run(s.model, sim::simulation_values(s), o);
  sim::Stop stop;
  stop.until = 1.0;
  auto r = run.run(sim::state_values(s, 0), stop);
  const double g = 9.81, h = 1.2, rr = 0.03, e = 0.5, v1 = std::sqrt(2 * g * h), t1 = std::sqrt(2 * h / g), t2 = t1 + 2 * e * v1 / g;
  REQUIRE(r.impacts.size() >= 2);
  CHECK(std::fabs(r.impacts[0].t - t1) < 1e-9);
  std::size_t regular = 0, at_impact = 0;
  double worst = 0;
  for (auto& x : r.samples) {
    const double k = x.t / o.sample_dt;
    if (std::fabs(k - std::round(k)) < 1e-9) ++regular;
    if (std::fabs(x.t - t1) < 1e-12) ++at_impact;
    // the flight's parabola (the cubic interpolant of a parabola is the parabola)
    double want = x.t <= t1 ? h + rr - g * x.t * x.t / 2 : x.t <= t2 ? rr + e * v1 * (x.t - t1) - g * (x.t - t1) * (x.t - t1) / 2 : NAN;
    if (!std::isnan(want)) worst = std::max(worst, std::fabs(x.q[0] - want));
  }
  INFO("largest difference from the parabolas: " << worst);
  CHECK(worst < 1e-8);
  // every regular time up to the end (500 intervals; the start too), and the first impact twice:
  // just before (falling) and just after (rising), at the same time
  CHECK(regular >= 500);
  REQUIRE(at_impact == 2);
  double before = 0, after = 0;
  for (auto& x : r.samples)
    if (std::fabs(x.t - t1) < 1e-12) (before == 0 ? before : after) = x.qd[0];
  CHECK(std::fabs(before + v1) < 1e-8);
  CHECK(std::fabs(after - e * v1) < 1e-8);
  // without sampling: the accepted steps only (a few dozen), as before
  o.sample_dt = 0;
  sim::Simulator steps(s.model, sim::simulation_values(s), o);
  auto r0 = steps.run(sim::state_values(s, 0), stop);
  CHECK(r0.samples.size() < 100);
}

TEST_CASE("simulate --samples and --dt: the CSV has the regular times", "[simulate][sampling][cli]") {
  int st = 0;
  std::filesystem::create_directories(std::filesystem::temp_directory_path() / "kinergy-sampling");
  const std::string csv = (std::filesystem::temp_directory_path() / "kinergy-sampling" / "ball.csv").string();
  kt::run_cli("simulate derivations/impact/bouncing_ball.yaml --until 1 --no-native --csv " + csv + " --samples 100", st);
  REQUIRE(st == 0);
  std::string text = kt::read_file(csv);
  // a header, 101 regular rows (t = 0, 0.01, …, 1) and the impacts' two rows each (the first at
  // t1 = 0.4946 s, the second at t2 = 0.9892 s)
  std::size_t rows = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) - 1;
  CHECK(rows >= 101 + 4);
  CHECK(text.find("\n0.01,") != std::string::npos);
  CHECK(text.find("\n0.5,") != std::string::npos);
  kt::run_cli("simulate derivations/impact/bouncing_ball.yaml --until 1 --no-native --csv " + csv + " --dt -1", st);
  CHECK(st != 0);
}
