/// @file derive.hpp  A worked solution, step by step: the problem, the given data, the
/// kinematics, each principle applied, the system, its solution in closed form and the numbers.
/// Built once from a Solution (derive), then written as plain Unicode text for terminals
/// (text) or as a standalone LaTeX document (latex; pdf runs pdflatex on it).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/draw/figure.hpp"
#include "kinergy/emit/emit.hpp"
#include "kinergy/emit/latex.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"

namespace kinergy::emit {

/// A piece of mathematics: an expression (printed by the plain or the LaTeX printer), or
/// fixed notation written out in both forms ("T_{1} + V_{1}" / "T₁ + V₁").
struct Math {
  GiNaC::ex e;
  std::string tex, text;  ///< fixed notation (used when either is set)
  bool values = false;    ///< print with the parameters replaced by their values and units
  std::string pre_tex, pre_text;  ///< notation before the expression ("\bar{I} = ")
  bool has_rhs = false;   ///< an inline equation "e = rhs"
  GiNaC::ex rhs;
  bool fixed() const { return !tex.empty() || !text.empty(); }
  static Math of(const GiNaC::ex& x, bool values = false) { return {x, "", "", values, "", "", false, 0}; }
  static Math notation(std::string tex, std::string text) {
    return {0, std::move(tex), std::move(text), false, "", "", false, 0};
  }
  /// "pre = x" inline, pre in both forms.
  static Math named(std::string pre_tex, std::string pre_text, const GiNaC::ex& x) {
    return {x, "", "", false, std::move(pre_tex) + " = ", std::move(pre_text) + " = ", false, 0};
  }
  /// "a = b" inline.
  static Math equation(const GiNaC::ex& a, const GiNaC::ex& b) { return {a, "", "", false, "", "", true, b}; }
};

/// Words and inline mathematics, in order.
struct Span {
  std::string words;  ///< text (when math is not set)
  bool is_math = false;
  Math math;
  static Span w(std::string s) { return {std::move(s), false, {}}; }
  static Span m(Math x) { return {"", true, std::move(x)}; }
};
using Spans = std::vector<Span>;

/// A displayed equation: sides joined by "=" (a chain), one tag; `also` holds more equations
/// shown beside it (x̄ = …, ȳ = …).
struct Row {
  std::vector<Math> sides;
  std::vector<std::vector<Math>> also;
  std::string tag;    ///< "E1.3": principle letter, analysis, number
  std::string label;  ///< \label key, unique in the document (empty: the tag is shown again)
};

struct Block {
  enum class Kind { Section, Subsection, Paragraph, Equations, Table, Figure };
  Kind kind = Kind::Paragraph;
  std::string title;                ///< Section, Subsection
  Spans spans;                      ///< Paragraph
  std::vector<Row> rows;            ///< Equations
  std::vector<std::string> header;  ///< Table: column titles
  std::vector<std::vector<Spans>> cells;  ///< Table: rows of cells
  std::shared_ptr<const draw::Sheet> sheet;  ///< Figure: the drawing (its caption is `title`); the LaTeX only
};

/// The width (pixels) the HTML page draws a figure at: no wider than the page's column (52em,
/// 832 px), so that the browser does not scale it down and its labels stay at 13 px (about the
/// body text's 16 px, above 8 pt): 640 for one panel, 800 for several.
int html_figure_width(const draw::Sheet& s);

struct Derivation {
  std::string title, description, file;
  std::vector<Block> blocks;
  std::string legend;       ///< "Equations are tagged by where they come from: K kinematics, …"
  SymbolTexts values_text;  ///< parameter → "9.81 m/s^2" (plain)
  TexSymbols values_tex;    ///< parameter → 9.81\,\mathrm{m/s^{2}}
  TexSymbols names;         ///< symbols whose TeX name would clash with another's
};

struct DeriveOptions {
  int digits = 4;       ///< significant digits of the numbers
  bool checks = true;   ///< end with the `expect` claims checked
};

/// The worked solution of a solved scene. `def` is the scene as written (parameter values and
/// units as the author wrote them, inertia kinds).
Derivation derive(const Solution& s, const DeriveOptions& o = {});

/// Plain Unicode text for terminals; expressions in the plain printer's form.
std::string text(const Derivation& d);

/// A standalone LaTeX document (article, amsmath); every equation tagged and labelled.
std::string latex(const Derivation& d);

struct HtmlOptions {
  std::string katex_dir = "/usr/share/javascript/katex";  ///< Debian's libjs-katex (katex.min.js, .css, fonts/)
};

/// One self-contained HTML page: the derivation's text, its mathematics typeset by KaTeX in the
/// browser (script, style and fonts inlined from `katex_dir`), its figures as inline SVG, and
/// `animations` (players from draw::animation_fragment) in a last section.
/// @throws InputError when KaTeX is not installed.
std::string html(const Derivation& d, const std::vector<std::string>& animations, const HtmlOptions& o = {});

/// What pdflatex did with a document.
struct PdfRun {
  bool ran = false;    ///< pdflatex was found and started
  bool ok = false;     ///< exit status 0 and a PDF written
  std::string log;     ///< the .log file
  std::string output;  ///< pdflatex's terminal output
  std::string error;   ///< what went wrong, in one line (empty when ok)
};

/// What went wrong in a failed pdflatex run, in one line, from its log (a missing package named by
/// the Debian package that has it).
std::string pdflatex_error(const std::string& log, int exit_status);

/// Is pdflatex on the PATH?
bool have_pdflatex();

/// Run pdflatex (-interaction=nonstopmode -halt-on-error, twice for references) on `tex` in a
/// fresh temporary directory; when it succeeds and `pdf_path` is not empty, copy the PDF there.
PdfRun run_pdflatex(const std::string& tex, const std::string& pdf_path);

/// Overfull \hbox warnings in a pdflatex log: the amount of each, in pt.
std::vector<double> overfull_boxes(const std::string& log);

}  // namespace kinergy::emit
