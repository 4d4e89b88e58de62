// Output independent of the address space (issue 11). GiNaC orders the terms of sums and
// products by hashes that mix in type-information addresses, and gives a sum inside a product
// the sign its first term (in that order) asks for; under address randomisation both change
// from run to run. kinergy's printers and its choices of form must not follow them: every
// derivation prints the same bytes in every run, with randomisation on and without any trick
// on the process (no re-execution, no personality flag).
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

/// Where a shared library is mapped in a new process (the line of /proc/self/maps naming libc).
std::string libc_mapping() {
  FILE* p = popen("grep -m1 libc /proc/self/maps", "r");
  if (!p) return "";
  char buf[512];
  std::string out;
  while (fgets(buf, sizeof buf, p)) out += buf;
  pclose(p);
  return out;
}

}  // namespace

TEST_CASE("address randomisation is on for the processes the tests start", "[reproducible]") {
  // otherwise the test below proves nothing: each new process must map its libraries elsewhere
  std::string a = libc_mapping(), b = libc_mapping(), c = libc_mapping();
  INFO("libc mapped at:\n" << a << b << c);
  REQUIRE(!a.empty());
  CHECK((a != b || b != c));
}

TEST_CASE("solve --json, derive, derive --latex and simulate --equations of every derivation: the same bytes over 5 runs",
          "[reproducible][approval][slow]") {
  auto files = kt::relative_scene_files("derivations");
  REQUIRE(files.size() >= 12);
  for (auto& f : files) {
    // (derive leaves its confirmation out of the derivation: the confirmation's bytes are tested
    // with solve --json, and derive is run without it here, which halves this test's time)
    for (std::string cmd : {"solve --json", "derive --no-confirm", "derive --latex -", "simulate --equations"}) {
      std::string args = cmd == "derive --latex -" ? "derive --no-confirm " + kt::shell_quoted(f) + " --latex -" : cmd + " " + kt::shell_quoted(f);
      INFO("kinergy " << args);
      int status = 0;
      std::string first = kt::run_cli(args, status);
      if (cmd != "simulate --equations") REQUIRE(status == 0);  // a scene may hold what the simulator refuses
      for (int run = 2; run <= 5; ++run) {
        int st = 0;
        std::string again = kt::run_cli(args, st);
        INFO("run " << run);
        CHECK(st == status);
        CHECK(again == first);
      }
    }
  }
}

TEST_CASE("the sources hold no re-execution and no personality flag", "[reproducible]") {
  // reproducible output comes from the code, not from switching randomisation off
  for (const char* dir : {"src", "include"})
    for (auto& e : fs::recursive_directory_iterator(fs::path(KINERGY_SOURCE_DIR) / dir)) {
      if (!e.is_regular_file()) continue;
      std::string text = kt::read_file(e.path());
      INFO(e.path().string());
      CHECK(text.find("personality") == std::string::npos);
      CHECK(text.find("/proc/self/exe") == std::string::npos);
    }
}
