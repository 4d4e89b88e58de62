// Closed form against simulation: every analysis of every derivation run as a simulation from
// its first state until its second is reached, the simulated positions and rates compared with
// the solved ones; conservative legs keep |ΔE/E₀| ≤ 1e-9 at tol 1e-12.
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/confirm/check.hpp"

namespace fs = std::filesystem;
namespace sim = kinergy::simulate;

TEST_CASE("every derivation's analyses, simulated at tol 1e-12, agree with the closed forms",
          "[simulate][derivations]") {
  sim::Options o;
  o.tol = 1e-12;
  o.native = false;  // the tape: the same doubles as the compiled code (tested below), no compiler runs
  int legs = 0, skipped = 0;
  for (const auto& f : kt::scene_files("derivations")) {
    kinergy::Solution s = kinergy::solve_file(f);
    for (auto& leg : sim::legs(s)) {
      INFO(fs::path(f).filename().string() << ": " << s.model.analyses[static_cast<std::size_t>(leg.analysis)].kind << " "
                                           << s.model.states[leg.from].name << " -> " << s.model.states[leg.to].name);
      if (s.model.analyses[static_cast<std::size_t>(leg.analysis)].type->at_state()) continue;  // kinetics at one state: no run
      if (!leg.why_not.empty()) {
        // the motion the equations cannot start (a power drive from rest: P/ω), and an analysis
        // with an effect switched inside it (the analyses on either side of the switch are run)
        INFO(leg.why_not);
        CHECK_THAT(leg.why_not, Catch::Contains("power drive") || Catch::Contains("is switched inside it") ||
                                    Catch::Contains("which has no value"));
        ++skipped;
        continue;
      }
      auto c = sim::check_leg(s, leg, o, 1e-10);
      INFO(c.worst_what << " (" << c.worst << ")");
      CHECK(c.ok);
      // the integration's own energy balance, conservative or not
      CHECK(std::fabs(c.run.drift) <= 1e-9);
      ++legs;
    }
  }
  CHECK(legs >= 55);
  // flywheel_power (a power drive from rest), flywheel_motor_then_coast 1 -> 3, rod_gravity_power_max
  // (its state 2 is placed by the extreme's variable), collar_spring_least_speed and
  // rod_full_revolution_least_speed (the speed at 1 is the parameter whose least value is asked)
  CHECK(skipped <= 5);
}

TEST_CASE("a leg ends where its state is defined: a turning point by its rate, a place by its position",
          "[simulate][derivations]") {
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/block_incline_friction.yaml");
  auto L = sim::legs(s);
  REQUIRE(L.size() == 2);
  CHECK(L[0].target == "x_dot reaches 0");  // state 2: {x_dot: 0}, the block's highest point
  CHECK(L[1].target.rfind("x reaches 0", 0) == 0);
  // state 2's distance is the closed form compared; the rate that ends the leg is not
  CHECK(std::isnan(L[0].expect.qd[0]));
  CHECK(!std::isnan(L[0].expect.q[0]));
}
