// What accuracy costs in time: closed forms from derivations/, each evaluated by every path
// kinergy has, side by side in one run, against a hand-written C++ double expression.
//
//   accuracy_cost [--out DIR] [--data DIR] [--repeats N] [--quick]
//
// Writes OUT/accuracy.md (table: time per evaluation, ratio to the hand-written double, relative
// error, the targets), and DATA/accuracy.dat with DATA/accuracy.gp (gnuplot draws OUT/accuracy.svg).
// Time: the median over N repeats of a loop long enough to take a few milliseconds; errors
// against GiNaC's evaluation of the same form at 1200 digits from the exact scene values.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <cln/cln.h>
#include <ginac/ginac.h>

#include "kinergy/common/error.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/evaluator.hpp"
#include "kinergy/numeric/native.hpp"
#include "kinergy/numeric/tape.hpp"
#include "kinergy/problem.hpp"

using namespace GiNaC;
using kinergy::numerics::Evaluator;
using kinergy::numerics::Tape;

namespace {

volatile double g_sink = 0;  // keeps the loops from being optimised away

/// A closed form of a derivation and the same formula written by hand in C++.
struct Form {
  std::string file, result;
  std::vector<std::string> params;  ///< the order of x[] in `hand`
  std::function<double(const double*)> hand;
};

// The yardstick: each formula as a person would type it (the closed forms kinergy derives for
// these scenes, checked against it below before anything is timed).
std::vector<Form> forms() {
  using std::cos;
  using std::sin;
  using std::sqrt;
  return {
      {"energy/sliding_rod.yaml", "omega2", {"g", "theta2", "l"},
       [](const double* x) { return sqrt(3 * x[0] * sin(x[1]) / x[2]); }},
      {"energy/atwood_pulley.yaml", "vA2", {"d", "g", "mA", "mB", "M"},
       [](const double* x) { return 2 * sqrt(x[0] * x[1] * (x[2] - x[3]) / (2 * x[2] + 2 * x[3] + x[4])); }},
      {"energy/sphere_in_bowl.yaml", "omega2", {"g", "theta0", "R", "r"},
       [](const double* x) { return sqrt(10 * x[0] * (1 - cos(x[1])) * (x[2] - x[3]) / 7) / x[3]; }},
      {"energy/bar_spring.yaml", "omega2", {"L0", "k", "L", "b", "g", "m"},
       [](const double* x) {
         const double L0 = x[0], k = x[1], L = x[2], b = x[3], g = x[4], m = x[5];
         return sqrt(3 * (2 * L0 * k * (L + b) + L * g * m - 2 * L * b * k - 2 * L0 * k * sqrt(L * L + b * b)) / m) / L;
       }},
      {"impact/turnstile_energy_loss.yaml", "lost", {"L", "M", "m", "v0", "e", "b"},
       [](const double* x) {
         const double L = x[0], M = x[1], m = x[2], v0 = x[3], e = x[4], b = x[5];
         return L * L * M * m * v0 * v0 * (1 + e) * (1 - e) / (2 * (12 * b * b * m + L * L * M));
       }},
      {"impact/pendulum_strikes_block.yaml", "v_block", {"m1", "m2", "e", "g", "l", "phi0"},
       [](const double* x) {
         const double m1 = x[0], m2 = x[1], e = x[2], g = x[3], l = x[4], phi0 = x[5];
         return m1 * (1 + e) * sqrt(2 * g * l * (1 - cos(phi0))) / (m1 + m2);
       }},
      {"impact/pendulum_strikes_block.yaml", "phi3", {"m1", "m2", "e", "phi0"},
       [](const double* x) {
         const double m1 = x[0], m2 = x[1], e = x[2], c = cos(x[3]);
         const double s = m1 + m2;
         return -std::acos((2 * e * m1 * m2 + 2 * m1 * m2 + e * e * m2 * m2 * c + m1 * m1 * c + m2 * m2 -
                            2 * e * m1 * m2 * c - e * e * m2 * m2) / (s * s));
       }},
      {"impact/glancing_disks.yaml", "vA", {"v_A", "m_A", "m_B", "e", "beta"},
       [](const double* x) {
         const double vA = x[0], mA = x[1], mB = x[2], e = x[3], c = cos(x[4]);
         const double c2 = c * c;
         return vA * sqrt(2 * mA * mB + e * e * mB * mB * c2 + mA * mA + mB * mB - 2 * e * mA * mB * c2 - 2 * mA * mB * c2 -
                          mB * mB * c2) / (mA + mB);
       }},
      {"energy/linkage_collar.yaml", "omega2", {"g", "theta2", "l", "r", "m1", "m2", "mC"},
       [](const double* x) {
         const double g = x[0], th = x[1], l = x[2], r = x[3], m1 = x[4], m2 = x[5], mC = x[6];
         const double s = sin(th), c = cos(th), c2 = c * c, s2 = s * s;
         const double q = sqrt(l * l - r * r * c2), q0 = sqrt(l * l - r * r);
         const double num = -g * s2 * (2 * m2 * r * s + 2 * mC * r * s + 2 * mC * q + m1 * r * s + m2 * q - (2 * mC + m2) * q0);
         const double den = 3 * l * l * m2 + 3 * l * l * mC + 3 * m2 * r * c2 * s * q + 3 * m2 * r * r * c2 * s2 +
                            6 * mC * r * c2 * s * q + 6 * mC * r * r * c2 * s2 + l * l * m1 - 2 * l * l * m2 * s2 -
                            3 * l * l * mC * s2 - 3 * m2 * r * r * c2 - 3 * mC * r * r * c2 - m1 * r * r * c2;
         return -sqrt(3 * (num / den) * (l * l - r * r * c2)) / (r * s);
       }},
  };
}

/// Median over `repeats` of the time per call of f, each repeat a loop of at least ~3 ms.
template <class F>
double ns_per_call(F&& f, int repeats) {
  using clock = std::chrono::steady_clock;
  long n = 1;
  for (;;) {  // calibrate
    auto t0 = clock::now();
    for (long i = 0; i < n; ++i) f();
    double s = std::chrono::duration<double>(clock::now() - t0).count();
    if (s > 3e-3 || n > (1L << 30)) break;
    n *= 2;
  }
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    auto t0 = clock::now();
    for (long i = 0; i < n; ++i) f();
    t.push_back(std::chrono::duration<double, std::nano>(clock::now() - t0).count() / static_cast<double>(n));
  }
  std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
  return t[t.size() / 2];
}

/// log10 of the relative error (a floor for exactly zero errors: the working precision).
double log_err(const numeric& got, const numeric& ref, double floor) {
  numeric d = abs(got - ref);
  if (d.is_zero()) return floor;
  numeric r = ref.is_zero() ? d : d / abs(ref);
  long saved = Digits;
  Digits = 30;
  double l = ex_to<numeric>((log(r) / log(numeric(10))).evalf()).to_double();
  Digits = saved;
  return std::max(l, floor);
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

struct Row {
  std::string form, path;
  double ns = 0, ratio = 0, log10_err = 0;
};

int labels_count(const std::vector<Row>& rows, const std::string& path) {
  int n = 0;
  for (auto& r : rows) n += r.path == path ? 1 : 0;
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = "docs", data_dir = ".";
  int repeats = 11;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) out_dir = argv[++i];
    else if (a == "--data" && i + 1 < argc) data_dir = argv[++i];
    else if (a == "--repeats" && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
    else if (a == "--quick") repeats = 3;
    else {
      std::cerr << "usage: accuracy_cost [--out DIR] [--data DIR] [--repeats N] [--quick]\n";
      return 2;
    }
  }
  const std::string root = KINERGY_SOURCE_DIR;
  std::vector<Row> rows;
  const std::vector<long> precisions = {15, 30, 50, 100, 1000};
  for (const Form& f : forms()) {
    kinergy::Solution s = kinergy::solve_file(root + "/derivations/" + f.file);
    const kinergy::Result* res = nullptr;
    for (auto& r : s.results)
      if (r.name == f.result) res = &r;
    if (!res) {
      std::cerr << f.file << ": no result " << f.result << "\n";
      return 1;
    }
    exmap env = s.model.numeric_environment();
    std::vector<ex> syms;
    std::vector<double> x;
    for (auto& name : f.params) {
      const auto* p = s.model.parameter(name);
      if (!p || !env.count(p->sym)) {
        std::cerr << f.file << ": no value for " << name << "\n";
        return 1;
      }
      syms.push_back(p->sym);
      x.push_back(kinergy::numerics::to_double(env[p->sym]));
    }
    const ex& form = res->closed;
    exmap own;
    for (auto& sy : syms) own[sy] = env[sy];
    numeric ref = *kinergy::numerics::evaluate(form, own, 1200);
    const std::string label = f.file.substr(f.file.find('/') + 1, f.file.size() - f.file.find('/') - 6) + ":" + f.result;

    // the hand-written formula is the same function (else the yardstick measures something else)
    double hand_v = f.hand(x.data());
    if (std::fabs(hand_v - ref.to_double()) > 1e-12 * std::fabs(ref.to_double())) {
      std::cerr << label << ": the hand-written formula gives " << hand_v << ", the closed form " << ref.to_double() << "\n";
      return 1;
    }
    // points around the scene's values (each input moved by a few ulps), cycled through
    const std::size_t P = 64, m = x.size();
    std::vector<double> pts(P * m);
    for (std::size_t k = 0; k < P; ++k)
      for (std::size_t j = 0; j < m; ++j) pts[k * m + j] = x[j] * (1 + 1e-15 * static_cast<double>((k * 7 + j) % 5));
    std::size_t k = 0;
    auto add = [&](const std::string& path, double ns, double lerr) { rows.push_back({label, path, ns, 0, lerr}); };

    const double floor_double = std::log10(std::ldexp(1.0, -53)) - 1;
    double ns_hand = ns_per_call([&] { g_sink = g_sink + f.hand(&pts[(k = (k + 1) % P) * m]); }, repeats);
    add("hand-written double", ns_hand, log_err(kinergy::numerics::exact(hand_v), ref, floor_double));

    Tape tape = Tape::compile(form, syms);
    // the tape as machine code (generated C++, compiled once, cached): called through a
    // function pointer, as the hand-written formula is called through std::function
    auto native = kinergy::numerics::NativeFunction::build(tape);
    auto fn = native.function();
    double ns_native = ns_per_call([&] { g_sink = g_sink + fn(&pts[(k = (k + 1) % P) * m]); }, repeats);
    add("compiled double (native code)", ns_native, log_err(kinergy::numerics::exact(fn(x.data())), ref, floor_double));

    double ns_tape = ns_per_call([&] { g_sink = g_sink + tape(&pts[(k = (k + 1) % P) * m]); }, repeats);
    add("compiled double (tape)", ns_tape, log_err(kinergy::numerics::exact(tape(x.data())), ref, floor_double));

    std::vector<double> outb(P);
    double ns_batch = ns_per_call([&] {
                        tape.batch(pts.data(), P, outb.data());
                        g_sink = g_sink + outb[0];
                      }, repeats) / static_cast<double>(P);
    add("compiled double, batch of 64", ns_batch, log_err(kinergy::numerics::exact(tape(x.data())), ref, floor_double));

    Evaluator ev(form, own);
    auto fast = ev.fast();
    double ns_fast = ns_per_call([&] { g_sink = g_sink + ev.fast()->value; }, repeats);
    add("double with error bound (solve)", ns_fast, log_err(kinergy::numerics::exact(fast->value), ref, floor_double));

    for (long p0 : precisions) {
      // a trigonometric function of an angle of 1 rad or more needs a few digits more than 15
      // (its integer digits, for reducing it): the least working precision that covers them
      long p = p0;
      std::optional<numeric> v;
      for (;;) {
        try {
          v = ev.at(p);
          break;
        } catch (const kinergy::numerics::NeedsPrecision& np) {
          p = np.digits;
        }
      }
      double ns = ns_per_call([&] { ev.at(p); }, p >= 1000 ? std::max(3, repeats / 3) : repeats);
      p = p0;
      add("CLN " + std::to_string(p) + " digits", ns, log_err(*v, ref, -static_cast<double>(p) - 2));
    }
    for (int n : {15, 50}) {
      auto d = ev.settled(n);
      double ns = ns_per_call([&] { ev.settled(n); }, repeats);
      add("settled " + std::to_string(n) + " digits (CLN, not proven)", ns,
          log_err(kinergy::numerics::round_sig(d->value, n), ref, -static_cast<double>(n) - 2));
    }
    // `--digits N`: ball arithmetic (Arb) until the ball fixes N digits: proven
    for (int n : {15, 50, 1000}) {
      auto d = ev.digits(n);
      if (!d || !d->proven) {
        std::cerr << label << ": " << n << " digits not proven\n";
        return 1;
      }
      double ns = ns_per_call([&] { ev.digits(n); }, n >= 1000 ? std::max(3, repeats / 3) : repeats);
      add("proven " + std::to_string(n) + " digits (Arb balls)", ns,
          log_err(kinergy::numerics::round_sig(d->value, n), ref, -static_cast<double>(n) - 2));
      if (n == 15) {
        // one value asked once: a new Evaluator's first call, its exact check and the balls' setup
        // included (the Evaluator's own construction, timed alone, taken off)
        const double both = ns_per_call([&] { Evaluator e1(form, own); e1.digits(15); }, std::max(3, repeats / 3));
        const double made = ns_per_call([&] { Evaluator e1(form, own); }, std::max(3, repeats / 3));
        add("proven 15 digits, first call (exact check and setup)", std::max(both - made, 0.0),
            log_err(kinergy::numerics::round_sig(d->value, n), ref, -static_cast<double>(n) - 2));
      }
    }
    {
      exmap at;
      for (std::size_t j = 0; j < m; ++j) at[syms[j]] = env[syms[j]];
      auto v = kinergy::numerics::evaluate(form, at, 17);
      double ns = ns_per_call([&] { kinergy::numerics::evaluate(form, at, 17); }, std::max(3, repeats / 2));
      add("GiNaC evalf (subs, 17 digits)", ns, log_err(*v, ref, -19));
    }
    for (auto& r : rows)
      if (r.form == label) r.ratio = r.ns / ns_hand;
    std::cerr << label << ": hand " << ns_hand << " ns, native " << ns_native / ns_hand << "x, tape " << ns_tape / ns_hand
              << "x, batch " << ns_batch / ns_hand << "x\n";
  }

  // summary per path: geometric means over the forms
  std::vector<std::string> paths;
  for (auto& r : rows)
    if (std::find(paths.begin(), paths.end(), r.path) == paths.end()) paths.push_back(r.path);
  std::map<std::string, std::string> target = {{"compiled double (native code)", "≤ 1.5×"},
                                                {"CLN 50 digits", "≤ 400×"},
                                                {"proven 15 digits (Arb balls)", "≤ 200×"},
                                                {"proven 50 digits (Arb balls)", "≤ 400× (aim 150×)"},
                                                {"proven 1000 digits (Arb balls)", "≤ 5000×"}};
  std::map<std::string, double> target_value = {{"compiled double (native code)", 1.5},
                                                {"CLN 50 digits", 400},
                                                {"proven 15 digits (Arb balls)", 200},
                                                {"proven 50 digits (Arb balls)", 400},
                                                {"proven 1000 digits (Arb balls)", 5000}};

  // one data block per path (gnuplot's `index`), and the script that draws them
  std::ofstream dat(data_dir + "/accuracy.dat");
  for (std::size_t i = 0; i < paths.size(); ++i) {
    dat << "# " << paths[i] << "\n";
    for (auto& r : rows)
      if (r.path == paths[i]) dat << r.ns << " " << r.log10_err << " " << r.form << "\n";
    dat << "\n\n";
  }
  std::ofstream gp(data_dir + "/accuracy.gp");
  gp << "set terminal svg size 1000,520 dynamic enhanced font 'sans,10' background 'white'\n"
     << "set output '" << out_dir << "/accuracy.svg'\n"
     << "set multiplot layout 1,2 title 'What accuracy costs: relative error against time per evaluation (closed forms from derivations/)'\n"
     << "set logscale x\nset grid\nset xlabel 'time per evaluation (ns)'\nset ylabel 'log_{10} relative error'\n"
     << "set key bottom left font ',8'\n";
  auto plot = [&](const char* yrange, const char* title) {
    gp << "set yrange " << yrange << "\nset title '" << title << "'\nplot ";
    for (std::size_t i = 0; i < paths.size(); ++i)
      gp << (i ? ", " : "") << "'" << data_dir << "/accuracy.dat' index " << i << " using 1:2 with points pointtype " << (i % 13) + 1
         << " pointsize 1.1 title '" << paths[i] << "'";
    gp << "\n";
  };
  plot("[-1010:0]", "all paths");
  gp << "unset key\n";
  plot("[-110:0]", "up to 100 digits");
  gp << "unset multiplot\n";

  std::ostringstream md;
  md << "# What accuracy costs in time\n\n"
     << "Generated by `bash tests/bench/run_accuracy.sh` (tests/bench/accuracy_cost.cpp); do not edit by hand.\n"
     << "Every path evaluates the same closed forms, taken from derivations/, in one run; time is the\n"
     << "median of " << repeats << " repeats of a loop of at least 3 ms, per evaluation. The error is relative,\n"
     << "against GiNaC's evaluation of the same form at 1200 digits from the scene's exact values.\n\n"
     << "## Summary (geometric mean over " << rows.size() / paths.size() << " forms)\n\n"
     << "| path | time per evaluation | × hand-written double | worst relative error | target | met |\n"
     << "|---|---:|---:|---:|---|---|\n";
  for (auto& p : paths) {
    double lt = 0, lr = 0, worst = -1e9;
    int n = 0;
    for (auto& r : rows)
      if (r.path == p) {
        lt += std::log(r.ns);
        lr += std::log(r.ratio);
        worst = std::max(worst, r.log10_err);
        ++n;
      }
    double t = std::exp(lt / n), ratio = std::exp(lr / n);
    char buf[256];
    std::string tt = t < 1e3 ? (std::snprintf(buf, sizeof buf, "%.1f ns", t), buf)
                     : t < 1e6 ? (std::snprintf(buf, sizeof buf, "%.2f µs", t / 1e3), buf)
                               : (std::snprintf(buf, sizeof buf, "%.2f ms", t / 1e6), buf);
    std::string ts = tt;
    std::snprintf(buf, sizeof buf, "%.2f", ratio);
    std::string rs = buf;
    std::snprintf(buf, sizeof buf, "1e%.0f", std::ceil(worst));
    std::string es = buf;
    std::string met = target.count(p) ? (ratio <= target_value[p] ? "yes" : "**no**") : "";
    md << "| " << p << " | " << ts << " | " << rs << " | " << es << " | " << (target.count(p) ? target[p] : "") << " | " << met << " |\n";
  }
  // the targets, read out: which were met, which missed and by how much
  md << "\nPaths: *native code* is the tape as generated C++ compiled once (cached) and called through a\n"
     << "function pointer, as the hand-written formula is called through `std::function`; *tape* interprets\n"
     << "the same instructions one point at a time, *batch* 64 points per instruction; *double with error\n"
     << "bound* is what `kinergy solve` runs (stable form, exact parts, running error bound); *CLN P digits*\n"
     << "is the tape in CLN floats of P digits; *settled N digits* raises CLN's precision until two\n"
     << "precisions round alike (a heuristic, not a proof: what `--digits N` did before Arb); *proven N\n"
     << "digits* is `--digits N`: exact arithmetic tried first, then the tape on Arb balls from the exact\n"
     << "inputs, the precision doubled until every value in the ball rounds to the same N digits. The\n"
     << "Evaluator keeps exact arithmetic's verdict that a value is not rational (and the module keeps the\n"
     << "tape's constants per precision), so the loop times the balls; *first call* is one value asked\n"
     << "once, on a new Evaluator: the exact check (GiNaC's substitution) and the balls' setup included;\n"
     << "*GiNaC evalf* substitutes and evaluates the expression tree.\n\n";
  for (auto& [p, t] : target_value) {
    std::vector<std::string> over;
    for (auto& r : rows)
      if (r.path == p && r.ratio > t) {
        char buf[128];
        std::snprintf(buf, sizeof buf, "%s (%.0f×)", r.form.c_str(), r.ratio);
        over.push_back(buf);
      }
    md << "- " << p << ", target " << target[p] << ": ";
    if (over.empty()) {
      md << "met on every form.\n";
    } else {
      md << "missed on " << over.size() << " of " << labels_count(rows, p) << " forms:";
      for (auto& o : over) md << " " << o << (&o == &over.back() ? "." : ",");
      md << "\n";
    }
  }
  // numeric roots (no closed form) to 100 proven digits: the target of issue 15
  md << "\n## Numeric roots, and values with a work integral or a root in them, to 100 proven digits (target: every root; `--digits 100`)\n\n"
     << "| scene | result | time for 100 digits | proven | met |\n|---|---|---:|---|---|\n";
  const std::vector<std::pair<const char*, std::size_t>> found = {
      {"tests/data/wound_spring.yaml", 0},                       // a root
      {"derivations/energy/wheel_cam_couple_angle.yaml", 0},     // a root of an equation with a work integral
      {"derivations/energy/wheel_cam_couple_numeric.yaml", 0},   // a closed form with a work integral
      {"tests/data/numeric/wound_spring_back.yaml", 1},          // a value solved from a root
      {"tests/data/numeric/wound_spring_chained.yaml", 1},       // a root of an equation that holds a root
      {"tests/data/numeric/rod_power_spring.yaml", 0},           // a numeric stationary point
      {"tests/data/numeric/rod_power_spring.yaml", 1},           // the extreme value there
  };
  for (const auto& [file, index] : found) {
    kinergy::Solution s = kinergy::solve_file(root + "/" + file);
    const kinergy::Result& r = s.results.at(index);
    exmap env = s.model.numeric_environment();
    std::optional<kinergy::Value> v;
    std::string why;
    double ns = 0;
    try {
      v = r.evaluate(env, 100, false);
      ns = ns_per_call([&] { r.evaluate(env, 100, false); }, std::max(3, repeats / 3));
    } catch (const std::exception& e) {
      why = e.what();
      why = why.substr(why.find(": ") + 2);
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f ms", ns / 1e6);
    const bool ok = v && v->proven;
    md << "| " << file << " | " << r.name << " | " << (v ? std::string(buf) : "—") << " | "
       << (ok ? "yes" : "no" + (why.empty() ? std::string() : ": " + why)) << " | " << (ok ? "yes" : "**no**") << " |\n";
  }
  md << "\nA root is proven by Newton's steps on ball midpoints, then a ball on which the residual is\n"
     << "defined and whose ends give it opposite proven signs. A work integral (no elementary\n"
     << "antiderivative) is enclosed by Arb's rigorous integration. A value solved from a root, or an\n"
     << "extreme at a numeric stationary point, runs on balls from the root's enclosure; a root of an\n"
     << "equation that holds another root is proven from that root's enclosure.\n";

  md << "\n## Per form (time in ns per evaluation; × hand-written)\n\n| form |";
  for (auto& p : paths) md << " " << p << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < paths.size(); ++i) md << "---:|";
  md << "\n";
  std::vector<std::string> labels;
  for (auto& r : rows)
    if (std::find(labels.begin(), labels.end(), r.form) == labels.end()) labels.push_back(r.form);
  for (auto& l : labels) {
    md << "| " << l << " |";
    for (auto& p : paths)
      for (auto& r : rows)
        if (r.form == l && r.path == p) {
          char buf[64];
          std::snprintf(buf, sizeof buf, " %.3g (%.3g×) |", r.ns, r.ratio);
          md << buf;
        }
    md << "\n";
  }
  char day[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(day, sizeof day, "%Y-%m-%d", std::gmtime(&now));
  md << "\n![error against time](accuracy.svg)\n\nRun on " << day << ". Machine: " << cpu_model() << ", compiler " << __VERSION__
     << ", one thread, Release build.\n";
  std::ofstream(out_dir + "/accuracy.md") << md.str();
  std::cout << md.str();
  return 0;
}
