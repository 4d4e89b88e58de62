// derive --html (issue 14, item 5): every derivation as one self-contained page, opened in
// headless Chromium (Debian's chromium): all its mathematics typeset by KaTeX without an error,
// its figures there, and each animation's drawing different at its last frame from its first.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "../support/helpers.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/problem.hpp"

namespace fs = std::filesystem;

TEST_CASE("derive --html without KaTeX says which Debian package has it", "[emit][html]") {
  kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/sliding_rod.yaml");
  auto d = kinergy::emit::derive(s);
  kinergy::emit::HtmlOptions o;
  o.katex_dir = "/nonexistent/katex";
  try {
    kinergy::emit::html(d, {}, o);
    FAIL("no error without KaTeX");
  } catch (const kinergy::InputError& e) {
    CHECK(std::string(e.what()) == "KaTeX is not installed (/nonexistent/katex/katex.min.js), so the page's mathematics cannot be typeset");
    CHECK(e.fix() == "install Debian's libjs-katex (bash .ci/setup --deps)");
  }
}

TEST_CASE("every derivation's page in headless Chromium: the mathematics typeset, the figures, the animations moving",
          "[emit][html][browser][slow]") {
  const std::string chromium = kt::chromium();
  if (chromium.empty()) {
    WARN("chromium is not installed: the pages are not opened (bash .ci/setup --deps installs it)");
    return;
  }
  // (a directory and a browser profile of this process's own: two suites run at once on one
  // machine do not remove each other's pages, nor meet in one profile)
  const fs::path dir = fs::temp_directory_path() / ("kinergy-pages-test-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<std::string> names;
  for (const auto& file : kt::scene_files("derivations")) {
    const std::string name = fs::path(file).stem().string() + ".html";
    int st = 0;
    std::string out = kt::run_cli("derive " + file + " --html " + (dir / name).string(), st);
    INFO(file << ": " << out);
    REQUIRE(st == 0);
    names.push_back(name);
  }
  REQUIRE(names.size() >= 60);
  // one browser for every page: a harness loads each in a frame (same directory, so its document
  // can be read), counts the typeset mathematics and its errors, the figures, and shows each
  // animation's first and last frames
  std::string list;
  for (auto& n : names) list += (list.empty() ? "'" : ",'") + n + "'";
  {
    std::ofstream h(dir / "harness.html");
    h << "<!DOCTYPE html><html><body><iframe id=\"f\" style=\"width:1000px;height:800px\"></iframe><script>\n"
         "const names = [" << list << "], out = [];\nlet i = 0;\nconst f = document.getElementById('f');\n"
         "function next() { if (i >= names.length) { document.body.setAttribute('data-done', out.join(';')); return; } f.src = names[i]; }\n"
         "f.addEventListener('load', function () {\n"
         "  const d = f.contentDocument, w = f.contentWindow;\n"
         "  const moved = [];\n"
         "  const anims = w.kinergyAnimations || {};\n"
         "  for (const id in anims) {\n"
         "    const a = anims[id], root = d.getElementById(id);\n"
         "    a.show(0); const g0 = root.querySelector('g[data-frame][display=\"inline\"]').innerHTML;\n"
         "    a.show(a.times.length - 1); const g1 = root.querySelector('g[data-frame][display=\"inline\"]').innerHTML;\n"
         "    moved.push(g0 !== g1 ? 1 : 0);\n"
         "  }\n"
         "  let least = 1000;\n"
         "  d.querySelectorAll('figure svg').forEach(function (s) {\n"
         "    s.querySelectorAll('text').forEach(function (t) { least = Math.min(least, t.getBoundingClientRect().height); });\n"
         "  });\n"
         "  out.push(names[i] + ' ' + d.body.getAttribute('data-math') + ' ' + d.querySelectorAll('.katex').length + ' ' +\n"
         "           d.querySelectorAll('.katex-error').length + ' ' + d.querySelectorAll('figure svg').length + ' ' + moved.join('') +\n"
         "           ' ' + Math.round(least * 100));\n"
         "  i++; next();\n"
         "});\nnext();\n</script></body></html>\n";
  }
  const std::string dom = kt::run_command(chromium + " --headless --no-sandbox --disable-gpu --user-data-dir=" + (dir / "profile").string() + " --allow-file-access-from-files "
                                                     "--virtual-time-budget=120000 --dump-dom file://" + (dir / "harness.html").string() +
                                          " 2>/dev/null");
  std::smatch all;
  REQUIRE(std::regex_search(dom, all, std::regex("data-done=\"([^\"]*)\"")));
  const std::string done = all[1];
  std::regex rec("([a-z0-9_]+\\.html) ([0-9]+) ([0-9]+) ([0-9]+) ([0-9]+) ([0-9]+) ([01]*) ([0-9]+)");
  std::size_t pages = 0, animations = 0;
  for (auto it = std::sregex_iterator(done.begin(), done.end(), rec); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    INFO(m[1]);
    const int typeset = std::stoi(m[2]), failed = std::stoi(m[3]), katex = std::stoi(m[4]), errors = std::stoi(m[5]), figures = std::stoi(m[6]);
    CHECK(typeset >= 20);     // every page has its kinematics, states, principles and results in TeX
    CHECK(failed == 0);       // KaTeX refused none
    CHECK(errors == 0);
    CHECK(katex == typeset);  // each typeset piece is on the page
    CHECK(figures >= 1);      // the states at least
    for (char c : m[7].str()) CHECK(c == '1');
    // every figure's words as tall on the page as 8 pt (10.7 px) or more: not scaled down (a
    // label's box is 1.16 times its size in DejaVu Sans)
    CHECK(std::stoi(m[8]) / 100.0 >= 1.1 * 8 * 96 / 72.0);
    animations += m[7].str().size();
    ++pages;
  }
  CHECK(pages == names.size());
  CHECK(animations >= 70);  // every analysis that can be simulated, impacts with what follows them
  // a screenshot of a page: the rendered mathematics as a person sees it (a PNG of some size)
  const fs::path shot = dir / "sliding_rod.png";
  kt::run_command(chromium + " --headless --no-sandbox --disable-gpu --user-data-dir=" + (dir / "profile").string() + " --hide-scrollbars --window-size=1000,1400 --virtual-time-budget=3000 "
                             "--screenshot=" + shot.string() + " file://" + (dir / "sliding_rod.html").string() + " >/dev/null 2>&1");
  const std::string png = kt::read_file(shot);
  REQUIRE(png.size() > 20000);
  CHECK(png.substr(1, 3) == "PNG");
  fs::remove_all(dir);
}
