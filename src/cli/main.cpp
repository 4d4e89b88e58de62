// kinergy — command line: a thin window onto the library.
//   kinergy solve SCENE [--digits N] [--json]
//   kinergy derive SCENE [--latex FILE.tex] [--pdf FILE.pdf] [--digits N]
//   kinergy verify SCENE... [--json]
// Exit status: 0 ok, 1 bad scene / no solution / a claim fails, 2 usage.
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>

#include "kinergy/common/error.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/emit/emit.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/verify/verify.hpp"

namespace {

int guarded(const std::string& file, const std::function<int()>& f) {
  try {
    return f();
  } catch (const kinergy::SceneError& e) {
    std::cerr << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << file << ":0:0: internal error: " << e.what()
              << " \u2014 this is a bug in kinergy; please report it with the scene\n";
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  kinergy::reproducible_process(argc, argv);
  CLI::App app{"kinergy: plane rigid-body motion by energy and momentum, in closed form"};
  app.require_subcommand(1);
  int digits = 15;
  bool as_json = false;
  std::string scene;
  std::vector<std::string> scenes;

  auto* solve = app.add_subcommand("solve", "solve a scene: each unknown in closed form and its value");
  solve->add_option("SCENE", scene, "scene file (YAML)")->required();
  solve->add_option("--digits", digits, "significant digits, guaranteed: CLN at a working precision raised until they settle (default: 15 from the compiled double evaluator when its error bound fixes them)")->check(CLI::Range(1, 10000));
  solve->add_flag("--json", as_json, "print JSON for tools");

  std::string tex_out, pdf_out;
  int derive_digits = 4;
  bool no_checks = false;
  auto* derive = app.add_subcommand("derive", "the worked solution step by step: text, or LaTeX / PDF");
  derive->add_option("SCENE", scene, "scene file (YAML)")->required();
  derive->add_option("--latex", tex_out, "write a standalone LaTeX document to FILE ('-': standard output)");
  derive->add_option("--pdf", pdf_out, "write a PDF (runs pdflatex in a temporary directory)");
  derive->add_option("--digits", derive_digits, "significant digits of the numbers (default 4)")->check(CLI::Range(1, 1000));
  derive->add_flag("--no-checks", no_checks, "leave out the checks of the scene's 'expect' claims");

  auto* verify = app.add_subcommand("verify", "check every 'expect' claim of the scenes");
  verify->add_option("SCENE", scenes, "scene files (YAML)")->required();
  verify->add_flag("--json", as_json, "print JSON for tools");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }

  if (*solve) {
    return guarded(scene, [&] {
      kinergy::Solution s = kinergy::solve_file(scene);
      kinergy::emit::Options o;
      o.digits = digits;
      o.guaranteed = solve->count("--digits") > 0;
      std::cout << (as_json ? kinergy::emit::json(s, o) : kinergy::emit::text(s, o));
      return 0;
    });
  }
  if (*derive) {
    return guarded(scene, [&] {
      kinergy::scene::SceneDef def = kinergy::scene::load_file(scene);
      kinergy::Solution s = kinergy::solve_scene(def);
      kinergy::emit::DeriveOptions o;
      o.digits = derive_digits;
      o.checks = !no_checks;
      kinergy::emit::Derivation d = kinergy::emit::derive(s, def, o);
      if (tex_out.empty() && pdf_out.empty()) {
        std::cout << kinergy::emit::text(d);
        return 0;
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
  int rc = 0;
  for (auto& f : scenes) {
    int r = guarded(f, [&] {
      kinergy::Solution s = kinergy::solve_file(f);
      auto checks = kinergy::verify::verify(s);
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
