// Every way a scene can be wrong ends with one line `FILE:LINE:COL: what is wrong — what would
// fix it` (a kinergy::SceneError) and, from the command line, exit status 1: never a crash, a
// hang, an uncaught exception, an "internal error" or a NaN printed as an answer.
//
// Most cases edit a good scene (kRod, kBlock) in one place and check that the error names that
// place: `at(text, needle, k)` is the line and column of the k-th character of `needle`, which
// must occur exactly once in the edited text. File cases live in tests/data/bad/.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>

#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"
#include "../support/helpers.hpp"
#include "../support/scene_errors.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

using namespace kt_errors;

// The sliding rod of derivations/energy/sliding_rod.yaml, without its description.
const std::string kRod = R"(title: Rod sliding on two tracks
parameters:
  m: 5 kg
  l: 1.2 m
  g: 9.81 m/s^2
  theta2: 30 deg
coordinates:
  theta: rad
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
  omega2: {form: sqrt(3*g*sin(theta2)/l), value: 3.50 rad/s}
)";

const std::string kRodExpect = "expect:\n  omega2: {form: sqrt(3*g*sin(theta2)/l), value: 3.50 rad/s}\n";
const std::string kRodFind = "omega2: {value: theta_dot@2, root: positive, unit: rad/s}";

// A block sent up a smooth incline with speed v1; it reaches x = 0.5 m (v1² > g sin β).
const std::string kBlock = R"(title: Block sent up an incline
parameters:
  m: 2 kg
  beta: 30 deg
  g: 9.81 m/s^2
  v1: 3 m/s
coordinates:
  x: m
bodies:
  block:
    mass: m
    inertia: particle
    position: [x*cos(beta), x*sin(beta)]
effects:
  gravity: {g: g}
states:
  1: {x: 0, x_dot: v1}
  2: {x: 0.5 m}
analyses:
  - energy: {from: 1, to: 2}
find:
  v2: {value: x_dot@2, root: positive, unit: m/s}
)";


std::string rod(const std::string& from, const std::string& to) { return edit(kRod, from, to); }
std::string block(const std::string& from, const std::string& to) { return edit(kBlock, from, to); }
/// The rod without its expect and with another find.
std::string rod_find(const std::string& find) { return edit(edit(kRod, kRodExpect, ""), kRodFind, find); }


// --- the command line ---

struct Run {
  int status = -1;
  std::string out, err;
};

/// Run `kinergy ARGS` with stdout and stderr captured (`prefix`: a command in front, as `timeout 60 `).
Run cli(const std::string& args, const std::string& prefix = "") {
  static int n = 0;
  fs::path base = fs::temp_directory_path() / ("kinergy_errors_" + std::to_string(getpid()) + "_" + std::to_string(++n));
  fs::path out = base.string() + ".out", err = base.string() + ".err";
  std::string cmd = prefix + "\"" + KINERGY_CLI + "\" " + args + " >\"" + out.string() + "\" 2>\"" + err.string() + "\"";
  int rc = std::system(cmd.c_str());
  Run r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  r.out = kt::read_file(out);
  r.err = kt::read_file(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

std::string bad_file(const std::string& name) { return std::string(KINERGY_SOURCE_DIR) + "/tests/data/bad/" + name; }

std::size_t lines_of(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

// ------------------------------------------------------------------------------------------

TEST_CASE("the scenes the error cases start from are good", "[errors]") {
  CHECK_FALSE(error_of(kRod).has_value());
  CHECK_FALSE(error_of(kBlock).has_value());
  CHECK_FALSE(error_of(rod_find("th: theta@2")).has_value());
}

TEST_CASE("YAML syntax errors point at the fault and say what to fix", "[errors][yaml]") {
  SECTION("bad indentation: a line deeper than the key above it") {
    auto t = rod("    mass: m\n", "   mass: m\n");
    expect_error(t, at(t, "    inertia:", 4), "YAML syntax error", "indent");
  }
  SECTION("bad indentation: a line shallower than its siblings") {
    auto t = rod("  l: 1.2 m\n", " l: 1.2 m\n");
    expect_error(t, at(t, " l: 1.2 m", 1), "YAML syntax error", "same number of spaces");
  }
  SECTION("a key without a space after ':'") {
    auto t = rod("    mass: m\n", "    mass:m\n");
    expect_error(t, at(t, "mass:m", 4), "no space after ':'", "mass: ");
  }
  SECTION("an unclosed '[' is shown where it opens, not lines later") {
    auto t = rod("[l/2*cos(theta), -l/2*sin(theta)]", "[l/2*cos(theta), -l/2*sin(theta)");
    expect_error(t, at(t, "[l/2*cos"), "unclosed '['", "']'");
  }
  SECTION("an unclosed '{'") {
    auto t = rod("{slender_rod: l}", "{slender_rod: l");
    expect_error(t, at(t, "{slender_rod"), "unclosed '{'", "'}'");
  }
  SECTION("a closing bracket that closes nothing") {
    auto t = rod("A: [l/2, 0]}", "A: [l/2, 0]}}");
    expect_error(t, at(t, "}}", 1), "closes nothing");
  }
  SECTION("a tab in the indentation") {
    auto t = rod("    mass: m\n", "\tmass: m\n");
    expect_error(t, at(t, "\tmass"), "a tab in the indentation", "spaces");
  }
  SECTION("a quote never closed (yaml-cpp would swallow the rest of the file into it)") {
    auto t = rod("    mass: m\n", "    mass: \"m\n");
    expect_error(t, at(t, "\"m"), "never closed", "\"");
    auto t2 = rod("title: Rod", "title: 'Rod");
    expect_error(t2, at(t2, "'Rod"), "never closed", "'");
  }
  SECTION("a '*' at the start of a value is a YAML alias") {
    auto t = rod("    mass: m\n", "    mass: *m\n");
    expect_error(t, at(t, "*m"), "alias", "quotes");
  }
  SECTION("two YAML documents in one file") {
    auto t = kRod + "---\ntitle: another scene\n";
    expect_error(t, at(t, "---"), "more than one YAML document", "one scene per file");
  }
  SECTION("nesting too deep for a scene") {
    auto t = "title: x\nparameters: " + std::string(5000, '[') + std::string(5000, ']') + "\n";
    auto e = error_of(t);
    REQUIRE(e);
    CHECK(e->pos().line == 2);
    CHECK_THAT(e->problem(), Contains("nested too deeply"));
    check_form(*e, "bad.yaml");
  }
}

TEST_CASE("an empty scene, or one that is not a map", "[errors][yaml]") {
  expect_error("", {1, 1}, "the scene is empty");
  expect_error("# only a comment\n\n", {1, 1}, "the scene is empty");
  expect_error("just some text\n", {1, 1}, "must be a map of sections");
  expect_error("- a\n- b\n", {1, 1}, "must be a map of sections");
  auto t = edit(kRod, "title: Rod sliding on two tracks\n", "");
  expect_error(t, {1, 1}, "has no 'title'", "title:");
}

TEST_CASE("wrong types: a list, a map or a text where another is needed", "[errors][types]") {
  SECTION("a list where a map is needed") {
    auto t = rod("bodies:\n  rod:\n    mass: m\n", "bodies:\n  - rod:\n    mass: m\n");
    // the whole body list is one list item now; what matters is the 'bodies' value
    auto e = error_of(t);
    REQUIRE(e);
    CHECK_THAT(e->problem(), Contains("'bodies' must be a map, not a list"));
    CHECK(e->pos().line == 10);
    check_form(*e, "bad.yaml");
    auto t2 = rod("points: {B: [-l/2, 0], A: [l/2, 0]}", "points: [B, A]");
    expect_error(t2, at(t2, "[B, A]"), "'points' must be a map, not a list");
    auto t3 = rod("  1: {theta: 0, theta_dot: 0}", "  1: [0, 0]");
    expect_error(t3, at(t3, "[0, 0]"), "'1' must be a map, not a list");
    // a list item among map entries at one indentation
    auto t4 = edit(kRod, "parameters:\n  m: 5 kg\n", "parameters:\n  - m: 5 kg\n");
    expect_error(t4, at(t4, "l: 1.2 m"), "a key among the '- ' items of a list", "not both");
  }
  SECTION("a map where a single value is needed") {
    auto t = rod("    mass: m\n", "    mass: {value: m}\n");
    expect_error(t, at(t, "{value: m}"), "'mass' must be a single value, not a map", "mass: m");
    auto t2 = rod("  m: 5 kg", "  m: {value: 5, unit: kg}");
    expect_error(t2, at(t2, "unit: kg"), "parameter 'm' takes its unit in its value, not under 'unit'", "m: {value: 5 kg}");
    auto t3 = rod("title: Rod sliding on two tracks", "title: [a, b]");
    expect_error(t3, at(t3, "[a, b]"), "'title' must be a single value, not a list");
  }
  SECTION("a position with 3 entries") {
    auto t = rod("[l/2*cos(theta), -l/2*sin(theta)]", "[l/2*cos(theta), -l/2*sin(theta), 0]");
    expect_error(t, at(t, "[l/2*cos"), "'position' must have 2 entries [x, y], not 3");
  }
  SECTION("a point with 1 entry") {
    auto t = rod("A: [l/2, 0]", "A: [l/2]");
    expect_error(t, at(t, "[l/2]"), "must have 2 entries");
  }
  SECTION("analyses as a map, where as a map, an empty value") {
    auto t = rod("  - energy: {from: 1, to: 2}", "  energy: {from: 1, to: 2}");
    expect_error(t, at(t, "energy:"), "'analyses' must be a list");
    auto t2 = rod("  2: {theta: theta2}", "  2: {theta: theta2, where: {a: b}}");
    expect_error(t2, at(t2, "{a: b}"), "'where' must be a list of equations");
    auto t3 = rod("    mass: m\n", "    mass:\n");
    expect_error(t3, at(t3, "mass:"), "'mass' must be a single value, not empty");
  }
  SECTION("a map key that is not a name") {
    auto t = rod("  m: 5 kg\n", "  ? [a, b]\n  : 5 kg\n");
    expect_error(t, at(t, "[a, b]"), "a map key must be a plain name");
  }
}

TEST_CASE("unknown keys at every level, with the nearest known key", "[errors][keys]") {
  SECTION("top level") {
    auto t = rod("analyses:", "analysis:");
    expect_error(t, at(t, "analysis:"), "unknown key 'analysis' in the scene", "did you mean 'analyses'?");
  }
  SECTION("a section indented into the one above") {
    auto t = rod("bodies:\n", "  bodies:\n");
    expect_error(t, at(t, "bodies:"), "'bodies' is indented", "beginning of its line");
  }
  SECTION("body") {
    auto t = rod("    angle: theta", "    angel: theta");
    expect_error(t, at(t, "angel"), "unknown key 'angel' in body 'rod'", "did you mean 'angle'?");
  }
  SECTION("inertia shape") {
    auto t = rod("{slender_rod: l}", "{slender_road: l}");
    expect_error(t, at(t, "slender_road"), "unknown inertia shape 'slender_road'", "did you mean 'slender_rod'?");
  }
  SECTION("effect") {
    auto t = rod("gravity: {g: g}", "gravity: {g: g, dirction: [0, -1]}");
    expect_error(t, at(t, "dirction"), "unknown key 'dirction' in gravity effect 'gravity'", "did you mean 'direction'?");
  }
  SECTION("find") {
    auto t = rod("root: positive, unit", "roots: positive, unit");
    expect_error(t, at(t, "roots"), "unknown key 'roots' in find 'omega2'", "did you mean 'root'?");
  }
  SECTION("expect") {
    auto t = rod("{form: sqrt", "{from: sqrt");
    expect_error(t, at(t, "from: sqrt"), "unknown key 'from' in expect 'omega2'", "did you mean 'form'?");
  }
  SECTION("state key") {
    auto t = rod("2: {theta: theta2}", "2: {thetta: theta2}");
    expect_error(t, at(t, "thetta"), "state '2' gives 'thetta'", "did you mean 'theta'?");
  }
  SECTION("analysis kind and option") {
    auto t = rod("- energy:", "- energi:");
    expect_error(t, at(t, "energi"), "unknown analysis 'energi'", "did you mean 'energy'?");
    auto t2 = rod("{from: 1, to: 2}", "{from: 1, too: 2}");
    expect_error(t2, at(t2, "too"), "unknown key 'too' in energy analysis");
  }
  SECTION("an expression that YAML cut at a comma inside {…}") {
    auto t = rod(kRodFind, "omega2: {value: atan2(theta_dot@2, 1)}");
    expect_error(t, at(t, "atan2("), "'atan2(theta_dot@2' is cut at a comma", "quotes");
    auto t2 = rod("gravity: {g: g}", "gravity: {g: g}\n  push: {force: rod.A, F: [m*g*atan2(l, l), 0]}");
    expect_error(t2, at(t2, "m*g*atan2"), "is cut at a comma", "quotes");
  }
}

TEST_CASE("undefined names in expressions, with the column inside the expression", "[errors][names]") {
  SECTION("in a position") {
    auto t = rod("-l/2*sin(theta)]", "-L/2*sin(theta)]");
    expect_error(t, at(t, "L/2*sin"), "unknown name 'L'", "did you mean 'l'?");
  }
  SECTION("inside a quoted expression") {
    auto t = rod("[l/2*cos(theta), -l/2*sin(theta)]", "[\"l/2*cos(theta) + L\", -l/2*sin(theta)]");
    expect_error(t, at(t, "L\""), "unknown name 'L'");
  }
  SECTION("on the second line of a block list") {
    auto t = rod("position: [l/2*cos(theta), -l/2*sin(theta)]", "position:\n      - l/2*cos(theta)\n      - -L/2*sin(theta)");
    expect_error(t, at(t, "L/2"), "unknown name 'L'");
  }
  SECTION("in a find") {
    auto t = rod("value: theta_dot@2", "value: omega_dot@2");
    expect_error(t, at(t, "omega_dot@2"), "unknown name 'omega_dot'", "did you mean 'theta_dot'?");
  }
  SECTION("in a 'where' condition, nothing near") {
    auto t = rod("2: {theta: theta2}", "2: {theta: theta2, where: [theta_dot = q]}");
    expect_error(t, at(t, "q]"), "unknown name 'q'", "parameters or coordinates");
  }
  SECTION("a point and a body that do not exist") {
    auto t = rod("value: theta_dot@2", "value: speed(rod.C)@2");
    expect_error(t, at(t, "speed("), "body 'rod' has no point 'C'");
    auto t2 = rod("gravity: {g: g}", "gravity: {g: g}\n  drive: {couple: rdo, M: m*g*l}");
    expect_error(t2, at(t2, "rdo"), "no body named 'rdo'", "did you mean 'rod'?");
    auto t3 = rod("gravity: {g: g}", "gravity: {g: g}\n  s: {spring: [rod.A, Q], k: m*g/l}");
    expect_error(t3, at(t3, "[rod.A, Q]", 8), "'Q' is neither a fixed point nor a body");
  }
  SECTION("a coordinate where only parameters may stand") {
    auto t = rod("B: [-l/2, 0]", "B: [-l/2, theta]");
    expect_error(t, at(t, "theta]"), "'theta' is a coordinate or rate");
  }
  SECTION("syntax inside an expression") {
    auto t = rod("value: theta_dot@2", "value: theta_dot@2 +");
    expect_error(t, at(t, "+,", 1), "expression ends too early");
    auto t2 = rod("value: theta_dot@2", "value: theta_dot@2 = 3");
    expect_error(t2, at(t2, "= 3"), "'=' is not allowed here");
    auto t3 = rod("    mass: m\n", "    mass: m$\n");
    expect_error(t3, at(t3, "$"), "unexpected '$'");
    auto t4 = rod("value: theta_dot@2", "value: sin(theta@2");
    expect_error(t4, at(t4, ", root"), "expected ')'");
  }
  SECTION("a number and a name with no operator between") {
    auto t = rod("-l/2*sin(theta)]", "-l/2*sin(theta) + 2 l]");
    expect_error(t, at(t, "l]"), "no operator before 'l'", "'*'");
  }
}

TEST_CASE("units: unknown, wrong for the place, or mixed", "[errors][units]") {
  SECTION("an unknown unit, with the usual spelling") {
    auto t = rod("g: 9.81 m/s^2", "g: 9.81 m/sec^2");
    expect_error(t, at(t, "sec^2"), "unknown unit 'sec'", "'s'");
    auto t2 = rod("m: 5 kg", "m: 5 kilo");
    expect_error(t2, at(t2, "kilo"), "unknown unit 'kilo'", "kg");
    auto t3 = rod("unit: rad/s}", "unit: rad/sec}");
    expect_error(t3, at(t3, "sec}"), "unknown unit 'sec'");
  }
  SECTION("a unit exponent too large (was an uncaught std::out_of_range)") {
    auto t = rod("g: 9.81 m/s^2", "g: 9.81 m/s^99999999999");
    expect_error(t, at(t, "99999999999"), "exponent", "m^2");
  }
  SECTION("'unknown' without a unit") {
    auto t = rod("m: 5 kg", "m: unknown");
    expect_error(t, at(t, "unknown"), "'unknown' needs a unit");
  }
  SECTION("mass + length in a position") {
    auto t = rod("[l/2*cos(theta), -l/2", "[l/2*cos(theta) + m, -l/2");
    expect_error(t, at(t, "l/2*cos(theta) + m"), "inconsistent units in 'position[0]'", "same kind of quantity");
  }
  SECTION("a state value with the wrong unit") {
    auto t = rod("2: {theta: theta2}", "2: {theta: 2 m}");
    expect_error(t, at(t, "2 m}"), "'theta' is given in m", "rad or deg");
    auto t2 = rod("2: {theta: theta2}", "2: {theta: l}");
    expect_error(t2, at(t2, "theta: l}", 7), "'theta' is in m but must be a pure number");
    auto t3 = block("2: {x: 0.5 m}", "2: {x: 0.5 m, t: 3 m}");
    expect_error(t3, at(t3, "3 m}"), "'t' is given in m but must be s");
  }
  SECTION("a rate given as a bare number") {
    auto t = block("x_dot: v1}", "x_dot: 3}");
    expect_error(t, at(t, "3}"), "has no unit", "x_dot: 3 m/s");
  }
  SECTION("an expect with a value in the wrong unit") {
    auto t = rod("value: 3.50 rad/s}", "value: 3.50 m/s}");
    expect_error(t, at(t, "3.50 m/s"), "the claimed value is in m/s", "rad/s");
    auto t2 = rod("value: 3.50 rad/s}", "value: 3.50}");
    expect_error(t2, at(t2, "3.50}"), "the claimed value is in no unit");
    auto t3 = rod("value: 3.50 rad/s}", "value: rad/s}");
    expect_error(t3, at(t3, "value: rad/s}", 7), "the claimed value has no number");
  }
  SECTION("an expect form and a find unit of the wrong dimension") {
    auto t = rod("{form: sqrt(3*g*sin(theta2)/l)", "{form: sqrt(3*g*sin(theta2)*l)");
    expect_error(t, at(t, "sqrt(3*g*sin(theta2)*l)"), "the claimed form has dimension m/s");
    auto t2 = rod("unit: rad/s}", "unit: m/s}");
    expect_error(t2, at(t2, "m/s}"), "the unit 'm/s' does not fit find 'omega2'", "rad/s");
  }
  SECTION("a couple given in N") {
    auto t = rod("  theta2: 30 deg\n", "  theta2: 30 deg\n  F0: 3 N\n");
    t = edit(t, "gravity: {g: g}", "gravity: {g: g}\n  drive: {couple: rod, M: F0}");
    expect_error(t, at(t, "F0}"), "'M' is in N", "N\u00b7m");
  }
  SECTION("a number with a unit written where an expression of parameters stands") {
    auto t = rod("gravity: {g: g}", "gravity: {g: g}\n  drive: {couple: rod, M: 3 N*m}");
    expect_error(t, at(t, "3 N*m"), "'3 N*m' is a number with a unit", "under parameters");
    auto t2 = rod("    mass: m\n", "    mass: 2 m\n");
    expect_error(t2, at(t2, "mass: 2 m", 6), "number with a unit", "'2*m'");
  }
  SECTION("a mass in N, a size in kg, a coordinate in kg, g in kg, a spring constant without unit") {
    auto t = rod("m: 5 kg", "m: 5 N");
    expect_error(t, at(t, "    mass: m", 10), "'mass' is in N");
    auto t2 = rod("{slender_rod: l}", "{slender_rod: m}");
    expect_error(t2, at(t2, "m}"), "'slender_rod' is in kg but must be in m");
    auto t3 = rod("theta: rad\n", "theta: kg\n");
    expect_error(t3, at(t3, "theta: kg", 7), "a coordinate is a length or an angle");
    auto t4 = rod("gravity: {g: g}", "gravity: {g: m}");
    expect_error(t4, at(t4, "m}"), "'g' is in kg but must be in m/s^2");
    auto t5 = rod("gravity: {g: g}", "gravity: {g: g}\n  s: {spring: [rod.A, rod.B], k: 10}");
    expect_error(t5, at(t5, "10}"), "'k' is a pure number", "N/m");
  }
}

TEST_CASE("states: unknown in X@S, missing @, missing or repeated in an analysis", "[errors][states]") {
  SECTION("an unknown state in X@S") {
    auto t = rod("value: theta_dot@2", "value: theta_dot@3");
    expect_error(t, at(t, "3,"), "no state named '3'", "the states are 1, 2");
    auto t2 = rod("value: theta_dot@2", "value: theta_dot@");
    expect_error(t2, at(t2, "@,"), "expected a state name after '@'");
  }
  SECTION("a find that uses a coordinate without @state") {
    auto t = rod("value: theta_dot@2", "value: theta_dot");
    expect_error(t, at(t, "theta_dot,"), "'omega2' depends on the motion but names no state", "@");
    auto t2 = rod("{form: sqrt(3*g*sin(theta2)/l)", "{form: theta_dot");
    expect_error(t2, at(t2, "theta_dot, value"), "'form' depends on the motion but names no state");
  }
  SECTION("an analysis naming a missing state") {
    auto t = rod("{from: 1, to: 2}", "{from: 1, to: 3}");
    expect_error(t, at(t, "3}"), "no state named '3'", "1, 2");
    auto t2 = rod("{from: 1, to: 2}", "{to: 2}");
    expect_error(t2, at(t2, "energy"), "energy analysis has no 'from'");
  }
  SECTION("an analysis naming the same state twice") {
    auto t = rod("{from: 1, to: 2}", "{from: 1, to: 1}");
    expect_error(t, at(t, "1}"), "'from' and 'to' are the same state");
  }
  SECTION("a state name that is not a name") {
    auto t = rod("  2: {theta: theta2}", "  2a-b: {theta: theta2}");
    expect_error(t, at(t, "2a-b"), "is not a valid state name");
  }
}

TEST_CASE("parameters: reserved names, duplicates, no value where a number is asked", "[errors][parameters]") {
  for (std::string name : {"T", "V", "t", "pi", "sin", "sqrt"}) {
    DYNAMIC_SECTION("reserved name " << name) {
      auto t = rod("  theta2: 30 deg\n", "  theta2: 30 deg\n  " + name + ": 2 m\n");
      expect_error(t, at(t, "  " + name + ": 2 m", 2), "'" + name + "' is a reserved name", name + "_1");
    }
  }
  SECTION("a coordinate named t") {
    auto t = rod("  theta: rad\n", "  theta: rad\n  t: rad\n");
    expect_error(t, at(t, "  t: rad", 2), "'t' is a reserved name and cannot name a coordinate");
  }
  SECTION("a duplicate key") {
    auto t = rod("  l: 1.2 m\n", "  l: 1.2 m\n  l: 1.5 m\n");
    expect_error(t, at(t, "l: 1.5 m"), "duplicate key 'l'", "give each key once");
  }
  SECTION("a name used for a parameter and a coordinate") {
    auto t = rod("  theta: rad\n", "  theta: rad\n  l: m\n");
    expect_error(t, at(t, "l: m\n"), "the name 'l' is used twice");
  }
  SECTION("a parameter without a value when a find asks for a unit") {
    auto t = rod("l: 1.2 m", "l: m");
    expect_error(t, at(t, "l: m"), "parameter 'l' has no value, but a number is asked for 'omega2'", "l: 2 m");
  }
  SECTION("a parameter without a value when an expect claims a value") {
    auto t = edit(rod("l: 1.2 m", "l: m"), ", unit: rad/s}", "}");
    expect_error(t, at(t, "l: m"), "parameter 'l' has no value, but a number is asked for 'omega2'");
  }
  SECTION("an angle parameter without a value: the example is an angle") {
    auto t = rod("theta2: 30 deg", "theta2: rad");
    expect_error(t, at(t, "theta2: rad"), "parameter 'theta2' has no value", "theta2: 30 deg");
  }
  SECTION("without a unit or a claimed value the closed form alone is fine") {
    auto t = edit(edit(rod("l: 1.2 m", "l: m"), ", unit: rad/s}", "}"), ", value: 3.50 rad/s}", "}");
    CHECK_FALSE(error_of(t).has_value());
  }
  SECTION("a parameter that is not a quantity") {
    auto t = rod("m: 5 kg", "m: [5, kg]");
    expect_error(t, at(t, "[5, kg]"), "'m' must be a single value, not a list");
  }
}

TEST_CASE("parameters: the range a parameter lies in, 'in: [lo, hi]'", "[errors][parameters]") {
  SECTION("a value inside its range solves") {
    expect_ok(rod("theta2: 30 deg", "theta2: {value: 30 deg, in: [10 deg, 80 deg]}"));
  }
  SECTION("a value outside its range, blamed where the value is written") {
    auto t = rod("theta2: 30 deg", "theta2: {value: 30 deg, in: [40 deg, 80 deg]}");
    expect_error(t, at(t, "30 deg,"), "parameter 'theta2' = 30 deg lies outside its range 'in: [40 deg, 80 deg]'", "inside the range");
  }
  SECTION("a map without 'value'") {
    auto t = rod("theta2: 30 deg", "theta2: {in: [40 deg, 80 deg]}");
    expect_error(t, at(t, "{in:"), "parameter 'theta2' has no 'value'", "value: deg");
  }
  SECTION("an unknown key beside 'value' and 'in'") {
    auto t = rod("theta2: 30 deg", "theta2: {value: 30 deg, range: [40 deg, 80 deg]}");
    expect_error(t, at(t, "range:"), "unknown key 'range' in parameter 'theta2'", "value, in");
  }
  SECTION("a range of three ends") {
    auto t = rod("theta2: 30 deg", "theta2: {value: 30 deg, in: [0, 40 deg, 80 deg]}");
    expect_error(t, at(t, "[0, 40"), "'in' must have 2 entries", "in: [0, 90 deg]");
  }
  SECTION("an end that is no number") {
    auto t = rod("theta2: 30 deg", "theta2: {value: 30 deg, in: [0, l]}");
    expect_error(t, at(t, "l]"), "the upper end of 'in' of parameter 'theta2' is not a number");
  }
  SECTION("an end of another dimension") {
    auto t = rod("l: 1.2 m", "l: {value: 1.2 m, in: [1 m, 2 s]}");
    expect_error(t, at(t, "2 s]"), "the upper end of 'in' of parameter 'l' is in s, and the parameter in m", "a unit of the parameter's kind (m)");
  }
  SECTION("an angle's end without its unit (180 would be 180 rad)") {
    auto t = rod("theta2: 30 deg", "theta2: {value: 30 deg, in: [0, 90]}");
    expect_error(t, at(t, "90]"), "the upper end of 'in' of angle 'theta2' has no unit", "90 deg");
  }
  SECTION("an empty range") {
    auto t = rod("theta2: 30 deg", "theta2: {value: 30 deg, in: [80 deg, 10 deg]}");
    expect_error(t, at(t, "[80 deg"), "must be a range [lo, hi] with lo < hi");
  }
  SECTION("an unknown takes no range: its root is chosen on its result") {
    auto t = rod("l: 1.2 m", "l: {value: unknown m, in: [1 m, 2 m]}");
    expect_error(t, at(t, "[1 m"), "'l' is an unknown", "root: {in: [lo, hi]}");
  }
}

TEST_CASE("non-positive masses and sizes are blamed where their value is written", "[errors][positive]") {
  SECTION("a negative mass parameter") {
    auto t = rod("m: 5 kg", "m: -5 kg");
    expect_error(t, at(t, "-5 kg"), "parameter 'm' is -5 kg, but it stands for the mass of 'rod', which must be zero or positive", "non-negative");
  }
  SECTION("a zero mass: a light body, but then nothing has mass and no motion is determined") {
    auto t = rod("m: 5 kg", "m: 0 kg");
    expect_error(t, at(t, "omega2: {value"), "'omega2' is not determined");
  }
  SECTION("a zero rod length") {
    auto t = rod("l: 1.2 m", "l: 0 m");
    expect_error(t, at(t, "0 m"), "parameter 'l' is 0 m, but it stands for the size 'l' of slender_rod", "positive");
  }
  SECTION("a mass expression that comes out negative") {
    auto t = rod("    mass: m\n", "    mass: m - 10*m\n");
    expect_error(t, at(t, "m - 10*m"), "the mass of 'rod' must be zero or positive, but it is -45");
  }
  SECTION("a mass that is not a real number") {
    auto t = rod("    mass: m\n", "    mass: m*sqrt(-1)\n");
    expect_error(t, at(t, "m*sqrt(-1)"), "not a real number");
  }
  SECTION("a negative spring free length") {
    auto t = block("  v1: 3 m/s\n", "  v1: 3 m/s\n  k: 5 N/m\n  L0: -1 m\n");
    t = edit(t, "gravity: {g: g}", "gravity: {g: g}\n  s: {spring: [block, O], k: k, free_length: L0}");
    t = edit(t, "coordinates:", "points:\n  O: [0, 0]\ncoordinates:");
    expect_error(t, at(t, "-1 m"), "free length, which must be zero or positive");
  }
}

TEST_CASE("effects: no kind, two kinds, a pin whose points do not coincide", "[errors][effects]") {
  SECTION("an effect with no kind") {
    auto t = rod("gravity: {g: g}", "gravity: {g: g}\n  pull: {M: m*g*l}");
    expect_error(t, at(t, "pull"), "effect 'pull' has no kind", "couple");
  }
  SECTION("an effect with two kinds") {
    auto t = rod("gravity: {g: g}", "gravity: {g: g}\n  drive: {couple: rod, force: rod.A, M: m*g*l}");
    expect_error(t, at(t, "force:"), "effect 'drive' names two kinds, 'couple' and 'force'", "split");
  }
  SECTION("an effect missing its option") {
    auto t = rod("gravity: {g: g}", "gravity: {g: g}\n  drive: {couple: rod}");
    expect_error(t, at(t, "drive"), "has no 'M'");
  }
  SECTION("a pin whose points do not coincide") {
    auto t = rod("gravity: {g: g}", "gravity: {g: g}\n  support: {pin: [O, rod.A]}");
    t = edit(t, "coordinates:", "points:\n  O: [0, 0]\ncoordinates:");
    expect_error(t, at(t, "[O, rod.A]"), "pin 'support': O and rod.A do not coincide");
  }
  SECTION("a force on a fixed point") {
    auto t = rod("gravity: {g: g}", "gravity: {g: g}\n  f: {force: O, F: [0, m*g]}");
    t = edit(t, "coordinates:", "points:\n  O: [0, 0]\ncoordinates:");
    expect_error(t, at(t, "O, F"), "a force acts on a body, but 'O' is a fixed point");
  }
  SECTION("friction whose direction nothing tells") {
    auto t = block("  v1: 3 m/s\n", "  v1: 3 m/s\n  mu: 0.2\n");
    t = edit(t, "gravity: {g: g}", "gravity: {g: g}\n  rub: {friction: block, mu: mu, normal: m*g*cos(beta)}");
    t = edit(edit(t, "1: {x: 0, x_dot: v1}", "1: {x: 0}"), "2: {x: 0.5 m}", "2: {x_dot: 0}");
    t = edit(t, "v2: {value: x_dot@2, root: positive, unit: m/s}", "d: {value: x@2, unit: m}");
    expect_error(t, at(t, "rub"), "the direction of the motion", "direction: positive|negative");
  }
}

TEST_CASE("find and expect: a claim that names no find, a claim of nothing, a bad root", "[errors][find]") {
  SECTION("an expect naming no find") {
    auto t = rod("expect:\n  omega2", "expect:\n  omega3");
    expect_error(t, at(t, "omega3"), "expect 'omega3' names no result under find", "did you mean 'omega2'?");
  }
  SECTION("an expect that claims nothing") {
    auto t = rod("omega2: {form: sqrt(3*g*sin(theta2)/l), value: 3.50 rad/s}", "omega2: {}");
    expect_error(t, at(t, "omega2: {}"), "claims nothing");
  }
  SECTION("a find without a value") {
    auto t = rod(kRodFind, "omega2: {root: positive, unit: rad/s}");
    expect_error(t, at(t, "omega2: {root"), "find 'omega2' has no 'value'");
  }
  SECTION("a root choice that is not one") {
    auto t = rod("root: positive", "root: up");
    expect_error(t, at(t, "up,"), "'root' must be positive, negative or {in: [lo, hi]}");
  }
  SECTION("a root range that holds no solution") {
    auto t = edit(rod("root: positive", "root: {in: [10, 20]}"), kRodExpect, "");
    expect_error(t, at(t, "omega2"), "no solution has 'omega2' with the root asked for", "-3.50179 or 3.50179");
  }
}

TEST_CASE("physics: unreachable states, contradictions, underdetermined and ambiguous results", "[errors][solve]") {
  SECTION("a block released from rest asked to rise (T2 would be negative)") {
    auto t = block("1: {x: 0, x_dot: v1}", "1: {x: 0, x_dot: 0}");
    expect_error(t, at(t, "energy"), "has no real solution for x_dot@2", "cannot be reached");
  }
  SECTION("a block sent up asked to rise higher than its speed allows") {
    auto t = block("2: {x: 0.5 m}", "2: {x: 1 m}");
    expect_error(t, at(t, "energy"), "x_dot@2^2 would be -0.81 (negative)", "kinetic energy would be negative");
  }
  SECTION("the rod asked to turn the wrong way from rest") {
    auto t = rod("2: {theta: theta2}", "2: {theta: -theta2}");
    expect_error(t, at(t, "energy"), "has no real solution for theta_dot@2");
  }
  SECTION("contradictory states: an energy balance that cannot hold") {
    auto t = block("2: {x: 0.5 m}", "2: {x: 0.5 m, x_dot: 3 m/s}");
    expect_error(t, at(t, "energy"), "the equations contradict each other", "cannot hold");
  }
  SECTION("a result that nothing determines") {
    auto t = rod_find("w3: theta_dot@3");
    t = edit(t, "  2: {theta: theta2}\n", "  2: {theta: theta2}\n  3: {}\n");
    expect_error(t, at(t, "w3"), "'w3' is not determined: theta_dot@3 is unknown", "give theta_dot@3");
    auto t2 = rod_find("t2: t@2");
    expect_error(t2, at(t2, "t2: t@2"), "'t2' is not determined: t@2 is unknown");
  }
  SECTION("too few values for the analysis") {
    auto t = rod("1: {theta: 0, theta_dot: 0}", "1: {theta: 0}");
    expect_error(t, at(t, "energy"), "nonlinear in several unknowns (theta_dot@1, theta_dot@2)", "give more values");
  }
  SECTION("ambiguous roots without root:") {
    auto t = rod_find("th2: theta@2");
    t = edit(t, "2: {theta: theta2}", "2: {theta_dot: 2 rad/s}");
    expect_error(t, at(t, "th2"), "'th2' has more than one solution", "root:");
  }
}

TEST_CASE("values undefined at the states are errors, not crashes", "[errors][undefined]") {
  SECTION("a result that divides by zero (was an internal error)") {
    auto t = rod_find("q: {value: 1/theta_dot@1}");
    expect_error(t, at(t, "q:"), "'q' is undefined at the states (a division by zero)");
    auto t2 = rod_find("q: 1/theta@1");
    expect_error(t2, at(t2, "q:"), "division by zero");
  }
  SECTION("log(0) and tan at a pole (were internal errors)") {
    auto t = rod_find("q: log(theta@1)");
    expect_error(t, at(t, "q:"), "log(0)");
    auto t2 = rod_find("q: tan(pi/2 + theta@1)");
    expect_error(t2, at(t2, "q:"), "a function at a pole");
  }
  SECTION("a result with no real value") {
    auto t = rod_find("q: acos(2 + theta@1)");
    expect_error(t, at(t, "q:"), "has no real value");
  }
  SECTION("undefined in the expression itself") {
    auto t = rod("    mass: m\n", "    mass: m*log(0)\n");
    expect_error(t, at(t, "log(0)"), "'log(0)' is undefined");
    auto t2 = rod("    mass: m\n", "    mass: m*0^(-1)\n");
    expect_error(t2, at(t2, "^("), "is undefined (division by zero)");
  }
  SECTION("a state value undefined for the parameters' values") {
    auto t = block("  v1: 3 m/s\n", "  v1: 3 m/s\n  one: 1 m\n");
    t = edit(t, "2: {x: 0.5 m}", "2: {x: one/(beta - pi/6)}");
    expect_error(t, at(t, "one/(beta"), "'x' at state '2' is undefined for the parameters' values");
    auto t2 = block("  v1: 3 m/s\n", "  v1: 3 m/s\n  one: 1 m\n");
    t2 = edit(t2, "2: {x: 0.5 m}", "2: {x: one*sqrt(-1)}");
    expect_error(t2, at(t2, "one*sqrt"), "is not a real number");
  }
  SECTION("a condition undefined at the state's values") {
    auto t = block("  v1: 3 m/s\n", "  v1: 3 m/s\n  one: 1 m\n  w: 1 rad/s\n");
    t = edit(t, "  1: {x: 0, x_dot: v1}\n", "  1: {x: 0, x_dot: v1}\n  0: {x: one, where: [\"x_dot/(x - one) = w\"]}\n");
    t = edit(t, "analyses:\n", "analyses:\n  - energy: {from: 0, to: 2}\n");
    expect_error(t, at(t, "x_dot/(x - one)"), "the condition at state 0 is undefined");
  }
}

TEST_CASE("pathological expressions end with an error, not a hang or a crash", "[errors][limits]") {
  SECTION("10^10^10 (was a hang, then a crash)") {
    auto t = rod("    mass: m\n", "    mass: m*10^10^10\n");
    expect_error(t, at(t, "^10^10"), "too large to compute exactly");
  }
  SECTION("a claimed form whose power of a product with a number has a huge exponent (was a hang, 1.6 GB)") {
    // GiNaC writes (12 l)^n as 12^n l^n: 12^(10^29) never returns; refused where it is written
    const std::string n = "123456789012345678901234567890";
    auto t = rod("form: sqrt(3*g*sin(theta2)/l)", "form: sqrt(3*g*sin(theta2)/l)*(12*l)^" + n + "/(12*l)^" + n);
    expect_error(t, at(t, "(12*l)^" + n + "/", 6), "a power here has the exponent 12345678901234567..., too large for exact arithmetic", "at most 100000");
    // a rational exponent too (GiNaC splits it into an integer power and a root)
    auto t2 = rod("form: sqrt(3*g*sin(theta2)/l)", "form: sqrt(3*g*sin(theta2)/l)*(2*l)^(" + n + "/2)");
    expect_error(t2, at(t2, "^(" + n), "too large for exact arithmetic");
  }
  SECTION("100000 nested parentheses (was a stack overflow)") {
    auto t = rod("    mass: m\n", "    mass: " + std::string(100000, '(') + "m" + std::string(100000, ')') + "\n");
    auto e = error_of(t);
    REQUIRE(e);
    CHECK(e->pos().line == 11);
    CHECK_THAT(e->problem(), Contains("nested too deeply"));
    check_form(*e, "bad.yaml");
  }
  SECTION("a unit in 100000 nested parentheses (was a stack overflow)") {
    auto t = rod("g: 9.81 m/s^2", "g: 9.81 " + std::string(100000, '(') + "m" + std::string(100000, ')'));
    auto e = error_of(t);
    REQUIRE(e);
    CHECK(e->pos().line == 5);
    check_form(*e, "bad.yaml");
  }
}

TEST_CASE("a file that does not exist, or is a directory", "[errors][files]") {
  std::string missing = bad_file("no_such_scene.yaml");
  try {
    kinergy::solve_file(missing);
    FAIL("a missing file was accepted");
  } catch (const kinergy::SceneError& e) {
    CHECK(e.pos().line == 1);
    CHECK(e.pos().col == 1);
    CHECK_THAT(e.problem(), Contains("does not exist"));
    check_form(e, missing);
  }
  std::string dir = std::string(KINERGY_SOURCE_DIR) + "/tests/data/bad";
  try {
    kinergy::solve_file(dir);
    FAIL("a directory was accepted");
  } catch (const kinergy::SceneError& e) {
    CHECK_THAT(e.problem(), Contains("directory"));
    check_form(e, dir);
  }
}

// ----------------------------------------------------------------- files in tests/data/bad/

namespace {
struct FileCase {
  const char* file;
  int line, col;
  const char* phrase;
};
const FileCase kFileCases[] = {
    {"bad_indentation.yaml", 12, 5, "indented deeper than line 11"},
    {"missing_space_after_colon.yaml", 11, 9, "no space after ':'"},
    {"unclosed_bracket.yaml", 13, 15, "unclosed '['"},
    {"tab_indentation.yaml", 11, 1, "a tab in the indentation"},
    {"unclosed_quote.yaml", 11, 11, "never closed"},
    {"two_documents.yaml", 28, 1, "more than one YAML document"},
    {"empty.yaml", 1, 1, "the scene is empty"},
    {"unit_exponent_overflow.yaml", 5, 15, "exponent '99999999999' of a unit is too large"},
    {"huge_power.yaml", 11, 15, "too large to compute exactly"},
    {"log_of_zero.yaml", 24, 3, "'q' is undefined at the states (log(0))"},
    {"division_by_zero.yaml", 24, 3, "'q' is undefined at the states (a division by zero)"},
    {"rise_too_high.yaml", 19, 5, "has no real solution for x_dot@2"},
    {"unknown_unit.yaml", 5, 13, "unknown unit 'sec'"},
    {"did_you_mean_key.yaml", 14, 5, "unknown key 'angel' in body 'rod'"},
};
}  // namespace

TEST_CASE("bad scene files: the library names the place", "[errors][files]") {
  for (auto& c : kFileCases) {
    DYNAMIC_SECTION(c.file) {
      std::string path = bad_file(c.file);
      REQUIRE(fs::exists(path));
      try {
        kinergy::solve_file(path);
        FAIL("the scene was accepted");
      } catch (const kinergy::SceneError& e) {
        INFO(e.what());
        CHECK(e.pos().file == path);
        CHECK(e.pos().line == c.line);
        CHECK(e.pos().col == c.col);
        CHECK_THAT(e.problem(), Contains(c.phrase));
        check_form(e, path);
      }
    }
  }
}

TEST_CASE("bad scene files: the command line prints one line and exits 1", "[errors][cli]") {
  for (auto& c : kFileCases) {
    DYNAMIC_SECTION(c.file) {
      std::string path = bad_file(c.file);
      Run r = cli("solve \"" + path + "\"");
      INFO("stderr: " << r.err);
      CHECK(r.status == 1);
      CHECK(r.out.empty());
      CHECK(lines_of(r.err) == 1);
      CHECK(r.err.back() == '\n');
      std::string prefix = path + ":" + std::to_string(c.line) + ":" + std::to_string(c.col) + ": ";
      CHECK(r.err.rfind(prefix, 0) == 0);
      CHECK_THAT(r.err, Contains(c.phrase));
      CHECK(r.err.find(kDash) != std::string::npos);
      CHECK(r.err.size() > r.err.find(kDash) + kDash.size() + 1);  // a fix follows the dash
      CHECK_FALSE(looks_broken(r.err));
    }
  }
}

// Scenes that once gave a physically impossible answer with exit 0, hung, ate memory or printed an
// unreadable message: the whole line is asserted.
namespace {
struct ExactCase {
  const char* file;
  const char* where;  ///< LINE:COL
  const char* message;
};
const ExactCase kExact[] = {
    // a motor couple smaller than the bearing's friction couple cannot bring the wheel up to speed
    {"negative_duration.yaml", "14:5",
     "the angular_momentum analysis from state '1' to '2' needs t@2 - t@1 = -12 s: state '2' would come before state '1' "
     "(the effects between them act against the change asked for) \u2014 check the sizes and directions of the effects, "
     "or what is given at state '2'"},
    // ½ I (ω₂² − ω₁²) = P t₂ < 0 with P > 0
    {"power_drive_backwards.yaml", "12:5",
     "the energy analysis from state '1' to '2' needs t@2 - t@1 = -60 s: state '2' would come before state '1' "
     "(the effects between them act against the change asked for) \u2014 check the sizes and directions of the effects, "
     "or what is given at state '2'"},
    {"time_backwards.yaml", "12:10",
     "state '2' is at t = 2 s, before state '1' (t = 5 s), but the angular_momentum analysis goes from '1' to '2' "
     "\u2014 give state '2' a later time, or swap 'from' and 'to'"},
    // reported through the contact impulse J_floor^2 < 0 before
    {"floor_out_of_reach.yaml", "29:5",
     "the conservation of energy, states 1 -> before has no real solution: the motion cannot reach that state with these "
     "values (its kinetic energy would be negative, and the impulse J_floor[before,after] that depends on it imaginary) "
     "\u2014 check the states and parameters: the energy given at the start is not enough"},
    // distances beyond the range of doubles: an internal error (CLN's overflow) and a check that passed
    {"pin_far_away.yaml", "8:14",
     "pin 'pin': O and bar.O do not coincide (apart by 1e400 m at some position) \u2014 fix the body's position/angle or "
     "the point so the pinned points stay together"},
    {"contact_far_away.yaml", "33:3",
     "contact 'hit': bullet and bar.Q are 1e400 m apart at state 'before', so they cannot strike each other there \u2014 "
     "give positions at 'before' that bring the two points together"},
    // an exponent that is a number only once the state's values are in (x@1 = 1 m)
    {"exponent_from_state.yaml", "9:14",
     "a power here has the exponent 1000000000, too large for exact arithmetic \u2014 check the exponent: at "
     "most 100000 in size (no physical quantity needs more)"},
    // cos of an angle of 1e18009 rad: no working precision up to 20000 digits holds it (was "(? or ?)")
    {"angle_beyond_precision.yaml", "31:3",
     "'omega2' cannot be evaluated (to choose among its solutions): it holds the sine or cosine of an angle too "
     "large for 20000 digits of working precision \u2014 give the angle reduced to one turn (below 360 deg or 2*pi rad)"},
    // yaml-cpp 0.7's LoadAll loops for ever on these, its memory growing
    {"comma_first.yaml", "1:1",
     "YAML syntax error: a ',' outside [ ] and { }, where a value should start \u2014 remove it, or quote the text it "
     "belongs to: a comma separates the entries of a list in [ ] or of a map in { }"},
    // found by the fuzzer: the comma need not be at the start of the line
    {"comma_indented.yaml", "2:2",
     "YAML syntax error: a ',' outside [ ] and { }, where a value should start \u2014 remove it, or quote the text it "
     "belongs to: a comma separates the entries of a list in [ ] or of a map in { }"},
    {"comma_after_flow.yaml", "3:1",
     "YAML syntax error: a ',' outside [ ] and { }, where a value should start \u2014 remove it, or quote the text it "
     "belongs to: a comma separates the entries of a list in [ ] or of a map in { }"},
    // yaml-cpp's documents are counted one at a time first: its LoadAll would never end on the loop
    {"many_documents.yaml", "65:1",
     "YAML syntax error: the text from here reads as document after document (more than 64) \u2014 a scene is one "
     "document: remove what starts here, or quote it (a ',' separates entries only inside [ ] and { })"},
    // 16 levels of nine aliases each stand for 9^17 values
    {"alias_bomb.yaml", "2:19",
     "the scene holds more than 100000 YAML values (aliases '*name' repeat the value they name) \u2014 write the scene "
     "without nested aliases: a scene needs a few hundred values"},
    {"deep_nesting.yaml", "2:77",
     "the scene nests lists and maps more than 64 deep \u2014 a scene nests a few levels: close the lists and maps opened above"},
    {"long_name.yaml", "3:3",
     "the parameter name 'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\u2026 (500 characters)' is 500 characters long, more "
     "than 64 \u2014 use a shorter name"},
    {"long_token.yaml", "5:13",
     "unknown name 'mmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmm\u2026 (5000 characters)' \u2014 define it under parameters or "
     "coordinates"},
    {"nul_byte.yaml", "1:9",
     "the file holds a NUL byte: it is not a text file \u2014 save the scene as plain text (UTF-8)"},
    // 0.5^1000000000 in exact arithmetic has a billion-bit denominator
    {"huge_power_parameter.yaml", "9:14",
     "a power here has the exponent 1000000000, too large for exact arithmetic \u2014 check the exponent: at most 100000 "
     "in size (no physical quantity needs more)"},
    // the incline's normal force has an x component: without it, momentum along x gave v = 0
    {"momentum_across_track.yaml", "23:5",
     "the bodies of this momentum analysis (all bodies) cannot move freely along x: a support the scene does not declare "
     "(a track, a surface, an axle) pushes on them along x with a force the analysis does not know \u2014 take the momentum "
     "along a direction in which they move freely (along their track), or declare the support (a pin, a track) so "
     "that its reaction is an unknown"},
    {"moment_of_undeclared_support.yaml", "25:5",
     "the bodies of this angular momentum analysis (all bodies) cannot turn freely about O: a support the scene does not "
     "declare (a track, a surface, an axle) has a moment about O the analysis does not know \u2014 take moments about a "
     "point they turn about freely (a pivot, a contact point on the ground, their mass centre), or declare the support "
     "(a pin, a track) so that its reaction is an unknown"},
    // a rolling relation held at the mass centre: no force there does the relation's virtual work
    {"constraint_wrong_place.yaml", "19:51",
     "constraint 'rolling': no force between disk at [x*cos(beta) + r*sin(beta), -x*sin(beta) + r*cos(beta)] and ground "
     "holds 'x + r*phi = 0' (along phi its work does not match the relation) \u2014 give in 'at' the place where the parts "
     "touch (the pitch point of a mesh, the contact point of a rolling body, where a cord leaves a drum)"},
    {"constraint_twice.yaml", "28:23",
     "the relation 'rA*phiA + rB*phiB = 0' is already the constraint on line 22 \u2014 write it once: remove it from "
     "'constraints:' when an effect holds it (its reaction can then be asked for)"},
    {"constraint_no_relative_motion.yaml", "26:56",
     "constraint 'mesh': gearA and OA never move relative to each other, so no force between them holds "
     "'rA*phiA + rB*phiB = 0' \u2014 name in 'between' (and 'at') the two parts whose contact keeps the relation"},
    {"rtol_out_of_range.yaml", "25:47",
     "'rtol' must be a relative difference from 0 to 1, not '2' \u2014 write e.g. 'rtol: 0.005' (half a percent)"},
    {"rtol_without_value.yaml", "25:32",
     "'rtol' loosens a claimed value, and 'y3' claims none \u2014 add 'value: NUMBER UNIT', or remove 'rtol'"},
    // a rod whose angle puts its end off its slot used to give a silently wrong answer
    {"track_off_slot.yaml", "17:18",
     "track 'slotA': rod.A is 1.15306 m off the line through [0, 0] along [1, 0] at theta = 1.851 \u2014 fix the body's "
     "position/angle or the point so that rod.A stays on its track for every value of the coordinates"},
    // with constraints the coordinates are not free: checked at the solved states
    {"track_off_at_state.yaml", "16:3",
     "track 'ice_line': disk is 0.2 m off the line through [0, 2*r] along [1, 0] at state '1' \u2014 fix the body's "
     "position/angle, the point or the track so that disk stays on it"},
    {"switch_unknown_state.yaml", "16:37", "effect 'motor': no state named '4' \u2014 name one of the states: 1, 2, 3"},
    {"switch_off_before_on.yaml", "16:44",
     "effect 'motor' is switched off at state '1', not after it is switched on (state '2'); states are in the order they "
     "are listed \u2014 switch it off at a later state, or list the states in the order they happen"},
    {"switch_inside_momentum.yaml", "22:5",
     "effect 'motor' is switched off at state '2', inside this angular_momentum analysis: its impulse covers only part of "
     "the interval \u2014 split the analysis at state '2' (one from '1' to '2', one from there to '3')"},
    {"friction_against_itself.yaml", "16:39",
     "friction 'rubbing' acts against the body it slides with \u2014 name the other body it slides on"},
    {"friction_across_set_changing_line.yaml", "15:3",
     "friction 'rubbing' acts between a body of this energy analysis and one outside it, and its work on block cannot be taken: its "
     "slip is not along a fixed line, or the distance moved along it is not a function of the coordinates \u2014 analyse both "
     "bodies together, or use an impulse-momentum analysis of the one"},
    {"pin_across_moving_point.yaml", "32:5",
     "pin 'middle' joins a body of this energy analysis to one outside it, and the pinned point does not keep to a fixed line "
     "(x or y): the work of its reaction is not one unknown force times a distance \u2014 list both bodies it joins in 'bodies', "
     "or take its reaction from an impulse-momentum analysis of the body"},
    // a round body touching a surface: its centre keeps to the track at the offset (-r inside a bowl)
    {"track_offset_wrong_side.yaml", "31:3",
     "track 'bowl': ball is 0.2 m off the circle of centre [0, 0] and radius R at distance r at state '1' \u2014 fix the body's "
     "position/angle, the point or the track so that ball stays on it"},
    {"track_offset_no_circle.yaml", "31:68",
     "track 'bowl': the offset -R leaves no circle for the point (R + offset = 0 m) \u2014 a ball of radius r inside a bowl of "
     "radius R has offset -r with r < R"},
    // pushed from rest into a bumper: no rate tells the direction of the motion (an unknown end
    // with a known direction is taken past the switching points: two_stage_bumper_max)
    {"force_max_end_unknown.yaml", "12:3",
     "the force of 'bumper' switches along the path (it has abs, max or min), and x is not known at state '2', nor the "
     "direction of the motion, so its work cannot be split where it switches \u2014 give x at that state, or a nonzero "
     "x_dot at a state"},
};
}  // namespace

TEST_CASE("bad input: the whole one-line error, from the library and the command line", "[errors][files]") {
  for (auto& c : kExact) {
    DYNAMIC_SECTION(c.file) {
      std::string path = bad_file(c.file);
      std::string want = path + ":" + c.where + ": " + c.message;
      try {
        kinergy::solve_file(path);
        FAIL("the scene was accepted");
      } catch (const kinergy::SceneError& e) {
        CHECK(std::string(e.what()) == want);
        check_form(e, path);
      }
      Run r = cli("solve \"" + path + "\"");
      CHECK(r.status == 1);
      CHECK(r.out.empty());
      CHECK(r.err == want + "\n");
    }
  }
}

TEST_CASE("solve and derive refuse a scene that asks for nothing", "[errors][cli]") {
  std::string path = bad_file("asks_nothing.yaml");
  for (std::string cmd : {"solve", "derive"}) {
    INFO(cmd);
    Run r = cli(cmd + " \"" + path + "\"");
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(r.err == path + ":1:1: the scene asks for nothing: it has no 'find' \u2014 add a 'find:' section naming the results "
                          "you want, e.g. 'find: {omega2: theta_dot@2}'\n");
  }
}

TEST_CASE("the guard against yaml-cpp's comma loop refuses only commas where a value starts", "[errors][yaml]") {
  // valid YAML that holds commas outside [ ] and { }: accepted
  for (std::string title : {"title: Pendulum [Beer 17.3], SI units\n", "title: Disk {A}, rolling\n", "title: Why?, a test\n",
                            "title: a rod\n  , continued on a line of its own\n", "title: 'quoted, with a comma'\n"}) {
    INFO(title);
    expect_ok(edit(kRod, "title: Rod sliding on two tracks\n", title));
  }
  expect_ok(edit(kRod, "title: Rod sliding on two tracks\n", "title: x\ndescription: &d >\n  , a text that starts with a comma\n"));
  // where yaml-cpp 0.7 would loop for ever: refused, at the comma
  struct Case {
    std::string text;
    int line, col;
  };
  for (const Case& c : {Case{"&x ,\n", 1, 4}, Case{"!t ,\n", 1, 4}, Case{"--- ,\n", 1, 5}, Case{"title: it is x:\"y\n---\n,\n", 3, 1},
                        Case{"{a: 1}, b\n", 1, 7}, Case{"[a, b]\n,\n", 2, 1},
                        // at any indentation, after blank lines, comments, directives or a document's end, and after
                        // one whole value in brackets or quotes
                        Case{" ,a\n", 1, 2}, Case{"\t,a\n", 1, 2}, Case{"\n ,erev\n", 2, 2}, Case{"# c\n  ,a\n", 2, 3},
                        Case{" &x ,a\n", 1, 5}, Case{"  [1]\n ,a\n", 2, 2}, Case{" {a: 1} ,b\n", 1, 9},
                        Case{" \"x\" ,a\n", 1, 6}, Case{"'x'\n,a\n", 2, 1}, Case{"title: x\n---\n ,b\n", 3, 2},
                        Case{"title: x\n...\n ,b\n", 3, 2}, Case{"%YAML 1.2\n---\n ,a\n", 3, 2},
                        Case{"--- [1]\n--- ,a\n", 2, 5},
                        // an anchor's or a tag's name ends at a ',' (found by the fuzzer: "&a/2, a/.")
                        Case{"&a/2, a/.\n", 1, 5}, Case{"&a,b\n", 1, 3}, Case{"!t,b\n", 1, 3}, Case{"!a!b:c,d\n", 1, 7},
                        // on a line that opens a block scalar (found by the fuzzer)
                        Case{"title: x\n,description: >\n  text\n", 2, 1},
                        // yaml-cpp takes a quote, bracket, anchor or tag right after a whole value for the start
                        // of another document (found by the fuzzer: a line of '"')
                        Case{"\"\"\"\",\n", 1, 5}, Case{"\"a\" \"b\" ,\n", 1, 9}, Case{"[1][2],\n", 1, 7},
                        Case{"'a'\"b\",\n", 1, 7}, Case{"\"a\"&x ,\n", 1, 7}, Case{"{a: 1}\"x\",\n", 1, 10}}) {
    INFO(c.text);
    auto e = error_of(c.text);
    REQUIRE(e.has_value());
    CHECK(e->pos().line == c.line);
    CHECK(e->pos().col == c.col);
    CHECK_THAT(e->problem(), Contains("a ',' outside [ ] and { }, where a value should start"));
  }
}

TEST_CASE("a scene larger than 1 MiB is refused before it is parsed", "[errors][files]") {
  std::string text = "title: a long description\ndescription: " + std::string(2 << 20, 'a') + "\n";
  auto e = error_of(text);
  REQUIRE(e.has_value());
  CHECK(std::string(e->what()) ==
        "bad.yaml:1:1: the scene is 2097192 bytes long, more than the 1048576 a scene may have \u2014 check that this is a "
        "scene file; a scene is a few kilobytes");
}

TEST_CASE("the command line: verify of a bad scene, a missing file", "[errors][cli]") {
  SECTION("verify: one line per bad scene, exit 1") {
    Run r = cli("verify \"" + bad_file("unclosed_bracket.yaml") + "\"");
    INFO("stderr: " << r.err);
    CHECK(r.status == 1);
    CHECK(lines_of(r.err) == 1);
    CHECK_THAT(r.err, Contains("unclosed '['"));
    CHECK_FALSE(looks_broken(r.err));
  }
  SECTION("a missing file") {
    std::string missing = bad_file("no_such_scene.yaml");
    Run r = cli("solve \"" + missing + "\"");
    INFO("stderr: " << r.err);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(lines_of(r.err) == 1);
    CHECK(r.err.rfind(missing + ":1:1: ", 0) == 0);
    CHECK_THAT(r.err, Contains("does not exist"));
    CHECK_FALSE(looks_broken(r.err));
  }
}

TEST_CASE("the command line: usage errors exit 2", "[errors][cli]") {
  std::string good = std::string(KINERGY_SOURCE_DIR) + "/derivations/energy/sliding_rod.yaml";
  SECTION("no subcommand") {
    Run r = cli("");
    CHECK(r.status == 2);
    CHECK(!r.err.empty());
  }
  SECTION("an unknown option") {
    Run r = cli("solve \"" + good + "\" --bogus");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Contains("--bogus"));
  }
  SECTION("--digits 0") {
    Run r = cli("solve \"" + good + "\" --digits 0");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Contains("--digits"));
    CHECK(r.out.empty());
  }
  SECTION("solve without a scene") {
    Run r = cli("solve");
    CHECK(r.status == 2);
  }
  SECTION("and a good scene still exits 0") {
    Run r = cli("solve \"" + good + "\"");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
  }
}

TEST_CASE("inputs the fuzzer found (each once a hang in yaml-cpp) end with one line, at once", "[errors][fuzz]") {
  // tests/fuzz/regressions: every input that once crashed, leaked or hung, kept as the fuzzer
  // wrote it; each must be refused with one line and exit 1 (the `timeout` turns a hang into 124)
  int n = 0;
  for (auto& e : fs::directory_iterator(fs::path(KINERGY_SOURCE_DIR) / "tests" / "fuzz" / "regressions")) {
    ++n;
    std::string path = e.path().string();
    INFO(path);
    Run r = cli("solve \"" + path + "\"", "timeout 60 ");
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.rfind(path + ":", 0) == 0);
  }
  CHECK(n >= 9);
}

TEST_CASE("drawn_as: a circle or a rectangle of lengths, for a body whose inertia has no outline", "[errors][draw]") {
  // the block with a length R to draw it by
  auto ball = [](const std::string& drawn) {
    return edit(block("    inertia: particle\n", "    inertia: particle\n" + drawn), "  v1: 3 m/s\n", "  v1: 3 m/s\n  R: 0.1 m\n");
  };
  CHECK_FALSE(error_of(ball("    drawn_as: {circle: R}\n")));
  CHECK_FALSE(error_of(ball("    drawn_as: {rectangle: [2*R, R]}\n")));
  auto t = ball("    drawn_as: {triangle: R}\n");
  expect_error(t, at(t, "{triangle"), "'drawn_as' names one outline: a circle or a rectangle", "drawn_as: {circle: R}");
  auto t2 = ball("    drawn_as: {circle: beta}\n");
  expect_error(t2, at(t2, "beta}"), "'drawn_as' is a pure number (or an angle) but must be in m", "a drawn size is a length");
  auto t3 = ball("    drawn_as: {circle: -R}\n");
  expect_error(t3, at(t3, "-R}"), "the size '-R' of circle");
  auto t4 = ball("    drawn_as: {rectangle: R}\n");
  expect_error(t4, at(t4, "R}\n"), "rectangle");
  auto t5 = ball("    drawn_as: circle\n");
  expect_error(t5, at(t5, "circle\n"), "'drawn_as' names one outline");
  // a rod is drawn as a rod: refused at its line
  auto t6 = rod("    inertia: {slender_rod: l}\n", "    inertia: {slender_rod: l}\n    drawn_as: {circle: l}\n");
  expect_error(t6, at(t6, "circle"), "body 'rod' is drawn as its shape (slender_rod), so 'drawn_as' would draw something else",
               "remove 'drawn_as'");
}
