// A derivation as one self-contained HTML page: the text as the LaTeX has it, the mathematics in
// TeX typeset in the browser by KaTeX (Debian's libjs-katex, its script, style and fonts inlined),
// the figures as inline SVG, and the animations of the scene's motion.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "derive_tex.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/common/markup.hpp"
#include "kinergy/draw/animation.hpp"
#include "kinergy/emit/derive.hpp"

namespace kinergy::emit {

namespace {

namespace fs = std::filesystem;

std::string escape(const std::string& s) { return xml_escape(s); }

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return "";
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += table[v & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

// KaTeX's style with its woff2 fonts as data URIs (a browser takes the first format it knows, so
// the woff and ttf URLs after them are never fetched), and its script.
struct Katex {
  std::string css, js;
};

Katex katex(const fs::path& dir) {
  Katex k;
  k.js = slurp(dir / "katex.min.js");
  k.css = slurp(dir / "katex.min.css");
  if (k.js.empty() || k.css.empty())
    throw InputError("KaTeX is not installed (" + (dir / "katex.min.js").string() + "), so the page's mathematics cannot be typeset",
                     "install Debian's libjs-katex (bash .ci/setup --deps)");
  std::string out;
  std::size_t at = 0;
  for (std::size_t u = k.css.find("url(fonts/"); u != std::string::npos; u = k.css.find("url(fonts/", at)) {
    const std::size_t close = k.css.find(')', u);
    if (close == std::string::npos) break;
    const std::string name = k.css.substr(u + 10, close - u - 10);
    out += k.css.substr(at, u - at);
    if (name.size() > 6 && name.compare(name.size() - 6, 6, ".woff2") == 0) {
      const std::string font = slurp(dir / "fonts" / name);
      if (font.empty())
        throw InputError("KaTeX's font " + name + " is missing", "install Debian's fonts-katex (with libjs-katex: bash .ci/setup --deps)");
      out += "url(data:font/woff2;base64," + base64(font) + ")";
    } else {
      out += k.css.substr(u, close + 1 - u);
    }
    at = close + 1;
  }
  k.css = out + k.css.substr(at);
  return k;
}

std::string spans_html(const Spans& spans, const Derivation& d) {
  std::string s;
  for (auto& sp : spans) {
    if (!sp.is_math) {
      s += escape(sp.words);
      continue;
    }
    const std::string tex = math_tex(sp.math, d);
    s += "<span class=\"m\" data-tex=\"" + escape(tex) + "\">" + escape(tex) + "</span>";
  }
  return s;
}

}  // namespace

int html_figure_width(const draw::Sheet& s) { return s.size() > 1 ? 800 : 640; }

std::string html(const Derivation& d, const std::vector<std::string>& animations, const HtmlOptions& o) {
  const Katex k = katex(o.katex_dir);
  std::ostringstream os;
  os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
     << "<meta name=\"generator\" content=\"kinergy derive --html\">\n"
     << "<title>" << escape(d.title) << "</title>\n<style>\n" << k.css << "\n</style>\n"
     << "<style>body{font-family:'DejaVu Serif',serif;max-width:52em;margin:2em auto;padding:0 1em;color:#111;line-height:1.45}"
        "h1{font-size:1.6em;text-align:center}p.from{text-align:center;font-size:.9em}"
        ".eq{display:flex;overflow-x:auto;margin:.1em 0}.eq>.m{flex:1}.eq .katex-display{margin:.3em 0}"
        "table{border-collapse:collapse;margin:.8em auto}th,td{padding:.2em .8em;text-align:left}"
        "thead th{border-top:2px solid #111;border-bottom:1px solid #111}tbody tr:last-child td{border-bottom:2px solid #111}"
        "figure{margin:1.2em 0;text-align:center}figure svg{max-width:100%;height:auto}figcaption{font-style:italic;font-size:.92em}"
     << draw::kAnimationStyle << "</style>\n</head>\n<body>\n<main>\n"
     << "<h1>" << escape(d.title) << "</h1>\n<p class=\"from\">Worked solution from <code>" << escape(d.file) << "</code></p>\n";
  if (!d.description.empty()) os << "<h2>Problem</h2>\n<p>" << escape(d.description) << "</p>\n";
  os << "<p>" << escape(d.legend) << "</p>\n";
  int section = 0;
  for (auto& b : d.blocks) {
    switch (b.kind) {
      case Block::Kind::Section:
        os << "<h2>" << ++section << " " << escape(b.title) << "</h2>\n";
        break;
      case Block::Kind::Subsection:
        os << "<h3>" << escape(b.title) << "</h3>\n";
        break;
      case Block::Kind::Paragraph:
        os << "<p>" << spans_html(b.spans, d) << "</p>\n";
        break;
      case Block::Kind::Equations: {
        // each row displayed and tagged as in the LaTeX, its lines aligned at the same places
        const double left = left_column(b, d);
        for (auto& r : b.rows) {
          std::string lines;
          for (auto& l : row_lines(r, d, left)) lines += (lines.empty() ? "" : " \\\\ ") + l;
          const std::string tex = "\\begin{aligned}" + lines + "\\end{aligned}\\tag{" + r.tag + "}";
          os << "<div class=\"eq\" id=\"" << escape(r.tag) << "\"><span class=\"m display\" data-tex=\"" << escape(tex) << "\">" << escape(tex)
             << "</span></div>\n";
        }
        break;
      }
      case Block::Kind::Table:
        os << "<table>\n<thead><tr>";
        for (auto& h : b.header) os << "<th>" << escape(h) << "</th>";
        os << "</tr></thead>\n<tbody>\n";
        for (auto& row : b.cells) {
          os << "<tr>";
          for (auto& c : row) os << "<td>" << spans_html(c, d) << "</td>";
          os << "</tr>\n";
        }
        os << "</tbody>\n</table>\n";
        break;
      case Block::Kind::Figure:
        os << "<figure>\n" << b.sheet->svg(html_figure_width(*b.sheet)) << "<figcaption>" << escape(b.title) << "</figcaption>\n</figure>\n";
        break;
    }
  }
  if (!animations.empty()) {
    os << "<h2>" << ++section << " The motion, simulated</h2>\n"
       << "<p>The scene's equations of motion integrated from the first state of each analysis until its second is reached, "
          "drawn at regular times (kinergy simulate --animate).</p>\n";
    for (auto& a : animations) os << a;
  }
  os << "</main>\n<script>\n" << k.js << "\n</script>\n"
     << "<script>\n"
        "// every piece of mathematics typeset in place; a failure shows in red with its TeX (and counts)\n"
        "window.kinergyMath = { typeset: 0, failed: 0 };\n"
        "document.querySelectorAll('.m[data-tex]').forEach(function (el) {\n"
        "  try {\n"
        "    katex.render(el.getAttribute('data-tex'), el, { displayMode: el.classList.contains('display'), throwOnError: true, output: 'htmlAndMathml' });\n"
        "    window.kinergyMath.typeset++;\n"
        "  } catch (e) {\n"
        "    el.style.color = '#b8231f';\n"
        "    el.title = String(e);\n"
        "    window.kinergyMath.failed++;\n"
        "  }\n"
        "});\n"
        "document.body.setAttribute('data-math', window.kinergyMath.typeset + ' ' + window.kinergyMath.failed);\n"
        "</script>\n</body>\n</html>\n";
  return os.str();
}

}  // namespace kinergy::emit
