// Derivation time of T, V, M(q) and Q for an N-link pendulum (issue 6, benchmark d).
//
//   derivation_time [--n LIST] [--min-seconds S] [--min-repeats R] [--out DIR] [--print-mass N]
//
// The scene: N uniform slender rods (mass m, length L each) hanging in a chain from a fixed pin
// O, under gravity g along −y. Coordinates th1..thN are absolute angles of the links from the
// x axis, so link i's mass centre is
//     r_Gi = Σ_{j<i} L (cos th_j, sin th_j) + L/2 (cos th_i, sin th_i),
// its angle is th_i, and its ends are O_i, B_i at ∓L/2 along the link. Link 1 is pinned at O,
// link i+1's O to link i's B. The pins are supports the coordinates already imply: they do no
// work, and the model checks that their two points coincide.
//
// For each N the scene text is generated once; each repeat then parses it (scene::load_string,
// timed apart: parse_ms), and times Model::build from the parsed SceneDef (build_ms) and, on that
// model, T = kinetic_energy(), V = potential_energy(), M(q) = mass_matrix() and
// Q_i = Σ_effects generalized_force(e, i) for every coordinate i (kinergy_tvmq_ms). The figure
// compared with sympy is kinergy_ms = build_ms + kinergy_tvmq_ms. Each repeat starts from a new
// Model (new GiNaC symbols, nothing carried over); each time reported is the median over at
// least --min-repeats repeats (3) and at least --min-seconds (0.2 s) in total, measured with
// std::chrono::steady_clock. The process CPU time of build + T/V/M/Q is measured beside it
// (kinergy_cpu_ms): on a shared machine other work stretches the wall-clock time, not that.
//
// Output: a table on stdout (N, kinergy_ms, build_ms, kinergy_tvmq_ms, parse_ms, kinergy_cpu_ms,
// repeats), and with --out DIR the same as DIR/derivation_time_kinergy.csv and .json.
// --print-mass N prints the entries of M(q) for the N-link scene, one "i j entry" line each
// (plain GiNaC text in th1..thN, m, L), for tests/bench/sympy_nlink.py to check against sympy.
//
// Like with like: sympy's `forcing` holds the velocity-product (centrifugal) terms, which T, V, M
// and Q do not. So each repeat also times, on a model built anew, the full equations of motion
// M(q) q̈ = f(q, q̇) = Q − c(q, q̇) as the simulator derives them (simulate::equations_of_motion:
// M, the velocity products c and every effect's Q): kinergy_eom_ms = build + that. --print-eom N
// prints M ("M i j entry") and f ("f i entry", rates th1_dot..thN_dot) for the check against
// sympy's mass_matrix and forcing.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/common/error.hpp"
#include "kinergy/model/model.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/simulate/equations.hpp"

namespace {

using GiNaC::ex;
using Clock = std::chrono::steady_clock;

volatile std::size_t g_sink = 0;  // keeps the timed work from being optimised away

/// The scene text of an N-link pendulum of uniform slender rods (see the file comment).
std::string nlink_scene(int n) {
  std::ostringstream s;
  s << "title: " << n << "-link pendulum of uniform slender rods\n"
    << "parameters: {m: 2 kg, L: 0.5 m, g: 9.81 m/s^2}\n"
    << "points: {O: [0, 0]}\n"
    << "coordinates:\n";
  for (int i = 1; i <= n; ++i) s << "  th" << i << ": rad\n";
  s << "bodies:\n";
  for (int i = 1; i <= n; ++i) {
    // r_Gi: the full links before this one, then half of this one
    std::string x, y;
    for (int j = 1; j < i; ++j) {
      x += "L*cos(th" + std::to_string(j) + ") + ";
      y += "L*sin(th" + std::to_string(j) + ") + ";
    }
    x += "L/2*cos(th" + std::to_string(i) + ")";
    y += "L/2*sin(th" + std::to_string(i) + ")";
    s << "  link" << i << ":\n"
      << "    mass: m\n"
      << "    inertia: {slender_rod: L}\n"
      << "    position: [" << x << ", " << y << "]\n"
      << "    angle: th" << i << "\n"
      << "    points: {O: [-L/2, 0], B: [L/2, 0]}\n";
  }
  s << "effects:\n"
    << "  gravity: {g: g}\n"
    << "  pin1: {pin: [O, link1.O]}\n";
  for (int i = 2; i <= n; ++i)
    s << "  pin" << i << ": {pin: [link" << i - 1 << ".B, link" << i << ".O]}\n";
  // one state with every coordinate given, so that the scene is complete and valid
  s << "states:\n  1: {";
  for (int i = 1; i <= n; ++i)
    s << (i > 1 ? ", " : "") << "th" << i << ": -pi/2 + " << i << "/10, th" << i << "_dot: 0";
  s << "}\n";
  return s.str();
}

/// T, V, M(q) and Q of a model, as the benchmark asks for them.
struct Derived {
  ex T, V;
  GiNaC::matrix M;
  std::vector<ex> Q;
};

Derived derive(const kinergy::model::Model& model) {
  Derived d;
  d.T = model.kinetic_energy();
  d.V = model.potential_energy();
  d.M = model.mass_matrix();
  // Q_i = Σ_e Q_i(e): gravity gives −∂V/∂q_i, the pins nothing (they do no work)
  d.Q.assign(model.coords.size(), 0);
  for (auto& e : model.effects)
    for (std::size_t i = 0; i < model.coords.size(); ++i) d.Q[i] += model.generalized_force(e, i);
  return d;
}

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/// CPU time of this process in ms (POSIX CLOCK_PROCESS_CPUTIME_ID).
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t k = v.size() / 2;
  return v.size() % 2 ? v[k] : (v[k - 1] + v[k]) / 2;
}

struct Row {
  int n = 0;
  double total_ms = 0, build_ms = 0, tvmq_ms = 0, parse_ms = 0, cpu_ms = 0;  ///< medians
  int repeats = 0;
  double eom_ms = 0, eom_cpu_ms = 0;  ///< build + full equations of motion (M, c, Q), medians
};

Row time_n(int n, double min_seconds, int min_repeats) {
  const std::string text = nlink_scene(n);
  std::vector<double> total, build, tvmq, parse, cpu, eom, eom_cpu;
  double spent_ms = 0;
  while (static_cast<int>(total.size()) < min_repeats || spent_ms < 1000 * min_seconds) {
    auto tp = Clock::now();
    const kinergy::scene::SceneDef def = kinergy::scene::load_string(text, "<nlink>");
    parse.push_back(ms_since(tp));
    double c0 = cpu_ms();
    auto t0 = Clock::now();
    kinergy::model::Model model = kinergy::model::Model::build(def);
    double b = ms_since(t0);
    auto t1 = Clock::now();
    Derived d = derive(model);
    double w = ms_since(t1);
    cpu.push_back(cpu_ms() - c0);
    g_sink = g_sink + d.T.nops() + d.V.nops() + d.M.rows() + d.Q.size();
    build.push_back(b);
    tvmq.push_back(w);
    total.push_back(b + w);
    // the full equations of motion, on a model of its own (nothing carried over from T, V, M, Q)
    double c1 = cpu_ms();
    auto t2 = Clock::now();
    kinergy::model::Model fresh = kinergy::model::Model::build(def);
    kinergy::simulate::Equations eq = kinergy::simulate::equations_of_motion(fresh);
    double e = ms_since(t2);
    eom_cpu.push_back(cpu_ms() - c1);
    g_sink = g_sink + eq.M.rows() + eq.c.size() + eq.forces.size();
    eom.push_back(e);
    spent_ms += b + w + e;
  }
  Row r{n, median(total), median(build), median(tvmq), median(parse), median(cpu), static_cast<int>(total.size())};
  r.eom_ms = median(eom);
  r.eom_cpu_ms = median(eom_cpu);
  return r;
}

std::vector<int> parse_list(const std::string& text) {
  std::vector<int> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(std::atoi(item.c_str()));
  return out;
}

int usage() {
  std::cerr << "usage: derivation_time [--n 1,2,4,8,16] [--min-seconds 0.2] [--min-repeats 3] "
               "[--out DIR] [--print-mass N] [--print-eom N]\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> ns{1, 2, 4, 8, 16};
  double min_seconds = 0.2;
  int min_repeats = 3, print_mass = 0, print_eom = 0;
  std::string out_dir;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--n" && i + 1 < argc) ns = parse_list(argv[++i]);
    else if (a == "--min-seconds" && i + 1 < argc) min_seconds = std::atof(argv[++i]);
    else if (a == "--min-repeats" && i + 1 < argc) min_repeats = std::max(1, std::atoi(argv[++i]));
    else if (a == "--out" && i + 1 < argc) out_dir = argv[++i];
    else if (a == "--print-mass" && i + 1 < argc) print_mass = std::atoi(argv[++i]);
    else if (a == "--print-eom" && i + 1 < argc) print_eom = std::atoi(argv[++i]);
    else return usage();
  }
  if (ns.empty() || std::any_of(ns.begin(), ns.end(), [](int n) { return n < 1; })) return usage();

  try {
    if (print_mass > 0) {
      auto model = kinergy::model::Model::build(kinergy::scene::load_string(nlink_scene(print_mass), "<nlink>"));
      GiNaC::matrix M = model.mass_matrix();
      for (unsigned i = 0; i < M.rows(); ++i)
        for (unsigned j = 0; j < M.cols(); ++j) std::cout << i << ' ' << j << ' ' << M(i, j) << '\n';
      return 0;
    }

    if (print_eom > 0) {
      auto model = kinergy::model::Model::build(kinergy::scene::load_string(nlink_scene(print_eom), "<nlink>"));
      auto eq = kinergy::simulate::equations_of_motion(model);
      for (unsigned i = 0; i < eq.M.rows(); ++i)
        for (unsigned j = 0; j < eq.M.cols(); ++j) std::cout << "M " << i << ' ' << j << ' ' << eq.M(i, j) << '\n';
      // f = Σ Q − c: what stands on the right of M q̈ = f
      for (std::size_t i = 0; i < eq.q.size(); ++i) {
        GiNaC::ex f = -eq.c[i];
        for (auto& ft : eq.forces) f += ft.Q[i];
        std::cout << "f " << i << ' ' << f << '\n';
      }
      return 0;
    }

    std::vector<Row> rows;
    std::printf("%4s %14s %12s %16s %12s %15s %8s %14s\n", "N", "kinergy_ms", "build_ms", "kinergy_tvmq_ms", "parse_ms",
                "kinergy_cpu_ms", "repeats", "kinergy_eom_ms");
    for (int n : ns) {
      Row r = time_n(n, min_seconds, min_repeats);
      std::printf("%4d %14.4f %12.4f %16.4f %12.4f %15.4f %8d %14.4f\n", r.n, r.total_ms, r.build_ms, r.tvmq_ms,
                  r.parse_ms, r.cpu_ms, r.repeats, r.eom_ms);
      std::fflush(stdout);
      rows.push_back(r);
    }

    if (!out_dir.empty()) {
      std::ofstream csv(out_dir + "/derivation_time_kinergy.csv");
      csv << "N,kinergy_ms,build_ms,kinergy_tvmq_ms,parse_ms,kinergy_cpu_ms,repeats,kinergy_eom_ms,kinergy_eom_cpu_ms\n";
      std::ofstream json(out_dir + "/derivation_time_kinergy.json");
      json << "[\n";
      char line[256];
      for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        std::snprintf(line, sizeof line, "%d,%.6g,%.6g,%.6g,%.6g,%.6g,%d,%.6g,%.6g\n", r.n, r.total_ms, r.build_ms,
                      r.tvmq_ms, r.parse_ms, r.cpu_ms, r.repeats, r.eom_ms, r.eom_cpu_ms);
        csv << line;
        std::snprintf(line, sizeof line,
                      "  {\"N\": %d, \"kinergy_ms\": %.6g, \"build_ms\": %.6g, \"kinergy_tvmq_ms\": %.6g, "
                      "\"parse_ms\": %.6g, \"kinergy_cpu_ms\": %.6g, \"repeats\": %d, \"kinergy_eom_ms\": %.6g}%s\n",
                      r.n, r.total_ms, r.build_ms, r.tvmq_ms, r.parse_ms, r.cpu_ms, r.repeats, r.eom_ms,
                      k + 1 < rows.size() ? "," : "");
        json << line;
      }
      json << "]\n";
      if (!csv || !json) {
        std::cerr << "derivation_time: cannot write to " << out_dir << "\n";
        return 1;
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "derivation_time: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
