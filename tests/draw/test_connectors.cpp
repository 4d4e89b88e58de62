// Issue 28 (finding 2, the automated check's "every support and connector drawn"): what the
// kinematics imply is drawn — a cord from a drum to a hanging block, gears by their pitch circles
// in mesh, the incline a wheel rolls on, the cord a bob hangs from — and every effect of every
// derivation has a drawn element. Expected places are worked by hand from the scenes' own text.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "../support/helpers.hpp"
#include "../../src/draw/connectors.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/confirm/check.hpp"

namespace {

namespace kd = kinergy::draw;

struct Drawn {
  kinergy::Solution s;
  kd::At at;
  kd::Figure f;
  kd::detail::Implied imp;
};

Drawn drawn(const std::string& rel, int state) {
  Drawn d{kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/" + rel), {}, {}, {}};
  const auto params = kinergy::simulate::simulation_values(d.s);
  d.at = kd::state_values(d.s.model, d.s.branch.sol, params, state);
  d.f = kd::scene_at(d.s.model, d.s.branch.sol, params, state);
  d.imp = kd::detail::implied(d.s.model, d.at);
  return d;
}

int body_of(const kinergy::model::Model& m, const std::string& name) {
  for (std::size_t b = 0; b < m.bodies.size(); ++b)
    if (m.bodies[b].name == name) return static_cast<int>(b);
  return -1;
}

// the shapes of `owner` that are lines lying along the line through (px, py) along (ux, uy)
int lines_along(const kd::Figure& f, const std::string& owner, double px, double py, double ux, double uy, double tol) {
  int n = 0;
  for (const auto& sh : f.shapes()) {
    if (sh.owner != owner || sh.kind != kd::Figure::Shape::Line) continue;
    bool on = true;
    for (auto [x, y] : sh.pts) on = on && std::fabs((x - px) * uy - (y - py) * ux) < tol;
    n += on;
  }
  return n;
}

}  // namespace

TEST_CASE("every effect and every relation of every derivation has a drawn element at every state it fixes", "[draw][connectors]") {
  int states = 0;
  std::vector<std::string> faults;
  for (const auto& file : kt::scene_files("derivations")) {
    kinergy::Solution s = kinergy::solve_file(file);
    const auto& m = s.model;
    const auto params = kinergy::simulate::simulation_values(s);
    for (std::size_t st = 0; st < m.states.size(); ++st) {
      kd::At at;
      try {
        at = kd::state_values(m, s.branch.sol, params, static_cast<int>(st));
      } catch (const kinergy::SceneError&) {
        continue;  // a state that leaves a coordinate free is not drawn (stderr says so)
      }
      ++states;
      const kd::Figure f = kd::scene_at(m, s.branch.sol, params, static_cast<int>(st));
      const std::string where = file + " state " + m.states[st].name + ": ";
      auto owns = [&](const std::string& owner) {
        return std::any_of(f.shapes().begin(), f.shapes().end(), [&](const kd::Figure::Shape& sh) { return sh.owner == owner; });
      };
      for (const auto& b : m.bodies)
        if (!owns("body " + b.name)) faults.push_back(where + "body '" + b.name + "' not drawn");
      for (const auto& e : m.effects)
        if (!owns(e.name)) faults.push_back(where + "effect '" + e.name + "' not drawn");
      // each `constraints:` relation accounted for by a connector drawn (a cord, a mesh, a surface
      // or guide, a hanging cord), not by the dashed stand-in
      for (const auto& l : kd::detail::implied(m, at).unexplained)
        faults.push_back(where + "relation " + std::to_string(l.k + 1) + " has no connector");
    }
  }
  INFO(states << " states drawn");
  for (auto& f : faults) UNSCOPED_INFO(f);
  CHECK(faults.empty());
  CHECK(states >= 120);
}

TEST_CASE("the Atwood machine: each block hangs from a cord tangent to the pulley's rim", "[draw][connectors]") {
  // pulley: a disk of radius r = 0.2 m about O = (0, 0); blockA at x = r, blockB at x = −r, both
  // moving vertically: the cords leave the rim at (±r, 0) and run straight down to the blocks
  const auto d = drawn("derivations/energy/atwood_pulley.yaml", 0);
  const auto& m = d.s.model;
  REQUIRE(d.imp.cords.size() == 2);
  for (const auto& c : d.imp.cords) {
    CHECK(c.drum == body_of(m, "pulley"));
    CHECK(c.r == Approx(0.2));
    CHECK(c.cx == Approx(0).margin(1e-12));
    CHECK(c.ty == Approx(0).margin(1e-12));
    CHECK(c.tx == Approx(c.body == body_of(m, "blockA") ? 0.2 : -0.2));
  }
  // drawn: a vertical cord line from each tangent point down to its block
  CHECK(lines_along(d.f, "cord", 0.2, 0, 0, 1, 1e-9) == 1);
  CHECK(lines_along(d.f, "cord", -0.2, 0, 0, 1, 1e-9) == 1);
  // the pulley's axle: a post down to ground below the rim, none inside the wheel
  for (const auto& sh : d.f.shapes())
    if (sh.owner == "axle" && sh.kind == kd::Figure::Shape::Line && sh.ink == kd::Ink::Support)
      for (auto [x, y] : sh.pts) CHECK((std::hypot(x, y) >= 0.2 || std::fabs(x) < 1e-12));
  CHECK(d.imp.unexplained.empty());
}

TEST_CASE("a hoist's drum known by its radius of gyration: drawn with its rim at the cord's radius", "[draw][connectors]") {
  // power_hoist: drum of gyration kd, the load at x = r moving with r φ: the cord leaves the drum
  // at (r, 0), so the drum is a wheel of radius r = 0.25 m (the scene's r)
  const auto d = drawn("derivations/energy/power_hoist.yaml", 0);
  const int drum = body_of(d.s.model, "drum");
  REQUIRE(d.imp.rim.count(drum) == 1);
  double rv = 0;
  for (const auto& p : d.s.model.params)
    if (p.name == "r") rv = GiNaC::ex_to<GiNaC::numeric>(p.value->evalf()).to_double();
  CHECK(d.imp.rim.at(drum) == Approx(rv));
  CHECK(d.f.has_circle(0, 0, rv));
}

TEST_CASE("meshed gears known by their radii of gyration: pitch circles of radii rA and rB, touching", "[draw][connectors]") {
  // rA φA + rB φB = 0 with centres rA + rB apart: pitch radii rA = 0.15 m and rB = 0.3 m
  const auto d = drawn("derivations/energy/meshed_gears.yaml", 0);
  REQUIRE(d.imp.meshes.size() == 1);
  CHECK(d.imp.meshes[0].ra == Approx(0.15));
  CHECK(d.imp.meshes[0].rb == Approx(0.3));
  CHECK(d.f.has_circle(0, 0, 0.15));
  CHECK(d.f.has_circle(0.45, 0, 0.3));
  CHECK(d.imp.unexplained.empty());
}

TEST_CASE("a disk rolling down an incline: the incline drawn through its contact point, hatched below", "[draw][connectors]") {
  // G = (x cos β + r sin β, −x sin β + r cos β), so the contact point is P = G − r (sin β, cos β)
  // and the incline runs along (cos β, −sin β) through it; r = 0.15 m, β = 20°
  const auto d = drawn("derivations/momentum/disk_rolls_incline_time.yaml", 0);
  const auto& m = d.s.model;
  const int disk = body_of(m, "disk");
  const double b = 20 * M_PI / 180, r = 0.15, gx = d.at(m.bodies[disk].x), gy = d.at(m.bodies[disk].y);
  const double px = gx - r * std::sin(b), py = gy - r * std::cos(b);
  CHECK(lines_along(d.f, "support", px, py, std::cos(b), -std::sin(b), 1e-9) == 1);
  // its hatching on the side away from the disk
  int hatch = 0;
  for (const auto& sh : d.f.shapes()) {
    if (sh.owner != "support" || sh.kind != kd::Figure::Shape::Line) continue;
    for (auto [x, y] : sh.pts) CHECK((x - px) * std::sin(b) + (y - py) * std::cos(b) <= 1e-9);
    ++hatch;
  }
  CHECK(hatch > 5);
}

TEST_CASE("a pendulum's bob with no pin: a cord from the fixed point it swings about", "[draw][connectors]") {
  // pendulum_strikes_block: the ball at (l sin φ, −l cos φ) keeps l from O = (0, 0)
  const auto d = drawn("derivations/impact/pendulum_strikes_block.yaml", 0);
  const auto& m = d.s.model;
  REQUIRE(d.imp.hangs.size() == 1);
  CHECK(d.imp.hangs[0].body == body_of(m, "ball"));
  CHECK(d.imp.hangs[0].cx == Approx(0).margin(1e-12));
  CHECK(d.imp.hangs[0].cy == Approx(0).margin(1e-12));
  const int ball = body_of(m, "ball");
  const double bx = d.at(m.bodies[ball].x), by = d.at(m.bodies[ball].y);
  CHECK(lines_along(d.f, "hang", 0, 0, bx / std::hypot(bx, by), by / std::hypot(bx, by), 1e-9) == 1);
  // a ball at the end of a rod pinned at O keeps its distance from O too, but the rod holds it: no cord
  CHECK(drawn("derivations/kinetics/ball_on_light_rod.yaml", 0).imp.hangs.empty());
  // the block it strikes rests on a floor (its weight presses it down): hatched below it
  bool floor = false;
  for (const auto& l : d.imp.lines) floor = floor || (l.body == body_of(m, "block") && std::fabs(l.uy) < 1e-12);
  CHECK(floor);
}

TEST_CASE("a torsion spring is drawn round the pin its body turns about, not round the mass centre", "[draw][connectors]") {
  // torsion_spring_bar: the bar turns about its end O (a pin to the fixed point O); the coil is
  // an arc of radius one glyph about O, half a bar's length from the bar's centre
  const auto d = drawn("derivations/energy/torsion_spring_bar.yaml", 0);
  const auto& O = d.s.model.fixed_points.at("O");
  const double ox = d.at(O.first), oy = d.at(O.second), g = d.f.glyph();
  int points = 0;
  for (const auto& sh : d.f.shapes()) {
    if (sh.owner != "coil") continue;
    for (auto [x, y] : sh.pts) {
      CHECK(std::hypot(x - ox, y - oy) == Approx(g).epsilon(1e-9));
      ++points;
    }
  }
  CHECK(points > 10);
}

TEST_CASE("drawn_as: the bouncing ball, a particle, drawn as a circle of its radius r = 0.03 m", "[draw]") {
  // the scene gives the ball's radius (drawn_as: {circle: r}); its centre at y = h + r at state 1
  const auto d = drawn("derivations/impact/bouncing_ball.yaml", 0);
  CHECK(d.f.has_circle(0, 1.2 + 0.03, 0.03));
  // and no block: no polygon among the ball's shapes
  for (const auto& sh : d.f.shapes())
    if (sh.owner == "body ball") CHECK(sh.kind != kd::Figure::Shape::Polygon);
}

TEST_CASE("a ladder's ends kept on lines by the coordinates: the wall and the track drawn, hatched away from the rod", "[draw][connectors]") {
  // sliding_rod at state 2 (theta = 30 deg, l = 1.2 m): G = (l/2 cos, -l/2 sin) = (0.5196, -0.3);
  // B = G + R(theta)(-l/2, 0) = (0, -0.6) keeps to x = 0, A = (l cos, 0) = (1.0392, 0) to y = 0. The
  // rod lies to the right of B's line and below A's: the wall hatched left, A's track above
  const auto d = drawn("derivations/energy/sliding_rod.yaml", 1);
  REQUIRE(d.imp.points.size() == 2);
  for (const auto& p : d.imp.points) {
    if (p.point == "B") {
      CHECK(p.px == Approx(0).margin(1e-12));
      CHECK(p.py == Approx(-0.6));
      CHECK(std::fabs(p.ux) == Approx(0).margin(1e-12));
      CHECK(p.nx == Approx(-1));
    } else {
      CHECK(p.point == "A");
      CHECK(p.px == Approx(1.2 * std::cos(M_PI / 6)));
      CHECK(p.py == Approx(0).margin(1e-12));
      CHECK(p.ny == Approx(1));
    }
  }
  CHECK(lines_along(d.f, "support", 0, -0.6, 0, 1, 1e-9) == 1);
  CHECK(lines_along(d.f, "support", 1.0392, 0, 1, 0, 1e-9) == 1);
}

TEST_CASE("curved arrows round one hub: each at a radius of its own, clear of the others", "[draw][connectors]") {
  // three arrows asked at 1.0, 1.2 and 1.2 glyphs round the origin, and one round another point:
  // 1.0, then 1.4 (1.2 is within 0.4 of 1.0), then 1.8; the other centre's keeps its 1.2
  kinergy::draw::Figure f;
  f.set_glyph(1);
  CHECK(f.ring(0, 0, 1.0) == Approx(1.0));
  CHECK(f.ring(0, 0, 1.2) == Approx(1.4));
  CHECK(f.ring(0, 0, 1.2) == Approx(1.8));
  CHECK(f.ring(5, 0, 1.2) == Approx(1.2));
  // many at one radius: each 0.4 further out, and it ends (a ring just 0.4 out is clear)
  double last = 0;
  for (int i = 0; i < 50; ++i) last = f.ring(0, 0, 1.0);
  CHECK(last == Approx(1.8 + 0.4 * 50));
}
