/// @file sweep.hpp  One scene solved over a grid of parameter values.
#pragma once
#include <string>
#include <vector>

#include "kinergy/scene/scene.hpp"

namespace kinergy::batch {

/// One swept parameter: `count` values evenly from `lo` to `hi` (both included), in the unit the
/// scene writes the parameter in. Written "NAME=LO..HI:COUNT" (`--set l=0.5..2:16`).
struct Range {
  std::string name;
  double lo = 0, hi = 0;
  int count = 0;
  std::string unit;  ///< the scene's unit of the parameter ("" for a pure number)
};

/// Read "NAME=LO..HI:COUNT" against the scene. @throws InputError naming what is wrong (the
/// form, a count below 2 or above 100 000, a parameter the scene does not have or gives no value).
Range parse_range(const std::string& text, const scene::SceneDef& def);

/// Every point of the grid (the ranges' Cartesian product, the last varying fastest), solved.
struct Sweep {
  std::vector<std::string> parameters;  ///< "l (m)"
  std::vector<std::string> results;     ///< "omega2 (rad/s)"
  struct Row {
    std::vector<double> at;      ///< the parameters' values
    std::vector<double> values;  ///< each result's value (NaN where it has none)
    std::string error;           ///< why this point has no solution ("" when it has)
  };
  std::vector<Row> rows;
};

/// @throws SceneError when the scene itself is bad (checked once, at its own values).
Sweep sweep(const scene::SceneDef& def, const std::vector<Range>& ranges);

/// The sweep as CSV (a header, then one row a point; an error in the last column) and as JSON.
std::string csv(const Sweep& s);
std::string json(const Sweep& s);

/// Each result against the first swept parameter (one curve per result and per value of the
/// others), by gnuplot into FILE.svg or FILE.png. @throws InputError when gnuplot fails.
void plot(const Sweep& s, const std::string& title, const std::string& file);

}  // namespace kinergy::batch
