// Issue 43: every derivation with its parameters as symbols, as an author writes it (`m: 2 kg` →
// `m: kg`, results asked without `unit:`), solves; its closed forms equal the numeric scene's at
// the derivation's values; and where the numeric scene is confirmed by simulation, the symbolic
// one is too, at sampled values of its parameters. (tests/symbolic/symbolize.py makes the same
// scenes for the command line.)
#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>
#include <sstream>

#include "../support/helpers.hpp"
#include "kinergy/confirm/confirm.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace fs = std::filesystem;

namespace {

/// The derivation's text with every parameter given a number made a symbol with its unit
/// (`mu: 0.25` → `mu: number`), `unit:` left out of every result and the `expect` claims left out.
std::string symbolize(const std::string& text) {
  static const std::regex top(R"(^([A-Za-z_]\w*):.*)");
  static const std::regex param(R"(^(\s+)([A-Za-z_]\w*):\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?:\s+(\S.*?))?\s*$)");
  static const std::regex unit(R"(,\s*unit:\s*[^,}]+)");
  // theta2: {value: 210 deg, in: [180 deg, 270 deg]} → theta2: {value: deg, in: […]}
  static const std::regex ranged(R"(^(\s+)([A-Za-z_]\w*):\s*\{value:\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?:\s+([^,}]+?))?\s*(,.*)$)");
  std::istringstream in(text);
  std::string line, block, out;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, top)) block = m[1];
    if (block == "expect") continue;
    if (block == "parameters" && std::regex_match(line, m, ranged)) {
      out += m[1].str() + m[2].str() + ": {value: " + (m[3].matched ? m[3].str() : std::string("number")) + m[4].str() + "\n";
      continue;
    }
    if (block == "parameters" && line.rfind("parameters:", 0) == 0 && line.find('{') != std::string::npos) {  // flow style: parameters: {m: 40 kg, …}
      const auto a = line.find('{'), b = line.rfind('}');
      std::istringstream items(line.substr(a + 1, b - a - 1));
      std::string item, made;
      while (std::getline(items, item, ',')) {
        const std::string indented = "  " + item;
        std::smatch pm;
        if (std::regex_match(indented, pm, param)) item = " " + pm[2].str() + ": " + (pm[3].matched ? pm[3].str() : std::string("number"));
        made += (made.empty() ? "" : ",") + item;
      }
      line = line.substr(0, a + 1) + made + "}";
    }
    if (block == "parameters" && std::regex_match(line, m, param))
      line = m[1].str() + m[2].str() + ": " + (m[3].matched ? m[3].str() : std::string("number"));
    if (block == "find") line = std::regex_replace(line, unit, "");
    out += line + "\n";
  }
  return out;
}

// Not solved with symbols: each refused with an error, never a wrong number.
const std::map<std::string, std::string> kNotYet = {
    // phi2 = phi0 erf^-1(m k^2 w2^2/(sqrt(pi) M0 phi0)): a function outside GiNaC's; refused, with the
    // equation it solves (its implicit form), rather than a number at a hidden sample
    {"wheel_cam_couple_angle.yaml", "no closed form in kinergy's functions: refused (neither a form nor a number)"},
};

}  // namespace

TEST_CASE("symbolic derivations: each solves, equals the numeric scene at its values, confirmed at sampled values", "[derivations][symbolic]") {
  std::vector<std::string> files;
  for (auto& e : fs::recursive_directory_iterator(fs::path(KINERGY_SOURCE_DIR) / "derivations"))
    if (e.path().extension() == ".yaml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 80);
  int solved = 0;
  for (auto& f : files) {
    const std::string name = fs::path(f).filename().string();
    DYNAMIC_SECTION(name) {
      const std::string text = symbolize(kt::read_file(f));
      if (kNotYet.count(name)) {
        CHECK_THROWS_AS([&] { auto s = kt::solve_text(text); kinergy::confirm(s); }(), kinergy::SceneError);
        continue;
      }
      kinergy::Solution num = kinergy::solve_file(f);
      kinergy::confirm(num);
      kinergy::Solution sym = kt::solve_text(text);
      kinergy::confirm(sym);
      ++solved;
      // the closed forms at the derivation's values: the numeric scene's values (in SI)
      const GiNaC::exmap at = num.model.parameter_values();
      GiNaC::exmap by_name;  // the symbolic scene's symbols → the numeric scene's values
      for (auto& p : sym.model.params)
        if (const auto* q = num.model.parameter(p.name); q && q->value) by_name[p.sym] = *q->value;
      REQUIRE(sym.results.size() == num.results.size());
      for (std::size_t i = 0; i < num.results.size(); ++i) {
        INFO(num.results[i].name << " = " << sym.results[i].closed);
        REQUIRE(sym.results[i].closed_form);
        auto v = kinergy::numerics::evaluate(sym.results[i].closed.subs(by_name), at, 30);
        REQUIRE(v);
        REQUIRE(num.results[i].si);
        const double a = v->to_double(), b = num.results[i].si->to_double();
        CHECK(std::fabs(a - b) <= 1e-12 * std::max(1.0, std::fabs(b)));
      }
      // where the numeric scene is confirmed by simulation (or the equations of motion), the
      // symbolic one is, at sampled values
      REQUIRE(sym.confirmed.size() == num.confirmed.size());
      for (std::size_t j = 0; j < num.confirmed.size(); ++j) {
        INFO("analysis " << j << ": " << sym.confirmed[j].note);
        if (num.confirmed[j].by == kinergy::Confirmed::By::Residuals) continue;
        CHECK(sym.confirmed[j].by == num.confirmed[j].by);
        CHECK(sym.confirmed[j].samples.size() == static_cast<std::size_t>(kinergy::kSamples));
      }
    }
  }
}

TEST_CASE("symbolic scenes: what the confirmation says, the forms of an ambiguous root, a root without a form", "[symbolic]") {
  // the compound pendulum with every parameter a symbol: confirmed by simulation at three sampled
  // values, the same on every run (the samples drawn from a fixed sequence)
  const std::string pendulum = symbolize(kt::derivation("energy/compound_pendulum.yaml"));
  auto s = kt::solve_text(pendulum);
  kinergy::confirm(s);
  REQUIRE(s.confirmed.size() == 1);
  CHECK(s.confirmed[0].by == kinergy::Confirmed::By::Simulation);
  // (m cancels from the closed forms: sampled for the simulation, not named)
  CHECK(s.confirmed[0].sampled == "L, g, theta0");
  REQUIRE(s.confirmed[0].samples.size() == 3);
  auto again = kt::solve_text(pendulum);
  kinergy::confirm(again);
  CHECK(again.confirmed[0].samples == s.confirmed[0].samples);
  // the rod leaving its wall, with symbols: the first angle along the motion where N = 0, by hand
  // from energy and Newton's law along x, cos θ₂ = 2 cos θ₀/3 + 2 v_A0²/(9 g L cos² θ₀) — not π,
  // the horizontal rod that the sample its choices were first made at left as the only root
  s = kt::solve_text(symbolize(kt::derivation("kinetics/rod_leaves_wall.yaml")));
  const GiNaC::ex th0 = kt::param(s.model, "theta0"), v = kt::param(s.model, "vA0"), g = kt::param(s.model, "g"), L = kt::param(s.model, "L");
  const GiNaC::ex want = GiNaC::acos(2 * GiNaC::cos(th0) / 3 + 2 * v * v / (9 * g * L * GiNaC::pow(GiNaC::cos(th0), 2)));
  for (auto at : {GiNaC::exmap{{th0, GiNaC::numeric(1, 3)}, {v, GiNaC::numeric(1, 2)}, {g, GiNaC::numeric(981, 100)}, {L, 3}},
                  GiNaC::exmap{{th0, GiNaC::numeric(1, 2)}, {v, GiNaC::numeric(1, 5)}, {g, 2}, {L, GiNaC::numeric(3, 2)}}}) {
    auto x = kinergy::numerics::evaluate(kt::result(s, "theta2").closed, at, 30), y = kinergy::numerics::evaluate(want, at, 30);
    REQUIRE(x);
    REQUIRE(y);
    CHECK(x->to_double() == Approx(y->to_double()).epsilon(1e-14));
  }
  // the linkage's crank angle without its range: near 0 (where angles are sampled) the crank
  // would turn the other way from pi, and sin theta2 has the other sign — both forms shown, never
  // "? or ?" (with 'in: [180 deg, 270 deg]', as the derivation states it, it solves)
  const std::string linkage = symbolize(kt::derivation("energy/linkage_collar.yaml"));
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(linkage, "{value: deg, in: [180 deg, 270 deg]}", "deg")),
                      Catch::Contains("'omega2' has more than one solution (") && Catch::Contains(" or -") &&
                          !Catch::Contains("?"));
  // a root of an equation in parameters without values: neither a form nor a number, refused
  REQUIRE_THROWS_WITH(kt::solve_text(symbolize(kt::derivation("energy/wheel_cam_couple_angle.yaml"))),
                      Catch::Contains("'phi2' has no closed form (it is a root of an equation found numerically: the root for phi@2 of "
                                      "0 = integral(M0*exp(-xi^2/phi0^2), xi, 0, phi@2) - k^2*m*w2^2/2), and parameter '") &&
                          Catch::Contains("has no value, so neither a form nor a number can be given"));
}

TEST_CASE("symbolic scenes: a parameter's range 'in:' places its samples, and a range 'over:' may hold parameters", "[symbolic]") {
  // the crank angle sampled inside its range [180 deg, 270 deg] (its middle 90 %), by the solve
  // and by the confirmation alike
  const std::string linkage = symbolize(kt::derivation("energy/linkage_collar.yaml"));
  auto s = kt::solve_text(linkage);
  kinergy::confirm(s);
  REQUIRE(s.confirmed.size() == 2);
  REQUIRE(s.confirmed[0].samples.size() == 3);
  const double pi = 3.14159265358979;
  for (auto& text : s.confirmed[0].samples) {
    std::smatch m;
    REQUIRE(std::regex_search(text, m, std::regex(R"(theta2 = ([0-9.]+))")));
    INFO(text);
    CHECK(std::stod(m[1]) > pi + 0.05 * pi / 2);
    CHECK(std::stod(m[1]) < 1.5 * pi - 0.05 * pi / 2);
  }
  // the root asked for, chosen at a sample, stated where the form does not prove it: omega2 =
  // -sqrt(X)/(r sin theta2) (X >= 0 where real) is positive where -sin theta2 >= 0
  {
    const GiNaC::ex th2 = kt::param(s.model, "theta2");
    const auto root = std::find_if(s.valid_where.begin(), s.valid_where.end(),
                                   [](const kinergy::principles::Condition& c) { return c.assumed.find("the root asked for") != std::string::npos; });
    REQUIRE(root != s.valid_where.end());
    CHECK(kt::symbolically_zero(root->e + GiNaC::sin(th2)));
    CHECK(root->assumed == "'omega2' > 0, the root asked for");
    // (omega3 = sqrt(...)/r is positive by its form: nothing stated for it)
    CHECK(std::count_if(s.valid_where.begin(), s.valid_where.end(),
                        [](const kinergy::principles::Condition& c) { return c.assumed.find("the root asked for") != std::string::npos; }) == 1);
  }
  for (int k = 0; k < 200; ++k) {
    const GiNaC::numeric v = kinergy::model::Model::sample_value(*s.model.parameter("theta2"), k % 2, k);
    CHECK(v.to_double() > pi);
    CHECK(v.to_double() < 1.5 * pi);
  }
  // a positive range with a unit, sampled evenly in its logarithm and inside it; a narrow one
  // given more digits than three where three would leave it
  auto narrow = kt::model_of(kt::edit(kt::derivation("energy/compound_pendulum.yaml"), "L: 0.9 m", "L: {value: m, in: [1.2 m, 1.2001 m]}"));
  for (int k = 0; k < 50; ++k) {
    const GiNaC::numeric v = kinergy::model::Model::sample_value(*narrow.parameter("L"), 1, k);
    CHECK(v > GiNaC::numeric(12, 10));
    CHECK(v < GiNaC::numeric(12001, 10000));
    CHECK(kinergy::model::Model::sample_digits(v) > 3);
  }
  // the collar's least speed with every parameter a symbol, its path 'over: [-a, a]': by hand,
  // the collar must get past x = 0 (directly below A), where the spring is shortest,
  // v0² = k ((L0 - h)² - (sqrt(a² + h²) - L0)²)/m
  s = kt::solve_text(symbolize(kt::derivation("energy/collar_spring_least_speed.yaml")));
  {
    const GiNaC::ex k = kt::param(s.model, "k"), m = kt::param(s.model, "m"), h = kt::param(s.model, "h"), L0 = kt::param(s.model, "L0"),
                    a = kt::param(s.model, "a");
    const GiNaC::ex want = GiNaC::sqrt(k * (GiNaC::pow(L0 - h, 2) - GiNaC::pow(GiNaC::sqrt(a * a + h * h) - L0, 2)) / m);
    const GiNaC::exmap at{{k, 200}, {m, 2}, {h, GiNaC::numeric(3, 10)}, {L0, GiNaC::numeric(1, 2)}, {a, GiNaC::numeric(2, 5)}};
    auto x = kinergy::numerics::evaluate(kt::result(s, "v0_min").closed, at, 30), y = kinergy::numerics::evaluate(want, at, 30);
    REQUIRE(x);
    REQUIRE(y);
    CHECK(x->to_double() == Approx(y->to_double()).epsilon(1e-14));
    CHECK(x->to_double() == Approx(2.0).epsilon(1e-12));
  }
  // a range empty at the parameters' values, said with the values
  REQUIRE_THROWS_WITH(kt::solve_text(kt::edit(symbolize(kt::derivation("energy/collar_spring_least_speed.yaml")), "over: [-a, a]", "over: [a, -a]")),
                      Catch::Contains("the range of 's' is empty at the sampled values") && Catch::Contains("is not below its upper end"));
}

TEST_CASE("symbolic scenes: closed forms confirmed at no sample are refused, not printed", "[symbolic]") {
  // a rod released past the upward vertical (100 deg < theta0 < 170 deg) falls counter-clockwise
  // through q = pi; by hand w3^2 = 3 g sin(theta0)/L. With the range it solves, confirmed by
  // simulation at samples inside it; without, theta0 is sampled in [0.2, 1.4] rad, where the rod
  // falls the other way and never reaches q = pi: the forms are confirmed nowhere, and refused
  const std::string rod = R"(title: Rod released from rest past the upward vertical
description: >
  Uniform slender rod OA, mass m, length L, pinned at O; q is the angle of OA from the x axis.
  Released from rest at q = theta0 with 100 deg < theta0 < 170 deg (A up and to the left of O),
  it falls counter-clockwise. Angular velocity as OA passes the left horizontal (q = pi) and the
  downward vertical (q = 3 pi/2).
  Hand: w3^2 = 3 g sin(theta0)/L, w2^2 = 3 g (1 + sin(theta0))/L.
parameters:
  m: kg
  L: m
  g: m/s^2
  theta0: {value: deg, in: [100 deg, 170 deg]}
points:
  O: [0, 0]
coordinates:
  q: rad
bodies:
  rod:
    mass: m
    inertia: {slender_rod: L}
    position: [L/2*cos(q), L/2*sin(q)]
    angle: q
    points: {O: [-L/2, 0], A: [L/2, 0]}
effects:
  gravity: {g: g}
  pivot: {pin: [O, rod.O]}
states:
  1: {q: theta0, q_dot: 0}
  3: {q: pi}
  2: {q: 3*pi/2}
analyses:
  - energy: {from: 1, to: 3}
  - energy: {from: 1, to: 2}
find:
  w3: {value: q_dot@3, root: positive}
  w2: {value: q_dot@2, root: positive}
  xA1: x(rod.A)@1
)";
  auto s = kt::solve_text(rod);
  kinergy::confirm(s);
  const GiNaC::ex th = kt::param(s.model, "theta0"), g = kt::param(s.model, "g"), L = kt::param(s.model, "L");
  const GiNaC::exmap at{{th, GiNaC::numeric(23, 10)}, {g, GiNaC::numeric(981, 100)}, {L, GiNaC::numeric(3, 2)}};
  CHECK(kt::value(kt::result(s, "w3").closed, at).to_double() == Approx(std::sqrt(3 * 9.81 * std::sin(2.3) / 1.5)).epsilon(1e-14));
  CHECK(s.confirmed[0].by == kinergy::Confirmed::By::Simulation);
  auto bare = kt::solve_text(kt::edit(rod, "theta0: {value: deg, in: [100 deg, 170 deg]}", "theta0: deg"));
  REQUIRE_THROWS_WITH(kinergy::confirm(bare), Catch::Contains("the closed forms are confirmed nowhere: at none of the") &&
                                                  Catch::Contains("does the scene have a solution that meets their conditions"));
}

TEST_CASE("symbolic scenes: a parameter without a value that no result holds only places the drawing (issue 44, item 8)", "[symbolic]") {
  // the compound pendulum with a point C at a height h that nothing uses: the results keep their
  // numbers (by hand omega2 = sqrt(3 g (1 - cos theta0)/L) from theta0 = 60 deg), and h is not sampled
  std::string text = kt::derivation("energy/compound_pendulum.yaml");
  text = kt::edit(kt::edit(text.substr(0, text.find("expect:")), "  theta0: 60 deg\n", "  theta0: 60 deg\n  h: m\n"), "  O: [0, 0]\n", "  O: [0, 0]\n  C: [0, h]\n");
  auto s = kt::solve_text(text);
  kinergy::confirm(s);
  REQUIRE(kt::result(s, "omega2").si);
  CHECK(kt::result(s, "omega2").si->to_double() == Approx(std::sqrt(3 * 9.81 * 0.5 / 0.9)).epsilon(1e-13));
  CHECK(s.confirmed[0].by == kinergy::Confirmed::By::Simulation);
  CHECK(s.confirmed[0].sampled.empty());
}
