#include "kinergy/emit/mathml.hpp"

#include <cctype>
#include <map>

#include "kinergy/common/error.hpp"
#include "kinergy/common/markup.hpp"

namespace kinergy::emit {

namespace {

// the characters of TeX's commands kinergy writes
const std::map<std::string, std::string> kGreekEntity{
    {"alpha", "α"},   {"beta", "β"},   {"gamma", "γ"},   {"delta", "δ"},  {"epsilon", "ϵ"}, {"varepsilon", "ε"}, {"zeta", "ζ"},
    {"eta", "η"},     {"theta", "θ"},  {"vartheta", "ϑ"}, {"iota", "ι"},   {"kappa", "κ"},   {"lambda", "λ"},     {"mu", "μ"},
    {"nu", "ν"},      {"xi", "ξ"},     {"pi", "π"},      {"varpi", "ϖ"},  {"rho", "ρ"},     {"varrho", "ϱ"},     {"sigma", "σ"},
    {"varsigma", "ς"}, {"tau", "τ"},   {"upsilon", "υ"}, {"phi", "ϕ"},    {"varphi", "φ"},  {"chi", "χ"},        {"psi", "ψ"},
    {"omega", "ω"},   {"Gamma", "Γ"},  {"Delta", "Δ"},   {"Theta", "Θ"},  {"Lambda", "Λ"},  {"Xi", "Ξ"},         {"Pi", "Π"},
    {"Sigma", "Σ"},   {"Upsilon", "Υ"}, {"Phi", "Φ"},    {"Psi", "Ψ"},    {"Omega", "Ω"},   {"infty", "∞"},      {"ell", "ℓ"}};
const std::map<std::string, std::string> kOperators{
    {"times", "×"}, {"cdot", "⋅"}, {"pm", "±"}, {"mp", "∓"}, {"leq", "≤"}, {"le", "≤"}, {"geq", "≥"}, {"ge", "≥"}, {"neq", "≠"},
    {"ne", "≠"},    {"approx", "≈"}, {"to", "→"}, {"rightarrow", "→"}, {"circ", "∘"}, {"lvert", "|"}, {"rvert", "|"}, {"vert", "|"},
    {"lbrace", "{"}, {"rbrace", "}"}, {"{", "{"}, {"}", "}"}, {"%", "%"}, {"int", "∫"}, {"sum", "∑"}, {"partial", "∂"}};
const std::map<std::string, std::string> kSpaces{{",", "0.1667em"}, {":", "0.2222em"}, {";", "0.2778em"}, {"!", "-0.1667em"},
                                                 {"quad", "1em"},   {"qquad", "2em"},   {" ", "0.25em"}};
const std::string kThin = "<mspace width=\"0.1667em\"/>";
bool is_function(const std::string& c) {
  static const char* names[] = {"sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos", "arctan", "sinh", "cosh", "tanh",
                                "exp", "ln", "log", "min", "max", "sgn"};
  for (const char* n : names)
    if (c == n) return true;
  return false;
}

/// A recursive descent over TeX: a list of atoms, each with its scripts.
class Reader {
public:
  explicit Reader(const std::string& tex) : s_(tex) {}

  std::string all() {
    std::string out = list('\0');
    if (i_ < s_.size()) fail("an unmatched '" + std::string(1, s_[i_]) + "'");
    return out;
  }

private:
  const std::string& s_;
  std::size_t i_ = 0;
  bool function_ = false;  ///< the atom just read is a function's name (sin, arctan)

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("the LaTeX '" + s_ + "' cannot be written as MathML: " + what + " at character " + std::to_string(i_ + 1),
                     "teach emit/mathml.cpp that command");
  }
  void skip_space() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  std::string command() {
    // after '\': letters, or one other character
    std::size_t b = i_;
    if (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) {
      while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) ++i_;
    } else if (i_ < s_.size()) {
      ++i_;
    }
    return s_.substr(b, i_ - b);
  }
  // {…} as one row, or a single atom
  std::string argument() {
    skip_space();
    if (i_ < s_.size() && s_[i_] == '{') {
      ++i_;
      std::string r = list('}');
      ++i_;
      return "<mrow>" + r + "</mrow>";
    }
    return atom();
  }
  // the raw text of {…} (for \mathrm and \text)
  std::string raw_group() {
    skip_space();
    if (i_ >= s_.size() || s_[i_] != '{') fail("a '{' expected");
    int depth = 0;
    std::size_t b = ++i_;
    for (; i_ < s_.size(); ++i_) {
      if (s_[i_] == '{') ++depth;
      if (s_[i_] == '}' && depth-- == 0) break;
    }
    if (i_ >= s_.size()) fail("an unclosed '{'");
    return s_.substr(b, i_++ - b);
  }
  std::string delimiter() {
    skip_space();
    if (i_ >= s_.size()) fail("a delimiter expected");
    if (s_[i_] == '\\') {
      ++i_;
      const std::string c = command();
      auto it = kOperators.find(c);
      if (it == kOperators.end()) fail("the delimiter \\" + c);
      return it->second;
    }
    const char c = s_[i_++];
    return c == '.' ? std::string() : std::string(1, c);
  }
  static std::string mo(const std::string& x, bool stretchy = false) {
    return "<mo" + std::string(stretchy ? " stretchy=\"true\"" : " stretchy=\"false\"") + ">" + xml_escape(x) + "</mo>";
  }

  std::string list(char close) {
    std::string out;
    for (;;) {
      skip_space();
      if (i_ >= s_.size()) {
        if (close) fail("an unclosed '{'");
        return out;
      }
      if (s_[i_] == close || (close == '\0' && s_[i_] == '}')) return out;
      if (s_.compare(i_, 6, "\\right") == 0) return out;
      function_ = false;
      std::string a = atom();
      const bool applied = function_;  // cos^{2} θ: the scripts on "cos", then the application
      // scripts: x^{2}, m_{1}, x_{1}^{2}
      std::string sub, sup;
      for (;;) {
        skip_space();
        if (i_ < s_.size() && s_[i_] == '_' && sub.empty()) {
          ++i_;
          sub = argument();
        } else if (i_ < s_.size() && s_[i_] == '^' && sup.empty()) {
          ++i_;
          sup = argument();
        } else {
          break;
        }
      }
      if (!sub.empty() && !sup.empty()) a = "<msubsup>" + a + sub + sup + "</msubsup>";
      else if (!sub.empty()) a = "<msub>" + a + sub + "</msub>";
      else if (!sup.empty()) a = "<msup>" + a + sup + "</msup>";
      // a function's name set off by thin spaces, as TeX's \sin is (3 g sin θ₂)
      out += applied ? kThin + a + "<mo>&#x2061;</mo>" + kThin : a;
    }
  }

  std::string atom() {
    skip_space();
    if (i_ >= s_.size()) fail("an argument expected");
    const char c = s_[i_];
    if (c == '{') return argument();
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i_ + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_ + 1])))) {
      std::size_t b = i_;
      while (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.')) ++i_;
      return "<mn>" + s_.substr(b, i_ - b) + "</mn>";
    }
    if (std::isalpha(static_cast<unsigned char>(c))) return "<mi>" + std::string(1, s_[i_++]) + "</mi>";
    if (c == '\\') {
      ++i_;
      return control(command());
    }
    if (c == '^' || c == '_') fail("a script with nothing under it");
    ++i_;
    if (c == '~') return "<mspace width=\"0.25em\"/>";
    if (c == '(' || c == ')' || c == '[' || c == ']' || c == '|') return mo(std::string(1, c));
    if (c == '-') return mo("−");
    if (c == '\'') return mo("′");
    return mo(std::string(1, c));
  }

  std::string control(const std::string& c) {
    if (c == "frac" || c == "dfrac" || c == "tfrac") {
      std::string num = argument();
      return "<mfrac>" + num + argument() + "</mfrac>";
    }
    if (c == "sqrt") {
      skip_space();
      if (i_ < s_.size() && s_[i_] == '[') {
        ++i_;
        std::string index = list(']');
        if (i_ >= s_.size()) fail("an unclosed '['");
        ++i_;
        std::string radicand = argument();
        return "<mroot>" + radicand + "<mrow>" + index + "</mrow></mroot>";
      }
      return "<msqrt>" + argument() + "</msqrt>";
    }
    if (c == "left") {
      const std::string open = delimiter();
      std::string inner = list('\0');
      if (s_.compare(i_, 6, "\\right") != 0) fail("\\left without \\right");
      i_ += 6;
      const std::string close = delimiter();
      return "<mrow>" + (open.empty() ? std::string() : mo(open, true)) + inner + (close.empty() ? std::string() : mo(close, true)) + "</mrow>";
    }
    if (c == "mathrm" || c == "text" || c == "operatorname") {
      const std::string t = raw_group();
      // \mathrm{m/s^{2}}: a unit; read as TeX in an upright row
      if (t.find_first_of("\\^_{") != std::string::npos) return "<mstyle mathvariant=\"normal\"><mrow>" + Reader(t).all() + "</mrow></mstyle>";
      return c == "text" ? "<mtext>" + xml_escape(t) + "</mtext>" : "<mi mathvariant=\"normal\">" + xml_escape(t) + "</mi>";
    }
    if (c == "dot" || c == "ddot" || c == "hat" || c == "bar" || c == "vec" || c == "overline") {
      static const std::map<std::string, std::string> accent{{"dot", "˙"}, {"ddot", "¨"}, {"hat", "^"}, {"bar", "‾"}, {"vec", "→"}, {"overline", "‾"}};
      return "<mover accent=\"true\">" + argument() + "<mo>" + accent.at(c) + "</mo></mover>";
    }
    if (is_function(c)) {
      function_ = true;
      return "<mi>" + c + "</mi>";
    }
    if (auto it = kGreekEntity.find(c); it != kGreekEntity.end()) return "<mi>" + it->second + "</mi>";
    if (c == "int" || c == "sum") return "<mo largeop=\"true\">" + kOperators.at(c) + "</mo>";
    if (auto it = kOperators.find(c); it != kOperators.end()) return mo(it->second);
    if (auto it = kSpaces.find(c); it != kSpaces.end()) return "<mspace width=\"" + it->second + "\"/>";
    if (c == "displaystyle" || c == "textstyle" || c == "limits") return "";
    fail("the command \\" + c);
  }
};

}  // namespace

std::string mathml(const std::string& tex, bool block) {
  return std::string("<math xmlns=\"http://www.w3.org/1998/Math/MathML\"") + (block ? " display=\"block\"" : "") + "><mrow>" +
         Reader(tex).all() + "</mrow></math>";
}

}  // namespace kinergy::emit
