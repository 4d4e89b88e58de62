// The inertia shapes: centroidal moments of inertia Ī of the textbook's bodies.
#include "kinergy/model/inertia.hpp"

#include <stdexcept>

#include "kinergy/scene/scene.hpp"

namespace kinergy::model {

using GiNaC::ex;
using GiNaC::pow;
using Sizes = std::vector<ex>;

const std::vector<InertiaShape>& inertia_shapes() {
  static const std::vector<InertiaShape> table = {
      {"slender_rod", 1, false, "a slender rod", [](const ex& m, const Sizes& a) { return m * pow(a[0], 2) / 12; }, Outline::Bar},  // m L²/12
      {"disk", 1, false, "a disk", [](const ex& m, const Sizes& a) { return m * pow(a[0], 2) / 2; }, Outline::Round},          // m r²/2
      {"cylinder", 1, false, "a cylinder", [](const ex& m, const Sizes& a) { return m * pow(a[0], 2) / 2; }, Outline::Round},      // m r²/2
      {"ring", 1, false, "a ring", [](const ex& m, const Sizes& a) { return m * pow(a[0], 2); }, Outline::Round},              // m r²
      {"hoop", 1, false, "a hoop", [](const ex& m, const Sizes& a) { return m * pow(a[0], 2); }, Outline::Round},              // m r²
      {"plate", 2, false, "a rectangular plate",
       [](const ex& m, const Sizes& a) { return m * (pow(a[0], 2) + pow(a[1], 2)) / 12; }, Outline::Rect},          // m (a² + b²)/12
      // a thin plate turning about an axis in its own plane, seen edge-on (a trapdoor, a plate
      // falling flat): about a centreline, b its width across the axis; about a diameter of a
      // circular plate of radius r. About an edge: pin it there (Ī + m (b/2)² = m b²/3)
      {"plate_edge_on", 1, false, "a rectangular plate turning about a centreline in its plane",
       [](const ex& m, const Sizes& a) { return m * pow(a[0], 2) / 12; }, Outline::EdgeOn, 1},                      // m b²/12
      {"disk_edge_on", 1, false, "a circular plate turning about a diameter",
       [](const ex& m, const Sizes& a) { return m * pow(a[0], 2) / 4; }, Outline::EdgeOn, 2},                       // m r²/4
      {"sphere", 1, false, "a sphere", [](const ex& m, const Sizes& a) { return 2 * m * pow(a[0], 2) / 5; }, Outline::Round},   // 2 m r²/5
      {"spherical_shell", 1, false, "a spherical shell",
       [](const ex& m, const Sizes& a) { return 2 * m * pow(a[0], 2) / 3; }, Outline::Round},                       // 2 m r²/3
      {"gyration", 1, false, "given radius of gyration", [](const ex& m, const Sizes& a) { return m * pow(a[0], 2); }, Outline::Gyration},          // m k²
      {"centroidal", 1, true, "given centroidal moment of inertia", [](const ex&, const Sizes& a) { return a[0]; }, Outline::Dot},                       // Ī given
      {"particle", 0, false, "", [](const ex&, const Sizes&) { return ex(0); }, Outline::Dot},
  };
  return table;
}

const InertiaShape& inertia_shape(const std::string& name) {
  for (auto& s : inertia_shapes())
    if (s.name == name) return s;
  throw std::logic_error("inertia shape '" + name + "' is not in the table");
}

}  // namespace kinergy::model

namespace kinergy::scene {

const std::vector<std::pair<std::string, int>>& inertia_shapes() {
  static const std::vector<std::pair<std::string, int>> names = [] {
    std::vector<std::pair<std::string, int>> n;
    for (auto& s : model::inertia_shapes()) n.push_back({s.name, s.sizes});
    return n;
  }();
  return names;
}

}  // namespace kinergy::scene
