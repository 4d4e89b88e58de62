// One scene solved over a grid of parameter values: CSV, JSON and a gnuplot plot.
#include "kinergy/app/app.hpp"
#include "kinergy/batch/sweep.hpp"

#include <unistd.h>

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

std::string number(double v) {
  if (std::isnan(v)) return "";
  std::ostringstream os;
  os << std::setprecision(15) << v;
  return os.str();
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
  return r;
}

Sweep sweep(const scene::SceneDef& def, const std::vector<Range>& ranges) {
  Sweep out;
  // the scene at its own values first: a bad scene is refused once, not at every point
  const Solution base = solve_scene(def);
  for (auto& r : ranges) out.parameters.push_back(r.name + (r.unit.empty() ? "" : " (" + r.unit + ")"));
  for (auto& res : base.results) out.results.push_back(res.name + (res.unit.empty() ? "" : " (" + res.unit + ")"));
  std::size_t total = 1;
  for (auto& r : ranges) total *= static_cast<std::size_t>(r.count);
  for (std::size_t k = 0; k < total; ++k) {
    poll_interrupt();
    Sweep::Row row;
    scene::SceneDef at = def;
    // the grid's k-th point, the last range varying fastest
    std::size_t rest = k;
    std::vector<double> values(ranges.size());
    for (std::size_t i = ranges.size(); i-- > 0;) {
      const Range& r = ranges[i];
      const std::size_t j = rest % static_cast<std::size_t>(r.count);
      rest /= static_cast<std::size_t>(r.count);
      values[i] = r.lo + (r.hi - r.lo) * static_cast<double>(j) / static_cast<double>(r.count - 1);
    }
    for (std::size_t i = 0; i < ranges.size(); ++i) {
      std::ostringstream v;
      v << std::setprecision(17) << values[i];
      app::set_parameter(at, ranges[i].name, v.str() + (ranges[i].unit.empty() ? "" : " " + ranges[i].unit));
    }
    row.at = values;
    try {
      const Solution s = solve_scene(at);
      for (auto& name : base.results) {
        double v = std::numeric_limits<double>::quiet_NaN();
        for (auto& res : s.results)
          if (res.name == name.name && res.si)
            if (auto value = res.evaluate(s.model.numeric_environment(), 15, true)) v = value->v.to_double();
        row.values.push_back(v);
      }
    } catch (const SceneError& e) {
      row.values.assign(base.results.size(), std::numeric_limits<double>::quiet_NaN());
      row.error = e.problem();
    }
    out.rows.push_back(std::move(row));
  }
  return out;
}

std::string csv(const Sweep& s) {
  std::ostringstream os;
  auto cell = [](const std::string& t) {
    std::string q = "\"";
    for (char c : t) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  for (auto& p : s.parameters) os << cell(p) << ",";
  for (auto& r : s.results) os << cell(r) << ",";
  os << "\"error\"\n";
  for (auto& row : s.rows) {
    for (double v : row.at) os << number(v) << ",";
    for (double v : row.values) os << number(v) << ",";
    os << (row.error.empty() ? "" : cell(row.error)) << "\n";
  }
  return os.str();
}

std::string json(const Sweep& s) {
  std::ostringstream os;
  os << "{\"parameters\": [";
  for (std::size_t i = 0; i < s.parameters.size(); ++i) os << (i ? ", " : "") << json_quote(s.parameters[i]);
  os << "], \"results\": [";
  for (std::size_t i = 0; i < s.results.size(); ++i) os << (i ? ", " : "") << json_quote(s.results[i]);
  os << "], \"rows\": [";
  auto list = [&](const std::vector<double>& v) {
    std::string t = "[";
    for (std::size_t i = 0; i < v.size(); ++i) t += (i ? ", " : "") + (std::isnan(v[i]) ? std::string("null") : number(v[i]));
    return t + "]";
  };
  for (std::size_t i = 0; i < s.rows.size(); ++i) {
    const auto& row = s.rows[i];
    os << (i ? ",\n  " : "\n  ") << "{\"at\": " << list(row.at) << ", \"values\": " << list(row.values)
       << ", \"error\": " << (row.error.empty() ? std::string("null") : json_quote(row.error)) << "}";
  }
  os << "\n]}\n";
  return os.str();
}

void plot(const Sweep& s, const std::string& title, const std::string& file) {
  namespace fs = std::filesystem;
  const std::string ext = fs::path(file).extension().string();
  std::string term;
  if (ext == ".svg") term = "svg size 900,600 dynamic background rgb 'white'";
  else if (ext == ".png") term = "png size 900,600";
  else throw InputError("the plot '" + file + "' is neither .svg nor .png", "name the plot FILE.svg or FILE.png");
  if (s.parameters.empty() || s.results.empty()) throw InputError("the sweep has no result to plot", "sweep a scene that finds something");
  fs::path dir = fs::temp_directory_path() / ("kinergy-sweep-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // one curve (a block of rows, gnuplot's index) for each value of the parameters after the first,
  // running along the first
  std::map<std::vector<double>, std::vector<const Sweep::Row*>> curves;
  for (auto& row : s.rows) curves[std::vector<double>(row.at.begin() + 1, row.at.end())].push_back(&row);
  std::ostringstream data;
  std::vector<std::string> names;
  for (auto& [others, rows] : curves) {
    std::string name;
    for (std::size_t i = 0; i < others.size(); ++i) name += (i ? ", " : "") + s.parameters[i + 1] + " = " + number(others[i]);
    names.push_back(name);
    for (auto* row : rows) {
      data << number(row->at[0]);
      for (double v : row->values) data << " " << (std::isnan(v) ? std::string("NaN") : number(v));
      data << "\n";
    }
    data << "\n\n";
  }
  {
    std::ofstream d(dir / "sweep.dat");
    d << data.str();
  }
  std::ostringstream gp;
  std::string t = title;
  for (char& c : t)
    if (c == '"') c = '\'';
  gp << "set terminal " << term << "\nset output '" << fs::absolute(file).string() << "'\n"
     << "set title \"" << t << "\"\nset grid\nset key top right\nset xlabel \"" << s.parameters[0] << "\"\nplot ";
  bool first = true;
  for (std::size_t c = 0; c < names.size() && c < 12; ++c)
    for (std::size_t r = 0; r < s.results.size(); ++r) {
      std::string label = s.results[r] + (names[c].empty() ? "" : ", " + names[c]);
      for (char& ch : label)
        if (ch == '"') ch = '\'';
      gp << (first ? "" : ", ") << "'sweep.dat' index " << c << " using 1:" << r + 2 << " with linespoints title \"" << label << "\"";
      first = false;
    }
  gp << "\n";
  {
    std::ofstream g(dir / "plot.gp");
    g << gp.str();
  }
  const int rc = run_program(dir, {"gnuplot", "plot.gp"}, dir / "gnuplot.log");
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (rc == 127) throw InputError("gnuplot is not installed, so the sweep cannot be plotted", "install Debian's gnuplot-nox, or write --csv");
  if (rc != 0) throw InputError("gnuplot could not draw '" + file + "' (exit " + std::to_string(rc) + ")", "check the directory and its permissions");
}

}  // namespace kinergy::batch
