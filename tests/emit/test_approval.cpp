// Approval of the derivations: `kinergy derive` on every scene of derivations/ must print
// exactly the approved text and LaTeX kept beside it,
//   derivations/<dir>/<name>.approved.txt   (kinergy derive SCENE)
//   derivations/<dir>/<name>.approved.tex   (kinergy derive SCENE --latex -)
// Any difference fails until the approved file is updated on purpose:
//   KINERGY_APPROVE=1 ctest --test-dir build -R approval
// rewrites the files that differ (then review them with git diff before committing).
// The command line runs from the source directory with the scene's relative path, so the
// files do not depend on where the tree is. The output does not depend on addresses either
// (tests/emit/test_reproducible.cpp runs every derivation five times with randomisation on).
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

/// Where two texts first differ: line number and both lines.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream x(a), y(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    bool ga = static_cast<bool>(std::getline(x, la)), gb = static_cast<bool>(std::getline(y, lb));
    if (!ga && !gb) return "they differ only in line endings";
    if (!ga || !gb || la != lb)
      return "line " + std::to_string(line) + ":\n  approved: " + (ga ? la : "(end of file)") +
             "\n  now:      " + (gb ? lb : "(end of output)");
  }
}

bool approving() {
  const char* a = std::getenv("KINERGY_APPROVE");
  return a && std::string(a) == "1";
}

void compare(const std::string& scene, const std::string& args, const std::string& ext) {
  int status = 0;
  std::string now = kt::run_cli(args, status);
  INFO("kinergy " << args);
  REQUIRE(status == 0);
  fs::path approved = fs::path(KINERGY_SOURCE_DIR) / fs::path(scene).replace_extension(ext);
  bool exists = fs::exists(approved);
  std::string before = exists ? kt::read_file(approved) : "";
  if (exists && before == now) return;
  if (approving()) {
    std::ofstream(approved, std::ios::binary) << now;
    WARN((exists ? "updated " : "wrote ") << approved.string());
    return;
  }
  INFO((exists ? first_difference(before, now) : "no approved file " + approved.string()));
  INFO("if the new output is right: KINERGY_APPROVE=1 ctest --test-dir <build> -R approval, then review git diff");
  FAIL("the derivation differs from its approved " << ext << " file");
}

}  // namespace

TEST_CASE("approval: every derivation prints its approved text and LaTeX", "[approval]") {
  auto files = kt::relative_scene_files("derivations");
  REQUIRE(files.size() >= 12);
  for (auto& f : files) {
    DYNAMIC_SECTION(f) {
      compare(f, "derive " + kt::shell_quoted(f), ".approved.txt");
      compare(f, "derive " + kt::shell_quoted(f) + " --latex -", ".approved.tex");
    }
  }
}
