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
#include "kinergy/common/process.hpp"

namespace kinergy::simulate {

namespace {

std::string num(double v, int digits = 10) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string unit_of(const model::Coordinate& c, bool rate) {
  std::string u = units::si_name(c.dim);
  if (u.empty() || u == "1") u = "rad";
  return rate ? u + "/s" : u;
}

}  // namespace

std::string text(const model::Model& m, const Run& r) {
  std::ostringstream os;
  const Sample& e = r.end;
  os << "end at t = " << num(e.t) << " s" << (r.stopped ? " (the stop condition)" : "") << ":\n";
  for (std::size_t i = 0; i < m.coords.size(); ++i)
    os << "  " << m.coords[i].name << " = " << num(e.q[i]) << " " << unit_of(m.coords[i], false) << "   "
       << m.coords[i].name << "_dot = " << num(e.qd[i]) << " " << unit_of(m.coords[i], true) << "\n";
  if (!r.impacts.empty()) {
    os << "impacts: " << r.impacts.size() << "\n";
    std::size_t shown = 0;
    for (auto& im : r.impacts) {
      if (++shown > 12 && shown < r.impacts.size()) {
        if (shown == 13) os << "  ...\n";
        continue;
      }
      os << "  t = " << num(im.t) << " s:";
      for (std::size_t j = 0; j < im.contacts.size(); ++j)
        os << " " << im.contacts[j] << " v_n " << num(im.vn_before[j], 8) << " -> " << num(im.vn_after[j], 8)
           << " m/s, impulse " << num(im.impulse[j], 8) << " N*s;";
      os << " energy lost " << num(im.loss, 10) << " J" << (im.comes_to_rest ? " (comes to rest)" : "") << "\n";
    }
  }
  for (auto& l : r.log) os << "  " << l << "\n";
  os << "energy audit:\n";
  os << "  E0 = T + V = " << num(r.E0) << " J,  E1 = " << num(r.E1) << " J\n";
  for (auto& [name, U] : r.work) os << "  work of " << name << ": " << num(U) << " J\n";
  if (!r.impacts.empty()) os << "  lost in impacts: " << num(r.impact_loss) << " J\n";
  os << "  " << (r.conservative ? "drift |E1 - E0|" : "balance |E1 - E0 - sum U + losses|") << " / "
     << num(r.energy_scale, 6) << " J = " << num(std::fabs(r.drift), 3) << "\n";
  return os.str();
}

std::string csv(const model::Model& m, const Run& r) {
  std::ostringstream os;
  os << "t";
  for (auto& c : m.coords) os << "," << c.name;
  for (auto& c : m.coords) os << "," << c.name << "_dot";
  os << ",T,V,E\n";
  for (auto& s : r.samples) {
    os << num(s.t, 17);
    for (double v : s.q) os << "," << num(v, 17);
    for (double v : s.qd) os << "," << num(v, 17);
    os << "," << num(s.T, 17) << "," << num(s.V, 17) << "," << num(s.T + s.V, 17) << "\n";
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
       << unit_of(m.coords[i], false) << ")'";
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
