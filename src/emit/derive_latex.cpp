// A derivation as a standalone LaTeX document: article, amsmath. Equations stand in align
// environments, each tagged (\tag) and labelled (\label) with the principle it comes from; an
// equation too wide for the line is broken at its terms, and a term too wide at the sum inside
// its widest parenthesis, fraction or root (\Bigl( … \Bigr) may span lines), so that nothing
// runs off the page.
#include <algorithm>
#include <sstream>

#include "kinergy/emit/derive.hpp"
#include "derive_tex.hpp"

namespace kinergy::emit {

namespace {

/// Room for an equation on a line, in em (11 pt, 160 mm text width = 41 em, less the tag).
constexpr double kLine = 33.0;
/// A left side wider than this goes into the right column with the rest.
constexpr double kLeft = 9.0;

}  // namespace

std::string math_tex(const Math& m, const Derivation& d) {
  if (m.fixed()) return m.tex;
  std::string s;
  if (!m.values) {
    s = latex(m.e, &d.names);
  } else {
    TexSymbols all = d.names;
    for (auto& [k, v] : d.values_tex) all[k] = v;
    s = latex(m.e, &all);
  }
  s = m.pre_tex + s;
  if (m.has_rhs) s += " = " + latex(m.rhs, &d.names);
  return s;
}

namespace {

std::string spans_tex(const Spans& spans, const Derivation& d) {
  std::string s;
  for (auto& sp : spans) s += sp.is_math ? "$" + math_tex(sp.math, d) + "$" : tex_text(sp.words);
  return s;
}

// --- breaking ---------------------------------------------------------------------------------

/// The top-level atoms of a TeX term: commands with their arguments, groups, \left…\right and
/// (…) pairs, single characters.
std::vector<std::string> atoms(const std::string& s) {
  std::vector<std::string> out;
  std::size_t i = 0;
  auto group_end = [&](std::size_t j) {  // s[j] == '{': index past the matching '}'
    int depth = 0;
    for (; j < s.size(); ++j) {
      if (s[j] == '\\') {
        ++j;
        continue;
      }
      if (s[j] == '{') ++depth;
      if (s[j] == '}' && --depth == 0) return j + 1;
    }
    return s.size();
  };
  auto command_end = [&](std::size_t j) {  // s[j] == '\\'
    ++j;
    if (j < s.size() && !std::isalpha(static_cast<unsigned char>(s[j]))) return j + 1;
    while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
    return j;
  };
  while (i < s.size()) {
    std::size_t st = i;
    if (s[i] == ' ') {
      ++i;
      continue;
    }
    if (s[i] == '\\') {
      std::size_t e = command_end(i);
      std::string cmd = s.substr(i, e - i);
      if (cmd == "\\left") {
        int depth = 0;
        std::size_t j = i;
        while (j < s.size()) {
          if (s.compare(j, 5, "\\left") == 0 && (j + 5 >= s.size() || !std::isalpha(static_cast<unsigned char>(s[j + 5])))) {
            ++depth;
            j += 5;
            continue;
          }
          if (s.compare(j, 6, "\\right") == 0 && (j + 6 >= s.size() || !std::isalpha(static_cast<unsigned char>(s[j + 6])))) {
            j += 6;
            if (--depth == 0) {
              // the delimiter after \right
              if (j < s.size() && s[j] == '\\') j = command_end(j);
              else ++j;
              break;
            }
            continue;
          }
          ++j;
        }
        i = j;
      } else {
        i = e;
        int args = cmd == "\\frac" ? 2 : (cmd == "\\sqrt" || cmd == "\\dot" || cmd == "\\mathrm" || cmd == "\\bar" ||
                                          cmd == "\\operatorname")
                                             ? 1
                                             : 0;
        for (int a = 0; a < args && i < s.size(); ++a) {
          while (i < s.size() && s[i] == ' ') ++i;
          if (i < s.size() && s[i] == '{') i = group_end(i);
          else if (i < s.size() && s[i] == '\\') i = command_end(i);
          else ++i;
        }
      }
    } else if (s[i] == '{') {
      i = group_end(i);
    } else if (s[i] == '(') {
      int depth = 0;
      std::size_t j = i;
      for (; j < s.size(); ++j) {
        if (s[j] == '(') ++depth;
        if (s[j] == ')' && --depth == 0) break;
      }
      i = std::min(j + 1, s.size());
    } else if (s[i] == '^' || s[i] == '_') {
      ++i;
      while (i < s.size() && s[i] == ' ') ++i;
      if (i < s.size() && s[i] == '{') i = group_end(i);
      else if (i < s.size() && s[i] == '\\') i = command_end(i);
      else ++i;
      // a script belongs to the atom before it
      if (!out.empty()) {
        out.back() += s.substr(st, i - st);
        continue;
      }
    } else if (std::isdigit(static_cast<unsigned char>(s[i]))) {
      while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;  // 12.5
    } else {
      ++i;
    }
    out.push_back(s.substr(st, i - st));
  }
  return out;
}

/// The argument of a one-brace group "{…}" at the start of s, and what follows.
std::pair<std::string, std::string> first_group(const std::string& s) {
  int depth = 0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (s[j] == '\\') {
      ++j;
      continue;
    }
    if (s[j] == '{') ++depth;
    if (s[j] == '}' && --depth == 0) return {s.substr(1, j - 1), s.substr(j + 1)};
  }
  return {s, ""};
}

std::vector<std::string> pieces(const std::string& side, double budget, int level);

/// Marks a piece that goes on a product: on a line of its own it is written "\times …".
const std::string kTimes = "\x01";

/// A term too wide for the line: open its widest bracket, fraction or root so that the sum
/// inside can break.
std::vector<std::string> term_pieces(const std::string& t, double budget, int level) {
  if (tex_width(t) <= budget || level > 5) return {t};
  // parts: literal text, or text that may break (a sum inside opened brackets)
  struct Part {
    std::string s;
    bool inner = false;
    bool fresh = false;  ///< starts a new piece (a line may break before it)
  };
  std::vector<Part> parts;
  bool opened = false;
  double wide = budget / 2;
  auto lit = [&](const std::string& x) { parts.push_back({x, false, false}); };
  auto brk = [&](const std::string& x) { parts.push_back({x, true, false}); };
  auto as = atoms(t);
  for (std::size_t ai = 0; ai < as.size(); ++ai) {
    const std::string& a = as[ai];
    if (!parts.empty()) lit(" ");
    if (tex_width(a) <= wide) {
      // a sizeable factor of a product may start a line of its own (× in front)
      if (ai > 0 && tex_width(a) > 2.5 && as[ai - 1] != "-" && as[ai - 1] != "+") {
        parts.push_back({kTimes + a, false, true});
        opened = true;
      } else {
        lit(a);
      }
      continue;
    }
    if (a.rfind("\\left(", 0) == 0 && a.rfind("\\right)") != std::string::npos) {
      auto r = a.rfind("\\right)");
      lit("\\Bigl(");
      brk(a.substr(6, r - 6));
      lit("\\Bigr)" + a.substr(r + 7));
    } else if (a.rfind("(", 0) == 0 && a.rfind(')') != std::string::npos) {
      auto r = a.rfind(')');
      lit("(");
      brk(a.substr(1, r - 1));
      lit(a.substr(r));
    } else if (a.rfind("\\frac", 0) == 0) {
      // \frac{N}{D} → \frac{1}{D}\Bigl(N\Bigr) (or \frac{1}{D}\,N when N is one term);
      // with a wide D: \Bigl(N\Bigr)\Big/\Bigl(D\Bigr)
      // (plain variables, not a structured binding: the lambda below captures num, which C++20
      // allows of a binding but clang 14 does not)
      std::string num, rest, den, tail;
      std::tie(num, rest) = first_group(a.substr(5));
      std::tie(den, tail) = first_group(rest);
      bool sum = tex_terms(num).size() >= 2;
      auto numerator = [&] {
        if (sum) lit("\\Bigl(");
        if (tex_width(num) > wide) brk(num);
        else lit(num);
        if (sum) lit("\\Bigr)");
      };
      if (tex_width(den) <= wide && !sum) {
        // the narrow factors of N in front stay above the bar: \frac{3 g}{D}\Bigl(…\Bigr)
        auto na = atoms(num);
        std::string front, back;
        std::size_t k = 0;
        while (k < na.size() && tex_width(na[k]) <= wide) front += (front.empty() ? "" : " ") + na[k++];
        for (; k < na.size(); ++k) back += (back.empty() ? "" : " ") + na[k];
        if (front == "-" ) front = "-1";
        lit("\\frac{" + (front.empty() ? std::string("1") : front) + "}{" + den + "}\\, ");
        if (back.empty()) lit("");
        else if (tex_width(back) > wide) brk(back);
        else lit(back);
      } else if (tex_width(den) <= wide) {
        lit("\\frac{1}{" + den + "}");
        numerator();
      } else {
        numerator();
        parts.push_back({"\\Big/\\Bigl(", false, true});
        brk(den);
        lit("\\Bigr)");
      }
      lit(tail);
    } else if (a.rfind("\\sqrt", 0) == 0) {
      auto [arg, tail] = first_group(a.substr(5));
      lit("\\Bigl(");
      brk(arg);
      lit("\\Bigr)^{1/2}" + tail);
    } else {
      lit(a);
      continue;
    }
    opened = true;
  }
  if (!opened) return {t};
  std::vector<std::string> out{""};
  for (auto& p : parts) {
    if (p.fresh) {
      out.push_back(p.s);
      continue;
    }
    if (!p.inner) {
      out.back() += p.s;
      continue;
    }
    auto in = pieces(p.s, budget - 2, level + 1);
    out.back() += in[0];
    for (std::size_t i = 1; i < in.size(); ++i) out.push_back(in[i]);
  }
  return out;
}

/// Pieces of a side that may stand on lines of their own, in order.
std::vector<std::string> pieces(const std::string& side, double budget, int level) {
  std::vector<std::string> out;
  for (auto& t : tex_terms(side)) {
    auto p = term_pieces(t, budget, level);
    out.insert(out.end(), p.begin(), p.end());
  }
  return out;
}

/// Lines of "lead side": pieces packed greedily into lines of at most `budget` em; lines after
/// the first are indented by \quad.
std::vector<std::string> pack(const std::string& lead, const std::string& side, double budget) {
  auto ps = pieces(side, budget - 2, 0);
  std::vector<std::string> lines;
  std::string line = lead;
  double w = tex_width(lead);
  bool fresh = true;
  for (auto p : ps) {
    bool times = p.rfind(kTimes, 0) == 0;
    if (times) p = p.substr(kTimes.size());
    double pw = tex_width(p);
    if (!fresh && w + pw > budget) {
      lines.push_back(line);
      line = times ? "\\quad {}\\times" : "\\quad {}";
      w = times ? 2.3 : 1.0;
    }
    line += (fresh ? "" : " ") + p;
    w += pw;
    fresh = false;
  }
  lines.push_back(line);
  return lines;
}

/// One equation chain as align lines ("left & right"): the "= side" parts packed onto lines
/// while they fit, a part too wide broken at its terms.
std::vector<std::string> chain(const std::vector<Math>& sides, const Derivation& d, double left_col) {
  std::vector<std::string> tex;
  for (auto& s : sides) tex.push_back(math_tex(s, d));
  std::vector<std::string> lines;
  if (tex.size() == 1) {
    for (auto& l : pack("", tex[0], kLine)) lines.push_back("& " + l);
    return lines;
  }
  bool left_ok = tex_width(tex[0]) <= kLeft;
  double budget = left_ok ? kLine - left_col : kLine;
  std::vector<std::string> right;
  std::string cur;
  double cw = 0;
  if (!left_ok) {
    // a long left side: everything in the right column
    auto ls = pack("", tex[0], kLine);
    right.insert(right.end(), ls.begin(), ls.end() - 1);
    cur = ls.back();
    cw = tex_width(cur);
  }
  for (std::size_t i = 1; i < tex.size(); ++i) {
    std::string seg = "= " + tex[i];
    double sw = tex_width(seg);
    if (!cur.empty() && cw + 0.5 + sw <= budget) {
      cur += " " + seg;
      cw += 0.5 + sw;
      continue;
    }
    if (!cur.empty()) right.push_back(cur);
    auto ls = pack("= ", tex[i], budget);
    right.insert(right.end(), ls.begin(), ls.end() - 1);
    cur = ls.back();
    cw = tex_width(cur);
  }
  if (!cur.empty()) right.push_back(cur);
  for (std::size_t k = 0; k < right.size(); ++k)
    lines.push_back(std::string(k == 0 && left_ok ? tex[0] + " " : "") + "&" + right[k]);
  return lines;
}

}  // namespace

double left_column(const Block& b, const Derivation& d) {
  // the left column is as wide as the widest short left side
  double left = 0;
  for (auto& r : b.rows) {
    auto consider = [&](const std::vector<Math>& sides) {
      if (sides.size() < 2) return;
      double w = tex_width(math_tex(sides[0], d));
      if (w <= kLeft) left = std::max(left, w);
    };
    consider(r.sides);
    for (auto& a : r.also) consider(a);
  }
  return left;
}

std::vector<std::string> row_lines(const Row& r, const Derivation& d, double left) {
  std::vector<std::string> lines;
  // short equations side by side: x = …, \qquad y = …
  bool beside = !r.also.empty();
  std::string joined_left;
  if (beside) {
    std::vector<std::vector<Math>> all{r.sides};
    for (auto& a : r.also) all.push_back(a);
    double total = 0;
    std::string right;
    for (std::size_t i = 0; i < all.size() && beside; ++i) {
      if (all[i].size() != 2) beside = false;
      std::string l = math_tex(all[i][0], d), rr = math_tex(all[i][1], d);
      if (i == 0) {
        joined_left = l;
        right = "= " + rr;
        total += tex_width(l) + tex_width(right);
      } else {
        right += ", \\qquad " + l + " = " + rr;
        total += 3 + tex_width(l) + tex_width(rr) + 1.3;
      }
    }
    if (beside && total <= kLine && tex_width(joined_left) <= kLeft) lines.push_back(joined_left + " &" + right);
    else beside = false;
  }
  if (!beside) {
    auto more = chain(r.sides, d, left);
    lines.insert(lines.end(), more.begin(), more.end());
    for (auto& a : r.also) {
      auto m = chain(a, d, left);
      lines.insert(lines.end(), m.begin(), m.end());
    }
  }
  return lines;
}

namespace {

void latex_equations(std::ostringstream& os, const Block& b, const Derivation& d) {
  const double left = left_column(b, d);
  os << "\\begin{align}\n";
  for (std::size_t ri = 0; ri < b.rows.size(); ++ri) {
    const Row& r = b.rows[ri];
    const std::vector<std::string> lines = row_lines(r, d, left);
    for (std::size_t k = 0; k < lines.size(); ++k) {
      os << "  " << lines[k];
      if (k + 1 < lines.size()) {
        os << " \\notag\\\\*\n";  // no page break inside one equation
      } else {
        os << " \\tag{" << r.tag << "}";
        if (!r.label.empty()) os << "\\label{" << r.label << "}";
        os << (ri + 1 < b.rows.size() ? "\\\\\n" : "\n");
      }
    }
  }
  os << "\\end{align}\n";
}

void latex_table(std::ostringstream& os, const Block& b, const Derivation& d) {
  os << "\\begin{center}\n\\begin{tabular}{" << std::string(b.header.size(), 'l') << "}\n\\toprule\n";
  for (std::size_t i = 0; i < b.header.size(); ++i) os << (i ? " & " : "") << tex_text(b.header[i]);
  os << " \\\\\n\\midrule\n";
  for (auto& row : b.cells) {
    for (std::size_t i = 0; i < row.size(); ++i) os << (i ? " & " : "") << spans_tex(row[i], d);
    os << " \\\\\n";
  }
  os << "\\bottomrule\n\\end{tabular}\n\\end{center}\n";
}

}  // namespace

std::string latex(const Derivation& d) {
  std::ostringstream os;
  os << "% Worked solution written by kinergy (kinergy derive --latex) from " << d.file << "\n"
     << "\\documentclass[11pt]{article}\n"
     << "\\usepackage[a4paper,margin=25mm]{geometry}\n"
     << "\\usepackage{amsmath,amssymb}\n"
     << "\\usepackage{booktabs}\n"
     << "\\usepackage{tikz}\n"
     << "\\allowdisplaybreaks\n"
     << "\\setlength{\\parindent}{0pt}\n"
     << "\\setlength{\\parskip}{0.7ex plus 0.3ex}\n"
     << "\\sloppy\n"
     << "\\title{" << tex_text(d.title) << "}\n"
     << "\\author{}\n"
     << "\\date{}\n"
     << "\\begin{document}\n"
     << "\\maketitle\n"
     << "\\vspace{-6ex}\n"
     << "\\begin{center}\\small Worked solution from \\texttt{" << tex_text(d.file) << "}\\end{center}\n";
  if (!d.description.empty()) os << "\\section*{Problem}\n" << tex_text(d.description) << "\n\n";
  os << tex_text(d.legend) << "\n\n";
  for (auto& b : d.blocks) {
    switch (b.kind) {
      case Block::Kind::Section:
        os << "\n\\section{" << tex_text(b.title) << "}\n";
        break;
      case Block::Kind::Subsection:
        os << "\n\\subsection*{" << tex_text(b.title) << "}\n";
        break;
      case Block::Kind::Paragraph:
        // a display belongs to the paragraph before it: no blank line in between
        os << "\n" << spans_tex(b.spans, d) << "\n";
        break;
      case Block::Kind::Equations:
        latex_equations(os, b, d);
        break;
      case Block::Kind::Table:
        os << "\n";
        latex_table(os, b, d);
        break;
      case Block::Kind::Figure:
        // drawn in place (not floated), the caption under it
        os << "\n\\begin{center}\n"
           << b.sheet->tikz(b.sheet->size() > 1 ? 15.5 : 10.5, 0, b.sheet->size() > 1 ? 560 : 520)
           << "\\\\[0.5ex]\n{\\small\\itshape " << tex_text(b.title) << "}\n\\end{center}\n";
        break;
    }
  }
  os << "\\end{document}\n";
  return os.str();
}

}  // namespace kinergy::emit
