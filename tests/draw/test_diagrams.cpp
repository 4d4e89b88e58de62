// Issue 28 (findings 6 and 8): the impulse–momentum diagrams' arrows on their bodies, named as
// the equations name them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "../support/helpers.hpp"
#include "each_figure.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/emit/latex.hpp"
#include "kinergy/problem.hpp"
#include "../../src/emit/figures.hpp"

namespace kd = kinergy::draw;

TEST_CASE("an unknown's label in a drawing: subscripted as its TeX, without its states", "[draw][diagram]") {
  using kinergy::emit::plain_name;
  CHECK(plain_name("Rx_axle[1,2]") == "R_x,axle");
  CHECK(plain_name("Ry_pin@2") == "R_y,pin");
  CHECK(plain_name("J_hit[before,after]") == "J_hit");
  CHECK(plain_name("N_floor") == "N_floor");
  CHECK(plain_name("xA") == "x_A");
  CHECK(plain_name("theta2") == "theta2");
  CHECK(plain_name("F") == "F");
}

TEST_CASE("a force on a particle from a point off its drawing is drawn from the particle's edge", "[draw][diagram]") {
  // block_slides_on_cart: the block rubs on the cart; the friction on the cart acts at the block,
  // 0.4 m above the cart's centre. On the cart's diagram it starts at the cart's top edge, above
  // its centre (a particle's box: ±g wide, ±0.7 g high)
  const auto d = kinergy::emit::derive(kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/momentum/block_slides_on_cart.yaml"));
  int checked = 0;
  for (const auto& b : d.blocks) {
    if (!b.sheet || b.sheet->size() != 3) continue;
    const kd::Figure& f = b.sheet->panel(1);  // the impulses
    for (const auto& sh : f.shapes()) {
      if (sh.kind != kd::Figure::Shape::Arrow || sh.ink != kd::Ink::Force) continue;
      // which body: the one whose drawing holds the arrow's tail
      bool on_some = false;
      for (const auto& body : f.shapes()) {
        if (body.owner.rfind("body ", 0) != 0 || body.kind != kd::Figure::Shape::Polygon) continue;
        double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
        for (auto [x, y] : body.pts) {
          x0 = std::min(x0, x);
          x1 = std::max(x1, x);
          y0 = std::min(y0, y);
          y1 = std::max(y1, y);
        }
        const double tol = 1e-9 * (1 + std::fabs(x1) + std::fabs(y1));
        const auto [tx, ty] = sh.pts[0];
        on_some = on_some || (tx >= x0 - tol && tx <= x1 + tol && ty >= y0 - tol && ty <= y1 + tol);
      }
      CHECK(on_some);
      ++checked;
    }
  }
  CHECK(checked >= 2);  // the friction on the block, and on the cart
}

TEST_CASE("a diagram and its equations cannot disagree: a load the equations hold and the diagram lacks is an error", "[draw][diagram]") {
  // a panel that draws the weight only, checked against equations that hold the weight and a pin
  kd::Figure f;
  f.owned_by("gravity");
  f.arrow(0, 0, 0, -1);
  f.owned_by("");
  kd::Sheet sheet(f);
  CHECK_NOTHROW(kinergy::emit::check_diagram(sheet, 0, {"gravity"}, "diagram"));
  try {
    kinergy::emit::check_diagram(sheet, 0, {"gravity", "pin", "cord"}, "impulse-momentum diagram of bar");
    FAIL("no error");
  } catch (const std::logic_error& e) {
    CHECK(std::string(e.what()) ==
          "the impulse-momentum diagram of bar does not draw 'pin', 'cord', which its equations hold (or which acts on it from outside its set)");
  }
}

TEST_CASE("the centre of percussion: the pin's impulse, zero, is drawn as zero at the pin", "[draw][diagram]") {
  // a blow at the centre of percussion (2L/3 below the pin for a bar pinned at its end) leaves the
  // pin's impulse zero: J (L/6) = Ī ω and J = m ω L/2 give L/6 · m L/2 = m L²/12, true for any J
  const auto d = kinergy::emit::derive(kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/impact/centre_of_percussion.yaml"));
  int found = 0;
  for (const auto& b : d.blocks) {
    if (!b.sheet || b.sheet->size() != 3) continue;
    for (const auto& l : b.sheet->panel(1).labels()) found += l.text == "\u222bR dt = 0";  // (the pin's R, as a textbook writes it)
  }
  CHECK(found == 1);
}

TEST_CASE("every derivation's impulse-momentum and free-body diagrams: each force arrow starts on a drawn body", "[draw][diagram]") {
  // a tail T is on a body when it lies in the convex hull of the body's drawn shapes (a circle by
  // 720 points round it, within 1e-5 of its radius): max over its points of (p - T)·n >= 0 in
  // every direction n, to a thousandth of a glyph
  auto on = [](const kd::Figure& f, const std::string& owner, double tx, double ty, double tol) {
    std::vector<std::pair<double, double>> pts;
    for (const auto& sh : f.shapes()) {
      if (sh.owner != owner || sh.ink == kd::Ink::Dimension) continue;
      if (sh.kind == kd::Figure::Shape::Circle)
        for (int i = 0; i < 720; ++i) pts.push_back({sh.pts[0].first + sh.r * std::cos(i * M_PI / 360), sh.pts[0].second + sh.r * std::sin(i * M_PI / 360)});
      else
        pts.insert(pts.end(), sh.pts.begin(), sh.pts.end());
    }
    if (pts.empty()) return false;
    for (int k = 0; k < 64; ++k) {
      const double nx = std::cos(k * M_PI / 32), ny = std::sin(k * M_PI / 32);
      double most = -1e300;
      for (auto [x, y] : pts) most = std::max(most, (x - tx) * nx + (y - ty) * ny);
      if (most < -tol) return false;
    }
    return true;
  };
  int arrows = 0;
  std::vector<std::string> faults;
  for (const auto& file : kt::scene_files("derivations")) {
    const auto d = kinergy::emit::derive(kinergy::solve_file(file));
    for (const auto& b : d.blocks) {
      if (!b.sheet || b.sheet->size() < 2) continue;
      // the impulses of an impulse-momentum diagram (3 panels), the forces of a free-body diagram (2)
      const kd::Figure& f = b.sheet->panel(b.sheet->size() == 3 ? 1 : 0);
      if (b.title.find("Positions at") != std::string::npos || b.title.find("at its states") != std::string::npos) continue;
      std::set<std::string> bodies;
      for (const auto& sh : f.shapes())
        if (sh.owner.rfind("body ", 0) == 0) bodies.insert(sh.owner);
      for (const auto& sh : f.shapes()) {
        if (sh.kind != kd::Figure::Shape::Arrow || sh.ink != kd::Ink::Force) continue;
        ++arrows;
        const auto [tx, ty] = sh.pts[0];
        const bool ok = std::any_of(bodies.begin(), bodies.end(), [&](const std::string& o) { return on(f, o, tx, ty, 1e-3 * f.glyph()); });
        if (!ok) faults.push_back(file + ": " + b.title.substr(0, 40) + ": '" + sh.owner + "' starts at (" + std::to_string(tx) + ", " + std::to_string(ty) + "), off every body");
      }
    }
  }
  INFO(arrows << " arrows");
  for (auto& f : faults) UNSCOPED_INFO(f);
  CHECK(faults.empty());
  CHECK(arrows >= 150);
}

TEST_CASE("every impulse-momentum diagram draws its momenta and impulses to one scale, the exceptions said (issue 47)",
          "[draw][diagram][scale]") {
  // each arrow drawn to scale is as long as its size times the diagram's one scale (to 1 %); an
  // arrow that is not (too short, or a size no equation gives alone) is named in the caption
  int diagrams = 0, to_scale = 0;
  std::vector<std::string> faults;
  kt::each_figure([&](const std::string& file, int, const kinergy::emit::Block& b) {
    {
      if (b.sheet->size() != 3 || b.title.find("Impulse-momentum diagram") == std::string::npos) return;
      ++diagrams;
      if (b.title.find(b.sheet->note) == std::string::npos) faults.push_back(file + ": the caption does not say the scale");
      double ratio = 0;
      int off = 0;
      for (std::size_t i = 0; i < 3; ++i)
        for (const auto& s : b.sheet->panel(i).shapes()) {
          if (s.kind != kd::Figure::Shape::Arrow || (s.ink != kd::Ink::Force && s.ink != kd::Ink::Momentum)) continue;
          if (!std::isfinite(s.magnitude)) {
            ++off;
            continue;
          }
          const double r = std::hypot(s.pts[1].first - s.pts[0].first, s.pts[1].second - s.pts[0].second) / s.magnitude;
          ++to_scale;
          if (ratio == 0) ratio = r;
          else if (std::fabs(r - ratio) > 0.01 * ratio) faults.push_back(file + ": an arrow off the diagram's scale (" + std::to_string(r / ratio) + ")");
        }
      const bool said = b.sheet->note.find("drawn longer") != std::string::npos || b.sheet->note.find("direction only") != std::string::npos;
      if (off > 0 && !said) faults.push_back(file + ": " + std::to_string(off) + " arrows not to scale and not said: " + b.title);
      if (ratio > 0 && b.sheet->note.rfind("Momenta and impulses are drawn to one scale", 0) != 0) faults.push_back(file + ": no scale said: " + b.title);
    }
  });
  INFO(diagrams << " diagrams, " << to_scale << " arrows to scale");
  for (auto& f : faults) UNSCOPED_INFO(f);
  CHECK(faults.empty());
  CHECK(diagrams >= 30);
  CHECK(to_scale >= 100);
}

TEST_CASE("no two figures of a worked solution alike: one an earlier figure draws is said, not drawn again (issue 47)",
          "[draw][diagram][figures]") {
  // a figure is alike an earlier one when each of its panels is one of the earlier one's (the
  // same marks at the same places, the same strokes and words)
  int figures = 0;
  std::vector<std::string> faults;
  std::string last;
  std::vector<std::vector<std::string>> seen;
  kt::each_figure([&](const std::string& file, int k, const kinergy::emit::Block& b) {
    if (file != last) seen.clear(), last = file;
    ++figures;
    std::vector<std::string> prints;
    for (std::size_t i = 0; i < b.sheet->size(); ++i) prints.push_back(kinergy::emit::panel_print(b.sheet->panel(i)));
    for (std::size_t j = 0; j < seen.size(); ++j)
      if (std::all_of(prints.begin(), prints.end(), [&](const std::string& p) { return std::find(seen[j].begin(), seen[j].end(), p) != seen[j].end(); }))
        faults.push_back(file + ": figure " + std::to_string(k) + " is alike figure " + std::to_string(j + 1));
    seen.push_back(prints);
  });
  INFO(figures << " figures");
  for (auto& f : faults) UNSCOPED_INFO(f);
  CHECK(faults.empty());
  CHECK(figures >= 150);
}
