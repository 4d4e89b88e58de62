// verify must catch wrong claims — a wrong factor, a flipped sign, the other root, a missing
// term, a number off in its third figure, a form right at the scene's values only — and must
// pass right claims written in another but equal form.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

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
