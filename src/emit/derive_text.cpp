// A derivation as plain Unicode text for terminals: headings underlined, paragraphs wrapped,
// equations one a line with their tags in a column, expressions in the plain printer's form
// (the form `solve` prints and scenes accept).
#include <algorithm>
#include <sstream>

#include "kinergy/emit/derive.hpp"

namespace kinergy::emit {

namespace {

constexpr std::size_t kWidth = 96;

/// Columns a UTF-8 text takes (code points, combining marks excluded).
std::size_t columns(const std::string& s) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if ((c & 0xC0) == 0x80) continue;
    if (c == 0xCC || (c == 0xCD && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) < 0xB0)) {
      continue;  // U+0300–U+036F combining marks
    }
    ++n;
  }
  return n;
}

std::string math_text(const Math& m, const Derivation& d) {
  if (m.fixed()) return m.text;
  std::string s = m.pre_text + (m.values ? plain(m.e, d.values_text) : plain(m.e));
  if (m.has_rhs) s += " = " + plain(m.rhs);
  return s;
}

/// Words and maths, wrapped at `width` with `indent` spaces; maths never break.
std::string wrap(const Spans& spans, const Derivation& d, std::size_t indent, std::size_t width) {
  std::vector<std::string> tokens;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty()) tokens.push_back(cur);
    cur.clear();
  };
  for (auto& s : spans) {
    if (s.is_math) {
      cur += math_text(s.math, d);
      continue;
    }
    for (char c : s.words) {
      if (c == ' ' || c == '\n') flush();
      else cur += c;
    }
    if (!s.words.empty() && (s.words.back() == ' ')) flush();
  }
  flush();
  std::string out, line(indent, ' ');
  std::size_t used = indent;
  bool empty = true;
  for (auto& t : tokens) {
    std::size_t w = columns(t);
    if (!empty && used + 1 + w > width) {
      out += line + "\n";
      line = std::string(indent, ' ');
      used = indent;
      empty = true;
    }
    if (!empty) {
      line += " ";
      ++used;
    }
    line += t;
    used += w;
    empty = false;
  }
  if (!empty) out += line + "\n";
  return out;
}

/// The terms of a plain expression at the top level: "a + b - c" → {"a", "+ b", "- c"}.
std::vector<std::string> plain_terms(const std::string& s) {
  std::vector<std::string> out;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c == '(') ++depth;
    else if (c == ')') --depth;
    else if (depth == 0 && (c == '+' || c == '-') && i > 0 && s[i - 1] == ' ' && i + 1 < s.size() && s[i + 1] == ' ') {
      out.push_back(s.substr(start, i - 1 - start));
      start = i;
    }
  }
  out.push_back(s.substr(start));
  return out;
}

/// One equation chain laid out from column `col`: "a = b = c", the "= side" parts packed onto
/// lines while they fit (under the first "="), a part too long broken at its terms.
std::vector<std::string> chain_lines(const std::vector<Math>& sides, const Derivation& d, std::size_t col) {
  std::vector<std::string> txt;
  for (auto& s : sides) txt.push_back(math_text(s, d));
  std::size_t room = kWidth > col + 20 ? kWidth - col : 20;
  std::size_t eq_col = columns(txt[0]) + 1;  // where "=" stands
  if (eq_col > 24 || columns(txt[0]) > room) eq_col = 4;
  std::vector<std::string> lines;
  // text at indent `ind`, broken at its terms (continuations 4 further in)
  auto put = [&](std::string line, const std::string& side, std::size_t ind) {
    auto terms = plain_terms(side);
    for (std::size_t i = 0; i < terms.size(); ++i) {
      if (i > 0 && columns(line) + 1 + columns(terms[i]) > room) {
        lines.push_back(line);
        line = std::string(ind + 4, ' ') + terms[i];
      } else {
        line += (i && !line.empty() ? " " : "") + terms[i];
      }
    }
    return line;
  };
  std::string cur = put("", txt[0], 0);
  for (std::size_t i = 1; i < txt.size(); ++i) {
    std::string seg = "= " + txt[i];
    if (columns(cur) + 1 + columns(seg) <= room) {
      cur += " " + seg;
      continue;
    }
    if (i == 1 && eq_col != 4) {
      // the first side starts on the line of the left side and goes on below it
      cur = put(cur + " = ", txt[i], eq_col + 2);
      continue;
    }
    lines.push_back(cur);
    cur = put(std::string(eq_col, ' ') + "= ", txt[i], eq_col + 2);
  }
  lines.push_back(cur);
  return lines;
}

void equations(std::ostringstream& os, const Block& b, const Derivation& d) {
  std::size_t tagw = 0;
  for (auto& r : b.rows) tagw = std::max(tagw, r.tag.size() + 2);
  for (auto& r : b.rows) {
    std::string tag = "(" + r.tag + ")";
    std::string lead = "  " + tag + std::string(tagw - tag.size(), ' ') + "  ";
    std::size_t col = lead.size();
    std::vector<std::vector<std::string>> eqs{chain_lines(r.sides, d, col)};
    for (auto& a : r.also) eqs.push_back(chain_lines(a, d, col));
    // several short equations side by side, else one under the other
    std::string joined;
    bool single = true;
    for (auto& e : eqs) single = single && e.size() == 1;
    if (single) {
      for (std::size_t i = 0; i < eqs.size(); ++i) joined += (i ? ",   " : "") + eqs[i][0];
      if (col + columns(joined) <= kWidth) {
        os << lead << joined << "\n";
        continue;
      }
    }
    bool first = true;
    for (auto& e : eqs)
      for (auto& l : e) {
        os << (first ? lead : std::string(col, ' ')) << l << "\n";
        first = false;
      }
  }
}

void table(std::ostringstream& os, const Block& b, const Derivation& d) {
  std::vector<std::vector<std::string>> cells;
  cells.push_back(b.header);
  for (auto& row : b.cells) {
    std::vector<std::string> r;
    for (auto& c : row) {
      std::string s = wrap(c, d, 0, 1000);
      while (!s.empty() && s.back() == '\n') s.pop_back();
      r.push_back(s);
    }
    cells.push_back(r);
  }
  std::vector<std::size_t> w(b.header.size(), 0);
  for (auto& r : cells)
    for (std::size_t i = 0; i < r.size() && i < w.size(); ++i) w[i] = std::max(w[i], columns(r[i]));
  for (std::size_t k = 0; k < cells.size(); ++k) {
    std::string line = "  ";
    for (std::size_t i = 0; i < cells[k].size() && i < w.size(); ++i) {
      line += cells[k][i];
      if (i + 1 < cells[k].size()) line += std::string(w[i] - columns(cells[k][i]) + 3, ' ');
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    os << line << "\n";
    if (k == 0) {
      std::size_t total = 0;
      for (std::size_t i = 0; i < w.size(); ++i) total += w[i] + (i + 1 < w.size() ? 3 : 0);
      std::string rule;
      for (std::size_t i = 0; i < total; ++i) rule += "\u2500";
      os << "  " << rule << "\n";
    }
  }
}

std::string underline(const std::string& s, const char* ch) {
  std::string r;
  for (std::size_t i = 0; i < columns(s); ++i) r += ch;
  return r;
}

}  // namespace

std::string text(const Derivation& d) {
  std::ostringstream os;
  os << d.title << "\n" << underline(d.title, "\u2550") << "\n";
  if (!d.description.empty()) os << "\n" << wrap({Span::w(d.description)}, d, 0, kWidth);
  os << "\n"
     << wrap({Span::w(d.legend)}, d, 0, kWidth);
  for (auto& b : d.blocks) {
    switch (b.kind) {
      case Block::Kind::Section:
        os << "\n" << b.title << "\n" << underline(b.title, "\u2500") << "\n";
        break;
      case Block::Kind::Subsection:
        os << "\n" << b.title << ":\n";
        break;
      case Block::Kind::Paragraph:
        os << wrap(b.spans, d, 0, kWidth);
        break;
      case Block::Kind::Equations:
        equations(os, b, d);
        break;
      case Block::Kind::Table:
        table(os, b, d);
        break;
      case Block::Kind::Figure:
        break;  // drawings are in the LaTeX (and `kinergy draw`)
    }
  }
  return os.str();
}

}  // namespace kinergy::emit
