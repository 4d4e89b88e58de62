/// @file sweep.hpp  One scene solved over a grid of parameter values.
#pragma once
#include <functional>
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
    /// How its values were had: "closed form" (a solution found elsewhere, shown to hold here),
    /// or "solved" (the scene solved at this point: the first point of its kind, a choice that
    /// changes near it, a double not accurate enough).
    std::string how;
  };
  std::vector<Row> rows;
  /// What the sweep did: points by closed form and solved one by one, and the sample of points
  /// solved in full (confirmed a second way) that the closed forms were checked against.
  struct Summary {
    std::size_t points = 0, closed = 0, solved = 0, failed = 0;
    std::size_t regions = 0;      ///< solutions found (each holds where its choices do)
    std::size_t confirmed = 0;    ///< sample points solved in full and compared
    double difference = 0;        ///< the largest relative difference at them
    std::string note;             ///< why every point was solved, when it was ("" otherwise)
  } summary;
};

/// How a sweep runs.
struct SweepOptions {
  /// Solve the scene at every point (no closed form carried between points).
  bool per_point = false;
  /// Points solved in full, each confirmed a second way (as `kinergy solve` does), and compared
  /// with the closed form's values to 1e-12: a disagreement is an error showing both.
  int samples = 8;
  bool confirm = true;
  /// Processes that solve points where no closed form is carried (--per-point, or a scene whose
  /// solution is a numeric root): each solves every jobs-th point, the rows coming back in order.
  int jobs = 1;
  /// Called now and then with (points done, points in all).
  std::function<void(std::size_t, std::size_t)> progress;
};

/// Every point, in order, to `row` as it is found (a large sweep is not held in memory). The
/// scene is solved once at its own values (a bad scene is refused once), then with the swept
/// parameters at a grid point, the choices of that solve traced (numeric/trace.hpp): wherever
/// every choice is shown to fall the same way (interval arithmetic over boxes of the grid), its
/// closed forms give the values, in doubles whose error bound holds them to 1e-13; elsewhere the
/// scene is solved at the point, and that solution is carried in turn.
/// @throws SceneError when the scene itself is bad, or a sample disagrees.
Sweep::Summary sweep_rows(const scene::SceneDef& def, const std::vector<Range>& ranges, const SweepOptions& options,
                          std::vector<std::string>& parameters, std::vector<std::string>& results,
                          const std::function<void(const Sweep::Row&)>& row);

/// The same, every row kept. @throws SceneError when the scene itself is bad.
Sweep sweep(const scene::SceneDef& def, const std::vector<Range>& ranges, const SweepOptions& options = {});

/// The sweep as CSV (a header, then one row a point: the parameters, the results, how, and an
/// error in the last column) and as JSON ({"parameters", "results", "rows", "summary"}).
std::string csv(const Sweep& s);
std::string json(const Sweep& s);
/// The same a row at a time, for a sweep that streams its rows (appended to `out`).
std::string csv_header(const std::vector<std::string>& parameters, const std::vector<std::string>& results);
void csv_row(const Sweep::Row& row, std::string& out);
std::string json_header(const std::vector<std::string>& parameters, const std::vector<std::string>& results);
void json_row(const Sweep::Row& row, bool first, std::string& out);
std::string json_footer(const Sweep::Summary& s);

/// Each result against the first swept parameter (one curve per result and per value of the
/// others, at most 12), by gnuplot into FILE.svg or FILE.png; with two parameters or more and over
/// 12 values of the second, a map of each result over the first two (colour and contour lines).
/// @throws InputError when gnuplot fails.
void plot(const Sweep& s, const std::string& title, const std::string& file);
/// The rows a plot of a streamed sweep keeps: at most 400 values of the first parameter, 200 of the
/// second, 8 of each other (evenly chosen, both ends among them), so that a plot of 10⁶ points is
/// drawn from at most 80 000.
class PlotRows {
public:
  explicit PlotRows(const std::vector<Range>& ranges);
  void add(const Sweep::Row& row);  ///< the sweep's next row, in order
  Sweep& rows() { return rows_; }   ///< set its parameters and results, then plot it
private:
  std::vector<std::size_t> counts_;
  std::vector<std::vector<bool>> keep_;
  std::size_t seen_ = 0;
  Sweep rows_;
};

/// @throws InputError when `file` is neither .svg nor .png (checked before a sweep runs).
void check_plot(const std::string& file);

}  // namespace kinergy::batch
