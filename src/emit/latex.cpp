// LaTeX printing of closed forms, as a person writes them:
//   \sqrt{\frac{3 g \sin \theta_{2}}{l}}   \frac{1}{4} m \sqrt{2 g h}   \cos^{2}\beta
// GiNaC's own term order changes from run to run, so the order of terms and factors is decided
// here, by the text the plain printer gives them (itself independent of GiNaC's order).
#include "kinergy/emit/latex.hpp"
#include "kinergy/print/factors.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <sstream>

#include "kinergy/emit/emit.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::emit {

using namespace GiNaC;

// ---------------------------------------------------------------------------------------------
// names

namespace {

const std::array<const char*, 34> kGreek = {
    "alpha", "beta",  "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta",   "theta",   "vartheta", "iota",  "kappa",
    "lambda", "mu",   "nu",    "xi",    "pi",      "rho",        "sigma", "tau",  "upsilon", "phi",      "varphi", "chi",
    "psi",   "omega", "Gamma", "Delta", "Theta",   "Lambda",     "Xi",    "Sigma", "Phi",    "Omega"};

bool is_greek(const std::string& s) {
  for (auto* g : kGreek)
    if (s == g) return true;
  return s == "Pi" || s == "Psi" || s == "Upsilon";
}

bool all_of(const std::string& s, int (*pred)(int)) {
  if (s.empty()) return false;
  for (unsigned char c : s)
    if (!pred(c)) return false;
  return true;
}

int is_lower(int c) { return std::islower(c); }
int is_digit(int c) { return std::isdigit(c); }

/// A subscript part: digits as they are, a Greek name as its letter, a lowercase word upright
/// (hit → \mathrm{hit}, rate2 → \mathrm{rate}2), anything else italic (A, An, x2).
std::string sub_part(const std::string& p) {
  if (p.empty()) return "";
  if (is_greek(p)) return "\\" + p;
  std::size_t letters = 0;
  while (letters < p.size() && std::isalpha(static_cast<unsigned char>(p[letters]))) ++letters;
  std::string word = p.substr(0, letters), tail = p.substr(letters);
  if (word.size() >= 2 && all_of(word, is_lower)) {
    if (word == "max" || word == "min") return "\\" + word + tail;
    return "\\mathrm{" + word + "}" + tail;
  }
  return p;
}

/// Head of a name: a Greek letter or one Latin letter, the rest of the head as a subscript
/// (theta2 → \theta, {2}; xA → x, {A}); a lowercase word stays a word (lost → \mathrm{lost}).
std::pair<std::string, std::string> head_parts(const std::string& h) {
  // the longest Greek name the head starts with, followed by nothing, a digit or a capital
  std::string best;
  for (auto* g : kGreek) {
    std::string s = g;
    if (h.compare(0, s.size(), s) != 0 || s.size() <= best.size()) continue;
    if (h.size() == s.size() || std::isdigit(static_cast<unsigned char>(h[s.size()])) ||
        std::isupper(static_cast<unsigned char>(h[s.size()])))
      best = s;
  }
  if (!best.empty()) return {"\\" + best, h.substr(best.size())};
  if (h.size() > 1 && h[0] == 'd' && is_greek(h.substr(1))) return {"\\Delta\\" + h.substr(1), ""};  // dtheta → Δθ
  std::string rest = h.substr(1);
  std::size_t letters = 0;
  while (letters < rest.size() && std::isalpha(static_cast<unsigned char>(rest[letters]))) ++letters;
  std::string word = rest.substr(0, letters);
  if (word.size() >= 2 && all_of(word, is_lower) && word != "max" && word != "min")
    return {"\\mathrm{" + h + "}", ""};
  return {std::string(1, h[0]), rest};
}

bool has_subscript(const std::string& tex) {
  int depth = 0;
  for (char c : tex) {
    if (c == '{') ++depth;
    else if (c == '}') --depth;
    else if (c == '_' && depth == 0) return true;
  }
  return false;
}

}  // namespace

std::string tex_at(const std::string& base, const std::string& state) {
  std::string s = all_of(state, is_digit) || state.size() == 1 ? state : "\\mathrm{" + state + "}";
  if (has_subscript(base)) return "(" + base + ")_{" + s + "}";
  return base + "_{" + s + "}";
}

namespace {

/// A name's parts between its '_' (omega_A → omega, A).
std::vector<std::string> underscore_parts(const std::string& name) {
  std::vector<std::string> parts;
  std::string cur;
  for (char c : name) {
    if (c == '_') {
      parts.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  parts.push_back(cur);
  return parts;
}

}  // namespace

std::string plain_name(const std::string& full) {
  std::string name = full.substr(0, std::min(full.find('@'), full.find('[')));
  const std::vector<std::string> parts = underscore_parts(name);
  if (parts[0].empty()) return name;
  // (a head of one Latin letter and a rest, as tex_name splits it: Rx → R, x)
  auto [base, rest] = head_parts(parts[0]);
  const bool letter = base.size() == 1;
  std::string out = letter ? base : parts[0], subs = letter ? rest : "";
  for (std::size_t i = 1; i < parts.size(); ++i)
    if (!parts[i].empty()) subs += (subs.empty() ? "" : ",") + parts[i];
  return subs.empty() ? out : out + "_" + subs;
}

std::string tex_name(const std::string& full) {
  std::string name = full, state;
  if (auto at = name.find('@'); at != std::string::npos) {
    state = name.substr(at + 1);
    name = name.substr(0, at);
  }
  if (auto br = name.find('['); br != std::string::npos) name = name.substr(0, br);  // J_hit[before,after]
  bool dot = false, ddot = false;
  if (name.size() > 5 && name.compare(name.size() - 5, 5, "_ddot") == 0) {
    ddot = true;
    name = name.substr(0, name.size() - 5);
  } else if (name.size() > 4 && name.compare(name.size() - 4, 4, "_dot") == 0) {
    dot = true;
    name = name.substr(0, name.size() - 4);
  }
  const std::vector<std::string> parts = underscore_parts(name);
  if (parts[0].empty()) return "\\mathrm{" + tex_text(full) + "}";
  auto [base, rest] = head_parts(parts[0]);
  std::vector<std::string> subs;
  if (!rest.empty()) subs.push_back(sub_part(rest));
  for (std::size_t i = 1; i < parts.size(); ++i)
    if (!parts[i].empty()) subs.push_back(sub_part(parts[i]));
  std::string tex = ddot ? "\\ddot{" + base + "}" : dot ? "\\dot{" + base + "}" : base;
  if (!subs.empty()) {
    tex += "_{";
    for (std::size_t i = 0; i < subs.size(); ++i) tex += (i ? "," : "") + subs[i];
    tex += "}";
  }
  if (!state.empty()) tex = tex_at(tex, state);
  return tex;
}

// ---------------------------------------------------------------------------------------------
// units, numbers, text

std::string tex_unit(const std::string& u) {
  if (u.empty()) return "";
  if (u == "deg") return "{}^{\\circ}";
  std::string out = "\\mathrm{";
  for (std::size_t i = 0; i < u.size(); ++i) {
    char c = u[i];
    if (c == '*' || c == ' ') {
      out += "\\,";
    } else if (c == '^') {
      // exponent: an optional sign and digits (or a parenthesised fraction)
      std::size_t j = i + 1;
      std::string e;
      if (j < u.size() && u[j] == '(') {
        while (j < u.size() && u[j] != ')') e += u[j++];
        e += ")";
        ++j;
        e = e.substr(1, e.size() - 2);
      } else {
        while (j < u.size() && (std::isdigit(static_cast<unsigned char>(u[j])) || u[j] == '-' || u[j] == '.' || u[j] == '/'))
          e += u[j++];
      }
      out += "^{" + e + "}";
      i = j - 1;
    } else if (static_cast<unsigned char>(c) == 0xC2 && i + 1 < u.size() && static_cast<unsigned char>(u[i + 1]) == 0xB7) {
      out += "\\,";  // ·
      ++i;
    } else if (c == '%') {
      out += "\\%";
    } else {
      out += c;
    }
  }
  return out + "}";
}

std::string tex_number(const std::string& d) {
  auto e = d.find_first_of("eE");
  if (e == std::string::npos) return d;
  std::string mant = d.substr(0, e), ex = d.substr(e + 1);
  if (!ex.empty() && ex[0] == '+') ex = ex.substr(1);
  if (mant == "1") return "10^{" + ex + "}";
  return mant + "\\times 10^{" + ex + "}";
}

std::string tex_quantity(const std::string& number, const std::string& unit) {
  if (unit.empty()) return tex_number(number);
  if (unit == "deg") return tex_number(number) + "^{\\circ}";
  return tex_number(number) + "\\," + tex_unit(unit);
}

std::string tex_text(const std::string& s) {
  static const std::vector<std::pair<std::string, std::string>> unicode = {
      {"\u2014", "---"}, {"\u2013", "--"}, {"\u2192", "$\\to$"}, {"\u2190", "$\\leftarrow$"},
      {"\u00b7", "$\\cdot$"}, {"\u00d7", "$\\times$"}, {"\u2212", "$-$"}, {"\u2264", "$\\le$"},
      {"\u2265", "$\\ge$"}, {"\u2260", "$\\ne$"}, {"\u2248", "$\\approx$"}, {"\u00b2", "$^2$"},
      {"\u00b3", "$^3$"}, {"\u00b0", "$^\\circ$"}, {"\u00bd", "$\\frac12$"}, {"\u221a", "$\\surd$"},
      {"\u2211", "$\\Sigma$"}, {"\u222b", "$\\int$"}, {"\u2202", "$\\partial$"}, {"\u2018", "`"},
      {"\u2019", "'"}, {"\u201c", "``"}, {"\u201d", "''"}, {"\u2026", "\\dots{}"}, {"\u00a0", "~"},
      {"\u03b1", "$\\alpha$"}, {"\u03b2", "$\\beta$"}, {"\u03b3", "$\\gamma$"}, {"\u03b4", "$\\delta$"},
      {"\u03b5", "$\\varepsilon$"}, {"\u03b8", "$\\theta$"}, {"\u03bb", "$\\lambda$"}, {"\u03bc", "$\\mu$"},
      {"\u03c0", "$\\pi$"}, {"\u03c1", "$\\rho$"}, {"\u03c3", "$\\sigma$"}, {"\u03c4", "$\\tau$"},
      {"\u03c6", "$\\phi$"}, {"\u03c9", "$\\omega$"}, {"\u0394", "$\\Delta$"}, {"\u03a9", "$\\Omega$"},
      {"\u2080", "$_0$"}, {"\u2081", "$_1$"}, {"\u2082", "$_2$"}, {"\u2083", "$_3$"},
      {"\u0304", ""}, {"\u0307", ""}};
  std::string o;
  for (std::size_t i = 0; i < s.size();) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x80) {
      bool done = false;
      for (auto& [u, t] : unicode)
        if (s.compare(i, u.size(), u) == 0) {
          o += t;
          i += u.size();
          done = true;
          break;
        }
      if (done) continue;
      // any other character: skip its bytes (pdflatex without extra fonts cannot set it)
      std::size_t n = (c >= 0xF0) ? 4 : (c >= 0xE0) ? 3 : (c >= 0xC0) ? 2 : 1;
      o += "?";
      i += n;
      continue;
    }
    switch (c) {
      case '\\': o += "\\textbackslash{}"; break;
      case '{': o += "\\{"; break;
      case '}': o += "\\}"; break;
      case '$': o += "\\$"; break;
      case '&': o += "\\&"; break;
      case '#': o += "\\#"; break;
      case '%': o += "\\%"; break;
      case '_': o += "\\_\\allowbreak{}"; break;
      case '^': o += "\\textasciicircum{}"; break;
      case '~': o += "\\textasciitilde{}"; break;
      case '<': o += "\\textless{}"; break;
      case '>': o += "\\textgreater{}"; break;
      case '|': o += "\\textbar{}"; break;
      case '*': o += "*\\allowbreak{}"; break;
      case '/': o += "/\\allowbreak{}"; break;
      case '\n': o += ' '; break;
      default: o += static_cast<char>(c);
    }
    ++i;
  }
  return o;
}

// ---------------------------------------------------------------------------------------------
// width of TeX (display style, em) and top-level terms

namespace {

// TeX's styles: 0 display, 1 text, 2 script, 3 scriptscript; a fraction sets its parts one
// style smaller (display → text keeps the size), scripts go to script size.
double size_of(int style) { return style <= 1 ? 1.0 : style == 2 ? 0.7 : 0.5; }
int frac_style(int style) { return std::min(style + 1, 3); }
int script_style(int style) { return std::max(2, std::min(style + 1, 3)); }

struct Measure {
  const std::string& s;
  std::size_t i = 0;

  // one argument: {…} or a single token
  double arg(int style) {
    while (i < s.size() && s[i] == ' ') ++i;
    if (i >= s.size()) return 0;
    if (s[i] == '{') {
      ++i;
      return group(style, '}');
    }
    return token(style);
  }

  std::string command() {
    std::size_t st = i;  // at the backslash
    ++i;
    if (i < s.size() && !std::isalpha(static_cast<unsigned char>(s[i]))) return s.substr(st, ++i - st);
    while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
    return s.substr(st, i - st);
  }

  double token(int style) {
    double k = size_of(style);
    char c = s[i];
    if (c == '\\') {
      std::string cmd = command();
      if (cmd == "\\frac" || cmd == "\\tfrac") {
        double a = arg(frac_style(style)), b = arg(frac_style(style));
        return std::max(a, b) + 0.3 * k;
      }
      if (cmd == "\\sqrt") return arg(style) + 1.0 * k;
      if (cmd == "\\mathrm" || cmd == "\\text" || cmd == "\\mathit" || cmd == "\\operatorname") return 0.95 * arg(style);
      if (cmd == "\\dot" || cmd == "\\ddot" || cmd == "\\bar" || cmd == "\\hat" || cmd == "\\vec" || cmd == "\\overline") return arg(style);
      if (cmd == "\\left" || cmd == "\\right" || cmd == "\\bigl" || cmd == "\\bigr" || cmd == "\\Bigl" ||
          cmd == "\\Bigr" || cmd == "\\Big" || cmd == "\\big") {
        if (i < s.size()) {
          if (s[i] == '\\') command();
          else ++i;
        }
        return 0.5 * k;
      }
      if (cmd == "\\," || cmd == "\\:" || cmd == "\\;") return 0.2 * k;
      if (cmd == "\\quad") return 1.0 * k;
      if (cmd == "\\qquad") return 2.0 * k;
      if (cmd == "\\ ") return 0.33 * k;
      if (cmd == "\\cdot" || cmd == "\\times" || cmd == "\\to" || cmd == "\\approx" || cmd == "\\le" || cmd == "\\ge")
        return 1.3 * k;
      if (cmd == "\\sin" || cmd == "\\cos" || cmd == "\\tan" || cmd == "\\exp" || cmd == "\\log" || cmd == "\\max" ||
          cmd == "\\min")
        return 1.7 * k;
      if (cmd == "\\ln") return 1.2 * k;
      if (cmd == "\\arcsin" || cmd == "\\arccos" || cmd == "\\arctan" || cmd == "\\sinh" || cmd == "\\cosh")
        return 3.0 * k;
      if (cmd == "\\int" || cmd == "\\sum") return 1.4 * k;
      if (cmd == "\\circ") return 0.5 * k;
      if (cmd == "\\lvert" || cmd == "\\rvert") return 0.3 * k;
      if (cmd == "\\notag" || cmd == "\\nonumber" || cmd == "\\displaystyle" || cmd == "\\textstyle") return 0;
      return 0.62 * k;  // a letter (\theta) or a symbol
    }
    ++i;
    if (c == '{') return group(style, '}');
    if (c == '^' || c == '_') return arg(script_style(style));
    // binary operators and relations carry their spacing (not in scripts)
    if (c == '+' || c == '-') return (style <= 1 ? 1.45 : 0.8) * k;
    if (c == '=' || c == '<' || c == '>') return (style <= 1 ? 1.6 : 0.8) * k;
    if (c == '(' || c == ')' || c == '[' || c == ']') return 0.4 * k;
    if (c == ',' || c == ';') return 0.45 * k;
    if (c == '.') return 0.3 * k;
    if (c == '/') return 0.5 * k;
    if (c == ' ' || c == '&') return 0;
    if (std::isdigit(static_cast<unsigned char>(c))) return 0.5 * k;
    if (c == 'm' || c == 'M' || c == 'W' || c == 'w') return 0.88 * k;
    return 0.58 * k;
  }

  double group(int style, char close) {
    double w = 0;
    while (i < s.size()) {
      if (s[i] == close) {
        ++i;
        return w;
      }
      w += token(style);
    }
    return w;
  }
};

}  // namespace

double tex_width(const std::string& tex) {
  Measure m{tex};
  return m.group(0, '\0');
}

std::vector<std::string> tex_terms(const std::string& s) {
  std::vector<std::string> out;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c == '\\') {
      // \left( … \right) count as brackets; other commands are skipped whole
      if (s.compare(i, 5, "\\left") == 0 && (i + 5 >= s.size() || !std::isalpha(static_cast<unsigned char>(s[i + 5])))) {
        ++depth;
        i += 5;
        continue;
      }
      if (s.compare(i, 6, "\\right") == 0 && (i + 6 >= s.size() || !std::isalpha(static_cast<unsigned char>(s[i + 6])))) {
        --depth;
        i += 6;
        continue;
      }
      ++i;
      continue;
    }
    if (c == '{' || c == '(' || c == '[') ++depth;
    else if (c == '}' || c == ')' || c == ']') --depth;
    else if (depth == 0 && (c == '+' || c == '-') && i > 0 && s[i - 1] == ' ' && i + 1 < s.size() && s[i + 1] == ' ') {
      out.push_back(s.substr(start, i - 1 - start));
      start = i;
    }
  }
  out.push_back(s.substr(start));
  return out;
}

// ---------------------------------------------------------------------------------------------
// the printer

namespace {

using detail::Factor;
using detail::Factors;
using enum detail::Prec;

/// Parentheses that grow with what they hold.
std::string paren(const std::string& s) {
  bool tall = s.find("\\frac") != std::string::npos || s.find("\\sqrt") != std::string::npos ||
              s.find("^{") != std::string::npos;
  return tall ? "\\left(" + s + "\\right)" : "(" + s + ")";
}

std::string number_text(const numeric& n) {
  if (n.is_integer()) {
    std::ostringstream os;
    os << n;
    return os.str();
  }
  if (n.is_rational()) {
    std::ostringstream a, b;
    a << abs(n.numer());
    b << n.denom();
    return std::string(n.is_negative() ? "-" : "") + "\\frac{" + a.str() + "}{" + b.str() + "}";
  }
  return tex_number(numerics::format(n, 15));
}

class Printer {
public:
  explicit Printer(const TexSymbols* sym) : sym_(sym) {}

  std::string print(const ex& e, int ctx) const {
    if (is_a<numeric>(e)) {
      numeric n = ex_to<numeric>(e);
      std::string s = number_text(n);
      bool compound = n.is_negative() || (n.is_rational() && !n.is_integer()) || s.find("\\times") != std::string::npos;
      return compound && ctx >= kPower ? paren(s) : (n.is_negative() && ctx >= kProduct ? paren(s) : s);
    }
    if (is_a<constant>(e) && e.is_equal(Pi)) return "\\pi";
    if (is_a<symbol>(e)) {
      if (sym_) {
        auto it = sym_->find(e);
        if (it != sym_->end()) {
          const std::string& t = it->second.tex;
          // 30^{\circ} under a power needs its parentheses too
          bool wrap = (!it->second.atomic && ctx >= kProduct) || (ctx >= kPower && t.find('^') != std::string::npos);
          return wrap ? paren(t) : t;
        }
      }
      return tex_name(ex_to<symbol>(e).get_name());
    }
    if (is_a<add>(e)) return sum(e, ctx);
    if (is_a<mul>(e)) return product(e, ctx);
    if (is_a<power>(e)) {
      ex k = e.op(1);
      if (detail::printed_as_product(e)) return product(e, ctx);
      if (is_a<numeric>(k) && ex_to<numeric>(k).is_rational()) return factor_text({e.op(0), ex_to<numeric>(k)}, ctx);
      if (is_a<function>(e.op(0)) && ex_to<function>(e.op(0)).get_name() == "exp")
        return "e^{" + print(e.op(0).op(0), 0) + "}";
      std::string s = base_text(e.op(0)) + "^{" + print(k, 0) + "}";
      return s;
    }
    if (is_a<function>(e)) return function_text(e, 1);
    return "\\mathrm{?}";
  }

private:
  const TexSymbols* sym_;

  static std::string key(const ex& e) { return plain(e); }

  /// A power's base: parenthesised unless it is a name or a positive integer.
  std::string base_text(const ex& b) const {
    if (is_a<symbol>(b)) {
      std::string s = print(b, kAtom);
      return s;
    }
    if (is_a<numeric>(b) && ex_to<numeric>(b).is_integer() && !ex_to<numeric>(b).is_negative()) return print(b, 0);
    if (is_a<constant>(b)) return print(b, 0);
    if (is_a<function>(b)) return paren(print(b, 0));
    return paren(print(b, 0));
  }

  /// An argument that needs no parentheses after \sin: a name or a positive integer.
  bool bare_argument(const ex& a) const {
    if (is_a<symbol>(a)) {
      if (sym_) {
        auto it = sym_->find(a);
        if (it != sym_->end()) return it->second.atomic;
      }
      return true;
    }
    if (is_a<constant>(a)) return true;
    return is_a<numeric>(a) && ex_to<numeric>(a).is_integer() && ex_to<numeric>(a).is_positive();
  }

  /// f(x) with a positive integer power k: \sin^{2}\theta, \ln^{2}(…), (\operatorname{atan2}(y, x))^{2}.
  std::string function_text(const ex& f, const numeric& k) const {
    std::string name = ex_to<function>(f).get_name();
    std::string power = k == 1 ? "" : "^{" + number_text(k) + "}";
    static const std::map<std::string, std::string> ops = {
        {"sin", "\\sin"},       {"cos", "\\cos"},       {"tan", "\\tan"},   {"log", "\\ln"},
        {"asin", "\\arcsin"},   {"acos", "\\arccos"},   {"atan", "\\arctan"}, {"sinh", "\\sinh"},
        {"cosh", "\\cosh"},     {"tanh", "\\tanh"}};
    if (name == "abs") {
      std::string s = "\\left\\lvert " + print(f.op(0), 0) + "\\right\\rvert";
      return k == 1 ? s : s + power;
    }
    if (name == "integral") {
      // ∫_a^b f dξ (a work integral with no elementary antiderivative)
      std::string s = "\\int_{" + print(f.op(2), 0) + "}^{" + print(f.op(3), 0) + "} " + print(f.op(0), kProduct) + "\\,\\mathrm{d}" +
                      print(f.op(1), kAtom);
      return k == 1 ? s : paren(s) + power;
    }
    if (name == "exp") {
      std::string s = "e^{" + print(f.op(0), 0) + "}";
      return k == 1 ? s : paren(s) + power;
    }
    auto it = ops.find(name);
    if (it != ops.end() && f.nops() == 1) {
      const ex& a = f.op(0);
      if (bare_argument(a)) return it->second + power + " " + print(a, kProduct);
      return it->second + power + paren(print(a, 0));
    }
    std::string s = "\\operatorname{" + name + "}(";
    for (std::size_t i = 0; i < f.nops(); ++i) s += (i ? ", " : "") + print(f.op(i), 0);
    s += ")";
    return k == 1 ? s : paren(s) + power;
  }

  // Order in a product: numbers, names, sums (in parentheses), functions — so that a function
  // written without parentheses (\sin\theta) comes last and nothing reads as its argument.
  // Rates and quantities at a state come after the parameters: m r^{2} \dot{\theta}_{2}.
  static int rank(const ex& x) {
    if (is_a<numeric>(x)) return 0;
    ex b = is_a<power>(x) ? x.op(0) : x;
    if (is_a<constant>(b)) return 1;
    if (is_a<symbol>(b)) {
      const std::string& n = ex_to<symbol>(b).get_name();
      return n.find('@') != std::string::npos || n.find("_dot") != std::string::npos ? 2 : 1;
    }
    if (is_a<function>(b)) return 5;
    if (is_a<add>(b)) return 3;
    return 4;
  }

  std::string factor_text(const Factor& f, int ctx) const {
    if (f.k == 1) return print(f.base, ctx);
    if (is_a<function>(f.base) && f.k.is_integer()) return function_text(f.base, f.k);
    std::string k = f.k.is_integer() ? number_text(f.k) : [&] {
      std::ostringstream os;
      os << f.k;
      return os.str();
    }();
    return base_text(f.base) + "^{" + k + "}";
  }

  /// Factors in order, each with its text. `alone`: the only thing in a numerator or
  /// denominator (a lone sum needs no parentheses there).
  std::vector<std::string> ordered(const std::vector<Factor>& v, bool alone) const {
    std::vector<std::pair<std::pair<int, std::string>, std::string>> keyed;
    for (auto& x : v)
      keyed.push_back({{rank(x.base), key(x.base)}, factor_text(x, alone && v.size() == 1 ? 0 : kProduct)});
    std::stable_sort(keyed.begin(), keyed.end(), [](auto& a, auto& b) { return a.first < b.first; });
    std::vector<std::string> out;
    for (auto& x : keyed) out.push_back(x.second);
    return out;
  }

  static std::string juxtapose(const std::vector<std::string>& parts) {
    std::string s;
    for (auto& p : parts) {
      if (p.empty()) continue;
      if (!s.empty()) {
        // two numbers side by side need a multiplication sign
        bool num_l = std::isdigit(static_cast<unsigned char>(s.back())) || s.back() == '}';
        bool num_r = std::isdigit(static_cast<unsigned char>(p.front()));
        s += num_l && num_r ? " \\cdot " : " ";
      }
      s += p;
    }
    return s;
  }

  /// √ of what the root groups hold, as one product written as one fraction:
  /// √3·√(g sin θ₂ / l) → \sqrt{\frac{3 g \sin\theta_2}{l}}.
  std::string root_text(const Factors& f) const {
    ex inner = 1;
    for (auto& x : f.root_num) inner = inner * x;
    for (auto& x : f.root_den) inner = inner / x;
    std::string in = is_a<mul>(inner) || is_a<power>(inner) ? product(inner, 0, true) : print(inner, 0);
    return "\\sqrt{" + in + "}";
  }

  std::string product(const ex& e, int ctx, bool one_fraction = false) const {
    Factors f = detail::split(e, ctx == 0);
    bool neg = f.coef.is_negative();
    numeric c = neg ? -f.coef : f.coef;
    // the numbers under a root made one reduced fraction; the number in front stays in front
    // (\frac{3 \sqrt{2 g h}}{2 l}, where the plain printer folds it in: sqrt(9*g*h/2)/l)
    if (!f.root_num.empty() || !f.root_den.empty()) {
      // a product under the root taken apart: its numbers join the others, x^-k goes below, a
      // number's sign kept apart (factors.hpp)
      bool minus = detail::flatten_roots(f);
      // a sign under the root goes into a sum there, √(−h (h − 2r)) = √(h (2r − h)): one form,
      // whichever way round GiNaC holds the sum (its term order follows addresses)
      for (exvector* v : {&f.root_den, &f.root_num})
        for (auto& x : *v)
          if (minus && is_a<add>(x)) {
            x = -x;
            minus = false;
          }
      numeric rn = 1, rd = 1;
      detail::take_root_numbers(f, rn, rd);
      // squares come out of the root, and a number below its bar goes above:
      // √(9x/8) → (3/4)·√(2x)
      auto out = [&](numeric& n, bool up) {
        if (n > numeric(1000000000)) return;
        for (numeric k = 2; k * k <= n; k = k + 1)
          while (irem(n, k * k).is_zero()) {
            n = n / (k * k);
            c = up ? c * k : c / k;
          }
      };
      if (c.is_rational()) {
        out(rn, true);
        out(rd, false);
        if (rd != 1) {
          rn = rn * rd;
          c = c / rd;
          rd = 1;
        }
      }
      // the number in front goes under the root when that reads simpler: 2/3·√(3x) → √(4x/3)
      if (c.is_rational()) {
        numeric fn = rn * c.numer() * c.numer(), fd = rd * c.denom() * c.denom();
        numeric h = gcd(fn, fd);
        fn = fn / h;
        fd = fd / h;
        if (fn + fd < rn + rd + c.numer() + c.denom()) {
          rn = fn;
          rd = fd;
          c = 1;
        }
      }
      if (rn != 1) f.root_num.insert(f.root_num.begin(), rn);
      if (rd != 1) f.root_den.insert(f.root_den.begin(), rd);
      if (minus) f.root_num.push_back(-1);  // the sums under the root take it when printed
    }
    bool has_root = !f.root_num.empty() || !f.root_den.empty();
    // the numerator: names, sums, the root, functions
    std::vector<std::pair<std::pair<int, std::string>, std::string>> top;
    for (auto& x : f.num) top.push_back({{rank(x.base), key(x.base)}, factor_text(x, kProduct)});
    // a root with nothing above its bar goes below the fraction bar: \frac{r}{\sqrt{l^{2} - x^{2}}}
    bool root_below = f.root_num.empty() && !f.root_den.empty();
    if (has_root && !root_below) top.push_back({{4, "~"}, root_text(f)});
    std::stable_sort(top.begin(), top.end(), [](auto& a, auto& b) { return a.first < b.first; });
    std::vector<std::string> tops;
    for (auto& x : top) tops.push_back(x.second);
    std::vector<std::string> bottoms = ordered(f.den, f.den.size() == 1 && c.denom() == 1 && !root_below);
    if (root_below) {
      Factors g;
      g.root_num = f.root_den;
      bottoms.push_back(root_text(g));
    }

    std::string s;
    numeric p = c.numer(), q = c.denom();
    // a float (a value taken numerically) to the digits of a number, not all its working digits
    auto digits = [](const numeric& x) {
      std::ostringstream os;
      if (x.is_rational()) os << x;
      else os << number_text(x);
      return os.str();
    };
    if (bottoms.empty() && !(one_fraction && q != 1)) {
      if (q != 1) {
        // ½ m v²: the number in front as a fraction
        std::ostringstream a, b;
        a << digits(p);
        b << q;
        s = juxtapose({"\\frac{" + a.str() + "}{" + b.str() + "}", juxtapose(tops)});
      } else {
        std::ostringstream a;
        a << digits(p);
        if (p != 1 || tops.empty()) s = a.str();
        s = juxtapose({s, juxtapose(tops)});
      }
    } else {
      std::ostringstream a, b;
      a << digits(p);
      b << q;
      std::string num = juxtapose({p != 1 ? a.str() : "", juxtapose(tops)});
      if (num.empty()) num = "1";
      // a lone sum on top needs no parentheses: \frac{a + b}{c}
      if (tops.size() == 1 && p == 1 && f.num.size() == 1 && f.num[0].k == 1 && is_a<add>(f.num[0].base))
        num = print(f.num[0].base, 0);
      std::string den = juxtapose({q != 1 ? b.str() : "", juxtapose(bottoms)});
      s = "\\frac{" + num + "}{" + den + "}";
    }
    if (neg) s = "-" + s;
    if (ctx > kProduct || (neg && ctx >= kProduct)) return paren(s);
    return s;
  }

  std::string sum(const ex& e, int ctx) const {
    // each term with its sign as printed (a product may take the sign of a sum it flipped):
    // positive terms first, each group in the order of its plain text
    std::vector<detail::Term> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      std::string t = print(e.op(i), kSum), k = key(e.op(i));
      bool neg = !t.empty() && t[0] == '-';
      if (neg) t = t.substr(1);
      if (!k.empty() && k[0] == '-') k = k.substr(1);
      terms.push_back({neg, k, t});
    }
    std::string s = detail::join_terms(std::move(terms));
    return ctx > kSum ? paren(s) : s;
  }
};

}  // namespace

std::string latex(const ex& e, const TexSymbols* symbols) { return Printer(symbols).print(e, 0); }

}  // namespace kinergy::emit
