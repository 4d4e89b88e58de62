// kinergy — command line: a thin window onto the library.
//   kinergy solve SCENE [--digits N] [--json]
//   kinergy derive SCENE [--latex FILE.tex] [--pdf FILE.pdf] [--digits N]
//   kinergy verify SCENE... [--json]
//   kinergy simulate SCENE --until T [--tol E] [--method M] [--csv FILE] [--plot FILE] [--samples N | --dt T] [--check]
// Exit status: 0 ok, 1 bad scene / no solution / a claim fails, 2 usage.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "kinergy/app/app.hpp"
#include "kinergy/batch/batch.hpp"
#include "kinergy/batch/sweep.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/common/process.hpp"
#include "kinergy/draw/animation.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/emit/emit.hpp"
#include "kinergy/model/poses.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/confirm/confirm.hpp"
#include "kinergy/simulate/report.hpp"
#include "kinergy/simulate/simulate.hpp"
#include "kinergy/verify/verify.hpp"

namespace {

/// A number option's text as a finite double in [lo, hi] (`lo_open`: lo itself excluded), or CLI11's
/// error text. (CLI11 takes "inf", "nan" and an empty text for numbers, and prints a range's
/// bounds in full: 1.797…e308 as 309 digits.)
CLI::Validator finite_in(double lo, double hi, bool lo_open, const std::string& what) {
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        // strtod, not stod: stod refuses a number too small for a normal double (1e-310)
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v)) return "'" + s + "' is not a number: give " + what;
        if (v < lo || v > hi || (lo_open && v == lo)) return s + " is out of range: give " + what;
        return "";
      },
      what);
}

/// An output file whose folder exists and may be written, checked before the work that fills it.
CLI::Validator writable_file() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        namespace fs = std::filesystem;
        if (s.empty()) return "the file name is empty";
        fs::path dir = fs::path(s).parent_path();
        if (dir.empty()) dir = ".";
        std::error_code ec;
        if (!fs::is_directory(dir, ec)) return "the folder '" + dir.string() + "' does not exist: create it first, or write elsewhere";
        if (fs::is_directory(fs::path(s), ec)) return "'" + s + "' is a folder: name a file";
        if (access(dir.c_str(), W_OK) != 0) return "the folder '" + dir.string() + "' may not be written: write elsewhere";
        return "";
      },
      "FILE");
}

/// solve and derive print the results a scene asks for: one that asks for none is refused.
void require_results(const kinergy::Solution& s) {
  if (s.results.empty())
    throw kinergy::SceneError({s.model.file, 1, 1}, "the scene asks for nothing: it has no 'find'",
                              "add a 'find:' section naming the results you want, e.g. 'find: {omega2: theta_dot@2}'");
}

int guarded(const std::string& file, const std::function<int()>& f) {
  try {
    return f();
  } catch (const kinergy::SceneError& e) {
    std::cerr << e.what() << "\n";
  } catch (const kinergy::simulate::SimulationError& e) {
    std::cerr << (e.pos().line > 0 ? e.pos().str() : file) << ": " << e.what() << " \u2014 " << e.fix() << "\n";
  } catch (const kinergy::InputError& e) {
    std::cerr << file << ": " << e.what() << " \u2014 " << e.fix() << "\n";
  } catch (const std::exception& e) {
    std::cerr << file << ":0:0: internal error: " << e.what()
              << " \u2014 this is a bug in kinergy; please report it with the scene\n";
  }
  return 1;
}

}  // namespace

namespace {

/// A scene for a state's numbers: solved when it has analyses (the states' unknown values), else
/// the model alone (the states as given).
struct Loaded {
  std::optional<kinergy::Solution> sol;
  std::optional<kinergy::model::Model> bare;
  /// The scene, with `sets` ("NAME=VALUE", as a scene writes a value) put in.
  /// Why the scene was not solved, where `draw_anyway` let it be drawn from the bare model.
  std::string unsolved;
  explicit Loaded(const std::string& file, const std::vector<std::string>& sets = {}, bool draw_anyway = false) {
    kinergy::scene::SceneDef def = kinergy::scene::load_file(file);
    for (const std::string& t : sets) {
      const std::size_t eq = t.find('=');
      if (eq == std::string::npos || eq == 0)
        throw kinergy::InputError("'" + t + "' does not set a parameter", "write NAME=VALUE as the scene writes a value, e.g. --set L=0.9 m");
      kinergy::app::set_parameter(def, t.substr(0, eq), t.substr(eq + 1));
    }
    if (def.analyses.empty()) {
      bare = kinergy::model::Model::build(def);
      return;
    }
    try {
      sol = kinergy::solve_scene(def);
    } catch (const kinergy::SceneError& e) {
      // (a drawing of a scene that cannot be, as it is given: the reason said beside it)
      if (!draw_anyway) throw;
      unsolved = e.what();
      bare = kinergy::model::Model::build(def);
    }
  }
  const kinergy::model::Model& model() const { return sol ? sol->model : *bare; }
};


/// `kinergy solve`: each unknown in closed form and its value.
struct SolveCommand {
  std::string scene;
  int digits = 15;
  bool as_json = false, no_confirm = false;
  CLI::App* solve = nullptr;

  void add(CLI::App& app) {
    solve = app.add_subcommand("solve", "solve a scene: each unknown in closed form and its value");
    solve->add_option("SCENE", scene, "scene file (YAML)")->required();
    solve->add_option("--digits", digits, "significant digits, proven: ball arithmetic (Arb) from the exact inputs, the precision raised until the ball fixes them; JSON adds the ball (default: 15 from the compiled double evaluator when its error bound fixes them, not proven)")->check(CLI::Range(1, 10000));
    solve->add_flag("--json", as_json, "print JSON for tools");
    solve->add_flag("--no-confirm", no_confirm, "do not confirm each analysis a second way (by a simulation of the same scene, else by the equations' residuals at 50 digits) before printing");
  }

  int run() const {
    return guarded(scene, [&] {
      kinergy::Solution s = kinergy::solve_file(scene);
      require_results(s);
      if (!no_confirm) kinergy::confirm(s);
      kinergy::emit::Options o;
      o.digits = digits;
      o.guaranteed = solve->count("--digits") > 0;
      std::cout << (as_json ? kinergy::emit::json(s, o) : kinergy::emit::text(s, o));
      return 0;
    });
  }
};

/// `kinergy derive`: the worked solution step by step.
struct DeriveCommand {
  std::string scene, tex_out, pdf_out, html_out;
  int derive_digits = 4;
  bool no_checks = false, no_confirm = false;

  void add(CLI::App& app) {
    auto* derive = app.add_subcommand("derive", "the worked solution step by step: text, LaTeX, PDF, or one HTML page");
    derive->add_option("SCENE", scene, "scene file (YAML)")->required();
    derive->add_option("--latex", tex_out, "write a standalone LaTeX document to FILE ('-': standard output)");
    derive->add_option("--pdf", pdf_out, "write a PDF (runs pdflatex in a temporary directory)");
    derive->add_option("--html", html_out, "write one self-contained HTML page: the mathematics typeset by KaTeX, the figures, "
                                           "and the motion of each analysis that can be simulated, animated")
        ->check(writable_file());
    derive->add_option("--digits", derive_digits, "significant digits of the numbers (default 4)")->check(CLI::Range(1, 1000));
    derive->add_flag("--no-checks", no_checks, "leave out the checks of the scene's 'expect' claims");
    derive->add_flag("--no-confirm", no_confirm, "do not confirm each analysis a second way before deriving");
  }

  int run() const {
    return guarded(scene, [&] {
      kinergy::scene::SceneDef def = kinergy::scene::load_file(scene);
      kinergy::Solution s = kinergy::solve_scene(def);
      require_results(s);
      if (!no_confirm) kinergy::confirm(s);
      kinergy::emit::DeriveOptions o;
      o.digits = derive_digits;
      o.checks = !no_checks;
      kinergy::emit::Derivation d = kinergy::emit::derive(s, o);
      if (tex_out.empty() && pdf_out.empty() && html_out.empty()) {
        std::cout << kinergy::emit::text(d);
        return 0;
      }
      if (!html_out.empty()) {
        // the page, with a player for the motion of each analysis that can be simulated
        const std::string page = kinergy::app::derivation_page(s, d);
        std::ofstream out(html_out, std::ios::binary);
        out << page;
        out.close();
        if (!out) throw kinergy::InputError("cannot write the page '" + html_out + "'", "check the directory and its permissions");
        if (tex_out.empty() && pdf_out.empty()) return 0;
      }
      std::string tex = kinergy::emit::latex(d);
      if (tex_out == "-") {
        std::cout << tex;
      } else if (!tex_out.empty()) {
        std::ofstream out(tex_out, std::ios::binary);
        out << tex;
        out.close();
        if (!out) {
          std::cerr << tex_out << ": cannot write the LaTeX file\n";
          return 1;
        }
      }
      if (!pdf_out.empty()) {
        auto r = kinergy::emit::run_pdflatex(tex, pdf_out);
        if (!r.ok) {
          std::cerr << pdf_out << ": " << r.error << "\n";
          return 1;
        }
      }
      return 0;
    });
  }
};

/// `kinergy verify`: every 'expect' claim of the scenes.
struct VerifyCommand {
  std::vector<std::string> scenes;
  bool as_json = false, no_confirm = false;
  double rtol = 0;

  void add(CLI::App& app) {
    auto* verify = app.add_subcommand("verify", "check every 'expect' claim of the scenes");
    verify->add_option("SCENE", scenes, "scene files (YAML)")->required();
    verify->add_flag("--json", as_json, "print JSON for tools");
    verify->add_option("--rtol", rtol, "accept a value within this relative difference of the derived one (e.g. 0.005: books round on the way)")
        ->check(finite_in(0, 1, true, "a relative tolerance such as 0.005"));
    verify->add_flag("--no-confirm", no_confirm, "do not confirm each analysis a second way before checking the claims");
  }

  int run() const {
    int rc = 0;
    for (auto& f : scenes) {
      int r = guarded(f, [&] {
        kinergy::Solution s = kinergy::solve_file(f);
        if (!no_confirm) kinergy::confirm(s);
        auto checks = kinergy::verify::verify(s, rtol);
        bool ok = true;
        for (auto& c : checks) ok = ok && c.ok();
        if (as_json) std::cout << kinergy::emit::json(s, {}, &checks);
        else if (checks.empty()) std::cout << f << ": no claims to check\n";
        else std::cout << kinergy::emit::text(checks, f);
        return ok ? 0 : 1;
      });
      rc = std::max(rc, r);
    }
    return rc;
  }
};

/// `kinergy draw`: the scene at a state, or a figure of its worked solution.
struct DrawCommand {
  std::string scene, draw_state, draw_out;
  std::vector<std::string> sets;
  int draw_figure = 0;

  void add(CLI::App& app) {
    auto* draw = app.add_subcommand("draw", "draw the scene at a state from its model: bodies, points, supports, springs, forces");
    draw->add_option("SCENE", scene, "scene file (YAML)")->required();
    draw->add_option("--state", draw_state, "the state to draw (default: the first that fixes every coordinate, those before it said as left out; 'all': every state side by side)");
    draw->add_option("--figure", draw_figure, "figure N of the worked solution (kinergy derive --pdf numbers them): the scene at its states, "
                                              "an impulse-momentum diagram")
        ->check(CLI::Range(1, 1000000));
    draw->add_option("-o,--output", draw_out, "FILE.svg, FILE.pdf, FILE.png or FILE.tex (a TikZ picture) (default: SVG on standard output)");
    draw->add_option("--set", sets, "NAME=VALUE: draw with parameter NAME at VALUE, as the scene writes a value ('L=0.9 m'); a parameter "
                                    "without a value that is not set is drawn at a sample value (1 in SI units), which stderr names");
  }

  int run() const {
    return guarded(scene, [&]() -> int {
      Loaded in(scene, sets, draw_figure == 0);
      const kinergy::model::Model& m = in.model();
      const auto& sol = in.sol;
      if (!in.unsolved.empty()) std::cerr << scene << ": warning: not solved, so drawn as the scene gives it: " << in.unsolved << "\n";
      if (m.states.empty()) throw kinergy::SceneError({scene, 1, 1}, "the scene has no states to draw", "add a state with every coordinate");
      // a parameter without a value: drawn at a sample value, said
      std::string samples;
      const GiNaC::exmap values = kinergy::draw::with_samples(m, sol ? kinergy::simulate::simulation_values(*sol) : m.parameter_values(), &samples);
      if (!samples.empty())
        std::cerr << scene << ": drawn with sample values for the parameters that have none: " << samples << " (give them with --set NAME=VALUE)\n";
      if (draw_figure > 0) {
        // the derivation's own figures, numbered as in its LaTeX
        if (!sol) throw kinergy::SceneError({scene, 1, 1}, "the scene has no analyses, so its worked solution has no figures", "draw it with --state");
        if (!draw_state.empty()) throw kinergy::InputError("--figure and --state cannot be used together", "leave out one of them");
        const auto d = kinergy::emit::derive(*sol);
        std::vector<const kinergy::emit::Block*> figs;
        for (auto& b : d.blocks)
          if (b.sheet) figs.push_back(&b);
        if (draw_figure > static_cast<int>(figs.size()))
          throw kinergy::InputError("the worked solution of '" + scene + "' has " + std::to_string(figs.size()) + (figs.size() == 1 ? " figure" : " figures") + ", not " +
                                        std::to_string(draw_figure),
                                    "give --figure from 1 to " + std::to_string(figs.size()));
        const auto& sheet = *figs[static_cast<std::size_t>(draw_figure - 1)]->sheet;
        if (draw_out.empty()) std::cout << sheet.svg();
        else kinergy::draw::write(sheet, draw_out);
        return 0;
      }
      std::vector<int> states{0};
      if (draw_state == "all") {
        states.clear();
        for (std::size_t i = 0; i < m.states.size(); ++i) states.push_back(static_cast<int>(i));
      } else if (!draw_state.empty()) {
        states[0] = m.state_index(draw_state);
        if (states[0] < 0)
          throw kinergy::SceneError({scene, 1, 1}, "there is no state '" + draw_state + "'", "name a state of the scene's 'states', or 'all'");
      }
      const GiNaC::exmap solved = sol ? sol->branch.sol : GiNaC::exmap{};
      std::vector<std::string> left_out;
      // by default the first state that can be drawn, those before it said as left out
      const kinergy::draw::Sheet sheet = draw_state.empty() ? kinergy::draw::Sheet(kinergy::draw::first_drawable(m, solved, values, left_out))
                                         : states.size() == 1 ? kinergy::draw::Sheet(kinergy::draw::scene_at(m, solved, values, states[0]))
                                                              : kinergy::draw::states_at(m, solved, values, states, &left_out);
      if (sheet.size() == 0)
        throw kinergy::SceneError({scene, 1, 1}, "no state of the scene fixes every coordinate, so none can be drawn",
                                  "give every coordinate at one state at least");
      for (auto& why : left_out) std::cerr << scene << ": left out of the drawing: " << why << "\n";
      // a pose that cannot be is drawn as the scene gives it, and said (a scene that was solved has
      // none; one that was not said why)
      for (std::size_t st = 0; st < m.states.size() && in.unsolved.empty(); ++st) {
        if (!draw_state.empty() && draw_state != "all" && static_cast<int>(st) != states[0]) continue;
        kinergy::draw::At at;
        try {
          at = kinergy::draw::state_values(m, solved, values, static_cast<int>(st));
        } catch (const kinergy::SceneError&) {
          continue;
        }
        for (auto& o : kinergy::model::overlapping(m, [&](const GiNaC::ex& e) { return at(e); }))
          std::cerr << scene << ": warning: at state '" << m.states[st].name << "' " << o << ": two bodies cannot be in one place (drawn as given)\n";
        if (draw_state.empty()) break;
      }
      if (draw_out.empty()) std::cout << sheet.svg();
      else kinergy::draw::write(sheet, draw_out);
      return 0;
    });
  }
};

/// `kinergy sweep`: a scene over a grid of parameter values.
struct SweepCommand {
  std::string scene;
  std::vector<std::string> sweep_sets;
  std::string sweep_csv, sweep_json, sweep_plot;
  kinergy::batch::SweepOptions options;
  bool no_confirm = false;

  void add(CLI::App& app) {
    auto* sweep = app.add_subcommand("sweep", "solve a scene over a grid of parameter values: CSV, JSON, a plot");
    sweep->add_option("SCENE", scene, "scene file (YAML)")->required();
    sweep->add_option("--set", sweep_sets, "NAME=LO..HI:COUNT, COUNT values from LO to HI in the unit the scene writes NAME in "
                                           "(repeat it for a grid; the last varies fastest)")->required();
    sweep->add_option("--csv", sweep_csv, "write the grid and each result to FILE.csv ('-': standard output, the default without --json)");
    sweep->add_option("--json", sweep_json, "write it as JSON to FILE ('-': standard output)");
    sweep->add_option("--plot", sweep_plot, "draw each result against the first parameter into FILE.svg or FILE.png (gnuplot)");
    sweep->add_flag("--per-point", options.per_point, "solve the scene at every point (slow): no closed form carried between points");
    sweep->add_option("--samples", options.samples, "points solved in full and compared with the closed forms (default 8)")
        ->check(CLI::Range(0, 10000));
    sweep->add_flag("--no-confirm", no_confirm, "do not confirm the sample points' solutions a second way (by simulation)");
    options.jobs = kinergy::available_cores();
    sweep->add_option("--jobs", options.jobs,
                      "processes that solve the points where no closed form is carried (--per-point, a numeric root); "
                      "default: the cores this process may use")
        ->check(CLI::Range(1, 1024));
  }

  int run() {
    return guarded(scene, [&]() -> int {
      const kinergy::scene::SceneDef def = kinergy::scene::load_file(scene);
      std::vector<kinergy::batch::Range> ranges;
      for (auto& t : sweep_sets) ranges.push_back(kinergy::batch::parse_range(t, def));
      if (sweep_csv.empty() && sweep_json.empty() && sweep_plot.empty()) sweep_csv = "-";
      options.confirm = !no_confirm;
      if (!sweep_plot.empty()) kinergy::batch::check_plot(sweep_plot);
      // the rows stream to their files as they come (a sweep of 10^6 points is not held)
      std::ofstream csv_file, json_file;
      auto open = [&](const std::string& path, std::ofstream& f) -> std::ostream* {
        if (path.empty()) return nullptr;
        if (path == "-") return &std::cout;
        f.open(path, std::ios::binary);
        if (!f) throw kinergy::InputError("cannot write '" + path + "'", "check the directory and its permissions");
        return &f;
      };
      std::ostream* csv_out = open(sweep_csv, csv_file);
      std::ostream* json_out = open(sweep_json, json_file);
      std::string cbuf, jbuf;
      bool first = true;
      kinergy::batch::Sweep kept;
      kinergy::batch::PlotRows plotted(ranges);
      const bool terminal = ::isatty(2) != 0;
      if (terminal)
        options.progress = [](std::size_t done, std::size_t total) {
          std::cerr << "\rkinergy sweep: " << done << " / " << total << " points" << std::flush;
        };
      auto flush = [&](bool all) {
        if (csv_out && (all || cbuf.size() > (1u << 16))) *csv_out << cbuf, cbuf.clear();
        if (json_out && (all || jbuf.size() > (1u << 16))) *json_out << jbuf, jbuf.clear();
      };
      kinergy::batch::Sweep::Summary sum = kinergy::batch::sweep_rows(
          def, ranges, options, kept.parameters, kept.results, [&](const kinergy::batch::Sweep::Row& row) {
            if (first) {
              if (csv_out) cbuf = kinergy::batch::csv_header(kept.parameters, kept.results);
              if (json_out) jbuf = kinergy::batch::json_header(kept.parameters, kept.results);
            }
            if (csv_out) kinergy::batch::csv_row(row, cbuf);
            if (json_out) kinergy::batch::json_row(row, first, jbuf);
            if (!sweep_plot.empty()) plotted.add(row);
            first = false;
            flush(false);
          });
      if (json_out) jbuf += kinergy::batch::json_footer(sum);
      flush(true);
      if (csv_out) csv_out->flush();
      if (json_out) json_out->flush();
      if ((csv_out && !*csv_out) || (json_out && !*json_out)) throw kinergy::InputError("cannot write the sweep", "check the disk and the files' directory");
      if (terminal) std::cerr << "\r\33[K";
      if (!sweep_plot.empty()) {
        plotted.rows().parameters = kept.parameters;
        plotted.rows().results = kept.results;
        kinergy::batch::plot(plotted.rows(), def.title, sweep_plot);
      }
      std::cerr << "kinergy sweep: " << sum.points << " points, " << sum.failed << " without a solution; " << sum.closed
                << " by closed form, " << sum.solved << " solved at the point";
      if (!sum.note.empty()) std::cerr << " (" << sum.note << ")";
      if (sum.confirmed > 0)
        std::cerr << "; the closed forms checked against " << sum.confirmed << " sample points solved in full"
                  << (options.confirm ? " and confirmed" : "") << ", largest relative difference " << std::setprecision(2) << sum.difference;
      std::cerr << "\n";
      return 0;
    });
  }
};

/// `kinergy batch`: many requests in one process.
struct BatchCommand {
  std::string batch_in = "-";

  void add(CLI::App& app) {
    auto* batch = app.add_subcommand("batch", "many scenes in one process: JSON Lines of requests in (a file, or '-' for standard input), "
                                              "JSON Lines of results out; a failing request is a result too, and never stops the batch");
    batch->add_option("REQUESTS", batch_in, "JSON Lines file of requests ({\"scene\": FILE} or {\"yaml\": TEXT}, with id, set, "
                                            "produce, digits; see docs/batch.md), '-' for standard input (the default)");
  }

  int run() const {
    // progress on stderr (a terminal's line rewritten), a summary at the end; exit 1 when a request failed
    std::ifstream file;
    if (batch_in != "-") {
      file.open(batch_in);
      if (!file) {
        std::cerr << batch_in << ": cannot read the requests \u2014 check the file's name and permissions\n";
        return 1;
      }
    }
    std::istream& in = batch_in == "-" ? std::cin : file;
    const bool tty = isatty(2);
    auto sum = kinergy::batch::run(in, std::cout, [&](const kinergy::batch::Summary& s) {
      if (tty) std::cerr << "\r" << s.requests << " requests, " << s.ok << " ok, " << s.failed << " failed" << std::flush;
    });
    if (tty) std::cerr << "\r";
    std::cerr << "kinergy batch: " << sum.requests << " requests, " << sum.ok << " ok, " << sum.failed << " failed\n";
    return sum.failed ? 1 : 0;
  }
};

/// `kinergy simulate`: the motion in time from a state, and each analysis run as a simulation.
struct SimulateCommand {
  std::string scene;
  double until = 0, tol = 1e-10, step = 0, sample_dt = 0;
  std::string method = "dopri5", from, csv_out, plot_out, animate_out;
  bool equations = false, check = false, no_native = false, as_json = false;
  int samples = 1000;
  CLI::App* simulate = nullptr;

  void add(CLI::App& app) {
    simulate = app.add_subcommand("simulate", "integrate the scene's motion in time from a state, with only the effects it lists");
    simulate->add_option("SCENE", scene, "scene file (YAML)")->required();
    simulate->add_option("--until", until, "end time in s (absolute, the start state's t is the origin)")
        ->check(finite_in(-1e300, 1e300, false, "a finite end time in s"));
    simulate->add_option("--from", from, "the state to start from (default: the first)");
    simulate->add_option("--tol", tol, "absolute and relative tolerance of the adaptive methods (default 1e-10)")->check(finite_in(1e-15, 1e-1, false, "a tolerance from 1e-15 to 0.1"));
    simulate->add_option("--method", method, "dopri5 (default), rkf78, bs (Bulirsch-Stoer), symplectic (fixed step, separable energy), rk4 (fixed step)");
    simulate->add_option("--step", step, "fixed step of symplectic and rk4 in s (default: span/10000)")
        ->check(finite_in(0, 1e300, true, "a positive step in s"));
    simulate->add_option("--animate", animate_out, "draw the motion into FILE.svg (plays by itself), FILE.html (play/pause, a time slider, "
                                                   "the impacts marked) or FILE.gif (gnuplot), at the samples of --samples/--dt")
        ->check(writable_file());
    simulate->add_option("--csv", csv_out, "write t, q, q_dot, T, V, E per step to FILE")->check(writable_file());
    simulate->add_option("--plot", plot_out, "draw coordinates and energy against time into FILE.svg or FILE.png (gnuplot)")
        ->check(writable_file());
    simulate->add_option("--samples", samples,
                         "for --csv and --plot: samples at N+1 regular times, from the start to --until every (until - start)/N s, from the integrator's dense output, "
                         "with every event exactly (default 1000; 0: the accepted steps themselves)")
        ->check(CLI::Range(0, 10000000));
    simulate->add_option("--dt", sample_dt, "for --csv and --plot: a sample every DT seconds instead of --samples")
        ->check(finite_in(0, 1e300, false, "a positive interval in s"));
    simulate->add_flag("--equations", equations, "print the equations of motion");
    simulate->add_flag("--check", check, "run every analysis of the scene as a simulation and compare with the closed forms");
    simulate->add_flag("--no-native", no_native, "evaluate the right-hand side by the tape instead of compiled machine code");
    simulate->add_flag("--json", as_json, "print the run for tools: the end state, every switch and impact at its instant, the log and the energy audit");
  }

  /// --check: every analysis run as a simulation and compared; an exit status when that is all
  /// there is to do (or a leg fails).
  std::optional<int> check_legs(const kinergy::model::Model& m, const std::optional<kinergy::Solution>& sol,
                                const kinergy::simulate::Options& o) const {
    namespace sim = kinergy::simulate;
    if (!sol) throw kinergy::SceneError({scene, 1, 1}, "the scene has no analyses, so no closed form to check", "add an analysis, or leave out --check");
    int bad = 0;
    for (auto& leg : sim::legs(*sol)) {
      const auto& a = m.analyses[static_cast<std::size_t>(leg.analysis)];
      if (a.type->at_state()) {
        // kinetics at a state: its accelerations against the equations of motion there
        std::cout << a.kind << " at " << m.states[leg.from].name << ": ";
        try {
          auto k = kinergy::check_kinetics(*sol, leg.analysis);
          std::cout << "the accelerations against the equations of motion; largest relative difference " << k.worst
                    << (k.what.empty() ? "" : " (" + k.what + ")") << (k.ok ? " ok" : " FAILS") << "\n";
          bad += k.ok ? 0 : 1;
        } catch (const kinergy::SceneError& e) {
          std::cout << "not checked: " << e.problem() << "\n";  // a state that does not fix a coordinate
        }
        continue;
      }
      std::cout << a.kind << " " << m.states[leg.from].name << " -> " << m.states[leg.to].name << ": ";
      if (!leg.why_not.empty()) {
        std::cout << "not simulated: " << leg.why_not << "\n";
        continue;
      }
      auto c = sim::check_leg(*sol, leg, o, std::max(100 * tol, 1e-13));
      // one verdict with solve's confirmation: a run the scene's effects do not take to the end
      // of an analysis over impulses is no second opinion, not a failure
      const bool none = kinergy::no_second_opinion(a, c);
      std::cout << "until " << leg.target << ", " << c.run.steps << " steps; largest relative difference "
                << c.worst << (c.worst_what.empty() ? "" : " (" + c.worst_what + ")")
                << (c.ok ? " ok" : none ? " not confirmed by simulation (no second opinion: the scene's effects alone do not take the motion there)" : " FAILS")
                << (c.note.empty() ? "" : "; " + c.note) << "\n";
      bad += c.ok || none ? 0 : 1;
    }
    if (!sol->model.analyses.empty() && !simulate->count("--until")) return bad ? 1 : 0;
    if (bad) return 1;
    return std::nullopt;
  }

  int run() {
    return guarded(scene, [&]() -> int {
      namespace sim = kinergy::simulate;
      Loaded in(scene);
      const kinergy::model::Model& m = in.model();
      const auto& sol = in.sol;
      if (!animate_out.empty()) {
        auto ext = std::filesystem::path(animate_out).extension();
        if (ext != ".svg" && ext != ".html" && ext != ".gif")
          throw kinergy::InputError("the animation '" + animate_out + "' is not .svg, .html or .gif", "name it FILE.svg, FILE.html or FILE.gif");
      }
      if (!plot_out.empty()) {
        auto ext = std::filesystem::path(plot_out).extension();
        if (ext != ".svg" && ext != ".png")
          throw kinergy::InputError("the plot '" + plot_out + "' is neither .svg nor .png", "name the plot FILE.svg or FILE.png");
      }
      sim::Options o;
      o.method = sim::method_from_name(method);
      o.tol = tol;
      o.step = step;
      o.native = !no_native;
      if (equations) std::cout << sim::equations_of_motion(m).text(m) << "\n";
      if (check)
        if (auto rc = check_legs(m, sol, o)) return *rc;
      if (!simulate->count("--until")) {
        if (equations) return 0;
        throw kinergy::SceneError({scene, 1, 1}, "simulate needs an end time", "add --until T (seconds)");
      }
      const int start = kinergy::app::state_index(m, from);
      sim::State s0 = kinergy::app::start_values(m, sol ? &*sol : nullptr, start);
      // a progress bar on stderr for long runs in a terminal
      const bool tty = isatty(2);
      auto t0 = std::chrono::steady_clock::now();
      bool shown = false;
      if (tty)
        o.progress = [&](double f) {
          double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          if (el < 0.5 && f < 1) return;
          int w = static_cast<int>(f * 40);
          std::cerr << "\r[" << std::string(static_cast<std::size_t>(w), '#') << std::string(static_cast<std::size_t>(40 - w), ' ') << "] "
                    << static_cast<int>(f * 100) << "%" << std::flush;
          shown = true;
        };
      // what --csv and --plot draw: regular samples (dense output), or the accepted steps
      if (!csv_out.empty() || !plot_out.empty() || !animate_out.empty()) o.sample_dt = sample_dt > 0 ? sample_dt : samples > 0 ? (until - s0.t) / samples : 0;
      const bool impulses = sim::impulses_at(m, start);
      auto c0 = std::chrono::steady_clock::now();
      // effects switched on or off at states are followed: the run switches them where it reaches those states
      sim::Run r = sim::run_following(m, sol ? sol->branch.sol : GiNaC::exmap{}, sol ? sim::simulation_values(*sol) : m.parameter_values(),
                                      start, s0, until, o, impulses);
      double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
      if (shown) std::cerr << "\n";
      // the model the run integrated: the scene's, with the gaps of the surfaces its bodies may leave
      const kinergy::model::Model& rm = r.model ? *r.model : m;
      if (as_json) std::cout << sim::json(rm, r);
      else
        std::cout << m.title << "\n"
                << "method " << sim::method_name(o.method) << ", tol " << tol << ", right-hand side " << (o.native ? "compiled" : "tape")
                << "; from state '" << m.states[static_cast<std::size_t>(start)].name << "' at t = " << s0.t << " s\n"
                << r.steps << " steps (" << r.rejected << " rejected), " << r.rhs_calls << " right-hand side evaluations, "
                << secs * 1e3 << " ms\n"
                << sim::text(rm, r);
      if (!csv_out.empty()) {
        std::ofstream out(csv_out);
        out << sim::csv(rm, r);
        if (!out) throw kinergy::InputError("cannot write the CSV file '" + csv_out + "'", "check the free space and the file's permissions");
      }
      if (!plot_out.empty()) sim::plot(rm, r, plot_out);
      if (!animate_out.empty()) {
        // the same samples, each drawn; every impact marked at its instant
        kinergy::draw::write_animation(rm, sol ? sim::simulation_values(*sol) : m.parameter_values(), sim::motion_of(r, m.title), animate_out);
      }
      return 0;
    });
  }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"kinergy: plane rigid-body motion by energy and momentum, in closed form", "kinergy"};
  app.require_subcommand(1);
#ifndef KINERGY_VERSION
#define KINERGY_VERSION "unknown"
#endif
  app.set_version_flag("--version", std::string("kinergy ") + KINERGY_VERSION);
  SolveCommand solve;
  DeriveCommand derive;
  VerifyCommand verify;
  DrawCommand draw;
  BatchCommand batch;
  SweepCommand sweep;
  SimulateCommand simulate;
  solve.add(app);
  derive.add(app);
  verify.add(app);
  draw.add(app);
  batch.add(app);
  sweep.add(app);
  simulate.add(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  // one subcommand is required: run it
  const std::string chosen = app.get_subcommands().front()->get_name();
  if (chosen == "solve") return solve.run();
  if (chosen == "derive") return derive.run();
  if (chosen == "verify") return verify.run();
  if (chosen == "draw") return draw.run();
  if (chosen == "batch") return batch.run();
  if (chosen == "sweep") return sweep.run();
  return simulate.run();
}
