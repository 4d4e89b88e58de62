// What the coordinates and constraints imply about how the bodies are held and joined, for the
// scene's drawing (figure.cpp): a cord from a drum to a hanging block, two wheels in mesh, the
// surface a wheel rolls on, the floor a block is pressed on, the guide a collar slides on, the
// cord a pendulum's bob hangs from. The scene says these only through its kinematics
// (`position: [r, r*phi - a]`, `constraints: [x + r*phi = 0]`); a textbook draws them.
#pragma once
#include <cstddef>
#include <map>
#include <vector>

#include "kinergy/draw/figure.hpp"

namespace kinergy::draw::detail {

struct Implied {
  /// A cord from the tangent point (tx, ty) of a drum (body `drum`, centre (cx, cy), radius r) to
  /// the centre of body `body`, which moves along the cord.
  struct Cord {
    int drum, body;
    double cx, cy, r, tx, ty;
  };
  /// Two wheels turning about fixed centres in mesh: their pitch circles' radii.
  struct Mesh {
    int a, b;
    double ra, rb;
  };
  /// A body whose centre keeps to the line along (ux, uy), held there (draw::line_support): by a
  /// surface at `offset` from its centre (a wheel rolling on it: the foot Ḡ − offset n̂, n̂ = k × u),
  /// or, at offset 0, by a surface its weight presses it onto or a guide — where loads press it
  /// across the line or other bodies move it.
  struct OnLine {
    int body;
    double ux, uy, offset;
  };
  /// A body whose centre keeps a fixed distance from the fixed point (cx, cy): a bob on a cord.
  struct Hang {
    int body;
    double cx, cy;
  };
  std::vector<Cord> cords;
  std::vector<Mesh> meshes;
  std::vector<OnLine> lines;
  std::vector<Hang> hangs;
  /// A named point of a body that the coordinates keep to a fixed line along (ux, uy) (a ladder's
  /// foot on the floor, its top on the wall), held by nothing the scene names: a surface through it,
  /// its ground on the side (nx, ny) away from the body's centre (none: a slot, both sides).
  struct PointOnLine {
    int body;
    std::string point;
    double px, py, ux, uy, nx, ny;
  };
  std::vector<PointOnLine> points;
  /// A body known only by its radius of gyration: the largest radius a cord or a mesh gives it.
  std::map<int, double> rim;
  /// A `constraints:` relation no connector accounts for: its index in the model's constraints,
  /// and the bodies it moves.
  struct Loose {
    std::size_t k;
    std::vector<int> bodies;
  };
  std::vector<Loose> unexplained;
};

/// The sum of the given loads on body b across (nx, ny) at `at` (its weight, a push, a spring's
/// pull), and the sum of their sizes; with `weight`, of its weight alone (the loads a textbook
/// writes W).
std::pair<double, double> pressing(const model::Model& m, const At& at, int b, double nx, double ny, bool weight);

/// The connectors implied at the values `at` (a state's coordinates and rates, parameters).
Implied implied(const model::Model& m, const At& at);

/// Draw them, for the bodies in `bodies` (all when null), owned by "cord", "mesh", "support",
/// "hang" and "constraint k" (a relation no connector accounts for, drawn as a dashed
/// link between its bodies).
void draw_implied(const model::Model& m, const At& at, const Implied& imp, Figure& f, const std::vector<int>* bodies);

}  // namespace kinergy::draw::detail
