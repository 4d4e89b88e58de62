// The measured size of a label's words: glyph by glyph from the fonts' own metrics, with the
// rules TeX (The TeXbook, appendix G) and SVG set them by.
#include "glyphs.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <vector>

namespace kinergy::draw::detail {

std::vector<std::pair<std::string, bool>> label_parts(const std::string& text) {
  std::vector<std::pair<std::string, bool>> out;
  for (std::size_t i = 0; i < text.size();) {
    const bool sub = text[i] == '_' && i + 1 < text.size() && text[i + 1] != ' ';
    std::size_t j = i + 1;
    if (sub)
      while (j < text.size() && text[j] != ' ' && text[j] != '_') ++j;
    else
      j = std::min(text.find('_', i + 1), text.size());
    out.push_back({sub ? text.substr(i + 1, j - i - 1) : text.substr(i, j - i), sub});
    i = j;
  }
  return out;
}

namespace {

// the next code point of UTF-8 text at i (advancing i); a stray byte as itself
unsigned next_code_point(const std::string& s, std::size_t& i) {
  const auto b = static_cast<unsigned char>(s[i++]);
  int more = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
  unsigned cp = more == 3 ? b & 0x07u : more == 2 ? b & 0x0Fu : more == 1 ? b & 0x1Fu : b;
  for (; more > 0 && i < s.size(); --more) cp = (cp << 6) | (static_cast<unsigned char>(s[i++]) & 0x3Fu);
  return cp;
}

const SvgGlyph& svg_glyph(unsigned cp) {
  // a character the table lacks: as wide as an "n", as tall as a capital
  static const SvgGlyph unknown{0, 0.64f, -0.24f, 0.77f};
  const SvgGlyph* end = kDejaVuSans + kDejaVuSansCount;
  const SvgGlyph* g = std::lower_bound(kDejaVuSans, end, cp, [](const SvgGlyph& a, unsigned c) { return a.cp < c; });
  return g != end && g->cp == cp ? *g : unknown;
}

}  // namespace

Extent svg_extent(const std::string& text, double px) {
  // each part's glyphs side by side at their advances; a subscript at kSubFont, its baseline
  // kSubDrop below the line's
  Extent e;
  for (auto& [part, sub] : label_parts(text)) {
    const double size = sub ? kSubFont : px, drop = sub ? kSubDrop : 0;
    for (std::size_t i = 0; i < part.size();) {
      const SvgGlyph& g = svg_glyph(next_code_point(part, i));
      e.width += size * g.advance;
      if (g.top > g.bottom) {
        e.above = std::max(e.above, size * g.top - drop);
        e.below = std::max(e.below, drop - size * g.bottom);
      }
    }
  }
  return e;
}

namespace {

const TexFont& tex_font(const std::string& family, double pt) {
  // the design size LaTeX takes at pt: 9 → cmmi9 (\footnotesize of 11 pt), 6 its scripts; 10 and 7
  static const std::map<std::string, const TexFont*> by_name = [] {
    std::map<std::string, const TexFont*> m;
    for (std::size_t k = 0; k < kTexFontCount; ++k) m[kTexFonts[k].name] = &kTexFonts[k];
    return m;
  }();
  const int sizes[] = {6, 7, 9, 10};
  int best = 10;
  for (int s : sizes)
    if (std::fabs(s - pt) < std::fabs(best - pt)) best = s;
  auto it = by_name.find(family + std::to_string(family == "cmex" ? 10 : best));
  return *(it != by_name.end() ? it->second : by_name.at("cmmi10"));
}

// The kern TeX puts between characters left and right of font f (0 where none), in ems.
double kern(const TexFont& f, unsigned left, unsigned right) {
  const auto index = static_cast<unsigned>(&f - kTexFonts);
  const TexKern* end = kTexKerns + kTexKernCount;
  const TexKern* k = std::lower_bound(kTexKerns, end, TexKern{index, left, right, 0}, [](const TexKern& a, const TexKern& b) {
    return a.font != b.font ? a.font < b.font : a.left != b.left ? a.left < b.left : a.right < b.right;
  });
  return k != end && k->font == index && k->left == left && k->right == right ? k->kern : 0;
}

// TeX's atom types, for the spaces between them
enum class Atom { Ord, Op, Bin, Rel, Open, Close, Punct };

struct Item {
  Atom type;
  Extent e;
  double ic = 0;        // a character's italic correction (pt), kept apart for its scripts
  bool is_char = false;  // a single character (its scripts placed by its italic correction)
  const TexFont* font = nullptr;  // a character's font and code, for the kerns between characters
  unsigned code = 0;
  double pt = 0;
};

// The spaces between atoms (in mu; TeX's table, appendix G): 1 thin, 2 medium, 3 thick; negative
// where the space is left out in script styles.
int space_between(Atom a, Atom b) {
  static const int table[7][7] = {
      //        Ord Op Bin Rel Open Close Punct
      /*Ord*/ {0, 1, -2, -3, 0, 0, 0},
      /*Op*/ {1, 1, 0, -3, 0, 0, 0},
      /*Bin*/ {-2, -2, 0, 0, -2, 0, 0},
      /*Rel*/ {-3, -3, 0, 0, -3, 0, 0},
      /*Open*/ {0, 0, 0, 0, 0, 0, 0},
      /*Close*/ {0, 1, -2, -3, 0, 0, 0},
      /*Punct*/ {-1, -1, 0, -1, -1, -1, -1},
  };
  return table[static_cast<int>(a)][static_cast<int>(b)];
}

class TexMeasure {
public:
  TexMeasure(const std::string& s, double pt) : s_(s), text_pt_(pt), script_pt_(pt >= 9.5 ? 7 : 6) {}

  Extent run() {
    std::size_t i = 0;
    return hlist(list(i, false, "", '\0'), false);
  }

private:
  const std::string& s_;
  double text_pt_, script_pt_;

  double size(bool script) const { return script ? script_pt_ : text_pt_; }
  // a math unit: an 18th of the quad of the symbol font (cmsy) at the style's size
  double mu(bool script) const { return tex_font("cmsy", size(script)).quad * size(script) / 18; }

  Item character(const std::string& family, unsigned code, Atom type, bool script) {
    const TexFont& f = tex_font(family, size(script));
    const double pt = family == "cmex" ? 10 : size(script);
    const TexChar& c = f.c[code & 127u];
    Item it{type, {pt * c.wd, pt * c.ht, pt * c.dp}, pt * c.ic, true, &f, code & 127u, pt};
    if (type == Atom::Op) {
      // a large operator centred on the axis (cmsy's axis height)
      const double axis = tex_font("cmsy", size(script)).axis * size(script), half = (it.e.above + it.e.below) / 2;
      it.e.above = half + axis;
      it.e.below = half - axis;
    }
    return it;
  }

  static Extent hlist_of(const std::vector<Item>& items, bool script, double mu) {
    Extent e;
    for (std::size_t k = 0; k < items.size(); ++k) {
      const Item& it = items[k];
      if (k > 0) {
        const int sp = space_between(items[k - 1].type, it.type);
        if (sp > 0 || (sp < 0 && !script)) e.width += mu * (std::abs(sp) == 1 ? 3 : std::abs(sp) == 2 ? 4 : 5);
      }
      // two characters of one font side by side: its kern between them, and (a font with an
      // interword space: roman, not math italic) no italic correction (rules 14 and 17)
      const bool joined = it.is_char && k + 1 < items.size() && items[k + 1].is_char && items[k + 1].font == it.font && it.type == Atom::Ord &&
                          items[k + 1].type == Atom::Ord;
      if (joined) e.width += it.pt * kern(*it.font, it.code, items[k + 1].code);
      // a character with no script keeps its italic correction (rule 17)
      e.width += it.e.width + (it.is_char && !(joined && it.font->space > 0) ? it.ic : 0);
      e.above = std::max(e.above, it.e.above);
      e.below = std::max(e.below, it.e.below);
    }
    return e;
  }

  Extent hlist(std::vector<Item> items, bool script) {
    // a Bin with nothing to join is an Ord (rules 5 and 6)
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (items[k].type != Atom::Bin) continue;
      const bool before = k == 0 || items[k - 1].type == Atom::Bin || items[k - 1].type == Atom::Op || items[k - 1].type == Atom::Rel ||
                          items[k - 1].type == Atom::Open || items[k - 1].type == Atom::Punct;
      const bool after = k + 1 == items.size() || items[k + 1].type == Atom::Rel || items[k + 1].type == Atom::Close || items[k + 1].type == Atom::Punct;
      if (before || after) items[k].type = Atom::Ord;
    }
    return hlist_of(items, script, mu(script));
  }

  // A command's name at i (after its backslash): letters, or one other character.
  std::string command(std::size_t& i) {
    std::size_t j = i;
    while (j < s_.size() && std::isalpha(static_cast<unsigned char>(s_[j]))) ++j;
    if (j == i && j < s_.size()) ++j;
    std::string name = s_.substr(i, j - i);
    i = j;
    return name;
  }

  // One argument (a group, or one token) as an Ord.
  Item argument(std::size_t& i, bool script, const std::string& family) {
    while (i < s_.size() && s_[i] == ' ') ++i;
    std::vector<Item> one;
    if (i < s_.size() && s_[i] == '{') {
      ++i;
      one = list(i, script, family, '}');
    } else {
      one = list(i, script, family, '\0', 1);
    }
    if (one.size() == 1) return one[0];
    return Item{Atom::Ord, hlist(one, script)};
  }

  // The scripts on `nucleus` (rules 17, 18; text and script styles, not cramped): a subscript
  // after its width without its italic correction, a superscript after it with; each followed by
  // \scriptspace (0.5 pt). The shifts from the symbol font's σ parameters at the nucleus's size
  // (drops at the scripts').
  void attach(Item& nucleus, const Item* sub, const Item* sup, bool script) {
    const TexFont& sy = tex_font("cmsy", size(script));
    const TexFont& ss = tex_font("cmsy", size(true));
    const double at = size(script), xh = sy.xheight * at;
    const double base = nucleus.e.width;
    double width = base + nucleus.ic;
    // (a character's box: no drop, rule 18a)
    const double up0 = nucleus.is_char ? 0 : nucleus.e.above - ss.sup_drop * size(true);
    const double down0 = nucleus.is_char ? 0 : nucleus.e.below + ss.sub_drop * size(true);
    double up = 0, down = 0;
    if (sup) {
      up = std::max({up0, sy.sup2 * at, sup->e.below + xh / 4});
      nucleus.e.above = std::max(nucleus.e.above, up + sup->e.above);
      width = base + nucleus.ic + sup->e.width + (sup->is_char ? sup->ic : 0) + 0.5;
    }
    if (sub) {
      down = sup ? std::max(down0, sy.sub2 * at) : std::max({down0, sy.sub1 * at, sub->e.above - 0.8 * xh});
      nucleus.e.below = std::max(nucleus.e.below, down + sub->e.below);
      nucleus.e.above = std::max(nucleus.e.above, sub->e.above - down);
      width = std::max(width, base + sub->e.width + (sub->is_char ? sub->ic : 0) + 0.5);
    }
    nucleus.e.width = width;
    nucleus.ic = 0;
    nucleus.is_char = false;
  }

  Item from_command(const std::string& name, std::size_t& i, bool script, const std::string& family) {
    static const std::map<std::string, unsigned> greek = {
        {"alpha", 011}, {"beta", 014}, {"gamma", 015}, {"delta", 016}, {"epsilon", 017}, {"zeta", 020}, {"eta", 021}, {"theta", 022},
        {"iota", 023}, {"kappa", 024}, {"lambda", 025}, {"mu", 026}, {"nu", 027}, {"xi", 030}, {"pi", 031}, {"rho", 032}, {"sigma", 033},
        {"tau", 034}, {"upsilon", 035}, {"phi", 036}, {"chi", 037}, {"psi", 040}, {"omega", 041}, {"varepsilon", 042}, {"vartheta", 043},
        {"varpi", 044}, {"varrho", 045}, {"varsigma", 046}, {"varphi", 047}, {"partial", 0100}, {"ell", 0140}};
    static const std::map<std::string, unsigned> capitals = {{"Gamma", 0}, {"Delta", 1}, {"Theta", 2}, {"Lambda", 3}, {"Xi", 4}, {"Pi", 5},
                                                             {"Sigma", 6}, {"Upsilon", 7}, {"Phi", 010}, {"Psi", 011}, {"Omega", 012}};
    static const std::map<std::string, std::pair<unsigned, Atom>> symbols = {
        {"cdot", {1, Atom::Bin}}, {"times", {2, Atom::Bin}}, {"pm", {6, Atom::Bin}}, {"infty", {061, Atom::Ord}}, {"leq", {024, Atom::Rel}},
        {"geq", {025, Atom::Rel}}, {"approx", {031, Atom::Rel}}, {"neq", {075, Atom::Rel}}, {"to", {041, Atom::Rel}}, {"circ", {016, Atom::Ord}}};
    static const std::map<std::string, int> spaces = {{",", 3}, {":", 4}, {">", 4}, {";", 5}, {"!", -3}};
    if (auto g = greek.find(name); g != greek.end()) return character("cmmi", g->second, Atom::Ord, script);
    if (auto c = capitals.find(name); c != capitals.end()) return character(family == "cmbx" ? "cmbx" : "cmr", c->second, Atom::Ord, script);
    if (auto y = symbols.find(name); y != symbols.end()) return character("cmsy", y->second.first, y->second.second, script);
    if (auto sp = spaces.find(name); sp != spaces.end()) return Item{Atom::Ord, {sp->second * mu(script), 0, 0}, 0, false};
    if (name == "int" || name == "sum") return character("cmex", name == "int" ? 0122 : 0120, Atom::Op, script);
    if (name == " ") return Item{Atom::Ord, {0.333334 * size(script), 0, 0}};
    if (name == "quad") return Item{Atom::Ord, {size(script), 0, 0}};
    if (name == "mathrm" || name == "mathbf" || name == "text" || name == "mathit")
      return argument(i, script, name == "mathbf" ? "cmbx" : name == "mathit" ? "cmmi" : "cmr");
    if (name == "bar" || name == "hat" || name == "vec" || name == "dot" || name == "ddot" || name == "tilde") {
      // the accent's box over its nucleus: raised by the nucleus's height less the x-height
      // (rule 12), cmr's accents 0.5686 em tall
      Item a = argument(i, script, family);
      const double xh = 0.430555 * size(script);
      a.e.above = std::max(a.e.above, std::max(a.e.above, xh) - xh + 0.5686 * size(script));
      a.type = Atom::Ord;
      return a;
    }
    // a command not known: as wide as an italic x
    return character("cmmi", 'x', Atom::Ord, script);
  }

  Item from_char(char ch, bool script, const std::string& family) {
    const bool roman = family == "cmr" || family == "cmbx";
    const std::string upright = family == "cmbx" ? "cmbx" : "cmr";
    if (std::isalpha(static_cast<unsigned char>(ch))) return character(roman ? family : "cmmi", static_cast<unsigned>(ch), Atom::Ord, script);
    if (std::isdigit(static_cast<unsigned char>(ch))) return character(upright, static_cast<unsigned>(ch), Atom::Ord, script);
    switch (ch) {
      case '+': return character("cmr", '+', Atom::Bin, script);
      case '-': return character("cmsy", 0, Atom::Bin, script);
      case '=': return character("cmr", '=', Atom::Rel, script);
      case '<': case '>': return character("cmmi", static_cast<unsigned>(ch == '<' ? 074 : 076), Atom::Rel, script);
      case '(': case '[': return character("cmr", static_cast<unsigned>(ch), Atom::Open, script);
      case ')': case ']': return character("cmr", static_cast<unsigned>(ch), Atom::Close, script);
      case ',': return character("cmmi", 073, Atom::Punct, script);
      case ';': return character("cmr", ';', Atom::Punct, script);
      case '.': return roman ? character(family, '.', Atom::Ord, script) : character("cmmi", 072, Atom::Ord, script);
      case '/': return roman ? character(family, '/', Atom::Ord, script) : character("cmmi", 075, Atom::Ord, script);
      case '|': return character("cmsy", 0152, Atom::Ord, script);
      default: return character("cmmi", 'x', Atom::Ord, script);
    }
  }

  // The atoms up to `end` (or `count` of them, 0: all), with their scripts attached.
  std::vector<Item> list(std::size_t& i, bool script, const std::string& family, char end, int count = 0) {
    std::vector<Item> items;
    while (i < s_.size() && (count == 0 || static_cast<int>(items.size()) < count)) {
      const char ch = s_[i];
      if (ch == end && end != '\0') {
        ++i;
        break;
      }
      if (ch == ' ') {
        ++i;
        continue;
      }
      if ((ch == '_' || ch == '^') && !items.empty()) {
        std::optional<Item> sub, sup;
        while (i < s_.size() && (s_[i] == '_' || s_[i] == '^')) {
          const bool down = s_[i++] == '_';
          (down ? sub : sup) = argument(i, true, family);
        }
        attach(items.back(), sub ? &*sub : nullptr, sup ? &*sup : nullptr, script);
        continue;
      }
      ++i;
      if (ch == '{') {
        auto inner = list(i, script, family, '}');
        items.push_back(Item{Atom::Ord, hlist(inner, script)});
      } else if (ch == '\\') {
        const std::string name = command(i);
        items.push_back(from_command(name, i, script, family));
      } else if (ch != '}') {
        items.push_back(from_char(ch, script, family));
      }
    }
    // scripts of the last atom may follow when a count stopped the list
    return items;
  }
};

}  // namespace

Extent tex_extent(const std::string& tex, double pt) { return TexMeasure(tex, pt).run(); }

Extent tex_text_extent(const std::string& text, double pt) {
  // roman at pt, an interword space a third of an em; a subscript "$_{\mathrm{x}}$" at script
  // size, lowered as in math, \scriptspace after it
  Extent e;
  const TexFont& roman = tex_font("cmr", pt);
  for (auto& [part, sub] : label_parts(text)) {
    if (sub) {
      const Extent s = tex_extent("{}_{\\mathrm{" + part + "}}", pt);
      e.width += s.width;
      e.above = std::max(e.above, s.above);
      e.below = std::max(e.below, s.below);
      continue;
    }
    for (std::size_t i = 0; i < part.size(); ++i) {
      const unsigned ch = static_cast<unsigned char>(part[i]) & 127u;
      if (ch == ' ') {
        e.width += roman.space * pt;
        continue;
      }
      const TexChar& c = roman.c[ch];
      e.width += pt * c.wd + (i + 1 < part.size() ? pt * kern(roman, ch, static_cast<unsigned char>(part[i + 1]) & 127u) : 0);
      e.above = std::max(e.above, pt * static_cast<double>(c.ht));
      e.below = std::max(e.below, pt * static_cast<double>(c.dp));
    }
  }
  return e;
}

}  // namespace kinergy::draw::detail
