// simulate --animate (issue 14, item 3): the motion drawn frame by frame from the model at the same
// samples as --csv and --plot. Expected positions by hand: the bouncing ball falls from rest at
// y0 = h + r = 1.23 m, y(t) = y0 − g t²/2 until its bottom meets the floor (y = r) at
// t1 = sqrt(2 h/g) = 0.49462 s (h = 1.2 m, g = 9.81 m/s²).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include "../support/helpers.hpp"
#include "kinergy/draw/animation.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace sim = kinergy::simulate;
namespace fs = std::filesystem;

namespace {

const double g = 9.81, h = 1.2, r = 0.03, t1 = std::sqrt(2 * h / g);

struct Ball {
  kinergy::Solution s;
  kinergy::draw::Motion motion;
};

// the ball from rest until t = 0.7 s, sampled every 0.01 s and at its impact
Ball ball() {
  Ball b{kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/impact/bouncing_ball.yaml"), {}};
  sim::Options o;
  o.native = false;
  o.sample_dt = 0.01;
  sim::Simulator run(b.s.model, sim::simulation_values(b.s), o);
  sim::Stop stop;
  stop.until = 0.7;
  auto res = run.run(sim::state_values(b.s, 0), stop);
  b.motion.title = b.s.model.title;
  for (auto& x : res.samples) b.motion.frames.push_back({x.t, x.q, x.qd});
  for (auto& im : res.impacts) b.motion.moments.push_back({im.t, "impact at floor"});
  return b;
}

// the world y of the ball's centre drawn in each frame (its marked point, world coordinates)
std::vector<double> ball_heights(const std::string& svg) {
  std::vector<double> out;
  std::regex mark("data-name=\"ball\\.G\" cx=\"[^\"]+\" cy=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), mark); it != std::sregex_iterator(); ++it) out.push_back(std::stod((*it)[1]));
  return out;
}

}  // namespace

TEST_CASE("animation SVG: one frame per sample, each the ball where it is then, taking turns in real time", "[draw][animate]") {
  Ball b = ball();
  const std::string svg = kinergy::draw::animation_svg(b.s.model, sim::simulation_values(b.s), b.motion);
  auto ys = ball_heights(svg);
  REQUIRE(ys.size() == b.motion.frames.size());
  int checked = 0;
  for (std::size_t i = 0; i < ys.size(); ++i) {
    const double t = b.motion.frames[i].t;
    if (t > t1 - 1e-9) continue;  // the fall, before the impact
    CHECK(std::fabs(ys[i] - (h + r - g * t * t / 2)) < 1e-5);
    ++checked;
  }
  CHECK(checked >= 49);
  // each frame shown from its time to the next over a loop as long as the motion (0.7 s)
  CHECK(svg.find("dur=\"0.7s\"") != std::string::npos);
  std::size_t animates = 0;
  for (std::size_t i = svg.find("<animate "); i != std::string::npos; i = svg.find("<animate ", i + 1)) ++animates;
  CHECK(animates == b.motion.frames.size());
  // the impact marked in the frames after it
  CHECK(svg.find(">t = 0.4946 s: impact at floor</text>") != std::string::npos);
  // the same bytes each time
  CHECK(kinergy::draw::animation_svg(b.s.model, sim::simulation_values(b.s), b.motion) == svg);
}

TEST_CASE("simulate --animate: SVG, HTML and GIF written, anything else refused", "[draw][animate][cli]") {
  const auto dir = fs::temp_directory_path() / "kinergy-animate-test";
  fs::create_directories(dir);
  int st = 0;
  for (const char* ext : {"svg", "html", "gif"}) {
    const auto file = dir / (std::string("ball.") + ext);
    fs::remove(file);
    std::string out = kt::run_cli("simulate derivations/impact/bouncing_ball.yaml --until 0.7 --samples 70 --animate " + file.string(), st);
    INFO(out);
    REQUIRE(st == 0);
    const std::string bytes = kt::read_file(file);
    if (std::string(ext) == "gif") CHECK(bytes.substr(0, 6) == "GIF89a");
    else if (std::string(ext) == "svg") CHECK(bytes.rfind("<svg", 0) == 0);
    else CHECK(bytes.rfind("<!DOCTYPE html>", 0) == 0);
  }
  std::string out = kt::run_cli("simulate derivations/impact/bouncing_ball.yaml --until 0.7 --animate " + (dir / "ball.mp4").string(), st);
  CHECK(st != 0);
  CHECK(out.find("the animation '" + (dir / "ball.mp4").string() + "' is not .svg, .html or .gif \u2014 name it FILE.svg, FILE.html or FILE.gif") !=
        std::string::npos);
}

TEST_CASE("the animation page in headless Chromium: the ball drawn lower at a later frame, by the fall", "[draw][animate][browser]") {
  const std::string chromium = kt::chromium();
  if (chromium.empty()) {
    WARN("chromium is not installed: the browser test is not run (bash .ci/setup --deps installs it)");
    return;
  }
  Ball b = ball();
  std::string html = kinergy::draw::animation_html(b.s.model, sim::simulation_values(b.s), b.motion);
  // a probe: frame 0, then the frame at t = 0.3 s; the ball's centre as the browser renders it
  std::size_t later = 0;
  while (b.motion.frames[later].t < 0.3 - 1e-9) ++later;
  const std::string probe =
      "<script>window.addEventListener('load', function () {\n"
      "  function y() { const c = document.querySelector('.stage g[data-frame][display=\"inline\"] circle[data-name=\"ball.G\"]');\n"
      "    const r = c.getBoundingClientRect(); return r.top + r.height / 2; }\n"
      "  kinergyShow(0); const y0 = y(); kinergyShow(" + std::to_string(later) + "); const y1 = y();\n"
      "  const svg = document.querySelector('.stage svg').getBoundingClientRect();\n"
      "  document.body.setAttribute('data-probe', y0 + ' ' + y1 + ' ' + svg.height);\n"
      "});</script>\n";
  html.insert(html.rfind("</body>"), probe);
  const auto dir = fs::temp_directory_path() / ("kinergy-browser-test-" + std::to_string(getpid()));  // (this process's own)
  fs::create_directories(dir);
  {
    std::ofstream out(dir / "ball.html");
    out << html;
  }
  const std::string dom = kt::run_command(chromium + " --headless --no-sandbox --disable-gpu --user-data-dir=" + (dir / "profile").string() + " --virtual-time-budget=2000 --dump-dom file://" +
                                          (dir / "ball.html").string() + " 2>/dev/null");
  std::smatch mt;
  REQUIRE(std::regex_search(dom, mt, std::regex("data-probe=\"([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\"")));
  const double y0 = std::stod(mt[1]), y1 = std::stod(mt[2]);
  // page y grows downward: the ball is lower (larger y) by its fall g t²/2 times the scale (pixels a metre)
  const double fall = g * b.motion.frames[later].t * b.motion.frames[later].t / 2;
  CHECK(y1 > y0);
  auto ys = ball_heights(html);
  REQUIRE(ys.size() > later);
  // the scale: page pixels per metre, from the SVG's own transform, and the page as rendered
  std::smatch sc;
  REQUIRE(std::regex_search(html, sc, std::regex("transform=\"matrix\\(([-0-9.e]+) 0 0")));
  std::smatch wh;
  REQUIRE(std::regex_search(html, wh, std::regex("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"[0-9]+\" height=\"([0-9]+)\"")));
  const double shown = std::stod(mt[3]) / std::stod(wh[1]);  // rendered height / drawn height
  CHECK(std::fabs((y1 - y0) - fall * std::stod(sc[1]) * shown) < 1.5);
  fs::remove_all(dir);
}
