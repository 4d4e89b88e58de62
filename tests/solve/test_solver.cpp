// The solver on small systems whose solutions are known: elimination, quadratics (two
// branches), sin(u) = c, a transcendental equation (numeric root, flagged), and rejections.
#include <catch2/catch.hpp>

#include <cmath>

#include "../support/helpers.hpp"
#include "kinergy/solve/solver.hpp"

using namespace GiNaC;
using kinergy::principles::Equation;
using kinergy::solve::Branch;
using kinergy::solve::Problem;
using kinergy::solve::SolveError;
using kinergy::solve::solve;

namespace {

Equation eq(const ex& lhs, const ex& rhs, const std::string& label = "test equation") {
  return Equation{lhs, rhs, "test", label, kinergy::SourcePos{"<test>", 1, 1}};
}

/// Numeric values of `u` over all branches, sorted.
std::vector<double> values_of(const std::vector<Branch>& bs, const ex& u, const exmap& env = {}) {
  std::vector<double> out;
  for (auto& b : bs) {
    auto it = b.sol.find(u);
    if (it == b.sol.end()) throw std::runtime_error("a branch without " + kt::str(u));
    out.push_back(kt::to_double(it->second, env));
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("solver: linear system by elimination", "[solve]") {
  realsymbol x("x"), y("y"), z("z");
  Problem p;
  // 2x + 3y − z = 5, x − y + 2z = 5, 3x + y + z = 9  →  x = 2, y = 1, z = 2
  p.equations = {eq(2 * x + 3 * y - z, 5), eq(x - y + 2 * z, 5), eq(3 * x + y + z, 9)};
  p.unknowns = {x, y, z};
  auto bs = solve(p);
  REQUIRE(bs.size() == 1);
  CHECK(bs[0].sol.at(x) == 2);
  CHECK(bs[0].sol.at(y) == 1);
  CHECK(bs[0].sol.at(z) == 2);
  CHECK(bs[0].numeric_only.empty());
  CHECK(bs[0].steps.size() == 3);
}

TEST_CASE("solver: linear in an unknown with symbolic coefficients", "[solve]") {
  possymbol a("a"), b("b");
  realsymbol x("x"), y("y");
  Problem p;
  // a x = b,  x y = 1  (nonlinear in x·y, linear in y once x is known)
  p.equations = {eq(x * y, 1), eq(a * x, b)};
  p.unknowns = {x, y};
  p.env = {{a, 2}, {b, 3}};
  auto bs = solve(p);
  REQUIRE(bs.size() == 1);
  CHECK(kt::symbolically_zero(bs[0].sol.at(x) - b / a));
  CHECK(kt::symbolically_zero(bs[0].sol.at(y) - a / b));
}

TEST_CASE("solver: the known values are substituted first", "[solve]") {
  realsymbol x("x"), y("y"), g("g_known");
  Problem p;
  p.equations = {eq(x + g * y, 7)};
  p.unknowns = {x};
  p.given = {{g, 2}, {y, 3}};
  auto bs = solve(p);
  REQUIRE(bs.size() == 1);
  CHECK(bs[0].sol.at(x) == 1);
}

TEST_CASE("solver: a quadratic makes two branches", "[solve][quadratic]") {
  realsymbol u("u");
  SECTION("u^2 - 3u + 2 = 0: roots 1 and 2") {
    Problem p;
    p.equations = {eq(pow(u, 2) - 3 * u + 2, 0)};
    p.unknowns = {u};
    auto bs = solve(p);
    REQUIRE(bs.size() == 2);
    auto v = values_of(bs, u);
    CHECK(v[0] == Approx(1.0).epsilon(1e-14));
    CHECK(v[1] == Approx(2.0).epsilon(1e-14));
    for (auto& b : bs) CHECK(b.numeric_only.empty());
  }
  SECTION("(1/2) m u^2 = m g h: u = +-sqrt(2 g h)") {
    possymbol m("m"), g("g"), h("h");
    Problem p;
    p.equations = {eq(m * pow(u, 2) / 2, m * g * h)};
    p.unknowns = {u};
    p.env = {{m, 3}, {g, numeric(981, 100)}, {h, 2}};
    auto bs = solve(p);
    REQUIRE(bs.size() == 2);
    bool plus = false, minus = false;
    for (auto& b : bs) {
      ex s = b.sol.at(u);
      plus = plus || kt::symbolically_zero(s - sqrt(2 * g * h));
      minus = minus || kt::symbolically_zero(s + sqrt(2 * g * h));
    }
    CHECK(plus);
    CHECK(minus);
  }
  SECTION("a quadratic with no real root is rejected") {
    Problem p;
    p.equations = {eq(pow(u, 2) + 1, 0, "energy equation")};
    p.unknowns = {u};
    CHECK_THROWS_AS(solve(p), SolveError);
    Problem q;
    q.equations = {eq(pow(u, 2) + u + 1, 0)};
    q.unknowns = {u};
    CHECK_THROWS_AS(solve(q), SolveError);
  }
}

TEST_CASE("solver: sin(u) = c gives asin(c) and pi - asin(c)", "[solve][trig]") {
  realsymbol u("u");
  possymbol c("c");
  Problem p;
  p.equations = {eq(sin(u), c)};
  p.unknowns = {u};
  p.env = {{c, numeric(3, 10)}};
  auto bs = solve(p);
  REQUIRE(bs.size() == 2);
  auto v = values_of(bs, u, p.env);
  double a = std::asin(0.3);
  CHECK(v[0] == Approx(a).epsilon(1e-14));
  CHECK(v[1] == Approx(M_PI - a).epsilon(1e-14));
  for (auto& b : bs) {
    CHECK(b.numeric_only.empty());  // closed forms
    CHECK(kt::symbolically_zero(sin(b.sol.at(u)) - c));
  }
  SECTION("cos(u) = c: +-acos(c)") {
    Problem q;
    q.equations = {eq(2 * cos(u) - 1, 0)};
    q.unknowns = {u};
    auto cs = solve(q);
    REQUIRE(cs.size() == 2);
    auto w = values_of(cs, u);
    CHECK(w[0] == Approx(-M_PI / 3).epsilon(1e-14));
    CHECK(w[1] == Approx(M_PI / 3).epsilon(1e-14));
  }
  SECTION("|sin(u)| would exceed 1: no solution") {
    Problem q;
    q.equations = {eq(sin(u), 2)};
    q.unknowns = {u};
    CHECK_THROWS_AS(solve(q), SolveError);
  }
  SECTION("quadratic in sin(u): 2 sin^2 u - 3 sin u + 1 = 0 (sin u = 1/2 or 1)") {
    Problem q;
    q.equations = {eq(2 * pow(sin(u), 2) - 3 * sin(u) + 1, 0)};
    q.unknowns = {u};
    auto cs = solve(q);
    REQUIRE(cs.size() >= 3);
    for (auto& b : cs) {
      double s = std::sin(kt::to_double(b.sol.at(u)));
      CHECK((std::abs(s - 0.5) < 1e-12 || std::abs(s - 1.0) < 1e-12));
    }
  }
}

TEST_CASE("solver: u + sin(u) = c has no closed form: a numeric root, flagged", "[solve][numeric-root]") {
  realsymbol u("u");
  possymbol c("c");
  Problem p;
  p.equations = {eq(u + sin(u), c)};
  p.unknowns = {u};
  p.env = {{c, 1}};
  auto bs = solve(p);
  REQUIRE(bs.size() == 1);  // u + sin u is increasing: one root
  CHECK(bs[0].numeric_only.count(u) == 1);
  // independent Newton iteration in double precision
  double x = 0.5;
  for (int i = 0; i < 50; ++i) x -= (x + std::sin(x) - 1) / (1 + std::cos(x));
  double got = kt::to_double(bs[0].sol.at(u));
  CHECK(got == Approx(x).epsilon(1e-14));
  CHECK(std::abs(got + std::sin(got) - 1) < 1e-14);
  // the root carries more digits than a double: the residual vanishes to ~30 digits
  auto r = kinergy::numerics::evaluate(bs[0].sol.at(u) + sin(bs[0].sol.at(u)) - 1, {}, 40);
  REQUIRE(r);
  CHECK(GiNaC::abs(*r) < kt::tol(28));
}

TEST_CASE("solver: a transcendental equation with several roots gives them all", "[solve][numeric-root]") {
  // (u − 1/3)² − 4 sin(u − 1/3) = 0 has the roots 1/3 and 1/3 + 1.9337537628270212…
  // Regression: the second root (residual 6.4e-58 after refinement) used to be dropped
  // because a residual folded to one float was judged against itself (fixed in 6a03d24).
  realsymbol u("u");
  ex v3 = u - numeric(1, 3);
  Problem p;
  p.equations = {eq(pow(v3, 2) - 4 * sin(v3), 0)};
  p.unknowns = {u};
  auto bs = solve(p);
  auto v = values_of(bs, u);
  REQUIRE(v.size() == 2);
  CHECK(v[0] == Approx(1.0 / 3).epsilon(1e-14));
  double x = 2;
  for (int i = 0; i < 50; ++i) x -= (x * x - 4 * std::sin(x)) / (2 * x - 4 * std::cos(x));
  CHECK(v[1] == Approx(x + 1.0 / 3).epsilon(1e-13));
  for (auto& b : bs) CHECK(b.numeric_only.count(u) == 1);
}

TEST_CASE("solver: u + sin(u) = c for a range of c (numeric roots are kept and the search ends)",
          "[solve][numeric-root]") {
  // Regression for two solver faults fixed in 6a03d24 (src/solve/solver.cpp, numeric_roots):
  // roots whose residual was not exactly 0.0 were thrown away (numerically_zero judged a
  // residual folded to one float against itself: 17 of 30 values c = k/10 failed), and for
  // c = 1/5 GiNaC::fsolve, called with double-precision bounds at Digits = 40, never returned.
  // Each solve runs in a child process killed after 10 s, so this test cannot hang.
  for (int k : {1, 2, 4, 5, 10, 15, 20, 29}) {
    ex c = numeric(k, 10);
    auto res = kt::in_child(
        [&](std::string& msg) {
          realsymbol u("u");
          Problem p;
          p.equations = {eq(u + sin(u), c)};
          p.unknowns = {u};
          auto bs = solve(p);
          if (bs.size() != 1) {
            msg = std::to_string(bs.size()) + " branches";
            return false;
          }
          ex root = bs[0].sol.at(u);
          auto r = kinergy::numerics::evaluate(root + sin(root) - c, {}, 40);
          msg = "u = " + kt::str(root);
          return r && GiNaC::abs(*r) < kt::tol(25) && bs[0].numeric_only.count(u) == 1;
        },
        10);
    INFO("c = " << c << ": " << res.message);
    CHECK(res.status == kt::ChildResult::Status::Ok);
  }
}

TEST_CASE("solver: a numeric root that falls on a point of the scan grid is found", "[solve][numeric-root]") {
  // Regression (fixed in 6a03d24): the residual is sampled on a grid ref − span + 2 span i/2000;
  // a root where it is exactly 0 (u = 1/2 here, and any root equal to the reference) showed no
  // strict sign change on either side and was lost ("no root was found near 0").
  realsymbol u("u");
  Problem p;
  p.equations = {eq(u + sin(u), numeric(1, 2) + sin(ex(numeric(1, 2))))};
  p.unknowns = {u};
  std::vector<Branch> bs;
  REQUIRE_NOTHROW(bs = solve(p));
  REQUIRE(bs.size() == 1);
  CHECK(kt::to_double(bs[0].sol.at(u)) == Approx(0.5).epsilon(1e-14));

  // x² − 4 sin x = 0: the root x = 0 is the reference itself
  Problem q;
  q.equations = {eq(pow(u, 2) - 4 * sin(u), 0)};
  q.unknowns = {u};
  auto cs = solve(q);
  auto v = values_of(cs, u);
  CHECK(v.size() == 2);
}

TEST_CASE("solver: inconsistent and underdetermined systems", "[solve][errors]") {
  realsymbol x("x"), y("y");
  SECTION("x + y = 1 and x + y = 2 contradict") {
    Problem p;
    p.equations = {eq(x + y, 1, "first"), eq(x + y, 2, "second")};
    p.unknowns = {x, y};
    try {
      solve(p);
      FAIL("no error");
    } catch (const SolveError& e) {
      CHECK(std::string(e.what()).find("contradict") != std::string::npos);
    }
  }
  SECTION("a given value that breaks an equation") {
    Problem p;
    p.equations = {eq(x, 1), eq(2 * x, 3)};
    p.unknowns = {x};
    CHECK_THROWS_AS(solve(p), SolveError);
  }
  SECTION("every branch of a quadratic contradicted by another equation") {
    Problem p;
    p.equations = {eq(pow(x, 2), 4), eq(pow(x, 3), 5)};
    p.unknowns = {x};
    CHECK_THROWS_AS(solve(p), SolveError);
  }
  SECTION("a quadratic branch removed by a second equation") {
    Problem p;
    p.equations = {eq(pow(x, 2), 4), eq(pow(x, 3), 8)};
    p.unknowns = {x};
    auto bs = solve(p);
    REQUIRE(bs.size() == 1);
    CHECK(bs[0].sol.at(x) == 2);
  }
  SECTION("one equation nonlinear in two unknowns cannot be solved") {
    Problem p;
    p.equations = {eq(x * y + pow(x, 2) * pow(y, 2), 1)};
    p.unknowns = {x, y};
    CHECK_THROWS_AS(solve(p), SolveError);
  }
}

TEST_CASE("solver: an unknown that appears only multiplied by another is solved through the product", "[solve][product]") {
  // Two gears from rest, an unknown tooth force F over an unknown time t (I, w, M, r, R given):
  //   I1 w1 = M t - r F t,  I2 w2 = R F t   →  F t = I2 w2/R,  t = (I1 w1 + r I2 w2/R)/M
  realsymbol F("F"), t("t"), I1("I1"), I2("I2"), w1("w1"), w2("w2"), M("M"), r("r"), R("R");
  Problem p;
  p.equations = {eq(I1 * w1, M * t - r * F * t, "gear 1"), eq(I2 * w2, R * F * t, "gear 2")};
  p.unknowns = {t, F};
  p.env = {{I1, 2}, {I2, 3}, {w1, 5}, {w2, 7}, {M, 11}, {r, 13}, {R, 17}};
  auto bs = solve(p);
  REQUIRE(bs.size() == 1);
  ex tt = (I1 * w1 + r * I2 * w2 / R) / M;
  CHECK(kt::symbolically_zero(bs[0].sol.at(t) - tt));
  CHECK(kt::symbolically_zero(bs[0].sol.at(F) - I2 * w2 / (R * tt)));
  CHECK(bs[0].sol.size() == 2);  // the product's stand-in is not a result
}

TEST_CASE("solver: an unknown that also appears alone is not a product", "[solve][product]") {
  // F t + F^2 = 3, F t^2 = 2: F appears alone too (F^2), so F t is no stand-in: refused, as before
  realsymbol F("F"), t("t");
  Problem p;
  p.equations = {eq(F * t + F * F, 3), eq(F * t * t, 2)};
  p.unknowns = {F, t};
  REQUIRE_THROWS_WITH(solve(p), Catch::Contains("nonlinear in several unknowns"));
}

TEST_CASE("solver: a product that is zero, factor by factor, and a root where the rest is 0/0 is none", "[solve][trig]") {
  realsymbol u("u"), v("v");
  // sin u (3 cos u − 2) = 0: u = 0, π from the first factor, ±acos(2/3) from the second — closed forms
  Problem p;
  p.equations = {eq(sin(u) * (3 * cos(u) - 2), 0)};
  p.unknowns = {u};
  auto bs = solve(p);
  auto vals = values_of(bs, u);
  REQUIRE(vals.size() == 4);
  CHECK(vals[0] == Approx(-std::acos(2.0 / 3)).epsilon(1e-14));
  CHECK(vals[1] == Approx(0.0).margin(1e-15));
  CHECK(vals[2] == Approx(std::acos(2.0 / 3)).epsilon(1e-14));
  CHECK(vals[3] == Approx(M_PI).epsilon(1e-14));
  for (auto& b : bs) CHECK(b.numeric_only.empty());
  // sin u (3 cos u − 2)/tan u = 0: at u = 0 and π the equation is 0/0 (its limit is ±1), no root
  Problem q;
  q.equations = {eq(sin(u) * (3 * cos(u) - 2) / tan(u), 0)};
  q.unknowns = {u};
  vals = values_of(solve(q), u);
  REQUIRE(vals.size() == 2);
  CHECK(vals[0] == Approx(-std::acos(2.0 / 3)).epsilon(1e-14));
  CHECK(vals[1] == Approx(std::acos(2.0 / 3)).epsilon(1e-14));
  // two unknowns, one only squared (v² = 2(1 − cos u)) and one equation v² = cos u: cos u = 2/3,
  // v = ±√(2/3)
  Problem r;
  r.equations = {eq(pow(v, 2), 2 * (1 - cos(u))), eq(pow(v, 2), cos(u))};
  r.unknowns = {u, v};
  auto rs = solve(r);
  REQUIRE(!rs.empty());
  for (auto& b : rs) {
    CHECK(std::cos(kt::to_double(b.sol.at(u))) == Approx(2.0 / 3).epsilon(1e-14));
    CHECK(std::fabs(kt::to_double(b.sol.at(v))) == Approx(std::sqrt(2.0 / 3)).epsilon(1e-14));
  }
  // …but one equation in two unknowns is underdetermined: refused as before, not a branch per sign
  Problem w;
  w.equations = {eq(pow(v, 2), 2 * (1 - cos(u)))};
  w.unknowns = {u, v};
  REQUIRE_THROWS_WITH(solve(w), Catch::Contains("nonlinear in several unknowns"));
}
