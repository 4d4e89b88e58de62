// One kind, one place: effect kinds, analysis kinds and inertia shapes live in their tables
// (src/effects/registry.cpp, src/analyses/registry.cpp, src/model/inertia.cpp); nothing else in
// src/ compares a kind's name, the scene loader accepts exactly the kinds of the table, and each is
// documented in docs/scene-format.md.
#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>
#include <sstream>

#include "../support/helpers.hpp"
#include "kinergy/model/analysis.hpp"
#include "kinergy/model/effect.hpp"
#include "kinergy/model/inertia.hpp"
#include "kinergy/scene/scene.hpp"

namespace fs = std::filesystem;

TEST_CASE("no code in src/ compares a kind's name", "[kinds]") {
  // `kind == "…"`, `kind != "…"` (and the same of any `.kind` or `k` that holds a kind's name)
  const std::regex compare(R"((\bkind|\.kind)\s*[!=]=\s*")");
  std::vector<std::string> found;
  for (auto& e : fs::recursive_directory_iterator(fs::path(KINERGY_SOURCE_DIR) / "src")) {
    if (!e.is_regular_file()) continue;
    std::istringstream in(kt::read_file(e.path()));
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      if (std::regex_search(line, compare))
        found.push_back(fs::relative(e.path(), KINERGY_SOURCE_DIR).string() + ":" + std::to_string(n) + ": " + line);
  }
  for (auto& f : found) INFO(f);
  CHECK(found.empty());
}

TEST_CASE("the scene loader takes the effect kinds from the table", "[kinds]") {
  std::vector<std::string> table;
  for (auto& k : kinergy::model::effect_kinds()) table.push_back(k.name);
  CHECK(kinergy::scene::effect_kinds() == table);
  std::vector<std::pair<std::string, int>> shapes;
  for (auto& s : kinergy::model::inertia_shapes()) shapes.push_back({s.name, s.sizes});
  CHECK(kinergy::scene::inertia_shapes() == shapes);
}

TEST_CASE("every kind of the tables is documented in docs/scene-format.md", "[kinds]") {
  const std::string doc = kt::read_file(fs::path(KINERGY_SOURCE_DIR) / "docs" / "scene-format.md");
  for (auto& k : kinergy::model::effect_kinds()) {
    INFO("effect kind " << k.name);
    CHECK(doc.find("| " + k.name + " | `{") != std::string::npos);
  }
  for (auto* k : kinergy::model::analysis_kinds()) {
    INFO("analysis kind " << k->name);
    CHECK(doc.find("- `- " + k->name + ": {") != std::string::npos);
  }
  for (auto& s : kinergy::model::inertia_shapes()) {
    INFO("inertia shape " << s.name);
    CHECK(doc.find(s.name) != std::string::npos);
  }
}
