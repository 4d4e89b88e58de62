// The label measurer against TeX itself: every label of every derivation's figures, set as the
// LaTeX document sets it (11 pt article, \footnotesize and \small), its box measured by TeX
// (\wd, \ht, \dp) and by kinergy's tables of Computer Modern's metrics (src/draw/glyphs.cpp).
// The layout keeps labels off strokes by that measure: it may be larger than TeX's, never smaller.
#include <catch2/catch.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "../../src/draw/glyphs.hpp"
#include "each_figure.hpp"
#include "kinergy/emit/derive.hpp"

TEST_CASE("labels measured from the fonts' metrics: as wide, high and deep as TeX sets them, or a little more", "[draw][labels][pdflatex]") {
  if (!kinergy::emit::have_pdflatex()) return;
  std::set<std::string> labels;
  static const std::regex node("\\\\node\\[anchor=base west[^\\]]*\\] at \\([^)]*\\) \\{\\$(.*)\\$\\};");
  kt::each_figure([&](const std::string&, int, const kinergy::emit::Block& b) {
    const std::string tikz = b.sheet->tikz(b.sheet->size() > 1 ? 15.5 : 10.5, 0, b.sheet->size() > 1 ? 560 : 520);
    for (auto m = std::sregex_iterator(tikz.begin(), tikz.end(), node); m != std::sregex_iterator(); ++m) labels.insert((*m)[1]);
  });
  REQUIRE(labels.size() >= 100);
  // (the preamble derive_latex writes: an 11 pt article with amsmath)
  std::ostringstream tex;
  tex << "\\documentclass[11pt]{article}\n\\usepackage{amsmath,amssymb}\n\\begin{document}\n";
  for (auto& l : labels)
    for (const char* size : {"\\footnotesize", "\\small"})
      tex << "\\setbox0\\hbox{" << size << " $" << l << "$}\\typeout{M: \\the\\wd0 : \\the\\ht0 : \\the\\dp0}\n";
  tex << "\\end{document}\n";
  const auto run = kinergy::emit::run_pdflatex(tex.str(), "");
  static const std::regex line("M: ([0-9.]+)pt ?: ([0-9.]+)pt ?: ([0-9.]+)pt");
  std::vector<std::array<double, 3>> measured;
  for (auto m = std::sregex_iterator(run.log.begin(), run.log.end(), line); m != std::sregex_iterator(); ++m)
    measured.push_back({std::stod((*m)[1]), std::stod((*m)[2]), std::stod((*m)[3])});
  REQUIRE(measured.size() == 2 * labels.size());
  std::size_t i = 0;
  int wider = 0;
  for (auto& l : labels)
    for (double pt : {9.0, 10.0}) {
      const auto& t = measured[i++];
      const auto e = kinergy::draw::detail::tex_extent(l, pt);
      INFO(l << " at " << pt << " pt: TeX " << t[0] << " × (" << t[1] << " + " << t[2] << "), kinergy " << e.width << " × (" << e.above << " + " << e.below << ")");
      // never smaller than TeX's box (by more than rounding), at most a point wider
      CHECK(e.width >= t[0] - 0.02);
      CHECK(e.width <= t[0] + 1.0);
      CHECK(e.above >= t[1] - 0.02);
      CHECK(e.above <= t[1] + 0.6);
      CHECK(e.below >= t[2] - 0.02);
      CHECK(e.below <= t[2] + 0.6);
      wider += e.width > t[0] + 0.3 ? 1 : 0;
    }
  // most within a third of a point (the rest: roman words' ligatures and kerns, left out)
  CHECK(wider <= static_cast<int>(labels.size()) / 2);
}
