// verify must catch wrong claims — a wrong factor, a flipped sign, the other root, a missing
// term, a number off in its third figure, a form right at the scene's values only — and must
// pass right claims written in another but equal form.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "../support/helpers.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/verify/verify.hpp"

namespace {

using kinergy::verify::Check;

// The sliding rod of derivations/energy/sliding_rod.yaml: omega2 = sqrt(3*g*sin(theta2)/l).
const std::string kRod = R"(title: Rod sliding on a horizontal and a vertical track
parameters: {m: 5 kg, l: 1.2 m, g: 9.81 m/s^2, theta2: 30 deg}
coordinates: {theta: rad}
bodies:
  rod:
    mass: m
    inertia: {slender_rod: l}
    position: [l/2*cos(theta), -l/2*sin(theta)]
    angle: theta
    points: {B: [-l/2, 0], A: [l/2, 0]}
effects:
  gravity: {g: g}
states:
  1: {theta: 0, theta_dot: 0}
  2: {theta: theta2}
analyses:
  - energy: {from: 1, to: 2}
find:
  omega2: {value: theta_dot@2, root: positive, unit: rad/s}
expect:
)";

// A block on a vertical spring, released from rest with the spring stretched by h: the energy
// equation is a quadratic in y2 with roots L0 + h (the start) and L0 - h - 2 m g/k.
const std::string kSpring = R"(title: Block on a vertical spring released from rest
parameters: {m: 2 kg, g: 9.81 m/s^2, k: 800 N/m, L0: 0.5 m, h: 0.3 m}
points: {B: [0, 0]}
coordinates: {y: m}
bodies:
  block: {mass: m, inertia: particle, position: [0, y], points: {P: [0, 0]}}
effects:
  gravity: {g: g}
  coil: {spring: [B, block.P], k: k, free_length: L0}
states:
  1: {y: L0 + h, y_dot: 0}
  2: {y_dot: 0}
analyses:
  - energy: {from: 1, to: 2}
find:
  y2: {value: y@2, root: {in: [0, L0]}, unit: m}
expect:
)";

// A block sent up a rough incline: d = v1^2/(2*g*(sin(beta) + mu_k*cos(beta))).
const std::string kIncline = R"(title: Block sent up a rough incline
parameters: {m: 12 kg, beta: 30 deg, v1: 6 m/s, mu_k: 0.25, g: 9.81 m/s^2}
coordinates: {x: m}
bodies:
  block: {mass: m, inertia: particle, position: [x*cos(beta), x*sin(beta)]}
effects:
  gravity: {g: g}
  rubbing: {friction: block, mu: mu_k, normal: m*g*cos(beta)}
states:
  1: {x: 0, x_dot: v1}
  2: {x_dot: 0}
analyses:
  - energy: {from: 1, to: 2}
find:
  d: {value: x@2, unit: m}
expect:
)";

// A simple pendulum released from theta0: omega2 = -sqrt(2*g*(1 - cos(theta0))/l).
const std::string kPendulum = R"(title: Simple pendulum released from an angle
parameters: {m: 1.5 kg, l: 0.8 m, g: 9.81 m/s^2, theta0: 50 deg}
coordinates: {theta: rad}
bodies:
  bob: {mass: m, inertia: particle, position: [l*sin(theta), -l*cos(theta)]}
effects:
  gravity: {g: g}
states:
  1: {theta: theta0, theta_dot: 0}
  2: {theta: 0}
analyses:
  - energy: {from: 1, to: 2}
find:
  omega2: {value: theta_dot@2, unit: rad/s}
expect:
)";

/// The checks of a scene whose expect block is `claim` (one line, indented by two spaces).
std::vector<Check> checks(const std::string& scene, const std::string& claim) {
  auto def = kinergy::scene::load_string(scene + "  " + claim + "\n", "<claim>");
  kinergy::Solution s = kinergy::solve_scene(def);
  return kinergy::verify::verify(s);
}

Check only(const std::vector<Check>& cs) {
  REQUIRE(cs.size() == 1);
  return cs[0];
}

bool fails(const Check& c) { return !c.ok() && c.detail.rfind("FAILS: derived ", 0) == 0; }

}  // namespace

TEST_CASE("wrong claims are caught", "[verify][wrong]") {
  SECTION("a wrong constant factor") {
    Check c = only(checks(kRod, "omega2: {form: sqrt(2*g*sin(theta2)/l)}"));
    INFO(c.detail);
    CHECK(fails(c));
    CHECK(c.detail.find(", claimed sqrt(2*g*sin(theta2)/l), at ") != std::string::npos);
  }
  SECTION("a flipped sign") {
    Check c = only(checks(kRod, "omega2: {form: -sqrt(3*g*sin(theta2)/l)}"));
    INFO(c.detail);
    CHECK(fails(c));
  }
  SECTION("the other root of a quadratic") {
    // the right root first, so that the scene is known to be right
    Check right = only(checks(kSpring, "y2: {form: L0 - h - 2*m*g/k}"));
    INFO(right.detail);
    CHECK(right.ok());
    Check c = only(checks(kSpring, "y2: {form: L0 + h}"));
    INFO(c.detail);
    CHECK(fails(c));
  }
  SECTION("a missing term") {
    Check right = only(checks(kIncline, "d: {form: v1^2/(2*g*(sin(beta) + mu_k*cos(beta)))}"));
    INFO(right.detail);
    CHECK(right.ok());
    Check c = only(checks(kIncline, "d: {form: v1^2/(2*g*sin(beta))}"));
    INFO(c.detail);
    CHECK(fails(c));
  }
  SECTION("a value off in its third significant figure, shown with its trailing zero") {
    Check c = only(checks(kRod, "omega2: {value: 3.49 rad/s}"));
    INFO(c.detail);
    CHECK(fails(c));
    // derived 3.5018 rad/s is 3.50 to three figures: written 3.50, not 3.5
    CHECK(c.detail.rfind("FAILS: derived 3.50 rad/s, claimed 3.49 rad/s, at ", 0) == 0);
  }
  SECTION("a value in another unit is compared in that unit") {
    Check c = only(checks(kRod, "omega2: {value: 33.5 rpm}"));  // 3.5018 rad/s = 33.44 rpm
    INFO(c.detail);
    CHECK(fails(c));
    CHECK(c.detail.rfind("FAILS: derived 33.4 rpm, claimed 33.5 rpm", 0) == 0);
  }
  SECTION("a form right at the scene's values only") {
    // sin(30 deg) = 1/2, so this equals the derived form at the scene's theta2 and nowhere else
    Check c = only(checks(kRod, "omega2: {form: sqrt(3*g/(2*l))}"));
    INFO(c.detail);
    CHECK(fails(c));
    CHECK(c.detail.find("they agree at the scene's values only") != std::string::npos);
  }
  SECTION("a claimed form with no real value at the scene's values") {
    Check c = only(checks(kRod, "omega2: {form: sqrt(-3*g*sin(theta2)/l)}"));
    INFO(c.detail);
    CHECK(fails(c));
  }
}

TEST_CASE("right claims in another but equal form pass", "[verify][wrong]") {
  SECTION("square roots split apart") {
    Check c = only(checks(kRod, "omega2: {form: sqrt(3)*sqrt(g/l)*sqrt(sin(theta2))}"));
    INFO(c.detail);
    CHECK(c.ok());
    CHECK((c.detail == "proved" || c.detail == "checked at 24 points, relative difference below 1e-40 at each"));
  }
  SECTION("the derived form itself is proved") {
    Check c = only(checks(kRod, "omega2: {form: sqrt(3*g*sin(theta2)/l)}"));
    CHECK(c.detail == "proved");
  }
  SECTION("1 - cos(x) written as 2 sin^2(x/2)") {
    Check a = only(checks(kPendulum, "omega2: {form: -sqrt(2*g*(1 - cos(theta0))/l)}"));
    INFO(a.detail);
    CHECK(a.ok());
    Check b = only(checks(kPendulum, "omega2: {form: -2*sin(theta0/2)*sqrt(g/l)}"));
    INFO(b.detail);
    CHECK(b.ok());
    Check w = only(checks(kPendulum, "omega2: {form: -2*sin(theta0)*sqrt(g/l)}"));
    INFO(w.detail);
    CHECK(fails(w));
  }
  SECTION("a value to its figures") {
    Check c = only(checks(kRod, "omega2: {value: 3.502 rad/s}"));
    INFO(c.detail);
    CHECK(c.ok());
    CHECK(c.detail.rfind("matches to 4 significant figures", 0) == 0);
  }
}

TEST_CASE("figures keep their trailing zeros", "[verify]") {
  using GiNaC::numeric;
  CHECK(kinergy::verify::figures(numeric(35018, 10000), 3) == "3.50");
  CHECK(kinergy::verify::figures(numeric(20), 4) == "20.00");
  CHECK(kinergy::verify::figures(numeric(12, 1000), 3) == "0.0120");
  CHECK(kinergy::verify::figures(numeric(-4870, 100), 4) == "-48.70");
  CHECK(kinergy::verify::figures(numeric(3500), 2) == "3500");
  CHECK(kinergy::verify::figures(numeric(0), 3) == "0.00");
  CHECK(kinergy::verify::figures(numeric(9996, 1000), 3) == "10.0");
}

TEST_CASE("kinergy verify exits 1 and says FAILS when a claim is wrong", "[verify][cli]") {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("kinergy-verify-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::path scene = dir / "wrong.yaml";
  {
    std::ofstream out(scene);
    out << kRod << "  omega2: {form: sqrt(2*g*sin(theta2)/l), value: 3.49 rad/s}\n";
  }
  std::string cmd = std::string(KINERGY_CLI) + " verify " + scene.string() + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::string out;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  int st = pclose(p);
  INFO(out);
  CHECK(WIFEXITED(st));
  CHECK(WEXITSTATUS(st) == 1);
  CHECK(out.find("omega2 (form): FAILS: derived sqrt(3*g*sin(theta2)/l), claimed sqrt(2*g*sin(theta2)/l), at ") !=
        std::string::npos);
  CHECK(out.find("omega2 (value): FAILS: derived 3.50 rad/s, claimed 3.49 rad/s, at the scene's values") !=
        std::string::npos);
  fs::remove_all(dir);
}

namespace {
// A block slides from rest down a smooth drop of h = 1 m (energy: v2 = sqrt(2 g h) = 4.429 m/s);
// the result asks the height back from v2, v2^2/(2 g) = 1 m exactly. A book that rounds v2 to
// 2 figures (4.4 m/s) gets 4.4^2/(2*9.81) = 0.9867 m: "0.99 m", off by 1.0 % from 1.0 m.
const char* kDrop = R"(title: a drop and back
parameters:
  m: 2 kg
  h: 1 m
  g: 9.81 m/s^2
coordinates:
  y: m
bodies:
  block: {mass: m, inertia: particle, position: [0, y]}
effects:
  gravity: {g: g}
states:
  1: {y: h, y_dot: 0}
  2: {y: 0}
analyses:
  - energy: {from: 1, to: 2}
find:
  v2: {value: y_dot@2, root: negative, unit: m/s}
  back: {value: y_dot@2^2/(2*g), unit: m}
expect:
)";

std::vector<Check> checks_rtol(const std::string& scene, const std::string& claim, double rtol) {
  auto def = kinergy::scene::load_string(scene + "  " + claim + "\n", "<claim>");
  return kinergy::verify::verify(kinergy::solve_scene(def), rtol);
}
}  // namespace

TEST_CASE("a value off by a book's rounding: by how much, and whether rounding reproduces it", "[verify][rounding]") {
  SECTION("the relative difference is said, and that rounding v2 to 2 figures gives the claim") {
    Check c = only(checks(kDrop, "back: {value: 0.99 m}"));
    INFO(c.detail);
    CHECK(fails(c));
    CHECK(c.detail.find("derived 1.0 m, claimed 0.99 m") != std::string::npos);
    CHECK(c.detail.find("relative difference 1%") != std::string::npos);
    CHECK(c.detail.find("rounding each intermediate value to 2 significant figures, as a book does, gives 0.99 m: the method "
                        "is right, the claim carries the rounding (accept it with --rtol 0.011)") != std::string::npos);
  }
  SECTION("a claim that rounding does not explain says so") {
    Check c = only(checks(kDrop, "back: {value: 0.95 m}"));
    INFO(c.detail);
    CHECK(fails(c));
    CHECK(c.detail.find("relative difference 5%") != std::string::npos);
    CHECK(c.detail.find("gives 0.99 m, not the claim either") != std::string::npos);
  }
  SECTION("--rtol accepts it within the tolerance, and not beyond") {
    Check c = only(checks_rtol(kDrop, "back: {value: 0.99 m}", 0.011));
    INFO(c.detail);
    CHECK(c.ok());
    CHECK(c.detail.rfind("within rtol 0.011: derived 1 m, claimed 0.99 m (relative difference 1%)", 0) == 0);
    Check d = only(checks_rtol(kDrop, "back: {value: 0.99 m}", 0.009));
    CHECK(!d.ok());
  }
}

TEST_CASE("kinergy verify --rtol: exit 0 within it, and a tolerance outside [0, 1] refused", "[verify][rounding][cli]") {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("kinergy-rtol-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::path scene = dir / "drop.yaml";
  {
    std::ofstream out(scene);
    out << kDrop << "  back: {value: 0.99 m}\n";
  }
  int st = 0;
  std::string out = kt::run_cli("verify " + scene.string(), st);
  CHECK(st == 1);
  out = kt::run_cli("verify --rtol 0.011 " + scene.string(), st);
  INFO(out);
  CHECK(st == 0);
  CHECK(out.find("back (value): within rtol 0.011: derived 1 m, claimed 0.99 m (relative difference 1%)") != std::string::npos);
  for (const char* bad : {"2", "-0.1", "nan"}) {
    out = kt::run_cli(std::string("verify --rtol ") + bad + " " + scene.string(), st);
    INFO(out);
    CHECK(st == 2);
    CHECK(out.find("give a relative tolerance such as 0.005") != std::string::npos);
  }
  fs::remove_all(dir);
}
