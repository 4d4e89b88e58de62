// One scene solved over a grid of parameter values: CSV, JSON and a gnuplot plot.
#include "kinergy/app/app.hpp"
#include "kinergy/batch/sweep.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

#include "kinergy/common/error.hpp"
#include "kinergy/common/interrupt.hpp"
#include "kinergy/common/markup.hpp"
#include "kinergy/common/process.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/units/units.hpp"

namespace kinergy::batch {

namespace {

/// v to 15 significant digits (as printf's %.15g), appended; nothing for NaN.
void number(double v, std::string& out) {
  if (std::isnan(v)) return;
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 15);
  out.append(buf, r.ptr);
}

std::string number(double v) {
  std::string s;
  number(v, s);
  return s;
}

std::string quoted(const std::string& t) {
  std::string q = "\"";
  for (char c : t) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

Range parse_range(const std::string& text, const scene::SceneDef& def) {
  const std::string form = "write NAME=LO..HI:COUNT, e.g. --set l=0.5..2:16 (in the unit the scene writes the parameter in)";
  Range r;
  const std::size_t eq = text.find('='), dots = text.find(".."), colon = text.rfind(':');
  if (eq == std::string::npos || dots == std::string::npos || colon == std::string::npos || !(eq < dots && dots < colon))
    throw InputError("'" + text + "' is not a range of a parameter", form);
  r.name = text.substr(0, eq);
  auto read = [&](const std::string& s, const std::string& what) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != s.size() || !std::isfinite(v)) throw InputError("the " + what + " of '" + text + "' is not a number", form);
    return v;
  };
  r.lo = read(text.substr(eq + 1, dots - eq - 1), "start");
  r.hi = read(text.substr(dots + 2, colon - dots - 2), "end");
  const double count = read(text.substr(colon + 1), "count");
  if (count != std::floor(count) || count < 2 || count > 100000)
    throw InputError("the count of '" + text + "' is not a whole number from 2 to 100000", form);
  r.count = static_cast<int>(count);
  const scene::ParameterDef* p = &app::parameter(def, r.name, "sweep");
  units::Quantity q;
  try {
    q = units::parse_quantity(p->value.s);
  } catch (const InputError&) {
    throw InputError("parameter '" + r.name + "' has no value to sweep", "sweep a parameter written with a value, such as 'l: 1.2 m'");
  }
  if (!q.has_number) throw InputError("parameter '" + r.name + "' has no value to sweep", "sweep a parameter written with a value, such as 'l: 1.2 m'");
  r.unit = q.unit.text;
  // inside the range the scene gives the parameter (`in: [lo, hi]`), where it gives one: its
  // closed forms are carried to every point without the scene's own check of the value
  if (p->in) {
    try {
      const double f = GiNaC::ex_to<GiNaC::numeric>(q.unit.factor.evalf()).to_double();
      const double lo = GiNaC::ex_to<GiNaC::numeric>(units::parse_quantity(p->in->first.s).si.evalf()).to_double(),
                   hi = GiNaC::ex_to<GiNaC::numeric>(units::parse_quantity(p->in->second.s).si.evalf()).to_double();
      if (std::min(r.lo, r.hi) * f < lo * (1 - 1e-15) - 1e-300 || std::max(r.lo, r.hi) * f > hi * (1 + 1e-15) + 1e-300)
        throw InputError("'" + text + "' leaves the range the scene gives '" + r.name + "', in: [" + p->in->first.s + ", " + p->in->second.s + "]",
                         "sweep '" + r.name + "' inside that range, or widen it in the scene");
    } catch (const InputError&) {
      throw;
    } catch (const std::exception&) {
      // (a range the scene cannot read is refused where the scene is read)
    }
  }
  return r;
}

std::string csv_header(const std::vector<std::string>& parameters, const std::vector<std::string>& results) {
  std::string out;
  for (auto& p : parameters) out += quoted(p) + ",";
  for (auto& r : results) out += quoted(r) + ",";
  return out + "\"how\",\"error\"\n";
}

void csv_row(const Sweep::Row& row, std::string& out) {
  for (double v : row.at) number(v, out), out += ',';
  for (double v : row.values) number(v, out), out += ',';
  out += row.how.empty() ? std::string() : quoted(row.how);
  out += ',';
  if (!row.error.empty()) out += quoted(row.error);
  out += '\n';
}

std::string csv(const Sweep& s) {
  std::string out = csv_header(s.parameters, s.results);
  for (auto& row : s.rows) csv_row(row, out);
  return out;
}

std::string json_header(const std::vector<std::string>& parameters, const std::vector<std::string>& results) {
  std::string out = "{\"parameters\": [";
  for (std::size_t i = 0; i < parameters.size(); ++i) out += (i ? ", " : "") + json_quote(parameters[i]);
  out += "], \"results\": [";
  for (std::size_t i = 0; i < results.size(); ++i) out += (i ? ", " : "") + json_quote(results[i]);
  return out + "], \"rows\": [";
}

void json_row(const Sweep::Row& row, bool first, std::string& out) {
  auto list = [&](const std::vector<double>& v) {
    out += '[';
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i) out += ", ";
      if (std::isnan(v[i])) out += "null";
      else number(v[i], out);
    }
    out += ']';
  };
  out += first ? "\n  {\"at\": " : ",\n  {\"at\": ";
  list(row.at);
  out += ", \"values\": ";
  list(row.values);
  out += ", \"how\": " + json_quote(row.how) + ", \"error\": " + (row.error.empty() ? std::string("null") : json_quote(row.error)) + "}";
}

std::string json_footer(const Sweep::Summary& s) {
  std::ostringstream os;
  os << "\n], \"summary\": {\"points\": " << s.points << ", \"closed_form\": " << s.closed << ", \"solved\": " << s.solved
     << ", \"without_solution\": " << s.failed << ", \"solutions\": " << s.regions << ", \"confirmed_samples\": " << s.confirmed
     << ", \"largest_difference\": " << std::setprecision(3) << s.difference << ", \"note\": " << json_quote(s.note) << "}}\n";
  return os.str();
}

std::string json(const Sweep& s) {
  std::string out = json_header(s.parameters, s.results);
  for (std::size_t i = 0; i < s.rows.size(); ++i) json_row(s.rows[i], i == 0, out);
  return out + json_footer(s.summary);
}

void check_plot(const std::string& file) {
  const std::string ext = std::filesystem::path(file).extension().string();
  if (ext != ".svg" && ext != ".png") throw InputError("the plot '" + file + "' is neither .svg nor .png", "name the plot FILE.svg or FILE.png");
}

namespace {

/// Distinct values of parameter i over the rows, in order.
std::vector<double> distinct(const Sweep& s, std::size_t i) {
  std::vector<double> v;
  for (auto& row : s.rows) v.push_back(row.at[i]);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

std::string gp_text(std::string t) {
  for (char& c : t)
    if (c == '"') c = '\'';
  return t;
}

/// A map of each result over the first two parameters (the others at their first values):
/// colour, contour lines and their values. Data: one block of rows for each value of the first.
std::string map_plot(const Sweep& s, const std::string& title, std::ostringstream& data) {
  std::vector<double> fixed;
  std::string at;
  for (std::size_t i = 2; i < s.parameters.size(); ++i) {
    fixed.push_back(distinct(s, i).front());
    at += (at.empty() ? ", at " : ", ") + s.parameters[i] + " = " + number(fixed.back());
  }
  std::map<double, std::map<double, const Sweep::Row*>> grid;
  for (auto& row : s.rows)
    if (std::equal(fixed.begin(), fixed.end(), row.at.begin() + 2)) grid[row.at[0]][row.at[1]] = &row;
  for (auto& [x, column] : grid) {
    for (auto& [y, row] : column) {
      data << number(x) << " " << number(y);
      for (double v : row->values) data << " " << (std::isnan(v) ? std::string("NaN") : number(v));
      data << "\n";
    }
    data << "\n";
  }
  const auto xs = distinct(s, 0), ys = distinct(s, 1);
  std::ostringstream gp;
  gp << "set multiplot layout 1," << std::min<std::size_t>(s.results.size(), 3) << " title \"" << gp_text(title + at) << "\"\n"
     << "set view map\nset contour base\nset cntrparam levels auto 8\nset palette rgbformulae 33,13,10\n"
     << "set cntrlabel start 20 interval " << std::max<std::size_t>(40, xs.size() / 3) << "\n"
     << "set style textbox opaque noborder\nunset key\nset xlabel \"" << gp_text(s.parameters[0]) << "\"\nset ylabel \""
     << gp_text(s.parameters[1]) << "\"\nset xrange [" << number(xs.front()) << ":" << number(xs.back()) << "]\nset yrange ["
     << number(ys.front()) << ":" << number(ys.back()) << "]\n";
  for (std::size_t r = 0; r < s.results.size() && r < 3; ++r) {
    const std::string c = std::to_string(r + 3);
    gp << "set title \"" << gp_text(s.results[r]) << " (blank: no solution)\"\n"
       << "splot 'sweep.dat' using 1:2:" << c << " with pm3d notitle, '' using 1:2:" << c
       << " with lines nosurface notitle, '' using 1:2:" << c << " with labels boxed nosurface notitle\n";
  }
  return gp.str() + "unset multiplot\n";
}

/// Each result against the first parameter: one curve for each value of the others (at most
/// 12 of them, evenly chosen). Data: one block (gnuplot's index) a curve.
std::string line_plot(const Sweep& s, std::ostringstream& data) {
  std::map<std::vector<double>, std::vector<const Sweep::Row*>> curves;
  for (auto& row : s.rows) curves[std::vector<double>(row.at.begin() + 1, row.at.end())].push_back(&row);
  std::vector<std::string> names;
  std::size_t longest = 0;
  for (auto& [others, rows] : curves) {
    std::string name;
    for (std::size_t i = 0; i < others.size(); ++i) name += (i ? ", " : "") + s.parameters[i + 1] + " = " + number(others[i]);
    names.push_back(name);
    longest = std::max(longest, rows.size());
    for (auto* row : rows) {
      data << number(row->at[0]);
      for (double v : row->values) data << " " << (std::isnan(v) ? std::string("NaN") : number(v));
      data << "\n";
    }
    data << "\n\n";
  }
  std::ostringstream gp;
  gp << "set grid\nset key top right\nset xlabel \"" << gp_text(s.parameters[0]) << "\"\nplot ";
  const std::size_t shown = std::min<std::size_t>(names.size(), 12);
  bool first = true;
  for (std::size_t k = 0; k < shown; ++k) {
    const std::size_t c = shown == 1 ? 0 : k * (names.size() - 1) / (shown - 1);
    for (std::size_t r = 0; r < s.results.size(); ++r) {
      const std::string label = s.results[r] + (names[c].empty() ? "" : ", " + names[c]);
      gp << (first ? "" : ", ") << "'sweep.dat' index " << c << " using 1:" << r + 2 << " with " << (longest > 50 ? "lines" : "linespoints")
         << " title \"" << gp_text(label) << "\"";
      first = false;
    }
  }
  return gp.str() + "\n";
}

}  // namespace

void plot(const Sweep& s, const std::string& title, const std::string& file) {
  namespace fs = std::filesystem;
  check_plot(file);
  const std::string ext = fs::path(file).extension().string();
  const std::string term = ext == ".svg" ? "svg size 900,600 dynamic background rgb 'white'" : "png size 900,600";
  if (s.parameters.empty() || s.results.empty()) throw InputError("the sweep has no result to plot", "sweep a scene that finds something");
  fs::path dir = fs::temp_directory_path() / ("kinergy-sweep-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // two parameters or more, the second with more values than curves can show: a map
  std::ostringstream data;
  const bool map = s.parameters.size() >= 2 && distinct(s, 1).size() > 12;
  const std::string body = map ? map_plot(s, title, data) : line_plot(s, data);
  {
    std::ofstream d(dir / "sweep.dat");
    d << data.str();
  }
  {
    std::ofstream g(dir / "plot.gp");
    g << "set terminal " << term << "\nset output '" << fs::absolute(file).string() << "'\n";
    if (!map) g << "set title \"" << gp_text(title) << "\"\n";
    g << body;
  }
  const int rc = run_program(dir, {"gnuplot", "plot.gp"}, dir / "gnuplot.log");
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (rc == 127) throw InputError("gnuplot is not installed, so the sweep cannot be plotted", "install Debian's gnuplot-nox, or write --csv");
  if (rc != 0) throw InputError("gnuplot could not draw '" + file + "' (exit " + std::to_string(rc) + ")", "check the directory and its permissions");
}

PlotRows::PlotRows(const std::vector<Range>& ranges) : counts_(ranges.size()), keep_(ranges.size()) {
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    counts_[i] = static_cast<std::size_t>(ranges[i].count);
    // the first parameter along the plot's x axis: ≤ 400 values; the second: ≤ 200 (a map's
    // rows, or ≤ 12 curves taken from them); the others: ≤ 8
    const std::size_t most = i == 0 ? 400 : (i == 1 ? 200 : 8);
    keep_[i].assign(counts_[i], counts_[i] <= most);
    if (counts_[i] > most)
      for (std::size_t k = 0; k < most; ++k) keep_[i][k * (counts_[i] - 1) / (most - 1)] = true;
  }
}

void PlotRows::add(const Sweep::Row& row) {
  std::size_t rest = seen_++;
  for (std::size_t i = counts_.size(); i-- > 0;) {
    if (!keep_[i][rest % counts_[i]]) return;
    rest /= counts_[i];
  }
  rows_.rows.push_back(row);
}

}  // namespace kinergy::batch
