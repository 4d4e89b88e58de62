// LaTeX printing of closed forms and names, and the derivations as real LaTeX: every one in
// derivations/ goes through pdflatex without an error and without an overfull line.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kinergy/emit/derive.hpp"
#include "kinergy/emit/latex.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"

namespace fs = std::filesystem;
using namespace GiNaC;
using kinergy::emit::latex;
using kinergy::emit::tex_name;

namespace {

std::vector<std::string> derivation_files() {
  std::vector<std::string> out;
  for (auto& e : fs::recursive_directory_iterator(fs::path(KINERGY_SOURCE_DIR) / "derivations"))
    if (e.path().extension() == ".yaml") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string relative(const std::string& f) { return fs::relative(f, KINERGY_SOURCE_DIR).generic_string(); }

}  // namespace

TEST_CASE("TeX names of scene symbols", "[emit][latex]") {
  CHECK(tex_name("theta") == "\\theta");
  CHECK(tex_name("theta2") == "\\theta_{2}");
  CHECK(tex_name("omega_A") == "\\omega_{A}");
  CHECK(tex_name("I_O") == "I_{O}");
  CHECK(tex_name("mu_k") == "\\mu_{k}");
  CHECK(tex_name("m1") == "m_{1}");
  CHECK(tex_name("xA") == "x_{A}");
  CHECK(tex_name("phi_dot") == "\\dot{\\phi}");
  CHECK(tex_name("theta_dot@2") == "\\dot{\\theta}_{2}");
  CHECK(tex_name("xA_dot@before") == "(\\dot{x}_{A})_{\\mathrm{before}}");
  CHECK(tex_name("J_hit[before,after]") == "J_{\\mathrm{hit}}");
  CHECK(tex_name("Jt_hit[1,2]") == "J_{t,\\mathrm{hit}}");
  CHECK(tex_name("lost") == "\\mathrm{lost}");
  CHECK(tex_name("v0") == "v_{0}");
  CHECK(tex_name("pin") == "\\mathrm{pin}");  // not \pi_{n}
  CHECK(tex_name("beta") == "\\beta");
  CHECK(tex_name("k_needed") == "k_{\\mathrm{needed}}");
  CHECK(tex_name("t@after") == "t_{\\mathrm{after}}");
  CHECK(tex_name("lambda1[before,after]") == "\\lambda_{1}");
}

TEST_CASE("closed forms in LaTeX, as a person writes them", "[emit][latex]") {
  possymbol g("g"), l("l"), m("m"), h("h"), r("r");
  realsymbol th2("theta2"), thd("theta_dot@2"), beta("beta"), e("e");
  CHECK(latex(sqrt(3 * g * sin(th2) / l)) == "\\sqrt{\\frac{3 g \\sin \\theta_{2}}{l}}");
  CHECK(latex(m * sqrt(2 * g * h) / 4) == "\\frac{1}{4} m \\sqrt{2 g h}");
  CHECK(latex(pow(l, 2) * m * pow(thd, 2) / 6) == "\\frac{1}{6} l^{2} m \\dot{\\theta}_{2}^{2}");
  CHECK(latex(-3 * sqrt(2 * g * h) / (2 * l)) == "-\\frac{3 \\sqrt{2 g h}}{2 l}");
  CHECK(latex(pow(cos(beta), 2)) == "\\cos^{2} \\beta");
  CHECK(latex(m * (1 + e) * cos(beta) / (m + r)) == "\\frac{m (1 + e) \\cos \\beta}{m + r}");
  CHECK(latex(r * sin(beta) / sqrt(pow(l, 2) - pow(r, 2))) == "\\frac{r \\sin \\beta}{\\sqrt{l^{2} - r^{2}}}");
  CHECK(latex(g - m * (h - r)) == "g - m (h - r)");  // never "g + -m (r - h)"
  CHECK(latex(sin(beta + th2)) == "\\sin(\\beta + \\theta_{2})");
  CHECK(latex(sqrt(4 * g * h * sin(beta) / 3)) == "\\sqrt{\\frac{4 g h \\sin \\beta}{3}}");
}

TEST_CASE("parameter values with units in place of names", "[emit][latex]") {
  possymbol g("g"), l("l");
  realsymbol th2("theta2");
  kinergy::emit::TexSymbols v;
  v[g] = {"9.81\\,\\mathrm{m/s^{2}}", false};
  v[l] = {"1.2\\,\\mathrm{m}", false};
  v[th2] = {"30^{\\circ}", true};
  CHECK(latex(sqrt(3 * g * sin(th2) / l), &v) ==
        "\\sqrt{\\frac{3 \\left(9.81\\,\\mathrm{m/s^{2}}\\right) \\sin 30^{\\circ}}{1.2\\,\\mathrm{m}}}");
  kinergy::emit::SymbolTexts t{{g, "9.81 m/s^2"}, {l, "1.2 m"}, {th2, "30 deg"}};
  CHECK(kinergy::emit::plain(sqrt(3 * g * sin(th2) / l), t) == "sqrt(3*(9.81 m/s^2)*sin(30 deg)/(1.2 m))");
  CHECK(kinergy::emit::tex_unit("m/s^2") == "\\mathrm{m/s^{2}}");
  CHECK(kinergy::emit::tex_unit("N*m") == "\\mathrm{N\\,m}");
  CHECK(kinergy::emit::tex_quantity("1.5e-3", "kg") == "1.5\\times 10^{-3}\\,\\mathrm{kg}");
}

TEST_CASE("sums split at their top-level terms", "[emit][latex]") {
  auto t = kinergy::emit::tex_terms("a + \\frac{b - c}{d} - \\left(e + f\\right)");
  REQUIRE(t.size() == 3);
  CHECK(t[0] == "a");
  CHECK(t[1] == "+ \\frac{b - c}{d}");
  CHECK(t[2] == "- \\left(e + f\\right)");
  CHECK(kinergy::emit::tex_width("\\frac{1}{2} m v^{2}") < kinergy::emit::tex_width("\\frac{1}{2} m v^{2} + m g h"));
}

TEST_CASE("the text derivation of the sliding rod", "[emit][derive]") {
  std::string f = std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/sliding_rod.yaml";
  auto def = kinergy::scene::load_file(f);
  kinergy::Solution s = kinergy::solve_scene(def);
  auto d = kinergy::emit::derive(s);
  std::string t = kinergy::emit::text(d);
  INFO(t);
  for (const char* part : {"Given", "Kinematics", "States", "Conservation of energy, states 1 \u2192 2",
                           "The system of equations", "Solution", "Results", "(E1.5)",
                           "theta_dot@2 = sqrt(3*g*sin(theta2)/l)", "sqrt(3*(9.81 m/s^2)*sin(30 deg)/(1.2 m))",
                           "= 3.502 rad/s", "form: proved"})
    CHECK(t.find(part) != std::string::npos);
  std::string x = kinergy::emit::latex(d);
  CHECK(x.find("\\documentclass") != std::string::npos);
  CHECK(x.find("\\tag{E1.5}\\label{eq:E1.5}") != std::string::npos);
  CHECK(x.find("\\end{document}") != std::string::npos);
}

TEST_CASE("every derivation compiles with pdflatex, nothing running off the page", "[emit][pdflatex][slow]") {
  if (!kinergy::emit::have_pdflatex()) {
    WARN("pdflatex is not installed: the LaTeX of the derivations is not compiled (bash .ci/setup --deps installs it)");
    return;
  }
  auto files = derivation_files();
  REQUIRE(files.size() >= 12);
  for (auto& f : files) {
    DYNAMIC_SECTION(relative(f)) {
      auto def = kinergy::scene::load_file(f);
      kinergy::Solution s = kinergy::solve_scene(def);
      auto d = kinergy::emit::derive(s);
      d.file = relative(f);
      std::string tex = kinergy::emit::latex(d);
      auto r = kinergy::emit::run_pdflatex(tex, "");
      REQUIRE(r.ran);
      {
        auto e = r.log.find("\n! ");
        INFO((e == std::string::npos ? std::string("no error in the log") : r.log.substr(e, 600)));
        CHECK(r.ok);
        CHECK(e == std::string::npos);
      }
      for (double pt : kinergy::emit::overfull_boxes(r.log)) {
        // the place: "detected at line N" (a display) or "in paragraph at lines N--M"
        auto p = r.log.find("Overfull \\hbox (");
        std::string where = p == std::string::npos ? "" : r.log.substr(p, 120);
        std::string line;
        auto at = where.find("line");
        if (at != std::string::npos) {
          std::size_t k = at;
          while (k < where.size() && !std::isdigit(static_cast<unsigned char>(where[k]))) ++k;
          int n = std::atoi(where.c_str() + k);
          std::istringstream in(tex);
          for (int i = 1; i <= n && std::getline(in, line); ++i) {
          }
        }
        INFO("Overfull \\hbox of " << pt << " pt: " << where << "\n" << line);
        CHECK(pt <= 5.0);
      }
    }
  }
}

TEST_CASE("pdflatex errors are reported, and kinergy derive --pdf writes a PDF", "[emit][pdflatex][cli]") {
  if (!kinergy::emit::have_pdflatex()) {
    WARN("pdflatex is not installed: --pdf is not tried (bash .ci/setup --deps installs it)");
    return;
  }
  auto bad = kinergy::emit::run_pdflatex("\\documentclass{article}\\begin{document}\\nosuchcommand\\end{document}\n", "");
  CHECK(bad.ran);
  CHECK_FALSE(bad.ok);
  CHECK(bad.error.find("Undefined control sequence") != std::string::npos);

  fs::path pdf = fs::temp_directory_path() / ("kinergy-derive-" + std::to_string(::getpid()) + ".pdf");
  std::string cmd = std::string(KINERGY_CLI) + " derive " + KINERGY_SOURCE_DIR + "/derivations/energy/sliding_rod.yaml --pdf " +
                    pdf.string() + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  char buf[4096];
  std::string out;
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  int st = pclose(p);
  INFO(out);
  CHECK(st == 0);
  REQUIRE(fs::exists(pdf));
  std::ifstream in(pdf, std::ios::binary);
  std::string head(4, '\0');
  in.read(head.data(), 4);
  CHECK(head == "%PDF");
  fs::remove(pdf);
}

TEST_CASE("a pdflatex run without TikZ says which Debian package draws the figures", "[emit][pdflatex]") {
  // the log pdflatex writes when a package is missing (TeX Live 2022), and one with another error
  const std::string missing = "(./derivation.tex\n! LaTeX Error: File `tikz.sty' not found.\n\nType X to quit or <RETURN> to proceed,\n";
  CHECK(kinergy::emit::pdflatex_error(missing, 1) ==
        "pdflatex cannot find TikZ (tikz.sty), which draws the figures: install Debian's texlive-pictures (bash .ci/setup --deps)");
  CHECK(kinergy::emit::pdflatex_error("x\n! Undefined control sequence.\nl.3 \\nosuch", 1) == "pdflatex failed: ! Undefined control sequence. l.3 \\nosuch");
  CHECK(kinergy::emit::pdflatex_error("no error line", 7) == "pdflatex failed: exit status 7");
}
