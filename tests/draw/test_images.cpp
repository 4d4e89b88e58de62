// Rendered-image approvals (issue 14): a few drawings rendered to pixels — SVG → PDF by
// rsvg-convert, PDF → grey PGM by pdftoppm at 48 dpi — and compared with approved images in
// tests/draw/images/ with a tolerance (fonts may differ a little between machines; a moved body, a
// flipped arrow or a lost label does not pass). KINERGY_APPROVE=1 writes the approved images; look
// at them (rsvg-convert the SVG to PNG) before committing.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "../support/helpers.hpp"
#include "kinergy/draw/animation.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace fs = std::filesystem;

namespace {

struct Grey {
  int w = 0, h = 0;
  std::string px;
};

// a binary PGM (P5, maxval 255)
Grey read_pgm(const std::string& bytes) {
  Grey g;
  std::size_t i = 0;
  auto token = [&]() {
    while (i < bytes.size() && (std::isspace(static_cast<unsigned char>(bytes[i])) || bytes[i] == '#')) {
      if (bytes[i] == '#')
        while (i < bytes.size() && bytes[i] != '\n') ++i;
      else ++i;
    }
    std::string t;
    while (i < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[i]))) t += bytes[i++];
    return t;
  };
  if (token() != "P5") return g;
  g.w = std::stoi(token());
  g.h = std::stoi(token());
  if (token() != "255") return {};
  ++i;  // the one whitespace before the pixels
  g.px = bytes.substr(i);
  if (g.px.size() != static_cast<std::size_t>(g.w) * static_cast<std::size_t>(g.h)) return {};
  return g;
}

// the SVG as pixels: rsvg-convert to PDF, pdftoppm to grey at 48 dpi
Grey render(const std::string& svg, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "kinergy-images-test";
  fs::create_directories(dir);
  {
    std::ofstream out(dir / (name + ".svg"));
    out << svg;
  }
  int st = 0;
  kt::run_command("rsvg-convert --format pdf --output " + (dir / (name + ".pdf")).string() + " " + (dir / (name + ".svg")).string() + " 2>&1", &st);
  REQUIRE(st == 0);
  kt::run_command("pdftoppm -gray -r 48 -singlefile " + (dir / (name + ".pdf")).string() + " " + (dir / name).string() + " 2>&1", &st);
  REQUIRE(st == 0);
  return read_pgm(kt::read_file(dir / (name + ".pgm")));
}

void approve(const std::string& svg, const std::string& name) {
  INFO(name);
  if (kt::run_command("command -v rsvg-convert >/dev/null && command -v pdftoppm >/dev/null && echo yes") != "yes\n") {
    WARN("rsvg-convert or pdftoppm is not installed: the image approvals are not run (bash .ci/setup --deps)");
    return;
  }
  const Grey got = render(svg, name);
  REQUIRE(got.w > 0);
  const fs::path approved = fs::path(KINERGY_SOURCE_DIR) / "tests" / "draw" / "images" / (name + ".pgm");
  if (std::getenv("KINERGY_APPROVE")) {
    fs::create_directories(approved.parent_path());
    std::ofstream out(approved, std::ios::binary);
    out << "P5\n" << got.w << " " << got.h << "\n255\n" << got.px;
    return;
  }
  const Grey want = read_pgm(kt::read_file(approved));
  REQUIRE(want.w > 0);
  REQUIRE(got.w == want.w);
  REQUIRE(got.h == want.h);
  // the mean difference, and the share of pixels far apart (ink where there was paper)
  double total = 0;
  std::size_t far = 0;
  for (std::size_t i = 0; i < got.px.size(); ++i) {
    const int d = std::abs(static_cast<unsigned char>(got.px[i]) - static_cast<unsigned char>(want.px[i]));
    total += d;
    far += d > 96 ? 1 : 0;
  }
  const double n = static_cast<double>(got.px.size());
  CHECK(total / n < 1.5);
  CHECK(static_cast<double>(far) / n < 0.002);
}

}  // namespace

TEST_CASE("rendered images: a scene at its states, an impact diagram and an animation's first frame, as approved", "[draw][images]") {
  const std::string root = KINERGY_SOURCE_DIR;
  {
    kinergy::Solution s = kinergy::solve_file(root + "/derivations/energy/sliding_rod.yaml");
    std::vector<int> all;
    for (std::size_t i = 0; i < s.model.states.size(); ++i) all.push_back(static_cast<int>(i));
    approve(kinergy::draw::states_at(s.model, s.branch.sol, kinergy::simulate::simulation_values(s), all).svg(), "sliding_rod_states");
  }
  {
    const std::string file = root + "/derivations/impact/sphere_hits_pivoted_bar.yaml";
    kinergy::Solution s = kinergy::solve_file(file);
    const auto d = kinergy::emit::derive(s);
    const kinergy::draw::Sheet* second = nullptr;
    int k = 0;
    for (auto& b : d.blocks)
      if (b.sheet && ++k == 2) second = b.sheet.get();
    REQUIRE(second);
    approve(second->svg(), "sphere_hits_pivoted_bar_figure2");
  }
  {
    kinergy::Solution s = kinergy::solve_file(root + "/derivations/energy/bar_spring.yaml");
    namespace sim = kinergy::simulate;
    sim::Options o;
    o.native = false;
    o.sample_dt = 0.01;
    sim::Simulator run(s.model, sim::simulation_values(s), o);
    sim::Stop stop;
    stop.until = 0.5;
    const auto r = run.run(sim::state_values(s, 0), stop);
    // the first frame is what a viewer without animation shows
    approve(kinergy::draw::animation_svg(s.model, sim::simulation_values(s), sim::motion_of(r, s.model.title)), "bar_spring_animation");
  }
}
