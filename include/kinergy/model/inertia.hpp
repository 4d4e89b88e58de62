/// @file inertia.hpp  The inertia shapes a body may name: the one table of shapes.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace kinergy::model {

/// How a body of that shape is drawn (src/draw): a bar of length a[0] along its x axis, a round
/// body of radius a[0] with a line showing its angle, a dashed circle of its radius of gyration
/// a[0] (its true outline unknown), an a[0] × a[1] rectangle, or a dot.
/// How a shape is drawn: Bar a line of its first size; EdgeOn a plate seen edge-on (turning about
/// an axis in its plane), a thick line `span` times its first size long.
enum class Outline { Bar, Round, Gyration, Rect, Dot, EdgeOn };

struct InertiaShape {
  std::string name;
  int sizes = 1;       ///< how many sizes it takes (0: written alone, e.g. `particle`)
  bool given = false;  ///< its one argument is Ī itself (kg·m²), not a length
  std::string words;   ///< in a derivation's text: "a slender rod" ("" for none)
  /// Ī from the mass and the sizes
  std::function<GiNaC::ex(const GiNaC::ex& m, const std::vector<GiNaC::ex>& a)> inertia;
  Outline outline = Outline::Dot;
  double span = 1;  ///< EdgeOn: its drawn length over its first size (2 for a circular plate's radius)
};

/// The table of shapes (src/model/inertia.cpp), in the order messages list them.
const std::vector<InertiaShape>& inertia_shapes();
/// The shape of that name. @pre the name is in the table (the scene checked it).
const InertiaShape& inertia_shape(const std::string& name);

}  // namespace kinergy::model
