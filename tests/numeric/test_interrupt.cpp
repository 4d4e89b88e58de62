// Ctrl-C from Python (common/interrupt.hpp, issue 29): a hook that throws stops a long computation
// where it is — a solve that scans for a numeric root, a simulation — and GiNaC's working precision
// is what it was before (numeric/digits.hpp), so what runs next gives what it gave before. The
// hook is called at every poll here (interval 0) and throws at a chosen one: the same place
// every run, on any machine.
#include <catch2/catch.hpp>

#include <string>

#include "../support/helpers.hpp"
#include "kinergy/common/interrupt.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/print/plain.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace sim = kinergy::simulate;

namespace {
int g_polls = 0, g_throw_at = 0;
void counting_hook() {
  if (++g_polls == g_throw_at) throw kinergy::Interrupted{};
}
/// The counting hook for a scope: it throws at poll number `at` (never for 0).
struct Hook {
  explicit Hook(int at) {
    g_polls = 0;
    g_throw_at = at;
    kinergy::set_interrupt_hook(&counting_hook, std::chrono::milliseconds(0));
  }
  ~Hook() { kinergy::set_interrupt_hook(nullptr); }
  Hook(const Hook&) = delete;
  Hook& operator=(const Hook&) = delete;
};
const std::string kCam = std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/wheel_cam_couple_angle.yaml";
}  // namespace

TEST_CASE("an interrupt stops a solve where it is, and the working precision is restored", "[interrupt]") {
  const kinergy::Solution whole = kinergy::solve_file(kCam);
  const std::string value = kinergy::numerics::format(*whole.results[0].si, 15);
  int polls = 0;
  {
    Hook count(0);
    kinergy::solve_file(kCam);
    polls = g_polls;
  }
  INFO("polls in one solve: " << polls);
  REQUIRE(polls >= 3);  // the search for the numeric root polls as it goes
  const long digits = GiNaC::Digits;
  for (int at : {1, polls / 2, polls}) {
    INFO("thrown at poll " << at);
    {
      Hook h(at);
      CHECK_THROWS_AS(kinergy::solve_file(kCam), kinergy::Interrupted);
    }
    CHECK(static_cast<long>(GiNaC::Digits) == digits);
    // and the same solve, after it, gives the same value
    CHECK(kinergy::numerics::format(*kinergy::solve_file(kCam).results[0].si, 15) == value);
  }
}

TEST_CASE("an interrupt stops a simulation where it is", "[interrupt][simulate]") {
  auto s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/compound_pendulum.yaml");
  sim::Options o;
  o.native = false;
  sim::Simulator run(s.model, sim::simulation_values(s), o);
  sim::Stop stop;
  stop.until = 1e9;  // some 10^9 steps: it ends only by the interrupt (or the step limit)
  Hook h(1000);
  CHECK_THROWS_AS(run.run(sim::state_values(s, 0), stop), kinergy::Interrupted);
  CHECK(g_polls == 1000);
}
