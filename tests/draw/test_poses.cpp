// No impossible poses (issue 47): no two bodies in one place at any state of any derivation, and
// a scene that puts them there is refused by derive and warned of by draw.
#include <catch2/catch.hpp>
#include <regex>

#include "kinergy/draw/figure.hpp"
#include "kinergy/model/poses.hpp"
#include "../support/helpers.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/confirm/check.hpp"

TEST_CASE("no two bodies overlap at any state of any derivation", "[draw][poses]") {
  int states = 0;
  std::vector<std::string> faults;
  for (const auto& file : kt::scene_files("derivations")) {
    const kinergy::Solution s = kinergy::solve_file(file);
    const auto values = kinergy::draw::with_samples(s.model, kinergy::simulate::simulation_values(s), nullptr);
    for (std::size_t st = 0; st < s.model.states.size(); ++st) {
      kinergy::draw::At at;
      try {
        at = kinergy::draw::state_values(s.model, s.branch.sol, values, static_cast<int>(st));
      } catch (const kinergy::SceneError&) {
        continue;  // (a state that does not fix a coordinate)
      }
      ++states;
      for (auto& f : kinergy::model::overlapping(s.model, [&](const GiNaC::ex& e) { return at(e); })) faults.push_back(file + " state " + s.model.states[st].name + ": " + f);
    }
  }
  INFO(states << " states");
  for (auto& f : faults) UNSCOPED_INFO(f);
  CHECK(faults.empty());
  CHECK(states >= 150);
}

TEST_CASE("two disks on axles closer than their radii: refused by solve at the state's line, drawn by draw with a warning", "[draw][poses][cli]") {
  // centres d = 0.2 m apart, radii r = 0.3 m: each reaches 2r − d = 0.4 m into the other (a
  // 32-gon's 0.398 m)
  const std::string file = std::string(KINERGY_SOURCE_DIR) + "/tests/data/bad/disks_in_one_place.yaml";
  try {
    (void)kinergy::solve_file(file);
    FAIL("solved a scene whose disks are in one place");
  } catch (const kinergy::SceneError& e) {
    const std::string what = e.what();
    CHECK(what.find("disks_in_one_place.yaml:26:3") != std::string::npos);  // (state 1's line)
    CHECK(what.find("diskA and diskB overlap by 0.398 m") != std::string::npos);
    CHECK(what.find("positions that keep them apart") != std::string::npos);
  }
  int status = -1;
  const std::string out = kt::run_cli("draw tests/data/bad/disks_in_one_place.yaml", status);
  CHECK(status == 0);
  CHECK(out.find("<svg") != std::string::npos);
  CHECK(out.find("warning: not solved, so drawn as the scene gives it") != std::string::npos);
  CHECK(out.find("diskA and diskB overlap by 0.398 m") != std::string::npos);
  // the same disks 0.7 m apart are no fault
  const std::string apart = kt::read_file(file);
  const std::string moved = std::regex_replace(apart, std::regex("d: 0.2 m"), "d: 0.7 m");
  CHECK(moved != apart);
  CHECK_NOTHROW(kinergy::solve_scene(kinergy::scene::load_string(moved, "apart.yaml")));
}
