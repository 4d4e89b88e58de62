// Every worked problem in derivations/ solves, and every claim in its `expect` holds.
#include <catch2/catch.hpp>

#include <filesystem>

#include "kinergy/problem.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/verify/verify.hpp"

namespace fs = std::filesystem;

static std::vector<std::string> scenes() {
  std::vector<std::string> out;
  for (auto& e : fs::recursive_directory_iterator(fs::path(KINERGY_SOURCE_DIR) / "derivations"))
    if (e.path().extension() == ".yaml") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST_CASE("every derivation solves and meets its expect", "[derivations]") {
  auto files = scenes();
  REQUIRE(files.size() >= 12);
  for (auto& f : files) {
    DYNAMIC_SECTION(fs::path(f).filename().string()) {
      kinergy::Solution s = kinergy::solve_file(f);
      auto checks = kinergy::verify::verify(s);
      REQUIRE(!checks.empty());  // a derivation without a claim proves nothing
      for (auto& c : checks) {
        INFO(c.name << " (" << c.what << "): " << c.detail);
        CHECK(c.ok());
      }
      for (auto& r : s.results) {
        INFO(r.name);
        CHECK(r.si.has_value());
      }
    }
  }
}

TEST_CASE("sliding rod: omega2 to 15 and 50 digits", "[derivations]") {
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/sliding_rod.yaml");
  REQUIRE(s.results.size() == 1);
  auto env = s.model.numeric_environment();
  auto v15 = s.results[0].value(env, 15);
  REQUIRE(v15);
  CHECK(kinergy::numerics::format(*v15, 15) == "3.50178525897863");
  auto v50 = s.results[0].value(env, 50);
  REQUIRE(v50);
  CHECK(kinergy::numerics::format(*v50, 50) == "3.5017852589786256052372546604589676703245542931001");
}
