// A simulation run as text, CSV and a gnuplot drawing.
#include "kinergy/simulate/report.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include "kinergy/common/error.hpp"
#include "kinergy/common/markup.hpp"
#include "kinergy/common/process.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::simulate {

namespace {

std::string unit_of(const model::Coordinate& c, bool rate) {
  std::string u = units::si_name(c.dim);
  if (u.empty() || u == "1") u = "rad";
  return rate ? u + "/s" : u;
}

}  // namespace

std::string json(const model::Model& m, const Run& r) {
  auto num = [](double v) {
    if (!std::isfinite(v)) return std::string("null");
    char b[32];
    std::snprintf(b, sizeof b, "%.17g", v);
    return std::string(b);
  };
  auto list = [&](const std::vector<double>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(v[i]);
    return s + "]";
  };
  std::ostringstream os;
  const Sample& e = r.end;
  os << "{\n  \"end\": {\"t\": " << num(e.t) << ", \"stopped\": " << (r.stopped ? "true" : "false") << ",\n    \"q\": {";
  for (std::size_t i = 0; i < m.coords.size(); ++i) os << (i ? ", " : "") << json_quote(m.coords[i].name) << ": " << num(e.q[i]);
  os << "},\n    \"q_dot\": {";
  for (std::size_t i = 0; i < m.coords.size(); ++i) os << (i ? ", " : "") << json_quote(m.coords[i].name) << ": " << num(e.qd[i]);
  os << "},\n    \"T\": " << num(e.T) << ", \"V\": " << num(e.V) << "},\n  \"switches\": [";
  for (std::size_t k = 0; k < r.switches.size(); ++k) {
    const Switch& s = r.switches[k];
    os << (k ? "," : "") << "\n    {\"t\": " << num(s.t) << ", \"effect\": " << json_quote(s.effect) << ", \"kind\": " << json_quote(s.kind)
       << ", \"text\": " << json_quote(s.text) << "}";
  }
  os << (r.switches.empty() ? "" : "\n  ") << "],\n  \"impacts\": [";
  for (std::size_t k = 0; k < r.impacts.size(); ++k) {
    const Impact& im = r.impacts[k];
    os << (k ? "," : "") << "\n    {\"t\": " << num(im.t) << ", \"contacts\": [";
    for (std::size_t j = 0; j < im.contacts.size(); ++j) os << (j ? ", " : "") << json_quote(im.contacts[j]);
    os << "], \"vn_before\": " << list(im.vn_before) << ", \"vn_after\": " << list(im.vn_after) << ", \"impulse\": " << list(im.impulse)
       << ", \"energy_lost\": " << num(im.loss) << ", \"comes_to_rest\": " << (im.comes_to_rest ? "true" : "false") << "}";
  }
  os << (r.impacts.empty() ? "" : "\n  ") << "],\n  \"log\": [";
  for (std::size_t k = 0; k < r.log.size(); ++k) os << (k ? "," : "") << "\n    " << json_quote(r.log[k]);
  os << (r.log.empty() ? "" : "\n  ") << "],\n  \"energy\": {\"E0\": " << num(r.E0) << ", \"E1\": " << num(r.E1) << ", \"lost_in_impacts\": " << num(r.impact_loss)
     << ", \"work\": {";
  for (std::size_t k = 0; k < r.work.size(); ++k) os << (k ? ", " : "") << json_quote(r.work[k].first) << ": " << num(r.work[k].second);
  os << "}, \"scale\": " << num(r.energy_scale) << ", \"drift\": " << num(r.drift) << ", \"conservative\": " << (r.conservative ? "true" : "false") << "},\n"
     << "  \"steps\": " << r.steps << ", \"rejected\": " << r.rejected << "\n}\n";
  return os.str();
}

std::string text(const model::Model& m, const Run& r) {
  std::ostringstream os;
  const Sample& e = r.end;
  os << "end at t = " << numerics::g_text(e.t, 10) << " s" << (r.stopped ? " (the stop condition)" : "") << ":\n";
  for (std::size_t i = 0; i < m.coords.size(); ++i)
    os << "  " << m.coords[i].name << " = " << numerics::g_text(e.q[i], 10) << " " << unit_of(m.coords[i], false) << "   "
       << m.coords[i].name << "_dot = " << numerics::g_text(e.qd[i], 10) << " " << unit_of(m.coords[i], true) << "\n";
  if (!r.impacts.empty()) {
    os << "impacts: " << r.impacts.size() << "\n";
    std::size_t shown = 0;
    for (auto& im : r.impacts) {
      if (++shown > 12 && shown < r.impacts.size()) {
        if (shown == 13) os << "  ...\n";
        continue;
      }
      os << "  t = " << numerics::g_text(im.t, 10) << " s:";
      for (std::size_t j = 0; j < im.contacts.size(); ++j)
        os << " " << im.contacts[j] << " v_n " << numerics::g_text(im.vn_before[j], 8) << " -> " << numerics::g_text(im.vn_after[j], 8)
           << " m/s, impulse " << numerics::g_text(im.impulse[j], 8) << " N*s;";
      os << " energy lost " << numerics::g_text(im.loss, 10) << " J" << (im.comes_to_rest ? " (comes to rest)" : "") << "\n";
    }
  }
  for (auto& l : r.log) os << "  " << l << "\n";
  os << "energy audit:\n";
  os << "  E0 = T + V = " << numerics::g_text(r.E0, 10) << " J,  E1 = " << numerics::g_text(r.E1, 10) << " J\n";
  for (auto& [name, U] : r.work) os << "  work of " << name << ": " << numerics::g_text(U, 10) << " J\n";
  if (!r.impacts.empty()) os << "  lost in impacts: " << numerics::g_text(r.impact_loss, 10) << " J\n";
  os << "  " << (r.conservative ? "drift |E1 - E0|" : "balance |E1 - E0 - sum U + losses|") << " / "
     << numerics::g_text(r.energy_scale, 6) << " J = " << numerics::g_text(std::fabs(r.drift), 3) << "\n";
  return os.str();
}

std::string csv(const model::Model& m, const Run& r) {
  std::ostringstream os;
  os << "t";
  for (auto& c : m.coords) os << "," << c.name;
  for (auto& c : m.coords) os << "," << c.name << "_dot";
  os << ",T,V,E\n";
  for (auto& s : r.samples) {
    os << numerics::g_text(s.t, 17);
    for (double v : s.q) os << "," << numerics::g_text(v, 17);
    for (double v : s.qd) os << "," << numerics::g_text(v, 17);
    os << "," << numerics::g_text(s.T, 17) << "," << numerics::g_text(s.V, 17) << "," << numerics::g_text(s.T + s.V, 17) << "\n";
  }
  return os.str();
}

void plot(const model::Model& m, const Run& r, const std::string& file) {
  namespace fs = std::filesystem;
  std::string ext = fs::path(file).extension().string();
  std::string term;
  if (ext == ".svg") term = "svg size 900,720 dynamic background rgb 'white'";
  else if (ext == ".png") term = "png size 900,720";
  else throw InputError("the plot '" + file + "' is neither .svg nor .png", "name the plot FILE.svg or FILE.png");
  fs::path dir = fs::temp_directory_path() / ("kinergy-plot-" + std::to_string(getpid()));
  fs::create_directories(dir);
  {
    std::ofstream d(dir / "run.csv");
    d << csv(m, r);
  }
  const std::size_t n = m.coords.size();
  std::ostringstream gp;
  gp << "set terminal " << term << "\n"
     << "set output '" << fs::absolute(file).string() << "'\n"
     << "set datafile separator ','\nset key outside right\nset grid\n"
     << "set multiplot layout 2,1 title \"" << m.title << "\"\n"
     << "set xlabel 't (s)'\nset ylabel 'coordinates'\nplot ";
  for (std::size_t i = 0; i < n; ++i)
    gp << (i ? ", " : "") << "'run.csv' using 1:" << i + 2 << " with lines title '" << m.coords[i].name << " ("
       << unit_of(m.coords[i], false) << ")' noenhanced";  // (as written: dome_gap, not dome with a subscript)
  gp << "\nset ylabel 'energy (J)'\nplot 'run.csv' using 1:" << 2 * n + 2 << " with lines title 'T', '' using 1:"
     << 2 * n + 3 << " with lines title 'V', '' using 1:" << 2 * n + 4 << " with lines title 'E = T + V'\n"
     << "unset multiplot\n";
  {
    std::ofstream g(dir / "plot.gp");
    g << gp.str();
  }
  int rc = run_program(dir, {"gnuplot", "plot.gp"}, dir / "gnuplot.log");
  std::string why;
  if (rc != 0) {
    std::ifstream l(dir / "gnuplot.log");
    std::getline(l, why);
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (rc == 127) throw InputError("gnuplot is not installed, so no plot", "install it (Debian: apt install gnuplot-nox), or leave out --plot");
  if (rc != 0) throw InputError("gnuplot could not draw '" + file + "': " + why, "check that the folder of the plot exists and is writable");
}

}  // namespace kinergy::simulate
