// kinergy draw (issue 14, first step): every derivation drawn at each of its states; the points
// read back from the SVG (their world places are kept as data) equal the model's positions there.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <regex>
#include <set>

#include "../support/helpers.hpp"
#include "each_figure.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/draw/names.hpp"
#include "../../src/emit/figures.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/confirm/check.hpp"

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

TEST_CASE("kinergy draw: a scene whose parameters have no value, at a sample value it names or at one given with --set", "[draw][cli]") {
  // the compound pendulum with L a symbol: at state 1, theta = -pi/2 - 60 deg = -150 deg, so its end B
  // is at L (cos theta, sin theta) = L (-0.8660, -0.5): at the sample L = 1 m, and at L = 0.9 m set
  const auto dir = std::filesystem::temp_directory_path() / "kinergy-draw-symbolic";
  std::filesystem::create_directories(dir);
  int st = 0;
  const std::string scene = "tests/data/symbolic_pendulum.yaml";
  std::string out = kt::run_cli("draw " + scene + " -o " + (dir / "a.svg").string(), st);
  CHECK(st == 0);
  CHECK(out.find("drawn with sample values for the parameters that have none: L = 1 m (give them with --set NAME=VALUE)") != std::string::npos);
  auto B = read_back(kt::read_file(dir / "a.svg")).points.at("bar.B");
  CHECK(B.first == Approx(-std::sqrt(3.0) / 2).epsilon(1e-5));
  CHECK(B.second == Approx(-0.5).epsilon(1e-5));
  out = kt::run_cli("draw " + scene + " --set \"L=0.9 m\" -o " + (dir / "b.svg").string(), st);
  CHECK(st == 0);
  CHECK(out.find("sample") == std::string::npos);
  B = read_back(kt::read_file(dir / "b.svg")).points.at("bar.B");
  CHECK(B.first == Approx(-0.9 * std::sqrt(3.0) / 2).epsilon(1e-5));
  CHECK(B.second == Approx(-0.45).epsilon(1e-5));
  // what --set refuses: another kind of quantity, a parameter the scene has not, no '='
  out = kt::run_cli("draw " + scene + " --set \"L=2 kg\"", st);
  CHECK(st != 0);
  CHECK(out.find("the value '2 kg' for 'L' is a mass, but the scene writes 'L: m', a length") != std::string::npos);
  out = kt::run_cli("draw " + scene + " --set Q=2", st);
  CHECK(st != 0);
  CHECK(out.find("the scene has no parameter 'Q'") != std::string::npos);
  out = kt::run_cli("draw " + scene + " --set L", st);
  CHECK(st != 0);
  CHECK(out.find("'L' does not set a parameter") != std::string::npos);
  // the worked solution's figures: drawn at the sample, each caption saying so, no NaN in its LaTeX
  const auto d = kinergy::emit::derive(kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/" + scene));
  const std::string tex = kinergy::emit::latex(d);
  CHECK(tex.find("nan") == std::string::npos);
  int figures = 0;
  for (const auto& b : d.blocks)
    if (b.sheet) {
      ++figures;
      CHECK(b.title.find("Drawn with sample values for the parameters that have none: L = 1 m.") != std::string::npos);
    }
  CHECK(figures >= 1);  // (the positions of its energy analysis are the scene's: not drawn twice)
}

TEST_CASE("kinergy draw: SVG on standard output or to a file, and what is refused", "[draw][cli]") {
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
  CHECK(out.find("is not .svg, .pdf, .png or .tex") != std::string::npos);
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

TEST_CASE("kinergy draw --state all: the states side by side at one scale, each panel's points the model's", "[draw][cli]") {
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/sliding_rod.yaml");
  const auto& m = s.model;
  REQUIRE(m.states.size() >= 2);
  const auto params = kinergy::simulate::simulation_values(s);
  std::vector<int> all;
  for (std::size_t i = 0; i < m.states.size(); ++i) all.push_back(static_cast<int>(i));
  const kinergy::draw::Sheet sheet = kinergy::draw::states_at(m, s.branch.sol, params, all);
  REQUIRE(sheet.size() == m.states.size());
  const std::string svg = sheet.svg();
  // one world group per panel, one scale for all (the same matrix scale)
  std::regex group("<g data-world=\"metres\" data-panel=\"([0-9]+)\" transform=\"matrix\\(([^ ]+) 0 0 ([^ ]+) ");
  std::vector<std::string> scales;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), group); it != std::sregex_iterator(); ++it) scales.push_back((*it)[2]);
  REQUIRE(scales.size() == m.states.size());
  for (auto& sc : scales) CHECK(sc == scales[0]);
  // each panel holds the marked points of the scene at its own state
  for (std::size_t i = 0; i < m.states.size(); ++i) {
    const std::string one = kinergy::draw::scene_at(m, s.branch.sol, params, static_cast<int>(i)).svg();
    auto single = read_back(one);
    const std::size_t a = svg.find("data-panel=\"" + std::to_string(i) + "\"");
    const std::size_t b = svg.find("</g>", a);
    auto panel = read_back(svg.substr(a, b - a));
    REQUIRE(panel.points.size() == single.points.size());
    for (auto& [name, p] : single.points) {
      CHECK(std::fabs(panel.points[name].first - p.first) < 1e-4);
      CHECK(std::fabs(panel.points[name].second - p.second) < 1e-4);
    }
  }
  int st = 0;
  std::string out = kt::run_cli("draw derivations/energy/sliding_rod.yaml --state all", st);
  CHECK(st == 0);
  CHECK(out == svg);
  // a state that does not fix a coordinate is left out, and the user told which and why
  out = kt::run_cli("draw derivations/impact/pendulum_strikes_block.yaml --state all", st);
  CHECK(st == 0);
  CHECK(out.find("left out of the drawing: state '3' does not fix x, so it cannot be drawn") != std::string::npos);
  CHECK(out.find("data-panel=\"2\"") != std::string::npos);
  CHECK(out.find("data-panel=\"3\"") == std::string::npos);
}

TEST_CASE("kinergy draw without --state: the first state that fixes every coordinate, those before it said (issue 44, item 10)", "[draw][cli]") {
  // a disk sliding while it spins: state 1 gives its place and rates but not its angle
  const std::string scene = kt::read_file(std::string(KINERGY_SOURCE_DIR) + "/tests/data/disk_spins_as_it_slides.yaml");
  const std::string file = kt::written("kinergy-draw-first", "nofix", scene);
  int st = 0;
  std::string out = kt::run_cli("draw " + file, st);
  INFO(out);
  CHECK(st == 0);
  CHECK(out.find("left out of the drawing: state '1' does not fix phi, so it cannot be drawn") != std::string::npos);
  CHECK(out.find("<svg") != std::string::npos);
  // state 2 itself, the same figure
  const auto s = kt::solve_text(scene);
  std::vector<std::string> left_out;
  const std::string first = kinergy::draw::first_drawable(s.model, s.branch.sol, s.model.parameter_values(), left_out).svg();
  CHECK(first == kinergy::draw::scene_at(s.model, s.branch.sol, s.model.parameter_values(), 1).svg());
  CHECK(left_out.size() == 1);
  // named, state 1 is still refused, saying why
  out = kt::run_cli("draw " + file + " --state 1", st);
  CHECK(st == 1);
  CHECK(out.find("state '1' does not fix phi, so it cannot be drawn") != std::string::npos);
  // where no state fixes every coordinate, the first state's reason
  out = kt::run_cli("draw " + kt::written("kinergy-draw-first", "none", kt::edit(scene, "phi: 0, phi_dot: 0}", "phi_dot: 0}")), st);
  CHECK(st == 1);
  CHECK(out.find("state '1' does not fix phi") != std::string::npos);
}

TEST_CASE("kinergy draw -o FILE.tex: a TikZ picture that pdflatex compiles", "[draw][cli][latex]") {
  const auto dir = std::filesystem::temp_directory_path() / "kinergy-draw-tex";
  std::filesystem::create_directories(dir);
  int st = 0;
  std::string out = kt::run_cli("draw derivations/momentum/gears_time_tooth_force.yaml --state all -o " + (dir / "g.tex").string(), st);
  INFO(out);
  REQUIRE(st == 0);
  const std::string pic = kt::read_file(dir / "g.tex");
  CHECK(pic.rfind("\\begin{tikzpicture}", 0) == 0);
  CHECK(pic.find("\\end{tikzpicture}") != std::string::npos);
  if (!kinergy::emit::have_pdflatex()) return;
  auto run = kinergy::emit::run_pdflatex("\\documentclass{article}\\usepackage{tikz}\\begin{document}\n" + pic + "\\end{document}\n", "");
  INFO(run.error);
  CHECK(run.ok);
}

TEST_CASE("every derivation's LaTeX draws its states, each momentum analysis and impact its impulse-momentum diagram, each "
          "kinetics analysis a free-body diagram of each body",
          "[draw][derive]") {
  int diagrams = 0;
  for (const auto& file : kt::scene_files("derivations")) {
    INFO(file);
    kinergy::Solution s = kinergy::solve_file(file);
    const std::string tex = kinergy::emit::latex(kinergy::emit::derive(s));
    CHECK(tex.find("The scene at its states") != std::string::npos);
    std::size_t want = 0, want_free = 0;
    for (auto& a : s.model.analyses) {
      if (a.type->at_state()) want_free += a.bodies.size();
      else want += a.kind == "energy" ? 0 : 1;
    }
    std::size_t got = 0, free = 0;
    for (std::size_t i = tex.find("Impulse-momentum diagram of"); i != std::string::npos; i = tex.find("Impulse-momentum diagram of", i + 1)) ++got;
    for (std::size_t i = tex.find("Free-body diagram of"); i != std::string::npos; i = tex.find("Free-body diagram of", i + 1)) ++free;
    CHECK(got >= want);
    CHECK(free == want_free);
    diagrams += static_cast<int>(got);
  }
  CHECK(diagrams >= 40);
}

namespace {

// the force arrows of a panel by the label at their head: label → (dx, dy)
std::map<std::string, std::pair<double, double>> arrows_of(const kinergy::draw::Figure& f) {
  std::map<std::string, std::pair<double, double>> out;
  for (auto& sh : f.shapes()) {
    if (sh.kind != kinergy::draw::Figure::Shape::Arrow) continue;
    for (auto& l : f.labels())
      if (std::fabs(l.x - sh.pts[1].first) < 1e-12 && std::fabs(l.y - sh.pts[1].second) < 1e-12)
        out[l.text] = {sh.pts[1].first - sh.pts[0].first, sh.pts[1].second - sh.pts[0].second};
  }
  return out;
}

// the sense of each curved arrow of a panel (counterclockwise +1, clockwise −1) by its label
std::map<std::string, int> turns_of(const kinergy::draw::Figure& f) {
  std::map<std::string, int> out;
  for (auto& sh : f.shapes()) {
    if (sh.kind != kinergy::draw::Figure::Shape::Arc) continue;
    const auto& p = sh.pts;
    // the turn from the first chord to the last step tells the sense
    const double ax = p[p.size() - 2].first - p[0].first, ay = p[p.size() - 2].second - p[0].second;
    const double bx = p.back().first - p[p.size() - 2].first, by = p.back().second - p[p.size() - 2].second;
    for (auto& l : f.labels())
      if (std::fabs(l.x - p.back().first) < 1e-9 && std::fabs(l.y - p.back().second) < 1e-9) out[l.text] = ax * by - ay * bx > 0 ? 1 : -1;
  }
  return out;
}

}  // namespace

TEST_CASE("the impact diagram of a sphere striking a pivoted bar: each arrow points the way the problem says", "[draw][derive]") {
  // by hand (the scene's description): the sphere moving right strikes the bar below the pin; the bar
  // swings counterclockwise after (ω = 3.31 rad/s), the sphere rebounds (v = −0.517 m/s), the pin's
  // impulse on the bar is +0.552 N s along x; the contact impulse pushes the bar right, the sphere left
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/impact/sphere_hits_pivoted_bar.yaml");
  const auto& m = s.model;
  const kinergy::model::Analysis* impact = nullptr;
  for (auto& a : m.analyses)
    if (a.instant()) impact = &a;
  REQUIRE(impact);
  REQUIRE(s.balances_of<kinergy::principles::ImpactBalance>().size() == 1);
  const int bar = m.body_index("bar"), sphere = m.body_index("sphere");
  auto bar_d = kinergy::emit::momentum_diagram(s, *impact, {bar}, s.balances_of<kinergy::principles::ImpactBalance>()[0]->shown, {}, nullptr);
  auto sphere_d = kinergy::emit::momentum_diagram(s, *impact, {sphere}, s.balances_of<kinergy::principles::ImpactBalance>()[0]->shown, {}, nullptr);
  REQUIRE(bar_d);
  REQUIRE(sphere_d);
  REQUIRE(bar_d->size() == 3);
  // before: the bar at rest (no momentum drawn), the sphere moving right
  CHECK(arrows_of(bar_d->panel(0)).empty());
  auto sp0 = arrows_of(sphere_d->panel(0));
  REQUIRE(sp0.count("m v\u0304"));
  CHECK(sp0["m v\u0304"].first > 0);
  // impulses: on the bar the pin's and the contact's, both along +x; on the sphere the contact's along −x
  auto bi = arrows_of(bar_d->panel(1));
  const std::string pin = "\u222bR dt";  // (the pin's impulse, as a textbook writes it)
  REQUIRE(bi.count(pin));
  CHECK(bi[pin].first > 0);
  CHECK(std::fabs(bi[pin].second) < 1e-9 * std::fabs(bi[pin].first));
  REQUIRE(bi.size() == 2);
  for (auto& [name, d] : bi) CHECK(d.first > 0);
  auto si = arrows_of(sphere_d->panel(1));
  REQUIRE(si.size() == 1);
  CHECK(si.begin()->second.first < 0);
  // after: the bar turns counterclockwise, the sphere moves left
  auto bt = turns_of(bar_d->panel(2));
  REQUIRE(bt.count("I\u0304 \u03c9"));
  CHECK(bt["I\u0304 \u03c9"] == 1);
  auto sp2 = arrows_of(sphere_d->panel(2));
  REQUIRE(sp2.count("m v\u0304"));
  CHECK(sp2["m v\u0304"].first < 0);
}

TEST_CASE("kinergy draw --figure N: a figure of the worked solution, as the LaTeX numbers it, and what is refused", "[draw][cli]") {
  int st = 0;
  const std::string scene = "derivations/impact/sphere_hits_pivoted_bar.yaml";
  // the states, then a diagram for each body the impact strikes (bar, sphere)
  std::string out = kt::run_cli("derive " + scene + " --latex -", st);
  REQUIRE(st == 0);
  CHECK(out.find("Figure 1: The scene at its states") != std::string::npos);
  CHECK(out.find("Figure 2: Impulse-momentum diagram of bar in the impact") != std::string::npos);
  CHECK(out.find("Figure 3: Impulse-momentum diagram of sphere in the impact") != std::string::npos);
  CHECK(out.find("Figure 4:") == std::string::npos);
  out = kt::run_cli("draw " + scene + " --figure 2", st);
  CHECK(st == 0);
  CHECK(out.find("data-panel=\"2\"") != std::string::npos);
  CHECK(out.find(">momenta at before</text>") != std::string::npos);
  CHECK(out.find(">J<tspan dy=\"4\" font-size=\"10\">hit</tspan></text>") != std::string::npos);
  out = kt::run_cli("draw " + scene + " --figure 4", st);
  CHECK(st != 0);
  CHECK(out.find("has 3 figures, not 4 \u2014 give --figure from 1 to 3") != std::string::npos);
  out = kt::run_cli("draw " + scene + " --figure 1 --state before", st);
  CHECK(st != 0);
  CHECK(out.find("--figure and --state cannot be used together") != std::string::npos);
  out = kt::run_cli("draw tests/data/simulate/huge_couple.yaml --figure 1", st);
  CHECK(st != 0);
  CHECK(out.find("the scene has no analyses, so its worked solution has no figures") != std::string::npos);
}

TEST_CASE("the docs' wrong geometry: it solves, and its picture puts the spring's end C to the right of O", "[draw][docs]") {
  // docs/pictures.md: bar_spring with C written [b, 0] instead of [0, b]. By hand: B goes from
  // (−L, 0) to (0, −L); the spring from length L + b = 2.5 m to sqrt(L² + b²) = 1.8028 m, so
  // ½ (m L²/3) ω² = m g L/2 + ½ k (2.5 − 1)² − ½ k (1.8028 − 1)², ω = 5.3088 rad/s (3.3252 as meant)
  const std::string file = std::string(KINERGY_SOURCE_DIR) + "/docs/examples/bar_spring_wrong_point.yaml";
  kinergy::Solution s = kinergy::solve_file(file);
  const double m = 10, L = 1.5, k = 40, L0 = 1, b = 1, g = 9.81;
  const double s1 = L + b, s2 = std::sqrt(L * L + b * b);
  const double w = std::sqrt((m * g * L / 2 + k * (s1 - L0) * (s1 - L0) / 2 - k * (s2 - L0) * (s2 - L0) / 2) * 2 / (m * L * L / 3));
  REQUIRE(kt::result(s, "omega2").si);
  CHECK(std::fabs(kt::result(s, "omega2").si->to_double() - w) < 1e-9 * w);
  auto back = read_back(kinergy::draw::scene_at(s.model, s.branch.sol, kinergy::simulate::simulation_values(s), 0).svg());
  REQUIRE(back.points.count("C"));
  CHECK(std::fabs(back.points["C"].first - b) < 1e-9);
  CHECK(std::fabs(back.points["C"].second) < 1e-9);
}

TEST_CASE("every derivation drawn as SVG, PDF, PNG and TikZ, each state side by side", "[draw][formats]") {
  const auto dir = std::filesystem::temp_directory_path() / "kinergy-draw-formats";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  int drawn = 0;
  for (const auto& file : kt::scene_files("derivations")) {
    INFO(file);
    kinergy::Solution s = kinergy::solve_file(file);
    std::vector<int> all;
    for (std::size_t i = 0; i < s.model.states.size(); ++i) all.push_back(static_cast<int>(i));
    std::vector<std::string> left_out;
    const auto sheet = kinergy::draw::states_at(s.model, s.branch.sol, kinergy::simulate::simulation_values(s), all, &left_out);
    REQUIRE(sheet.size() >= 1);
    CHECK(sheet.size() + left_out.size() == s.model.states.size());
    const std::string stem = (dir / std::filesystem::path(file).stem()).string();
    for (const char* ext : {".svg", ".pdf", ".png", ".tex"}) {
      kinergy::draw::write(sheet, stem + ext);
      const std::string bytes = kt::read_file(stem + ext);
      if (std::string(ext) == ".svg") CHECK(bytes.rfind("<svg", 0) == 0);
      if (std::string(ext) == ".pdf") CHECK(bytes.rfind("%PDF", 0) == 0);
      if (std::string(ext) == ".png") CHECK(bytes.substr(1, 3) == "PNG");
      if (std::string(ext) == ".tex") CHECK(bytes.rfind("\\begin{tikzpicture}", 0) == 0);
    }
    ++drawn;
  }
  CHECK(drawn >= 60);
}

TEST_CASE("every figure of every derivation: no label over another, over a title or the + and = between panels, or off the page",
          "[draw][derive][labels]") {
  // laid out as the HTML page (svg()) and the LaTeX (tikz(): the widths derive_latex asks for) lay them out
  int figures = 0, labels = 0;
  std::vector<std::string> faults;
  kt::each_figure([&](const std::string& file, int k, const kinergy::emit::Block& b) {
    {
      ++figures;
      const bool several = b.sheet->size() > 1;
      // (the HTML page's SVG; the LaTeX's TikZ, its words at 8 pt, as wide as derive_latex asks)
      for (auto [height, cm] : {std::pair<int, double>{1600, 0}, {several ? 560 : 520, several ? 15.5 : 10.5}}) {
        const int width = cm == 0 ? kinergy::emit::html_figure_width(*b.sheet) : 0;
        const auto laid = b.sheet->text_boxes(width, height, cm);
        const auto& boxes = laid.boxes;
        const double W = laid.width, H = laid.height;
        if (cm == 0) {
          // the SVG is that page
          std::smatch sz;
          const std::string svg = b.sheet->svg(width, height);
          REQUIRE(std::regex_search(svg, sz, std::regex("width=\"([0-9]+)\" height=\"([0-9]+)\"")));
          CHECK(std::stod(sz[1]) == W);
          CHECK(std::stod(sz[2]) == H);
        }
        for (std::size_t i = 0; i < boxes.size(); ++i) {
          const auto& p = boxes[i];
          if (!p.label) continue;
          ++labels;
          if (p.x0 < 0 || p.y0 < 0 || p.x1 > W || p.y1 > H) faults.push_back(file + " figure " + std::to_string(k) + ": '" + p.text + "' off the page");
          for (std::size_t j = 0; j < boxes.size(); ++j) {
            const auto& q = boxes[j];
            if (j == i || (q.label && j < i)) continue;
            if (p.x0 < q.x1 && q.x0 < p.x1 && p.y0 < q.y1 && q.y0 < p.y1)
              faults.push_back(file + " figure " + std::to_string(k) + ": '" + p.text + "' over " + (q.label ? "'" + q.text + "'" : "a title or a sign"));
          }
        }
      }
    }
  });
  INFO(figures << " figures, " << labels << " labels");
  for (auto& f : faults) UNSCOPED_INFO(f);
  CHECK(faults.empty());
  CHECK(figures >= 150);
}

TEST_CASE("a fixed pin's ground: below the pin, above it where the body hangs from it, and its point named once", "[draw]") {
  // the compound pendulum's pin O at the origin: at state 1 the bar is 30° below the horizontal
  // (its centre not below the pin), at state 2 it hangs straight down (the ground above O)
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/compound_pendulum.yaml");
  const auto params = kinergy::simulate::simulation_values(s);
  for (int st : {0, 1}) {
    const auto f = kinergy::draw::scene_at(s.model, s.branch.sol, params, st);
    int hatch = 0;
    for (const auto& sh : f.shapes()) {
      if (sh.ink != kinergy::draw::Ink::Support || sh.kind != kinergy::draw::Figure::Shape::Line) continue;
      ++hatch;
      for (const auto& [x, y] : sh.pts) {
        INFO("state " << st + 1 << ": (" << x << ", " << y << ")");
        if (st == 0) CHECK(y < 1e-12);
        else CHECK(y > -1e-12);
      }
    }
    CHECK(hatch == 6);  // its bar and five strokes
    // the ground's point O and the bar's point O pinned there: named once
    int named_O = 0;
    for (const auto& l : f.labels()) named_O += l.text == "O";
    CHECK(named_O == 1);
  }
}

namespace {

/// The words of a label outside its subscripts: "W_blockA" → "W", "R_{x,\mathrm{axle}}" → "R",
/// "\int F\,dt" → " F dt" (TeX commands dropped).
std::string outside_subscripts(const std::string& s, bool tex) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    if (s[i] == '_') {
      ++i;
      if (tex && i < s.size() && s[i] == '{') {
        int depth = 0;
        do {
          depth += s[i] == '{' ? 1 : s[i] == '}' ? -1 : 0;
          ++i;
        } while (i < s.size() && depth > 0);
      } else if (tex) {
        ++i;
      } else {
        while (i < s.size() && s[i] != ' ' && s[i] != '_') ++i;
      }
      continue;
    }
    if (tex && s[i] == '\\') {  // a command: \bar, \int, \, ...
      ++i;
      while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
      out += ' ';
      continue;
    }
    out += s[i++];
  }
  return out;
}

/// The first raw name in a label's words: a '+' before a name, or a run of two or more letters
/// outside a subscript other than "dt" and a unit after a number (6 m/s, 20 rad/s, as
/// "6\,\mathrm{rad/s}" in TeX) ("" when none).
std::string raw_name(const std::string& words) {
  if (!words.empty() && words[0] == '+') return words;
  // (commands are dropped before: "6\,\mathrm{m/s}" reads "6 , {m/s}")
  static const std::regex unit("[0-9][ ,{]+[A-Za-z/]+");
  std::string rest = std::regex_replace(words, unit, "0");
  std::smatch m;
  static const std::regex run("[A-Za-z]{2,}");
  while (std::regex_search(rest, m, run)) {
    if (m.str() != "dt") return m.str();
    rest = m.suffix();
  }
  return "";
}

}  // namespace

TEST_CASE("every figure of every derivation names things as a textbook does: no raw name, no '+' (issue 47)", "[draw][derive][labels]") {
  // θ for theta, φ_A for phiA, W_A for the weight of gearA, N, F, P, M, T by kind; a name of more
  // than one letter only inside a subscript (R_{x,axle}); the coordinates' senses without "+"
  CHECK(raw_name(outside_subscripts("W_blockA", false)).empty());
  CHECK(raw_name(outside_subscripts("R_{x,\\mathrm{axle}}", true)).empty());
  CHECK(raw_name(outside_subscripts("\\int W_{\\mathrm{rod}}\\,dt", true)).empty());
  CHECK(raw_name(outside_subscripts("+phiA", false)) == "+phiA");
  CHECK(raw_name(outside_subscripts("v_1 = 6 m/s", false)).empty());
  CHECK(raw_name(outside_subscripts("\\omega_{1} = 30\\,\\mathrm{rad/s}", true)).empty());
  CHECK(raw_name(outside_subscripts("v = ms", false)) == "ms");
  CHECK(raw_name(outside_subscripts("\\mathrm{drive}\\,\\Delta t", true)) == "drive");
  int labels = 0;
  std::vector<std::string> faults;
  kt::each_figure([&](const std::string& file, int k, const kinergy::emit::Block& b) {
    for (std::size_t i = 0; i < b.sheet->size(); ++i)
      for (const auto& l : b.sheet->panel(i).labels()) {
        ++labels;
        const std::string bad = raw_name(outside_subscripts(l.text, false)) + raw_name(outside_subscripts(l.tex, true));
        if (!bad.empty()) faults.push_back(file + " figure " + std::to_string(k) + ": '" + l.text + "' ('" + bad + "')");
      }
  });
  INFO(labels << " labels");
  for (auto& f : faults) UNSCOPED_INFO(f);
  CHECK(faults.empty());
  CHECK(labels >= 1000);
}

TEST_CASE("names as a textbook writes them: Greek letters, subscripts, words left as words (issue 47)", "[draw][labels]") {
  using kinergy::draw::short_name;
  using kinergy::draw::textbook;
  auto text = [](const std::string& id) { return textbook(id) ? textbook(id)->text : std::string("-"); };
  auto tex = [](const std::string& id) { return textbook(id) ? textbook(id)->tex : std::string("-"); };
  CHECK(text("theta") == "\u03b8");
  CHECK(tex("theta") == "\\theta");
  CHECK(text("phiA") == "\u03d5_A");
  CHECK(tex("phiA") == "\\phi_{A}");
  CHECK(text("beta") == "\u03b2");  // (not eta with a b)
  CHECK(text("mus") == "\u03bc_s");
  CHECK(text("omega0") == "\u03c9_0");
  CHECK(text("kd") == "k_d");
  CHECK(text("OA") == "O_A");
  CHECK(text("x") == "x");
  CHECK(tex("v_max") == "v_{\\mathrm{max}}");
  CHECK(text("rod") == "-");
  CHECK(text("ball1") == "-");
  CHECK(text("bumper") == "-");
  CHECK(short_name("gearA")->text == "A");
  CHECK(short_name("ball2")->text == "2");
  CHECK(short_name("A")->text == "A");
  CHECK_FALSE(short_name("disk"));
  CHECK_FALSE(short_name("AB2x"));
}

TEST_CASE("label: a body's and an effect's own names in the figures, and what a label may not hold (issue 47)", "[draw][labels]") {
  // the drum of drum_blocks_on_table labelled D: its weight W_D and momentum m... in every figure;
  // the table's friction labelled F_k: F_k Δt in the impulse diagram
  std::string scene = kt::derivation("momentum/drum_blocks_on_table.yaml");
  scene = kt::edit(scene, "drum: {mass: M, inertia: {disk: r}, position: [0, 0], angle: phi}",
                   "drum: {mass: M, inertia: {disk: r}, position: [0, 0], angle: phi, label: \"D\"}");
  scene = kt::edit(scene, "direction: positive}", "direction: positive, label: \"F_k\"}");
  const auto d = kinergy::emit::derive(kt::solve_text(scene));
  std::set<std::string> texts;
  for (const auto& b : d.blocks)
    if (b.sheet)
      for (std::size_t i = 0; i < b.sheet->size(); ++i)
        for (const auto& l : b.sheet->panel(i).labels()) texts.insert(l.text);
  CHECK(texts.count("W_D"));
  CHECK(texts.count("W_D \u0394t"));
  CHECK(texts.count("F_k \u0394t"));
  CHECK(texts.count("D"));  // (at the drum's centre)
  CHECK_FALSE(texts.count("W_drum"));
  // a Greek command is its letter in SVG
  CHECK(kinergy::draw::from_tex("\\theta_{A}").text == "\u03b8_A");
  // what a label may not be
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "label: \"D\"", "label: \"\"")), Catch::Contains("the label of body 'drum' is a name in TeX"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "label: \"D\"", "label: \"D$\"")),
                    Catch::Contains("the label of body 'drum' holds '$', which TeX would not take as part of a name"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "label: \"D\"", "label: \"D_{1\"")), Catch::Contains("has braces that do not close"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "label: \"F_k\"", "label: [F, k]")), Catch::Contains("the label of effect 'table' is a name in TeX"));
}

TEST_CASE("label: a point's and a coordinate's own names in the figures, and the forms refused (issue 47)", "[draw][labels]") {
  // compound_pendulum: the pin O labelled O_1, the bar's end B labelled P, θ labelled β
  std::string scene = kt::derivation("energy/compound_pendulum.yaml");
  scene = kt::edit(scene, "  O: [0, 0]\ncoordinates:\n  theta: rad", "  O: {at: [0, 0], label: \"O_1\"}\ncoordinates:\n  theta: {unit: rad, label: \"\\\\beta\"}");
  scene = kt::edit(scene, "points: {O: [-L/2, 0], B: [L/2, 0]}", "points: {O: [-L/2, 0], B: {at: [L/2, 0], label: \"P\"}}");
  const auto s = kt::solve_text(scene);
  CHECK(kt::result(s, "omega2").si->to_double() > 0);  // (the same problem: labels change no number)
  const auto d = kinergy::emit::derive(s);
  std::set<std::string> texts, tex;
  for (const auto& b : d.blocks)
    if (b.sheet)
      for (std::size_t i = 0; i < b.sheet->size(); ++i)
        for (const auto& l : b.sheet->panel(i).labels()) texts.insert(l.text), tex.insert(l.tex);
  CHECK(texts.count("O_1"));
  CHECK(texts.count("P"));
  CHECK(texts.count("\u03b2"));
  CHECK(tex.count("\\beta"));
  CHECK_FALSE(texts.count("B"));
  CHECK_FALSE(texts.count("\u03b8"));
  // (the bar's own O, pinned at the ground's O, keeps its name)
  CHECK(texts.count("O"));
  // the forms refused, each at its line
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "{at: [0, 0], label: \"O_1\"}", "{label: \"O_1\"}")), Catch::Contains("point 'O' has no 'at'"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "{at: [0, 0], label: \"O_1\"}", "{at: [0, 0], name: \"O_1\"}")), Catch::Contains("unknown key 'name' in point 'O' — use one of: at, label"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "label: \"P\"", "label: \"P%\"")),
                    Catch::Contains("the label of point 'B' holds '%'"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "{unit: rad, label: \"\\\\beta\"}", "{label: \"\\\\beta\"}")),
                    Catch::Contains("coordinate 'theta' has no 'unit'"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "{unit: rad, label: \"\\\\beta\"}", "{unit: kg, label: \"\\\\beta\"}")),
                    Catch::Contains("a coordinate is a length or an angle"));
  CHECK_THROWS_WITH(kt::solve_text(kt::edit(scene, "label: \"\\\\beta\"", "label: [b]")), Catch::Contains("the label of coordinate 'theta' is a name in TeX"));
}
