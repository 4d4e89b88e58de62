#include "kinergy/units/units.hpp"

#include <cctype>
#include <map>

#include "kinergy/common/error.hpp"

namespace kinergy::units {

using GiNaC::ex;
using GiNaC::numeric;

Dimension Dimension::operator*(const Dimension& o) const {
  Dimension d;
  for (int i = 0; i < 3; ++i) d.e[i] = e[i] + o.e[i];
  return d;
}
Dimension Dimension::operator/(const Dimension& o) const {
  Dimension d;
  for (int i = 0; i < 3; ++i) d.e[i] = e[i] - o.e[i];
  return d;
}
Dimension Dimension::pow(const numeric& p) const {
  Dimension d;
  for (int i = 0; i < 3; ++i) d.e[i] = e[i] * p;
  return d;
}
bool Dimension::operator==(const Dimension& o) const {
  for (int i = 0; i < 3; ++i)
    if (e[i] != o.e[i]) return false;
  return true;
}

static std::string power_text(const char* name, const numeric& p) {
  std::ostringstream os;
  os << name;
  if (p != 1) {
    os << "^";
    if (p.is_integer()) os << p;
    else os << "(" << p << ")";
  }
  return os.str();
}

std::string Dimension::str() const {
  static const char* names[3] = {"kg", "m", "s"};
  std::string num, den;
  for (int i = 0; i < 3; ++i) {
    if (e[i].is_zero()) continue;
    if (e[i].is_positive()) num += (num.empty() ? "" : "\u00b7") + power_text(names[i], e[i]);
    else den += (den.empty() ? "" : "\u00b7") + power_text(names[i], -e[i]);
  }
  if (num.empty() && den.empty()) return "1";
  if (num.empty()) num = "1";
  return den.empty() ? num : num + "/" + den;
}

namespace {

// Exact conversion factors. 1 lbf = 0.45359237 kg × 9.80665 m/s² = 4.4482216152605 N (exact);
// 1 ft = 0.3048 m; 1 slug = 1 lbf·s²/ft; 1 hp = 550 ft·lbf/s.
const numeric kFt(3048, 10000);
const numeric kIn(254, 10000);
const numeric kLbf(numeric(44482216152605LL) / numeric(10000000000000LL));

struct Entry {
  ex factor;
  Dimension dim;
};

const std::map<std::string, Entry>& table() {
  static const std::map<std::string, Entry> t = [] {
    const Dimension M = Dimension::mass(), L = Dimension::length(), T = Dimension::time();
    const Dimension F = M * L / (T * T), E = F * L, P = E / T, none;
    std::map<std::string, Entry> m;
    m["m"] = {1, L};
    m["mm"] = {numeric(1, 1000), L};
    m["cm"] = {numeric(1, 100), L};
    m["km"] = {1000, L};
    m["ft"] = {kFt, L};
    m["in"] = {kIn, L};
    m["mi"] = {numeric(1609344, 1000), L};
    m["kg"] = {1, M};
    m["g"] = {numeric(1, 1000), M};
    m["slug"] = {kLbf / kFt, M};
    m["N"] = {1, F};
    m["kN"] = {1000, F};
    m["lb"] = {kLbf, F};
    m["lbf"] = {kLbf, F};
    m["kip"] = {1000 * kLbf, F};
    m["s"] = {1, T};
    m["ms"] = {numeric(1, 1000), T};
    m["min"] = {60, T};
    m["h"] = {3600, T};
    m["rad"] = {1, none};
    m["deg"] = {GiNaC::Pi / 180, none};
    m["rev"] = {2 * GiNaC::Pi, none};
    m["rpm"] = {2 * GiNaC::Pi / 60, none / T};
    m["Hz"] = {1, none / T};
    m["J"] = {1, E};
    m["kJ"] = {1000, E};
    m["W"] = {1, P};
    m["kW"] = {1000, P};
    m["hp"] = {550 * kFt * kLbf, P};
    return m;
  }();
  return t;
}

std::string known_units() {
  std::string s;
  for (auto& [k, v] : table()) s += (s.empty() ? "" : " ") + k;
  return s;
}

// What to write instead of an unknown unit: the usual spellings students reach for.
std::string unit_advice(const std::string& name) {
  static const std::map<std::string, std::string> alias = {
      {"sec", "s"},     {"secs", "s"},     {"second", "s"},   {"seconds", "s"},  {"S", "s"},
      {"hr", "h"},      {"hrs", "h"},      {"hour", "h"},     {"hours", "h"},    {"minute", "min"},
      {"minutes", "min"}, {"mins", "min"}, {"meter", "m"},    {"meters", "m"},   {"metre", "m"},
      {"metres", "m"},  {"M", "m"},        {"feet", "ft"},    {"foot", "ft"},    {"inch", "in"},
      {"inches", "in"}, {"kgs", "kg"},     {"KG", "kg"},      {"Kg", "kg"},      {"kilogram", "kg"},
      {"kilograms", "kg"}, {"gram", "g"},  {"grams", "g"},    {"lbs", "lb"},     {"pound", "lb"},
      {"pounds", "lb"}, {"n", "N"},        {"newton", "N"},   {"newtons", "N"},  {"kn", "kN"},
      {"j", "J"},       {"joule", "J"},    {"joules", "J"},   {"w", "W"},        {"watt", "W"},
      {"watts", "W"},   {"kw", "kW"},      {"KW", "kW"},      {"rads", "rad"},   {"radian", "rad"},
      {"radians", "rad"}, {"degree", "deg"}, {"degrees", "deg"}, {"revs", "rev"}, {"revolution", "rev"},
      {"revolutions", "rev"}, {"RPM", "rpm"}, {"HP", "hp"},   {"slugs", "slug"}, {"hz", "Hz"}};
  auto a = alias.find(name);
  if (a != alias.end()) return "write '" + a->second + "'";
  return "use one of: " + known_units();
}

// unit   := factor (('*' | '·' | '/') factor)*
// factor := NAME ('^' INT)? | '1' | '(' unit ')' ('^' INT)?
struct UnitParser {
  const std::string& s;
  std::size_t i = 0;
  int depth = 0;  ///< nested '(': bounded, so a pathological text cannot exhaust the stack

  void skip() {
    while (i < s.size() && s[i] == ' ') ++i;
  }
  [[noreturn]] void fail(const std::string& what, const std::string& fix) const {
    throw InputError(what, fix, static_cast<int>(i) + 1);
  }
  bool at_mul() {
    skip();
    if (i < s.size() && s[i] == '*') { ++i; return true; }
    if (s.compare(i, 2, "\u00b7") == 0) { i += 2; return true; }
    return false;
  }
  Unit unit() {
    Unit u = factor();
    for (;;) {
      if (at_mul()) {
        Unit f = factor();
        u.factor *= f.factor;
        u.dim = u.dim * f.dim;
      } else if (i < s.size() && s[i] == '/') {
        ++i;
        Unit f = factor();
        u.factor /= f.factor;
        u.dim = u.dim / f.dim;
      } else {
        return u;
      }
    }
  }
  Unit factor() {
    skip();
    Unit u;
    if (i < s.size() && s[i] == '(') {
      if (++depth > 20) fail("a unit nested too deeply in parentheses", "write the unit plainly, e.g. kg*m^2/s^2");
      ++i;
      u = unit();
      --depth;
      skip();
      if (i >= s.size() || s[i] != ')') fail("unit has an unclosed '('", "close it with ')'");
      ++i;
    } else if (i < s.size() && s[i] == '1') {
      ++i;
    } else {
      std::size_t b = i;
      while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
      std::string name = s.substr(b, i - b);
      if (name.empty()) {
        i = b;
        fail("expected a unit name", "write a unit such as m, kg, s, N, rad, deg, ft, lb");
      }
      auto it = table().find(name);
      if (it == table().end()) {
        i = b;
        fail("unknown unit '" + name + "'", unit_advice(name));
      }
      u.factor = it->second.factor;
      u.dim = it->second.dim;
    }
    skip();
    if (i < s.size() && s[i] == '^') {
      ++i;
      skip();
      bool paren = i < s.size() && s[i] == '(';
      if (paren) ++i;
      bool neg = i < s.size() && s[i] == '-';
      if (neg) ++i;
      std::size_t b = i;
      while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
      if (b == i) fail("expected an integer exponent after '^'", "write e.g. m^2 or s^-2");
      if (i - b > 2) {
        i = b;
        fail("the exponent '" + s.substr(b, s.find_first_not_of("0123456789", b) - b) + "' of a unit is too large",
             "a unit's exponent is a small integer, e.g. m^2 or s^-2");
      }
      int p = std::stoi(s.substr(b, i - b));
      if (neg) p = -p;
      if (paren) {
        if (i >= s.size() || s[i] != ')') fail("unclosed '(' in exponent", "write s^(-2)");
        ++i;
      }
      u.factor = GiNaC::pow(u.factor, p);
      u.dim = u.dim.pow(p);
    }
    return u;
  }
};

}  // namespace

Unit parse_unit(const std::string& text) {
  UnitParser p{text};
  p.skip();
  if (p.i >= text.size()) throw InputError("empty unit", "write a unit such as m, kg, s, N, rad");
  Unit u = p.unit();
  p.skip();
  if (p.i != text.size())
    p.fail("unexpected '" + text.substr(p.i, 1) + "' in unit '" + text + "'",
           "combine units with *, / and ^ (e.g. m/s^2, N*m)");
  u.text = text;
  // trim
  while (!u.text.empty() && u.text.front() == ' ') u.text.erase(0, 1);
  while (!u.text.empty() && u.text.back() == ' ') u.text.pop_back();
  return u;
}

bool parse_decimal(const std::string& s, std::size_t& pos, numeric& out, int* sig_figs) {
  // [+-]? digits ('.' digits)? ([eE] [+-]? digits)?  — read exactly: "9.81" is 981/100.
  std::size_t i = pos;
  bool neg = false;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) neg = s[i++] == '-';
  std::string digits;
  int frac = 0;
  bool seen_digit = false, dot = false;
  while (i < s.size()) {
    char c = s[i];
    if (std::isdigit(static_cast<unsigned char>(c))) {
      digits += c;
      seen_digit = true;
      if (dot) ++frac;
      ++i;
    } else if (c == '.' && !dot) {
      dot = true;
      ++i;
    } else {
      break;
    }
  }
  if (!seen_digit) return false;
  long exp10 = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    bool eneg = false;
    if (j < s.size() && (s[j] == '-' || s[j] == '+')) eneg = s[j++] == '-';
    std::size_t b = j;
    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
    if (j > b) {
      if (j - b > 4) throw InputError("exponent too large in '" + s.substr(pos, j - pos) + "'", "write a number between 1e-9999 and 1e9999");
      exp10 = std::stol(s.substr(b, j - b));
      if (eneg) exp10 = -exp10;
      i = j;
    }
  }
  // significant figures: digits without leading zeros (trailing zeros count when written).
  if (sig_figs) {
    std::size_t k = digits.find_first_not_of('0');
    *sig_figs = k == std::string::npos ? 1 : static_cast<int>(digits.size() - k);
  }
  numeric v(digits.c_str());
  v = v / GiNaC::pow(numeric(10), numeric(frac));
  if (exp10 != 0) v = v * GiNaC::pow(numeric(10), numeric(exp10));
  out = neg ? -v : v;
  pos = i;
  return true;
}

Quantity parse_quantity(const std::string& text) {
  Quantity q;
  std::size_t i = 0;
  while (i < text.size() && text[i] == ' ') ++i;
  if (text.compare(i, 7, "unknown") == 0 &&
      (i + 7 == text.size() || text[i + 7] == ' ')) {
    q.unknown = true;
    i += 7;
  } else {
    numeric v;
    std::size_t j = i;
    // a leading digit, sign or dot means a number (units never start with those)
    if (i < text.size() &&
        (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '-' || text[i] == '+' ||
         text[i] == '.')) {
      if (!parse_decimal(text, j, v, &q.sig_figs))
        throw InputError("'" + text + "' is not a number", "write e.g. 9.81 m/s^2", static_cast<int>(i) + 1);
      q.has_number = true;
      q.number = v;
      i = j;
    }
  }
  std::string rest = text.substr(i);
  bool blank = rest.find_first_not_of(' ') == std::string::npos;
  if (blank) {
    if (q.unknown) throw InputError("'unknown' needs a unit", "write e.g. 'unknown N/m' (or 'unknown number' for a pure number)");
    if (q.has_number) {
      q.unit.text = "";
      q.si = q.number;
      return q;  // dimensionless number
    }
    throw InputError("empty quantity", "write a number and a unit, e.g. '5 kg'");
  }
  // `number`: a pure number without a value (`mu_k: number`), or an unknown one (`unknown number`)
  if (!q.has_number && rest.find_first_not_of(' ') == rest.find("number") &&
      rest.find_first_not_of(' ', rest.find("number") + 6) == std::string::npos) {
    q.unit.text = "";
    return q;
  }
  try {
    q.unit = parse_unit(rest);
  } catch (const InputError& e) {
    throw InputError(e.what(), e.fix(), e.column() + static_cast<int>(i));
  }
  if (q.has_number) q.si = q.number * q.unit.factor;
  return q;
}

std::string si_name(const Dimension& d) {
  const Dimension M = Dimension::mass(), L = Dimension::length(), T = Dimension::time();
  const Dimension F = M * L / (T * T);
  const std::pair<Dimension, const char*> names[] = {
      {Dimension{}, ""},          {L, "m"},
      {L / T, "m/s"},             {L / (T * T), "m/s^2"},
      {Dimension{} / T, "rad/s"}, {Dimension{} / (T * T), "rad/s^2"},
      {M, "kg"},                  {T, "s"},
      {F, "N"},                   {F * L, "J"},
      {F * L / T, "W"},           {F / L, "N/m"},
      {F * T, "N\u00b7s"},        {F * L * T, "N\u00b7m\u00b7s"},
      {M * L * L, "kg\u00b7m^2"},
  };
  for (auto& [dim, name] : names)
    if (dim == d) return name;
  return d.str();
}

}  // namespace kinergy::units
