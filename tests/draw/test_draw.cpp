// kinergy draw (issue 14, first step): every derivation drawn at each of its states; the points
// read back from the SVG (their world places are kept as data) equal the model's positions there.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <regex>

#include "../support/helpers.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/simulate/check.hpp"

namespace {

// the world group's transform and each marked point's (cx, cy)
struct ReadBack {
  std::map<std::string, std::pair<double, double>> points;
};

ReadBack read_back(const std::string& svg) {
  ReadBack r;
  std::regex mark("<circle data-name=\"([^\"]+)\" cx=\"([^\"]+)\" cy=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), mark); it != std::sregex_iterator(); ++it)
    r.points[(*it)[1]] = {std::stod((*it)[2]), std::stod((*it)[3])};
  return r;
}

}  // namespace

TEST_CASE("every derivation drawn at each state: the drawn points are the model's", "[draw]") {
  int drawn = 0;
  for (const auto& file : kt::scene_files("derivations")) {
    kinergy::Solution s = kinergy::solve_file(file);
    const auto& m = s.model;
    const auto params = kinergy::simulate::simulation_values(s);
    for (std::size_t st = 0; st < m.states.size(); ++st) {
      INFO(file << " state " << m.states[st].name);
      kinergy::draw::Figure f;
      try {
        f = kinergy::draw::scene_at(m, s.branch.sol, params, static_cast<int>(st));
      } catch (const kinergy::SceneError& e) {
        // a state that does not fix a coordinate (placed by a parameter without a value, say)
        CHECK(std::string(e.what()).find("cannot be drawn") != std::string::npos);
        continue;
      }
      const std::string svg = f.svg();
      auto back = read_back(svg);
      // each body's centre and named points, at the state's coordinates
      auto sv = kinergy::simulate::state_values(s, static_cast<int>(st));
      GiNaC::exmap at = params;
      for (std::size_t i = 0; i < m.coords.size(); ++i) at[m.coords[i].q] = sv.q[i];
      at[m.t] = std::isnan(sv.t) ? 0 : sv.t;
      auto num = [&](const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(e.subs(at).evalf()).to_double(); };
      for (auto& b : m.bodies) {
        REQUIRE(back.points.count(b.name + ".G"));
        auto [x, y] = back.points[b.name + ".G"];
        const double scale = 1e-5 * (1 + std::fabs(num(b.x)) + std::fabs(num(b.y)));
        CHECK(std::fabs(x - num(b.x)) <= scale);
        CHECK(std::fabs(y - num(b.y)) <= scale);
        for (auto& [pn, lp] : b.points) {
          kinergy::model::PointRef ref;
          ref.body = static_cast<int>(&b - &m.bodies[0]);
          ref.lx = lp.first;
          ref.ly = lp.second;
          auto [px, py] = m.position(ref);
          REQUIRE(back.points.count(b.name + "." + pn));
          CHECK(std::fabs(back.points[b.name + "." + pn].first - num(px)) <= scale * 10);
          CHECK(std::fabs(back.points[b.name + "." + pn].second - num(py)) <= scale * 10);
        }
      }
      // the same bytes every time
      CHECK(kinergy::draw::scene_at(m, s.branch.sol, params, static_cast<int>(st)).svg() == svg);
      ++drawn;
    }
  }
  CHECK(drawn >= 100);
}

TEST_CASE("kinergy draw: SVG on standard output or to a file; what is refused", "[draw][cli]") {
  int st = 0;
  std::string out = kt::run_cli("draw derivations/energy/sliding_rod.yaml --state 2", st);
  CHECK(st == 0);
  CHECK(out.rfind("<svg", 0) == 0);
  CHECK(out.find("data-name=\"rod.A\"") != std::string::npos);
  out = kt::run_cli("draw derivations/energy/sliding_rod.yaml --state 9", st);
  CHECK(st != 0);
  CHECK(out.find("there is no state '9'") != std::string::npos);
  const auto dir = std::filesystem::temp_directory_path() / "kinergy-draw-test";
  std::filesystem::create_directories(dir);
  out = kt::run_cli("draw derivations/energy/sliding_rod.yaml -o " + (dir / "rod.gif").string(), st);
  CHECK(st != 0);
  CHECK(out.find("is not .svg, .pdf or .png") != std::string::npos);
  kt::run_cli("draw derivations/energy/sliding_rod.yaml -o " + (dir / "rod.svg").string(), st);
  CHECK(st == 0);
  CHECK(kt::read_file(dir / "rod.svg").rfind("<svg", 0) == 0);
  // PNG and PDF through rsvg-convert (installed by .ci/setup): their signatures
  for (const char* ext : {"png", "pdf"}) {
    const auto file = dir / (std::string("rod.") + ext);
    std::filesystem::remove(file);
    out = kt::run_cli("draw derivations/energy/bar_spring.yaml -o " + file.string(), st);
    INFO(out);
    REQUIRE(st == 0);
    const std::string bytes = kt::read_file(file);
    CHECK(bytes.substr(1, 3) == (std::string(ext) == "png" ? "PNG" : "PDF"));
  }
}
