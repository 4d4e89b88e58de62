// What an analysis kind writes its section of a derivation with: the notation of quantities at
// states, and the rows and lists every section writes the same way.
#include "kinergy/emit/sections.hpp"

#include <algorithm>

namespace kinergy::emit {

bool digits_only(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string subscript_digits(const std::string& s) {
  static const char* sub[] = {"\u2080", "\u2081", "\u2082", "\u2083", "\u2084",
                              "\u2085", "\u2086", "\u2087", "\u2088", "\u2089"};
  std::string o;
  for (char c : s) o += sub[c - '0'];
  return o;
}

std::string text_at(const std::string& base, const std::string& state) {
  if (digits_only(state)) return base + subscript_digits(state);
  return base + "(" + state + ")";
}

std::string tex_word(const std::string& s) { return "\\mathrm{" + tex_text(s) + "}"; }

std::string text_interval(const std::string& a, const std::string& b) { return a + " \u2192 " + b; }

std::string tex_interval_sub(const std::string& a, const std::string& b) {
  auto one = [](const std::string& s) { return digits_only(s) || s.size() == 1 ? s : "\\mathrm{" + s + "}"; };
  return one(a) + "\\to " + one(b);
}

std::string text_interval_sub(const std::string& a, const std::string& b) {
  if (digits_only(a) && digits_only(b)) return subscript_digits(a) + "\u2192" + subscript_digits(b);
  return "(" + a + "\u2192" + b + ")";
}

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += std::string(i ? (i + 1 == names.size() ? " and " : ", ") : "") + names[i];
  return out;
}

Row Sections::equation(Tags& tags, const principles::Equation& q) {
  auto [lhs, rhs] = sides(q);
  Row row = tags.row({Math::of(lhs), Math::of(rhs)});
  remember(q, row.tag);
  return row;
}

std::string Sections::bodies(const model::Analysis& a) const {
  std::vector<std::string> names;
  for (int b : a.bodies) names.push_back(solution().model.bodies[static_cast<std::size_t>(b)].name);
  return listed(names);
}

}  // namespace kinergy::emit
