// Names as a textbook writes them: Greek letters spelled out become letters, what follows a
// symbol's letter becomes its subscript, and words stay words (draw/names.hpp).
#include "kinergy/draw/names.hpp"

#include <array>
#include <cctype>
#include <utility>

namespace kinergy::draw {

namespace {

struct Greek {
  const char* name;
  const char* text;  // UTF-8
  const char* tex;
};

// longest first where one name begins another (theta before eta, epsilon before ... )
constexpr std::array<Greek, 28> kGreek{{{"epsilon", "\u03b5", "\\varepsilon"},
                                        {"lambda", "\u03bb", "\\lambda"},
                                        {"Lambda", "\u039b", "\\Lambda"},
                                        {"alpha", "\u03b1", "\\alpha"},
                                        {"gamma", "\u03b3", "\\gamma"},
                                        {"Gamma", "\u0393", "\\Gamma"},
                                        {"delta", "\u03b4", "\\delta"},
                                        {"Delta", "\u0394", "\\Delta"},
                                        {"theta", "\u03b8", "\\theta"},
                                        {"Theta", "\u0398", "\\Theta"},
                                        {"kappa", "\u03ba", "\\kappa"},
                                        {"sigma", "\u03c3", "\\sigma"},
                                        {"Sigma", "\u03a3", "\\Sigma"},
                                        {"omega", "\u03c9", "\\omega"},
                                        {"Omega", "\u03a9", "\\Omega"},
                                        {"beta", "\u03b2", "\\beta"},
                                        {"zeta", "\u03b6", "\\zeta"},
                                        {"iota", "\u03b9", "\\iota"},
                                        {"eta", "\u03b7", "\\eta"},
                                        {"rho", "\u03c1", "\\rho"},
                                        {"tau", "\u03c4", "\\tau"},
                                        {"varphi", "\u03c6", "\\varphi"},
                                        {"phi", "\u03d5", "\\phi"},  // (as the equations set it)
                                        {"Phi", "\u03a6", "\\Phi"},
                                        {"chi", "\u03c7", "\\chi"},
                                        {"psi", "\u03c8", "\\psi"},
                                        {"mu", "\u03bc", "\\mu"},
                                        {"nu", "\u03bd", "\\nu"}}};

bool upper(char c) { return std::isupper(static_cast<unsigned char>(c)) != 0; }
bool lower(char c) { return std::islower(static_cast<unsigned char>(c)) != 0; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

/// Does `s` read as a subscript: empty, digits, capitals then digits, or one small letter?
bool subscript_like(const std::string& s) {
  if (s.size() == 1 && lower(s[0])) return true;
  std::size_t i = 0;
  while (i < s.size() && upper(s[i])) ++i;
  while (i < s.size() && digit(s[i])) ++i;
  return i == s.size();
}

}  // namespace

Name subscripted(const Name& base, const std::string& sub) {
  if (sub.empty()) return base;
  // (a word is set upright in TeX; one letter or digits as they are)
  const bool word = sub.size() > 1 && !subscript_like(sub);
  return {base.text + "_" + sub, base.tex + "_{" + (word ? "\\mathrm{" + sub + "}" : sub) + "}"};
}

Name subscripted(const Name& base, const Name& sub) {
  if (sub.text.empty()) return base;
  const std::string b = base.tex.find('_') == std::string::npos ? base.tex : "{" + base.tex + "}";
  return {base.text + "_" + sub.text, b + "_{" + sub.tex + "}"};
}

std::optional<Name> textbook(const std::string& id) {
  if (id.empty()) return std::nullopt;
  // what follows the letter: a subscript as it is, or — written after '_' — any word (v_max)
  auto sub = [](std::string rest) -> std::optional<std::string> {
    if (rest.size() > 1 && rest[0] == '_') {
      rest = rest.substr(1);
      for (char c : rest)
        if (!std::isalnum(static_cast<unsigned char>(c))) return std::nullopt;
      return rest;
    }
    if (!subscript_like(rest)) return std::nullopt;
    return rest;
  };
  for (const Greek& g : kGreek) {
    const std::string n = g.name;
    if (id.rfind(n, 0) != 0) continue;
    if (auto rest = sub(id.substr(n.size()))) return subscripted({g.text, g.tex}, *rest);
  }
  if (!std::isalpha(static_cast<unsigned char>(id[0]))) return std::nullopt;
  const auto rest = sub(id.substr(1));
  if (!rest) return std::nullopt;
  return subscripted({id.substr(0, 1), id.substr(0, 1)}, *rest);
}

Name from_tex(const std::string& tex) {
  std::string text;
  for (std::size_t i = 0; i < tex.size();) {
    const char c = tex[i];
    if (c == '\\') {
      // a command: a Greek letter as the letter, any other dropped (its argument stays)
      std::size_t j = i + 1;
      while (j < tex.size() && std::isalpha(static_cast<unsigned char>(tex[j]))) ++j;
      std::string cmd = tex.substr(i + 1, j - i - 1);
      if (cmd == "epsilon") cmd = "varepsilon";
      for (const Greek& g : kGreek)
        if (std::string(g.tex) == "\\" + cmd) text += g.text;
      i = j;
      continue;
    }
    if (c != '{' && c != '}') text += c;
    ++i;
  }
  return {text, tex};
}

std::optional<Name> short_name(const std::string& body) {
  // a word and the capitals or digits it ends in: gearA → A, ball2 → 2
  std::size_t i = body.size();
  while (i > 0 && (upper(body[i - 1]) || digit(body[i - 1]))) --i;
  if (i > 1 && i < body.size() && lower(body[i - 1])) return Name{body.substr(i), body.substr(i)};
  if (auto n = textbook(body); n && body.size() <= 2) return n;
  return std::nullopt;
}

}  // namespace kinergy::draw
