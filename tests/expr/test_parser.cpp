// The expression parser with a context written in the test: exact decimals, precedence and
// associativity, X@S binding, built-in quantities and the columns of errors.
#include <catch2/catch.hpp>

#include <map>

#include "../support/helpers.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/expr/parser.hpp"

using namespace GiNaC;
using kinergy::InputError;

namespace {

/// Names x, y, z, rod.A (a point: only inside quantities); `X@S` renames every symbol s to s@S;
/// quantities `speed(P)` and `T()` / `T(body)` give marker symbols and record their arguments.
class TestContext : public kinergy::expr::Context {
public:
  realsymbol x{"x"}, y{"y"}, z{"z"};
  std::vector<std::pair<std::string, std::vector<std::string>>> calls;

  ex name(const std::string& id) override {
    if (id == "x") return x;
    if (id == "y") return y;
    if (id == "z") return z;
    throw InputError("unknown name '" + id + "'", "use x, y or z");
  }
  ex quantity(const std::string& f, const std::vector<std::string>& args) override {
    calls.push_back({f, args});
    if (f == "speed" && args.size() == 1) return sym("speed[" + args[0] + "]");
    if (f == "T") return sym("T[" + (args.empty() ? std::string() : args[0]) + "]");
    throw InputError("unknown function '" + f + "'", "use speed or T");
  }
  ex at_state(const ex& e, const std::string& state) override {
    if (state != "1" && state != "2" && state != "top")
      throw InputError("no state named '" + state + "'", "use 1, 2 or top");
    exmap m;
    for (const ex& s : kt::symbols_in(e)) m[s] = sym(kt::str(s) + "@" + state);
    return e.subs(m);
  }
  ex sym(const std::string& n) {
    auto it = syms_.find(n);
    if (it == syms_.end()) it = syms_.emplace(n, realsymbol(n)).first;
    return it->second;
  }

private:
  std::map<std::string, realsymbol> syms_;
};

ex P(const std::string& text, TestContext& c) { return kinergy::expr::parse(text, c); }

/// The column of the InputError thrown by parsing `text` (0 when none is thrown).
int error_column(const std::string& text, bool equation = false) {
  TestContext c;
  try {
    if (equation) kinergy::expr::parse_equation(text, c);
    else kinergy::expr::parse(text, c);
  } catch (const InputError& e) {
    return e.column();
  }
  return 0;
}

bool same(const ex& a, const ex& b) { return (a - b).expand().is_zero(); }

}  // namespace

TEST_CASE("parser: decimals are exact rationals", "[expr][parser]") {
  TestContext c;
  CHECK(P("9.81", c) == numeric(981, 100));
  CHECK(P("1e-6", c) == numeric(1, 1000000));
  CHECK(P("2.5E3", c) == 2500);
  CHECK(P("0.1 + 0.2", c) == numeric(3, 10));  // exactly, not 0.30000000000000004
  CHECK(P("1.50", c) == numeric(3, 2));
  CHECK(P("007", c) == 7);
  CHECK(P("6.02e23", c) == numeric(602) * pow(numeric(10), 21));
  CHECK(P("1e-6*x", c).is_equal(numeric(1, 1000000) * c.x));
  // a decimal never becomes a float
  ex v = P("3.14159 * 2", c);
  REQUIRE(is_a<numeric>(v));
  CHECK(ex_to<numeric>(v).is_rational());
}

TEST_CASE("parser: precedence and associativity", "[expr][parser]") {
  TestContext c;
  ex x = c.x, y = c.y, z = c.z;
  CHECK(same(P("-x^2", c), -pow(x, 2)));           // −(x²), not (−x)²
  CHECK(P("-2^2", c) == -4);
  CHECK(P("2^3^2", c) == 512);                     // right-associative: 2^(3^2)
  CHECK(P("2**3**2", c) == 512);
  CHECK(P("(2^3)^2", c) == 64);
  CHECK(P("2^-1", c) == numeric(1, 2));            // a sign in the exponent
  CHECK(P("2^-1^2", c) == numeric(1, 2));          // 2^(−(1²))
  CHECK(same(P("x - y - z", c), x - y - z));       // left-associative
  CHECK(same(P("x / y / z", c), x / (y * z)));
  CHECK(same(P("x + y * z", c), x + y * z));
  CHECK(same(P("x * y ^ 2", c), x * pow(y, 2)));
  CHECK(same(P("-x * -y", c), x * y));
  CHECK(same(P("--x", c), x));
  CHECK(same(P("+x", c), x));
  CHECK(same(P("(x + y) * z", c), (x + y) * z));
  CHECK(same(P("x^2 / 2", c), pow(x, 2) / 2));
  CHECK(same(P("1/2*x", c), x / 2));
  CHECK(same(P("  x\t+  y ", c), x + y));          // white space anywhere
}

TEST_CASE("parser: functions and constants", "[expr][parser]") {
  TestContext c;
  ex x = c.x, y = c.y;
  CHECK(P("pi", c).is_equal(Pi));
  CHECK(P("sin(pi/6)", c) == numeric(1, 2));
  CHECK(same(P("sqrt(x)^2", c), x));
  CHECK(P("atan2(y, x)", c).is_equal(atan2(y, x)));
  CHECK(P("log(x)", c).is_equal(log(x)));
  CHECK(P("ln(x)", c).is_equal(log(x)));
  CHECK(P("abs(-3)", c) == 3);
  CHECK(P("exp(0)", c) == 1);
  CHECK(P("cos(x)^2", c).is_equal(pow(cos(x), 2)));
  CHECK(kinergy::expr::is_math_function("atan2"));
  CHECK(!kinergy::expr::is_math_function("speed"));
}

TEST_CASE("parser: X@S binds a name or a parenthesised expression to a state", "[expr][parser][states]") {
  TestContext c;
  ex x1 = c.sym("x@1"), y1 = c.sym("y@1"), x2 = c.sym("x@2"), y2 = c.sym("y@2");
  CHECK(P("x@1", c).is_equal(x1));
  CHECK(same(P("x@1 + x@2", c), x1 + x2));
  CHECK(same(P("(x + y)@2", c), x2 + y2));
  CHECK(same(P("(x*y)@1 - x", c), x1 * y1 - c.x));
  CHECK(same(P("x@1^2", c), pow(x1, 2)));     // @ binds tighter than ^
  CHECK(same(P("-x@1", c), -x1));
  CHECK(same(P("x @ top", c), c.sym("x@top")));  // spaces around @
  CHECK(same(P("speed(rod.A)@2", c), c.sym("speed[rod.A]@2")));
}

TEST_CASE("parser: built-in quantities receive their raw arguments", "[expr][parser]") {
  TestContext c;
  P("speed( rod.A ) + T() + T(rod)", c);
  REQUIRE(c.calls.size() == 3);
  CHECK(c.calls[0].first == "speed");
  REQUIRE(c.calls[0].second.size() == 1);
  CHECK(c.calls[0].second[0] == "rod.A");  // trimmed
  CHECK(c.calls[1].first == "T");
  CHECK(c.calls[1].second.empty());
  CHECK(c.calls[2].second == std::vector<std::string>{"rod"});
  // nested brackets stay in one argument
  TestContext d;
  P("speed(f(a, b))", d);
  REQUIRE(d.calls.size() == 1);
  CHECK(d.calls[0].second == std::vector<std::string>{"f(a, b)"});
}

TEST_CASE("parser: equations", "[expr][parser]") {
  TestContext c;
  ex x = c.x, y = c.y;
  CHECK(same(kinergy::expr::parse_equation("x + 2 = y", c), x + 2 - y));
  CHECK(same(kinergy::expr::parse_equation("x*y", c), x * y));  // bare expression: = 0
}

TEST_CASE("parser: errors name the column of the fault (1-based)", "[expr][parser][errors]") {
  CHECK(error_column("x + * y") == 5);        // unexpected '*'
  CHECK(error_column("x y") == 3);            // unexpected 'y'
  CHECK(error_column("(x + y") == 7);         // expected ')' at the end
  CHECK(error_column("x + foo") == 5);        // unknown name: where the name starts
  CHECK(error_column("2 * (x + foo)") == 10);
  CHECK(error_column("x / 0") == 3);          // division by zero: at the '/'
  CHECK(error_column("x + ") == 5);           // ends too early
  CHECK(error_column("x @") == 3);            // no state name
  CHECK(error_column("x@9") == 3);            // unknown state: where its name starts
  CHECK(error_column("sin(x") == 6);
  CHECK(error_column("atan2(x)") == 1);       // wrong number of arguments: at the call
  CHECK(error_column("x + bogus(y)") == 5);   // unknown function
  CHECK(error_column("x = 1") == 3);          // '=' in an expression
  CHECK(error_column("") == 1);               // empty
  CHECK(error_column("x $ y") == 3);
  // in an equation, columns count from the start of the whole text
  CHECK(error_column("x = y + foo", true) == 9);
  CHECK(error_column("x = y = 1", true) == 7);  // the second '='
  CHECK(error_column("foo = y", true) == 1);
  // and the message says what is wrong
  TestContext c;
  try {
    P("x + foo", c);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("foo") != std::string::npos);
    CHECK(!e.fix().empty());
  }
}
