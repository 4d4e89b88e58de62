#include "kinergy/expr/parser.hpp"

#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

#include "kinergy/common/error.hpp"
#include "kinergy/units/units.hpp"

namespace kinergy::expr {

using GiNaC::ex;

bool is_math_function(const std::string& n) {
  static const std::set<std::string> f = {"sin",  "cos",  "tan",  "asin", "acos", "atan", "atan2",
                                          "sqrt", "exp",  "log",  "ln",   "abs",  "sinh", "cosh",
                                          "tanh", "max",  "min"};
  return f.count(n) > 0;
}

namespace {

// Nesting deeper than this is no formula a person wrote; refusing it keeps the recursive
// descent from running out of stack.
constexpr int kMaxDepth = 200;
// A number raised to a power is computed exactly; refuse results beyond this many bits.
constexpr double kMaxBits = 1 << 20;

struct Parser {
  const std::string& s;
  Context& ctx;
  std::size_t i = 0;
  int depth = 0;

  struct Deeper {
    Parser& p;
    explicit Deeper(Parser& q, std::size_t at) : p(q) {
      if (++p.depth > kMaxDepth) p.fail("the expression is nested too deeply", "simplify the expression", at);
    }
    ~Deeper() { --p.depth; }
  };

  // b^x, refusing exact numbers too large to compute (10^10^10)
  ex raise(const ex& b, const ex& x, std::size_t at) const {
    using GiNaC::numeric;
    if (GiNaC::is_a<numeric>(b) && GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_integer()) {
      const numeric& nb = GiNaC::ex_to<numeric>(b);
      const numeric& nx = GiNaC::ex_to<numeric>(x);
      if (nb.is_rational() && !nb.is_zero() && abs(nb) != 1) {
        double bits = (double(nb.numer().int_length()) + double(nb.denom().int_length())) *
                      std::abs(nx.to_double());
        if (!(bits <= kMaxBits))
          fail("the number " + text_of(b) + "^" + text_of(x) + " is too large to compute exactly",
               "write a smaller number, or give the value as a decimal with an exponent (e.g. 1e30)", at);
      }
    }
    // any other base to an exponent beyond kMaxExponent, before GiNaC::pow: it evaluates
    // (12 (l² − r²))^n as 12^n (l² − r²)^n, and 12^n with n = 10^29 never returns
    if (GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_real() && abs(GiNaC::ex_to<numeric>(x)) > kMaxExponent &&
        !(GiNaC::is_a<numeric>(b) && (b.is_zero() || abs(GiNaC::ex_to<numeric>(b)) == 1)))
      fail("a power here has the exponent " + text_of(x) + ", too large for exact arithmetic",
           "check the exponent: at most " + std::to_string(kMaxExponent) + " in size (no physical quantity needs more)", at);
    // 0 to a negative power: refused before GiNaC::pow, whose node would leak when its
    // evaluation throws the division by zero
    if (b.is_zero() && GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_real() && GiNaC::ex_to<numeric>(x).is_negative())
      fail("'" + text_of(b) + "^" + text_of(x) + "' is undefined (division by zero)", "check the expression", at);
    try {
      return GiNaC::pow(b, x);
    } catch (const std::exception& e) {
      fail("'" + text_of(b) + "^" + text_of(x) + "' is undefined (" + math_fault(e) + ")", "check the expression", at);
    }
  }
  // What GiNaC's complaint means, in words.
  static std::string math_fault(const std::exception& e) {
    std::string w = e.what();
    if (w.find("division by zero") != std::string::npos) return "division by zero";
    if (w.find("log(0)") != std::string::npos) return "the logarithm of zero";
    if (w.find("pole") != std::string::npos) return "the function is infinite there";
    return w;
  }
  static std::string text_of(const ex& e) {
    std::ostringstream os;
    os << e;
    std::string t = os.str();
    return t.size() > 20 ? t.substr(0, 17) + "..." : t;
  }

  [[noreturn]] void fail(const std::string& what, const std::string& fix, std::size_t at) const {
    throw InputError(what, fix, static_cast<int>(at) + 1);
  }
  void skip() {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  }
  bool eat(char c) {
    skip();
    if (i < s.size() && s[i] == c) {
      ++i;
      return true;
    }
    return false;
  }
  bool peek(char c) {
    skip();
    return i < s.size() && s[i] == c;
  }

  ex expr() {
    ex e = term();
    for (;;) {
      if (eat('+')) e = e + term();
      else if (eat('-')) e = e - term();
      else return e;
    }
  }
  ex term() {
    ex e = unary();
    for (;;) {
      skip();
      if (s.compare(i, 2, "**") == 0) return e;  // handled in power
      if (eat('*')) e = e * unary();
      else if (peek('/')) {
        std::size_t at = i;
        ++i;
        ex d = unary();
        if (d.is_zero()) fail("division by zero", "remove the zero divisor", at);
        e = e / d;
      } else return e;
    }
  }
  ex unary() {
    skip();
    Deeper guard(*this, i);
    if (eat('-')) return -unary();
    if (eat('+')) return unary();
    return power();
  }
  ex power() {
    ex b = postfix();
    skip();
    std::size_t at = i;
    if (s.compare(i, 2, "**") == 0) {
      i += 2;
      return raise(b, unary(), at);
    }
    if (eat('^')) return raise(b, unary(), at);
    return b;
  }
  ex postfix() {
    ex e = primary();
    skip();
    if (peek('@')) {
      std::size_t at = i;
      ++i;
      skip();
      std::size_t b = i;
      while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_')) ++i;
      if (b == i) fail("expected a state name after '@'", "write e.g. theta_dot@2", at);
      std::string st = s.substr(b, i - b);
      try {
        return ctx.at_state(e, st);
      } catch (const InputError& err) {
        if (err.column() > 0) throw;
        throw InputError(err.what(), err.fix(), static_cast<int>(b) + 1);
      }
    }
    return e;
  }
  std::string name() {
    std::size_t b = i;
    while (i < s.size() &&
           (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_' || s[i] == '.'))
      ++i;
    return s.substr(b, i - b);
  }
  std::vector<std::string> raw_args() {
    // after '(' : split on top-level commas up to the matching ')'
    std::vector<std::string> args;
    int depth = 0;
    std::string cur;
    while (i < s.size()) {
      char c = s[i++];
      if (c == '(' || c == '[') ++depth;
      if ((c == ')' || c == ']') && depth == 0) {
        args.push_back(cur);
        for (auto& a : args) {
          while (!a.empty() && std::isspace(static_cast<unsigned char>(a.front()))) a.erase(0, 1);
          while (!a.empty() && std::isspace(static_cast<unsigned char>(a.back()))) a.pop_back();
        }
        if (args.size() == 1 && args[0].empty()) args.clear();
        return args;
      }
      if (c == ')' || c == ']') --depth;
      if (c == ',' && depth == 0) {
        args.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
    fail("unclosed '('", "close the argument list with ')'", i);
  }
  // At i, a name follows a number or a name with no operator between ("2 l", "0.1 m"): say so.
  void juxtaposed() {
    skip();
    if (i >= s.size() || !(std::isalpha(static_cast<unsigned char>(s[i])) || s[i] == '_')) return;
    std::size_t k = i;
    while (k > 0 && std::isspace(static_cast<unsigned char>(s[k - 1]))) --k;
    if (k == 0 || k == i) return;
    char prev = s[k - 1];
    if (!(std::isalnum(static_cast<unsigned char>(prev)) || prev == '_' || prev == '.' || prev == ')')) return;
    std::size_t e = i;
    while (e < s.size() && (std::isalnum(static_cast<unsigned char>(s[e])) || s[e] == '_')) ++e;
    std::string n = s.substr(i, e - i);
    fail("no operator before '" + n + "'",
         "write '*' to multiply (e.g. 2*l); a value with a unit goes under parameters (e.g. 'a: 0.1 m') and is used by its name",
         i);
  }

  ex call_math(const std::string& f, std::size_t at) {
    std::vector<ex> a;
    if (!eat(')')) {
      do a.push_back(expr());
      while (eat(','));
      if (!eat(')')) fail("expected ')' after the arguments of " + f, "close the call with ')'", i);
    }
    std::size_t want = f == "atan2" || f == "max" || f == "min" ? 2 : 1;
    if (a.size() != want)
      fail(f + " takes " + std::to_string(want) + " argument" + (want > 1 ? "s" : ""),
           "write e.g. " + f + (want > 1 ? "(y, x)" : "(x)"), at);
    try {
      return math(f, a);
    } catch (const std::exception& e) {
      fail("'" + f + "(" + text_of(a[0]) + (a.size() > 1 ? ", " + text_of(a[1]) : std::string()) + ")' is undefined (" +
               math_fault(e) + ")",
           "check the argument of " + f, at);
    }
  }
  static ex math(const std::string& f, const std::vector<ex>& a) {
    if (f == "sin") return GiNaC::sin(a[0]);
    if (f == "cos") return GiNaC::cos(a[0]);
    if (f == "tan") return GiNaC::tan(a[0]);
    if (f == "asin") return GiNaC::asin(a[0]);
    if (f == "acos") return GiNaC::acos(a[0]);
    if (f == "atan") return GiNaC::atan(a[0]);
    if (f == "atan2") return GiNaC::atan2(a[0], a[1]);
    if (f == "sqrt") return GiNaC::sqrt(a[0]);
    if (f == "exp") return GiNaC::exp(a[0]);
    if (f == "log" || f == "ln") return GiNaC::log(a[0]);
    if (f == "abs") return GiNaC::abs(a[0]);
    // max(a, b) = (a + b + |a − b|)/2, min(a, b) = (a + b − |a − b|)/2: a force that acts in part
    // of the motion (a bumper: k*max(x - L, 0)) is integrated piece by piece, split where |·| turns
    if (f == "max") return (a[0] + a[1] + GiNaC::abs(a[0] - a[1])) / 2;
    if (f == "min") return (a[0] + a[1] - GiNaC::abs(a[0] - a[1])) / 2;
    if (f == "sinh") return GiNaC::sinh(a[0]);
    if (f == "cosh") return GiNaC::cosh(a[0]);
    return GiNaC::tanh(a[0]);
  }
  ex primary() {
    skip();
    if (i >= s.size()) fail("expression ends too early", "complete the expression", i);
    std::size_t at = i;
    char c = s[i];
    if (c == '(') {
      ++i;
      ex e = expr();
      if (!eat(')')) {
        juxtaposed();
        fail("expected ')'", "close the parenthesis", i);
      }
      return e;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      GiNaC::numeric v;
      bool ok = false;
      try {
        ok = units::parse_decimal(s, i, v);
      } catch (const InputError& e) {
        fail(e.what(), e.fix(), at);
      }
      if (!ok) fail("bad number", "write a decimal such as 9.81", at);
      return v;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::string n = name();
      skip();
      if (i < s.size() && s[i] == '(') {
        ++i;
        if (is_math_function(n)) return call_math(n, at);
        std::vector<std::string> args = raw_args();
        try {
          return ctx.quantity(n, args);
        } catch (const InputError& e) {
          if (e.column() > 0) throw;
          throw InputError(e.what(), e.fix(), static_cast<int>(at) + 1);
        }
      }
      if (n == "pi") return GiNaC::Pi;
      try {
        return ctx.name(n);
      } catch (const InputError& e) {
        if (e.column() > 0) throw;
        throw InputError(e.what(), e.fix(), static_cast<int>(at) + 1);
      }
    }
    fail(std::string("unexpected '") + c + "'", "check the expression's syntax", at);
  }
};

}  // namespace

ex parse(const std::string& text, Context& ctx) {
  Parser p{text, ctx};
  p.skip();
  if (p.i >= text.size()) throw InputError("empty expression", "write an expression", 1);
  ex e = p.expr();
  p.skip();
  if (p.i != text.size()) {
    if (text[p.i] == '=')
      p.fail("'=' is not allowed here", "write an expression, not an equation", p.i);
    p.juxtaposed();
    p.fail("unexpected '" + text.substr(p.i, 1) + "'", "check the expression's syntax", p.i);
  }
  return e;
}

ex parse_equation(const std::string& text, Context& ctx) {
  auto eq = text.find('=');
  if (eq == std::string::npos) return parse(text, ctx);
  if (text.find('=', eq + 1) != std::string::npos)
    throw InputError("more than one '=' in an equation", "write one equation 'lhs = rhs'",
                     static_cast<int>(text.find('=', eq + 1)) + 1);
  std::string lhs = text.substr(0, eq), rhs = text.substr(eq + 1);
  ex l, r;
  l = parse(lhs, ctx);
  try {
    r = parse(rhs, ctx);
  } catch (const InputError& e) {
    throw InputError(e.what(), e.fix(), e.column() + static_cast<int>(eq) + 1);
  }
  return l - r;
}

}  // namespace kinergy::expr
