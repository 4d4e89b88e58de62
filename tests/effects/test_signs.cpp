// One sign rule for every support and connection (issue 44, item 7; docs/scene-format.md, "Signs
// of forces"): a force is reported on its first party that is a body; a surface's N is positive
// when it pushes; a force along a line (a constraint effect's F, a guide's N) is positive up, or
// to the right along a horizontal line — however the relation or the line is written. Expected
// values by hand in the comments.
#include <catch2/catch.hpp>

#include <cmath>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"

using kt::derivation;
using kt::edit;
using kt::solve_text;

namespace {
double value(const std::string& text, const std::string& name) { return kt::result(solve_text(text), name).si->to_double(); }
}  // namespace

TEST_CASE("a rolling disk's friction is counted up the incline, however its relation and parties are written", "[effects][signs]") {
  // By hand: m a = m g sin(beta) - F, (1/2) m r^2 alpha = -F r... with F up the slope and
  // a = -r alpha: F = m g sin(beta)/3 = 8.947 N, positive (up the incline)
  const std::string disk = derivation("kinetics/disk_rolls_incline_friction.yaml");
  const double F = 8 * 9.81 * std::sin(20 * M_PI / 180) / 3;
  CHECK(value(disk, "F1") == Approx(F).epsilon(1e-12));
  const std::string flipped = edit(disk, "constraint: \"x + r*phi = 0\"", "constraint: \"-x - r*phi = 0\"");
  CHECK(value(flipped, "F1") == Approx(F).epsilon(1e-12));
  CHECK(value(edit(flipped, "between: [disk, O]", "between: [O, disk]"), "F1") == Approx(F).epsilon(1e-12));
  CHECK(value(edit(disk, "constraint: \"x + r*phi = 0\"", "constraint: \"r*phi = -x\""), "F1") == Approx(F).epsilon(1e-12));
}

TEST_CASE("a pin between two bodies: its impulse is the one on its first party, whichever body the analysis takes", "[effects][signs]") {
  // By hand (collar_rod_pin_reaction): the collar's momentum along x, M v = J on it, with
  // v = m sqrt(3 g L/((4M + m)(M + m))); the rod takes -J, so its own balance gives the same J
  const std::string collar = derivation("momentum/collar_rod_pin_reaction.yaml");
  const double M = 3, m = 2, L = 1, g = 9.81, J = M * m * std::sqrt(3 * g * L / ((4 * M + m) * (M + m)));
  CHECK(value(collar, "J") == Approx(J).epsilon(1e-12));
  const std::string rod = edit(edit(collar, "along: x, bodies: [collar]}\n  - energy", "along: x, bodies: [rod]}\n  - energy"),
                               "energy: {from: 1, to: 2, bodies: [collar]}", "energy: {from: 1, to: 2, bodies: [rod]}");
  CHECK(value(rod, "J") == Approx(J).epsilon(1e-12));
  CHECK(value(rod, "F") == Approx(3 * M * m * g / (4 * M + m)).epsilon(1e-12));
  // written the other way round, the pin's first party is the rod: -J
  CHECK(value(edit(collar, "pin: [collar, rod.A]", "pin: [rod.A, collar]"), "J") == Approx(-J).epsilon(1e-12));
}

TEST_CASE("a contact between two bodies: impulse_x, impulse_y on its first party, its size J positive", "[effects][signs][impact]") {
  // By hand (free_rod_struck_by_puck): J = (1 + e) m M v0/(M + 4 m) up on the rod, down on the puck
  std::string puck = derivation("impact/free_rod_struck_by_puck.yaml");
  puck = edit(puck, "find:\n", "find:\n  Jy: {value: \"impulse_y(hit, before, after)\", unit: N*s}\n");
  const double J = 1.7 * 0.4 * 2 * 8 / (2 + 1.6);
  CHECK(value(puck, "J") == Approx(J).epsilon(1e-12));
  CHECK(value(puck, "Jy") == Approx(-J).epsilon(1e-12));  // on the puck
  const std::string rod_first = edit(puck, "contact: [puck, rod.B], normal: [0, 1]", "contact: [rod.B, puck], normal: [0, -1]");
  CHECK(value(rod_first, "J") == Approx(J).epsilon(1e-12));
  CHECK(value(rod_first, "Jy") == Approx(J).epsilon(1e-12));  // on the rod
}

TEST_CASE("a vertical guide's N is counted to the right, whichever way its line is written", "[effects][signs][track]") {
  // rod_leaves_wall at its release: the wall pushes the rod's top to the right (N > 0); written as
  // a guide along [0, 1] (normal k x t = [-1, 0]) or [0, -1], N is the same number
  std::string rod = derivation("kinetics/rod_leaves_wall.yaml");
  rod = edit(edit(rod, "  - kinetics: {at: 2}\n", "  - kinetics: {at: 2}\n  - kinetics: {at: 1}\n"), "find:\n", "find:\n  Nw: {value: N(wall)@1, unit: N}\n");
  const double N = value(rod, "Nw");
  CHECK(N > 0);
  CHECK(value(edit(rod, "along: [0, 1]}, pushes: right}", "along: [0, 1]}, holds: both}"), "Nw") == Approx(N).epsilon(1e-12));
  CHECK(value(edit(rod, "along: [0, 1]}, pushes: right}", "along: [0, -1]}, holds: both}"), "Nw") == Approx(N).epsilon(1e-12));
}
