// `--digits N` prints proven digits: ball arithmetic (Arb) from the exact inputs. Checked against
// references computed without kinergy: the 100-digit claims of tests/stability (mpmath, hand
// formulas: tests/stability/references.py), GiNaC's own evaluation of every derivation's closed
// form at 120 digits (another code path), and mpmath for a numeric root
// (tests/data/numeric/wound_spring_reference.py). The double path's reported error bound is
// checked against its true error, known from the balls.
#include <catch2/catch.hpp>

#include "../support/helpers.hpp"
#include "kinergy/numeric/ball.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/evaluator.hpp"
#include "kinergy/numeric/roots.hpp"
#include "kinergy/problem.hpp"

namespace fs = std::filesystem;
using namespace GiNaC;
namespace kn = kinergy::numerics;

namespace {

/// x lies within the value's ball, widened by `slack` (a reference's own rounding).
bool inside(const kinergy::Value& v, const numeric& x, const numeric& slack) {
  return v.lo - slack <= x && x <= v.hi + slack;
}

/// Half a unit in the n-th significant digit of x: what rounding x to n digits may move it.
numeric half_ulp(const numeric& x, int n) {
  if (x.is_zero()) return 0;
  const long e = static_cast<long>(std::floor(std::log10(std::fabs(x.to_double()))));
  return pow(numeric(10), numeric(e - n + 1)) / 2;
}

}  // namespace

TEST_CASE("proven: every 100-digit reference of tests/stability, and the double's bound holds its true error",
          "[numeric][proven][stability]") {
  int compared = 0, doubles = 0;
  for (auto& f : kt::scene_files("tests/stability")) {
    kinergy::Solution s = kinergy::solve_file(f);
    auto env = s.model.numeric_environment();
    for (auto& x : s.model.expects) {
      if (!x.value) continue;
      kinergy::Result r = kt::result(s, x.name);
      r.unit_factor = x.value->unit.factor;  // in the claim's unit
      INFO(fs::path(f).filename().string() << ": " << x.name << " = " << r.closed);
      auto v = r.evaluate(env, 100, false);
      REQUIRE(v);
      CHECK(v->proven);
      const numeric& ref = x.value->number;
      if (ref.is_zero()) {
        CHECK(v->how == kinergy::Value::How::Exact);
        CHECK(v->v.is_zero());
      } else {
        // the 100 digits printed are the reference's, and the reference (rounded to 100 digits
        // itself) lies in the ball
        CHECK(kn::format(v->v, 100) == kn::format(ref, 100));
        CHECK(inside(*v, ref, half_ulp(ref, 100)));
      }
      // the double: |double − exact| ≤ its bound, the exact value known to within the ball's radius
      kn::Evaluator ev(r.closed / r.unit_factor, env);
      if (auto d = ev.fast()) {
        const numeric dv = kn::exact(d->value);
        const numeric err = std::max(abs(dv - v->lo), abs(dv - v->hi));  // ≥ the true error
        INFO("double " << d->value << " +- " << d->bound << "; error at most " << err.to_double());
        CHECK((err.to_double() <= d->bound * (1 + 1e-12) || abs(dv - (v->lo + v->hi) / 2) <= numeric(d->bound) + (v->hi - v->lo) / 2));
        ++doubles;
      }
      ++compared;
    }
  }
  CHECK(compared >= 40);
  CHECK(doubles >= 40);
}

TEST_CASE("proven: every derivation at 40 digits, inside GiNaC's 120-digit value, and the double's bound holds its true error",
          "[numeric][proven][derivations]") {
  int proven = 0, doubles = 0, unproven = 0;
  for (const auto& f : kt::scene_files("derivations")) {
    kinergy::Solution s = kinergy::solve_file(f);
    auto env = s.model.numeric_environment();
    for (auto& r : s.results) {
      if (!r.si) continue;
      INFO(fs::path(f).filename().string() << ": " << r.name << " = " << r.closed);
      const int n = r.closed_form ? 40 : kinergy::kRootDigits;
      auto v = r.evaluate(env, n, false);
      REQUIRE(v);
      if (!v->proven) {
        // only a value with a number found numerically in it (a work integral by quadrature)
        CHECK(!r.closed_form);
        CHECK_THAT(v->note(), Catch::StartsWith("not proven"));
        ++unproven;
        continue;
      }
      ++proven;
      if (!r.closed_form) continue;  // a numeric root: its reference is its own test below
      auto ref = kn::evaluate(r.closed / r.unit_factor, env, 120);
      REQUIRE(ref);
      CHECK(kn::format(v->v, n) == kn::format(*ref, n));
      CHECK(inside(*v, *ref, abs(*ref) * kn::tenth(110) + kn::tenth(300)));
      kn::Evaluator ev(r.closed / r.unit_factor, env);
      if (auto d = ev.fast()) {
        const numeric dv = kn::exact(d->value);
        const numeric err = abs(dv - *ref);
        INFO("double " << d->value << " +- " << d->bound << "; true error " << err.to_double());
        CHECK(err <= numeric(d->bound) + abs(*ref) * kn::tenth(100));
        ++doubles;
      }
    }
  }
  CHECK(proven >= 100);
  CHECK(doubles >= 100);
  CHECK(unproven <= 2);  // the two cam couples: a work integral by quadrature
}

TEST_CASE("proven: a numeric root to 100 digits, against mpmath", "[numeric][proven][roots][cli]") {
  // tests/data/numeric/wound_spring_reference.py (mpmath findroot at 130 digits)
  const std::string ref =
      "11.92637250575801691601068288980028746113727739067796439947445583912450084496527079522433628389232332";
  int status = 0;
  std::string out = kt::run_cli("solve tests/data/wound_spring.yaml --digits 100", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= " + ref + " rad   (no closed form: taken numerically; proven: ball radius "));
  out = kt::run_cli("solve tests/data/wound_spring.yaml --digits 300 --json", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("\"value\": \"" + ref.substr(0, 60)));
  CHECK_THAT(out, Catch::Contains("\"proven\": true"));
  // a root in degrees: the unit's factor π/180 goes into the equation, not into a rounded number
  auto s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/tests/data/wound_spring.yaml");
  kinergy::Result r = s.results.at(0);
  r.unit_factor = Pi / 180;
  auto v = r.evaluate(s.model.numeric_environment(), 50, false);
  REQUIRE(v);
  CHECK(v->proven);
  // 11.926372505758016916… rad × 180/π (mpmath, the same script)
  CHECK(kn::format(v->v, 50) == "683.33080948079844959356773303339006929961599118197");
}

TEST_CASE("proven: a zero exact arithmetic does not see says its sign is not fixed, and a tiny value beside it is proven",
          "[numeric][proven][cli]") {
  int status = 0;
  std::string out = kt::run_cli("solve tests/data/numeric/unsigned_zero.yaml --digits 20", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= 0 m   (sign not fixed: |value| <= "));
  CHECK_THAT(out, Catch::Contains("= 1e-80 m   (proven: ball radius "));
  out = kt::run_cli("solve tests/data/numeric/unsigned_zero.yaml --digits 20 --json", status);
  CHECK_THAT(out, Catch::Contains("\"evaluation\": \"sign not fixed: |value| <= "));
}

TEST_CASE("proven: a work integral on balls (Arb's integration), both ends known and an end found as a root, against mpmath",
          "[numeric][proven][integrate][cli]") {
  // tests/data/numeric/cam_couple_reference.py (the error function and its inverse, mpmath at 130 digits)
  const std::string omega2 =
      "6.709051266990077198931405617897785301369551713751955930937200383654461045560510640815708011204599476";
  const std::string phi2 =
      "0.7144304417732017885921246356422574111507979678465891313871478517160731816232707870618938450965197532";
  int status = 0;
  std::string out = kt::run_cli("solve derivations/energy/wheel_cam_couple_numeric.yaml --digits 100", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= " + omega2 + " rad/s   (proven: ball radius "));
  out = kt::run_cli("solve derivations/energy/wheel_cam_couple_angle.yaml --digits 100", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= " + phi2 + " rad   (no closed form: taken numerically; proven: ball radius "));
  out = kt::run_cli("solve derivations/energy/wheel_cam_couple_numeric.yaml --digits 20 --json", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("\"proven\": true"));
  CHECK_THAT(out, Catch::Contains("\"midpoint\": \"" + omega2.substr(0, 21)));
  // the default (no --digits) takes the integral by tanh-sinh quadrature in CLN: not a proof, the same digits
  out = kt::run_cli("solve derivations/energy/wheel_cam_couple_numeric.yaml", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= " + kn::format(numeric(omega2.c_str()), 15) + " rad/s"));
}

TEST_CASE("proven: values that hold numbers found numerically — solved from a numeric root, an extreme at a numeric stationary point",
          "[numeric][proven][roots][cli]") {
  // tests/data/numeric/roots_reference.py (mpmath at 80 digits)
  int status = 0;
  std::string out = kt::run_cli("solve tests/data/numeric/rod_power_spring.yaml --digits 60", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= 33.5318066590265941049948173215214111221693048198773393115431 deg   (no closed form: taken numerically; proven: "));
  CHECK_THAT(out, Catch::Contains("= 51.7450284033851464407020667140752353478537453449013265684211 W   (no closed form: taken numerically; proven: "));
  // h2 = (L/2) sin(theta2), from the root theta2
  auto text = kt::read_file(std::string(KINERGY_SOURCE_DIR) + "/tests/data/wound_spring.yaml") + "  h2: {value: L/2*sin(theta@2), unit: m}\n";
  auto s = kinergy::solve_scene(kinergy::scene::load_string(text, "wound.yaml"));
  auto h = s.results.at(1).evaluate(s.model.numeric_environment(), 60, false);
  REQUIRE(h);
  CHECK(h->proven);
  CHECK(kn::format(h->v, 60) == "-0.298596962139167321553855347774685689832307129805543319664395");
  // w3 solved (energy 2 -> 3) from the root theta2: -w1 = -46 rad/s by the energy from 1 to 3,
  // which the ball holds (not exact: the root's number is only enclosed)
  auto b = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/tests/data/numeric/wound_spring_back.yaml");
  auto w3 = b.results.at(1).evaluate(b.model.numeric_environment(), 50, false);
  REQUIRE(w3);
  CHECK(w3->proven);
  CHECK(w3->how == kinergy::Value::How::Precise);
  CHECK(w3->lo <= -46);
  CHECK(-46 <= w3->hi);
  CHECK(w3->hi - w3->lo < pow(numeric(10), -48));
  // two roots chained: theta3 solves an equation that holds theta2 (energy 2 -> 3), found again
  // in theta2's symbol and proven from theta2's enclosure
  out = kt::run_cli("solve tests/data/numeric/wound_spring_chained.yaml --digits 60", status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= 10.7851151437233129700227140465640679186130620610097942492588 rad   (no closed form: taken numerically; proven: "));
}

TEST_CASE("ball arithmetic: integrals against mpmath, and undefined or ill-posed ones", "[numeric][proven][integrate]") {
  symbol x("x"), xi("xi"), a("a");
  auto proven = [&](const ex& e, const numeric& av, int n) {
    kn::BallEvaluator b(kn::Tape::compile(e, {a}, kn::Tape::Accept::Integrals), {av});
    return b.digits(n, 20000);
  };
  auto I = [&](const ex& f, const ex& lo, const ex& hi) { return kn::integral_of(f.subs(x == xi), xi, lo, hi); };
  // tests/data/numeric/cam_couple_reference.py, 60 digits each
  auto p = proven(I(exp(-pow(x, 2)), 0, a), 1, 60);
  REQUIRE(p);
  CHECK(kn::format(p->value, 60) == "0.746824132812427025399467436131853005354499686812606329027654");
  // backwards: the negative
  p = proven(I(exp(-pow(x, 2)), a, 0), 1, 60);
  REQUIRE(p);
  CHECK(kn::format(p->value, 60) == "-0.746824132812427025399467436131853005354499686812606329027654");
  // √x at the end 0: a branch point where the path begins (Arb subdivides towards it)
  p = proven(I(sqrt(x) * atan(x), 0, a), 2, 60);
  REQUIRE(p);
  CHECK(kn::format(p->value, 60) == "1.54043578241733831790671836361164442957549035806207395335286");
  p = proven(I(asin(x / 2) / (1 + x), a, 3 * a), numeric(1, 2), 60);
  REQUIRE(p);
  CHECK(kn::format(p->value, 60) == "0.25917824262648267532135704956239017464477346076993992355939");
  // the input inside the integrand too: x^(1/3) ln x on [1, 3a] with a = 1
  p = proven(I(log(x) * pow(x, numeric(1, 3)) * a, 1, 3 * a), 1, 60);
  REQUIRE(p);
  CHECK(kn::format(p->value, 60) == "1.69376832795479268340019867820928025101552197511098844186564");
  // an empty path is an exact 0
  p = proven(I(exp(x), a, a), 1, 20);
  REQUIRE(p);
  CHECK(p->kind == kn::Proven::Kind::Exact);
  // √x on [−1, 1]: undefined on part of the path (no value, not an imaginary one)
  CHECK(!proven(I(sqrt(x), -a, a), 1, 20));
  // 1/x across 0: no precision decides it (a pole on the path), and it says so rather than hang
  CHECK_THROWS_WITH(proven(I(1 / x, -a, 2 * a), 1, 20), Catch::Contains("no working precision") && Catch::Contains("singular on its path"));
  // an integral compiles only for balls; its double and CLN evaluations refuse
  CHECK_THROWS_WITH(kn::Tape::compile(I(exp(x), 0, a), {a}), Catch::Contains("runs only on balls"));
  kn::Tape t = kn::Tape::compile(I(exp(x), 0, a), {a}, kn::Tape::Accept::Integrals);
  CHECK(t.has_integrals());
  CHECK_THROWS_AS(t(std::vector<double>{1.0}), std::logic_error);
  // an integral inside an integrand is not taken
  CHECK_THROWS(kn::Tape::compile(I(I(exp(x), 0, xi), 0, a), {a}, kn::Tape::Accept::Integrals));
  // an end known only to a ball (π/2) where the integrand's domain ends (√cos ξ): Arb integrates
  // to the ball's midpoint, which may lie past π/2; that is not decided, never "proven undefined"
  // (∫₀^{π/2} √cos ξ dξ = 1.19814023473559220743992249228 by mpmath, which a proof would give)
  kn::BallEvaluator edge(kn::Tape::compile(I(sqrt(cos(x)), 0, a), {a}, kn::Tape::Accept::Integrals), {Pi / 2});
  try {
    auto e = edge.digits(20, 4000);
    REQUIRE(e);
    CHECK(kn::format(e->value, 20) == "1.1981402347355922074");
  } catch (const std::domain_error& err) {
    CHECK_THAT(err.what(), Catch::Contains("no working precision"));
  }
}

TEST_CASE("ball arithmetic: a root is not proven at a jump of the residual", "[numeric][proven][roots]") {
  symbol u("u");
  // atan2(u, −1) jumps from π to −π at u = 0: opposite signs around 0, and no root there
  CHECK(!kn::root_digits(atan2(u, -1), u, 0, numeric(-1, 2), numeric(1, 2), {}, 20, 4000));
  CHECK(!kn::root_digits(atan2(u, -1), u, numeric(1, 1000), 0, 0, {}, 20, 4000));
  // a true root beside it is proven: atan2(u, 1) = u near 0, root 0 exactly
  auto z = kn::root_digits(atan2(u, 1) - numeric(1, 10), u, numeric(1, 10), 0, 1, {}, 20, 4000);
  REQUIRE(z);
  // tan(1/10) = 0.10033467208545054505808004578 (its series)
  CHECK(kn::format(z->value, 20) == "0.10033467208545054506");
}

TEST_CASE("ball arithmetic: undefined, indeterminate and exact cases of the tape", "[numeric][proven]") {
  symbol x("x");
  auto proven = [&](const ex& e, const numeric& xv, int n) {
    kn::BallEvaluator b(kn::Tape::compile(e, {x}), {xv});
    return b.digits(n, 4000);
  };
  // √ of a negative number and a division by an exact zero are undefined: nothing
  CHECK(!proven(sqrt(x - 2), 1, 10));
  CHECK(!proven(1 / (x - 1), 1, 10));
  CHECK(!proven(log(x - 1), 1, 10));
  // a divisor that is zero but not exactly (1 - cos²x - sin²x): it cannot be decided
  CHECK_THROWS_WITH(proven(1 / (1 - pow(cos(x), 2) - pow(sin(x), 2)), 1, 10), Catch::Contains("cannot be decided"));
  // a square root of an exact zero is 0
  auto z = proven(sqrt(x - 1), 1, 10);
  REQUIRE(z);
  CHECK(z->kind == kn::Proven::Kind::Exact);
  // π to 60 digits (its digits known: 3.14159265358979323846264338327950288419716939937510582097494)
  auto p = proven(4 * atan(x), 1, 60);
  REQUIRE(p);
  CHECK(kn::format(p->value, 60) == "3.14159265358979323846264338327950288419716939937510582097494");
  CHECK(p->at.lo < p->at.hi);
  // a radius printed rounds up
  CHECK(kn::round_up2(numeric(1234, 100000)) == numeric(13, 1000));
  CHECK(kn::round_up2(numeric(13, 1000)) == numeric(13, 1000));
}

TEST_CASE("proven: without the ball arithmetic module, --digits says where it looked and what to do",
          "[numeric][proven][cli]") {
  // the module is loaded only when proven digits are asked for: without it the default still works
  int status = 0;
  const std::string env = "KINERGY_ARB_MODULE=/nonexistent/kinergy_arb.so ";
  std::string out = kt::run_command("cd " + kt::shell_quoted(KINERGY_SOURCE_DIR) + " && " + env + kt::shell_quoted(KINERGY_CLI) +
                                        " solve derivations/energy/rolling_disk_incline.yaml 2>&1",
                                    &status);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("= 3.66345061712305 m/s"));
  out = kt::run_command("cd " + kt::shell_quoted(KINERGY_SOURCE_DIR) + " && " + env + kt::shell_quoted(KINERGY_CLI) +
                            " solve derivations/energy/rolling_disk_incline.yaml --digits 30 2>&1",
                        &status);
  CHECK(status != 0);
  CHECK_THAT(out, Catch::Contains("the ball arithmetic module kinergy_arb.so was not found (looked for /nonexistent/kinergy_arb.so)") &&
                      Catch::Contains("set KINERGY_ARB_MODULE to its path"));
  CHECK_THAT(out, !Catch::Contains("terminate") && !Catch::Contains("internal error"));
}
