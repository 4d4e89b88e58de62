// The three evaluation paths of a closed form (compiled double with a running error bound, CLN at
// a given precision, N guaranteed digits) and the stable rewrites, against 120-digit values.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cln/cln.h>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/evaluator.hpp"
#include "kinergy/numeric/native.hpp"
#include "kinergy/numeric/stable.hpp"
#include "kinergy/numeric/tape.hpp"

using namespace GiNaC;
using kinergy::numerics::Evaluator;

namespace {

numeric reference(const ex& e, const exmap& values) { return *kinergy::numerics::evaluate(e, values, 120); }

double rel_error(double got, const numeric& want) {
  numeric g = kinergy::numerics::exact(got);
  if (want.is_zero()) return std::fabs(got);
  return std::fabs(((g - want) / want).to_double());
}

numeric dec(const char* s) { return numeric(s); }  // "1/1000000" style exact numbers

}  // namespace

TEST_CASE("stable forms are identities", "[numeric][stable]") {
  realsymbol x("x"), y("y"), A("A"), a("a"), b("b"), e("e");
  const std::vector<ex> forms = {
      A - A * cos(x),          3 * A + 3 * A * cos(x),   1 - sin(x),          A * cos(y) - A * cos(x),
      sin(y) - sin(x),         sqrt(a) - sqrt(b),        2 - sqrt(b),         pow(a, 2) - pow(b, 2),
      1 - pow(e, 2),           A * (1 - cos(x)) / a,     sqrt(6 * A * (1 - cos(x))),
      sin(x) - cos(x),         A * cos(x) - A * sin(x),  sin(x) + cos(x),     sqrt(ex(2)) + sin(-Pi / 4 - x) - cos(-Pi / 4 - x),
  };
  exmap at = {{x, dec("7/10")}, {y, dec("13/10")}, {A, dec("3/2")}, {a, dec("5/2")}, {b, dec("7/5")}, {e, dec("9/10")}};
  for (const ex& f : forms) {
    ex s = kinergy::numerics::stable_form(f);
    INFO(f << "  ->  " << s);
    CHECK(!s.is_equal(f));  // every one of them is rewritten
    numeric d = reference(s - f, at);
    CHECK(abs(d) < numeric(1, 1000000) * pow(numeric(10), -100));
  }
  // √2 + sin(−π/4 − x) − cos(−π/4 − x) = √2 (1 − cos x) = 2√2 sin²(x/2): no sum is left
  CHECK(!kinergy::numerics::stable_form(sqrt(ex(2)) + sin(-Pi / 4 - x) - cos(-Pi / 4 - x)).has(cos(x)));
  // forms without a cancelling pattern are left alone
  CHECK(kinergy::numerics::stable_form(sqrt(3 * A * sin(x) / a)).is_equal(sqrt(3 * A * sin(x) / a)));
}

TEST_CASE("fast: 1 - cos of a tiny angle keeps its digits, the naive form does not", "[numeric][evaluator]") {
  realsymbol th("theta"), g("g"), L("L");
  ex w = sqrt(3 * g * (1 - cos(th)) / L);
  exmap v = {{th, dec("1/1000000")}, {g, dec("981/100")}, {L, dec("6/5")}};
  Evaluator ev(w, v);
  numeric want = reference(w, v);
  auto f = ev.fast();
  REQUIRE(f);
  INFO("fast form " << ev.fast_form());
  CHECK(rel_error(f->value, want) <= 1e-15);
  CHECK(f->bound >= std::fabs(f->value - want.to_double()));  // the bound holds
  CHECK(f->bound <= 1e-14 * std::fabs(f->value));             // and is tight
  auto n = ev.naive();
  REQUIRE(n);
  // 1 − cos(1e-6) = 5e-13 computed from a cosine rounded to 1.1e-16: a relative error ~1e-4
  CHECK(rel_error(n->value, want) > 1e-6);
  CHECK(n->bound >= std::fabs(n->value - want.to_double()));  // the naive bound admits it
}

TEST_CASE("fast: exact parts make a zero exactly zero", "[numeric][evaluator]") {
  realsymbol J("J"), L("L"), d("d");
  // pivot impulse of a bar struck at d below the pin: J (1 − 3d/(2L)); d = 2L/3 exactly
  ex R = J * (2 * L - 3 * d) / (2 * L);
  Evaluator ev(R, {{J, 12}, {L, dec("3/2")}, {d, 1}});
  auto f = ev.fast();
  REQUIRE(f);
  CHECK(f->value == 0);
  CHECK(f->bound == 0);
  auto p = ev.digits(30);
  REQUIRE(p);
  CHECK(p->exact);
  CHECK(p->value.is_zero());
}

TEST_CASE("fast: 1 - e^2 with 1 - e = 1e-12", "[numeric][evaluator]") {
  realsymbol e("e"), m("m"), v("v");
  ex loss = m * pow(v, 2) * (1 - pow(e, 2)) / 2;
  exmap at = {{e, dec("999999999999/1000000000000")}, {m, 2}, {v, dec("3/2")}};
  Evaluator ev(loss, at);
  auto f = ev.fast();
  REQUIRE(f);
  CHECK(rel_error(f->value, reference(loss, at)) <= 1e-15);
  // e rounded to a double is already 1e-4 off in 1 − e: the naive path cannot do better
  CHECK(rel_error(ev.naive()->value, reference(loss, at)) > 1e-6);
}

TEST_CASE("fast: sqrt(a) - sqrt(b) for nearly equal a and b", "[numeric][evaluator]") {
  realsymbol v("v"), g("g"), h("h");
  // speed gained: √(v² + 2gh) − v with 2gh ≪ v²
  ex dv = sqrt(pow(v, 2) + 2 * g * h) - sqrt(pow(v, 2));
  exmap at = {{v, 300}, {g, dec("981/100")}, {h, dec("1/100000000")}};
  Evaluator ev(dv, at);
  auto f = ev.fast();
  REQUIRE(f);
  INFO("fast form " << ev.fast_form());
  CHECK(rel_error(f->value, reference(dv, at)) <= 1e-14);
  CHECK(f->bound >= std::fabs(f->value - reference(dv, at).to_double()));
}

TEST_CASE("fast: differences of nearly equal angles", "[numeric][evaluator]") {
  realsymbol a("a"), b("b"), g("g");
  ex w = sqrt(g * (cos(b) - cos(a)));  // released at a, asked at b = a − 1e-6
  exmap at = {{a, Pi / 6}, {b, Pi / 6 - dec("1/1000000")}, {g, dec("981/100")}};
  Evaluator ev(w, at);
  auto f = ev.fast();
  REQUIRE(f);
  INFO("fast form " << ev.fast_form());
  CHECK(rel_error(f->value, reference(w, at)) <= 1e-14);
}

TEST_CASE("CLN at a given precision agrees with a 120-digit value to that precision", "[numeric][evaluator]") {
  realsymbol th("theta"), g("g"), l("l");
  ex w = sqrt(3 * g * sin(th) / l);
  exmap at = {{th, Pi / 6}, {g, dec("981/100")}, {l, dec("6/5")}};
  Evaluator ev(w, at);
  numeric want = reference(w, at);
  for (long p : {15L, 30L, 50L, 100L}) {
    auto v = ev.at(p);
    REQUIRE(v);
    CHECK(abs((*v - want) / want) < pow(numeric(10), -(p - 2)));
  }
}

TEST_CASE("digits: N right digits, and the working precision that gave them", "[numeric][evaluator]") {
  realsymbol th("theta"), g("g"), l("l");
  ex w = sqrt(3 * g * sin(th) / l);
  exmap at = {{th, Pi / 6}, {g, dec("981/100")}, {l, dec("6/5")}};
  Evaluator ev(w, at);
  auto d = ev.digits(50);
  REQUIRE(d);
  CHECK(!d->exact);
  CHECK(d->working > 50);
  CHECK(kinergy::numerics::format(kinergy::numerics::round_sig(d->value, 50), 50) ==
        "3.5017852589786256052372546604589676703245542931001");
  // exact rational values come out exact
  realsymbol m("m"), v("v");
  auto T = Evaluator(m * pow(v, 2) / 2, {{m, 5}, {v, dec("3/2")}}).digits(40);
  REQUIRE(T);
  CHECK(T->exact);
  CHECK(T->value == numeric(45, 8));
  // a value that is zero but not exactly computable (sin of an angle equal to π) is reported as zero
  auto z = Evaluator(sin(th) * g, {{th, Pi}, {g, dec("981/100")}}).digits(20);
  REQUIRE(z);
  CHECK(z->value.is_zero());
}

TEST_CASE("undefined values give nothing, not a number", "[numeric][evaluator]") {
  realsymbol x("x"), y("y");
  Evaluator ev(sqrt(x - y), {{x, 1}, {y, 2}});
  CHECK(!ev.digits(20));
  CHECK(!ev.at(30));
  Evaluator dz(1 / (x - y), {{x, 1}, {y, 1}});
  CHECK(!dz.digits(20));
}

TEST_CASE("tape: a batch gives the same doubles as one point at a time", "[numeric][tape]") {
  realsymbol th("theta"), g("g"), l("l");
  auto t = kinergy::numerics::Tape::compile(sqrt(3 * g * sin(th) / l) + pow(cos(th), 3) / l, {th, g, l});
  std::vector<double> X;
  for (int k = 0; k < 37; ++k) {
    X.push_back(0.01 * k);
    X.push_back(9.81);
    X.push_back(1 + 0.1 * k);
  }
  std::vector<double> out(37);
  t.batch(X.data(), 37, out.data());
  for (std::size_t k = 0; k < 37; ++k) CHECK(out[k] == t(&X[3 * k]));
}

TEST_CASE("native code: the tape compiled to machine code gives the tape's doubles", "[numeric][native]") {
  // one shared cache folder for the test run (the user's own cache is not touched)
  const auto cache = std::filesystem::temp_directory_path() / ("kinergy-test-cache-" + std::to_string(getpid()));
  setenv("KINERGY_CACHE", cache.c_str(), 1);
  realsymbol th("theta"), g("g"), l("l"), e("e");
  const std::vector<ex> forms = {sqrt(3 * g * sin(th) / l), pow(cos(th), 3) / l - pow(g, -2) + atan2(th, l),
                                 l * pow(1 - e, 5) * exp(-th) + log(g) * tan(th) + acos(th / 2)};
  std::vector<double> x = {0.5235987755982988, 9.81, 1.2, 0.7};
  for (const ex& f : forms) {
    INFO(f);
    auto t = kinergy::numerics::Tape::compile(f, {th, g, l, e});
    auto n = kinergy::numerics::NativeFunction::build(t);
    CHECK(n(x.data()) == t(x.data()));  // bit for bit: the same operations in the same order
    // the second build of the same tape comes from the cache
    auto again = kinergy::numerics::NativeFunction::build(t);
    CHECK(again(x.data()) == n(x.data()));
  }
  std::filesystem::remove_all(cache);
  // a cache that cannot be written: a clear error, and the tape still evaluates
  setenv("KINERGY_CACHE", "/proc/kinergy-cannot-write-here", 1);
  auto t = kinergy::numerics::Tape::compile(sqrt(g), {g});
  CHECK_THROWS_WITH(kinergy::numerics::NativeFunction::build(t), Catch::Contains("KINERGY_CACHE"));
  CHECK(t(x.data() + 1) == std::sqrt(9.81));
  unsetenv("KINERGY_CACHE");
}

// A residual at the noise floor (issue 43, finding 2): c·(sin(acos z) − √(1 − z²)) is zero, and a
// product shows no terms whose size would tell; at 30 digits it evaluates to ~1e-31 · c. It is
// zero because it shrinks with the working precision; a small value that is there stays.
TEST_CASE("negligible: rounding noise shrinks with the digits, a small value does not", "[numeric]") {
  symbol z("z"), c("c");
  const exmap at{{z, numeric(2, 3) + numeric(1, 7)}, {c, numeric(12)}};
  const ex noise = c * (sin(acos(z)) - sqrt(1 - pow(z, 2)));
  auto v = kinergy::numerics::evaluate(noise, at, 30);
  REQUIRE(v);
  CHECK(kinergy::numerics::negligible(noise, at, 30) == std::optional<bool>(true));
  // the same product with a real 1e-40 in it is not zero, however small
  const ex small = c * (sin(acos(z)) - sqrt(1 - pow(z, 2)) + numeric(1, 10) * pow(numeric(10), -39));
  CHECK(kinergy::numerics::negligible(small, at, 30) == std::optional<bool>(false));
  const ex couple = c * numeric(1, 1000000000000);  // 1e-12 N·m is a couple
  CHECK(kinergy::numerics::negligible(couple, at, 30) == std::optional<bool>(false));
}
