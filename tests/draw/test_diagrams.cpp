// Issue 28 (findings 6 and 8): the impulse–momentum diagrams' arrows on their bodies, named as
// the equations name them.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "../support/helpers.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/emit/latex.hpp"
#include "kinergy/problem.hpp"

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
