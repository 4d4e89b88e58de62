// Honour or refuse (issue 25): every option of every effect kind, in every kind of analysis it can
// meet, is either honoured — the scene solves and each analysis is confirmed by a simulation of
// the same scene, so the principle and the simulator read the option alike — or refused at its
// line with a clear message. The table below says which, row by row; a kind or an option the
// table does not have fails the completeness check, so a new one cannot be half-honoured.
// The contexts: `energy` (a block on a line coupled to a wheel, one degree of freedom, from
// state 1 to 2 and 2 to 3; `timed`: the same between given times, for a power drive), `momentum` (the block alone over a duration), `angular` (the wheel
// alone about its fixed centre over a duration), `impact` (the block striking a fixed stop),
// `across` (energy from 1 to 3 with the effect switched at 2), `least` (the least speed at state
// 1 for which state 2 is reached) and `extreme` (the greatest kinetic energy over the positions of
// state 2).
#include <catch2/catch.hpp>

#include <map>
#include <regex>
#include <set>

#include "../support/helpers.hpp"
#include "../support/scene_errors.hpp"
#include "kinergy/confirm/confirm.hpp"
#include "kinergy/model/analysis.hpp"
#include "kinergy/model/effect.hpp"

namespace {

struct Row {
  std::string kind, option;  ///< option: a key of the kind, or "" for the kind with its required keys alone
  std::string context;       ///< energy, momentum, angular, impact, across
  std::string effect;        ///< the effect's entry under `effects:` (named `e`)
  bool honoured;             ///< else refused
  /// refused: part of the message; honoured: "" (every analysis confirmed by simulation), or
  /// "residuals" where a simulation cannot stand for every analysis (a switch inside one; a state
  /// between given times whose position energy does not fix; a stick row the block's one line
  /// already holds): each confirmed, the first way that applies
  std::string phrase;
};

// clang-format off
const std::vector<Row> kTable = {
  // gravity: along x (direction), so that it works on the block's line
  {"gravity", "", "energy", "e: {gravity: g}", true, ""},
  {"gravity", "g", "momentum", "e: {gravity: g, direction: [1, 0]}", true, ""},
  {"gravity", "direction", "energy", "e: {gravity: g, direction: [1, 0]}", true, ""},
  {"gravity", "direction", "angular", "e: {gravity: g, direction: [1, 0]}", true, ""},
  {"gravity", "direction", "impact", "e: {gravity: g, direction: [1, 0]}", true, ""},
  // spring from the block to the fixed point A
  {"spring", "k", "energy", "e: {spring: [block, A], k: k, free_length: a/2}", true, ""},
  {"spring", "free_length", "energy", "e: {spring: [block, A], k: k, free_length: 3*a/2}", true, ""},
  {"spring", "acts", "energy", "e: {spring: [block, A], k: k, free_length: a/2, acts: tension}", true, ""},
  {"spring", "k", "momentum", "e: {spring: [block, A], k: k, free_length: a/2}", false, "pushes with a force that changes with the motion"},
  {"spring", "k", "impact", "e: {spring: [block, A], k: k, free_length: a/2}", true, ""},
  {"torsion_spring", "k", "energy", "e: {torsion_spring: wheel, k: kt}", true, ""},
  {"torsion_spring", "free_angle", "energy", "e: {torsion_spring: wheel, k: kt, free_angle: 0.3}", true, ""},
  {"torsion_spring", "k", "angular", "e: {torsion_spring: wheel, k: kt}", false, "turns with a couple that changes with the motion"},
  {"damper", "c", "energy", "e: {damper: [block, A], c: c}", false, "depends on the speeds"},
  {"damper", "c", "momentum", "e: {damper: [block, A], c: c}", false, "pushes with a force that changes with the motion"},
  {"torsion_damper", "c", "energy", "e: {torsion_damper: wheel, c: ct}", false, "depends on the speeds"},
  {"torsion_damper", "c", "angular", "e: {torsion_damper: wheel, c: ct}", false, "turns with a couple that changes with the motion"},
  {"couple", "M", "energy", "e: {couple: wheel, M: M0}", true, ""},
  {"couple", "M", "angular", "e: {couple: wheel, M: M0}", true, ""},
  {"couple", "M", "impact", "e: {couple: wheel, M: M0}", true, ""},
  {"couple", "against", "energy", "e: {couple: wheel, M: M0, against: block}", true, ""},
  {"couple", "against", "energy", "e: {couple: wheel, M: M0, against: wheel}", false, "acts against the body it turns"},
  {"force", "F", "energy", "e: {force: block, F: [F0, 0]}", true, ""},
  {"force", "F", "momentum", "e: {force: block, F: [F0, 0]}", true, ""},
  {"force", "at", "energy", "e: {force: wheel, at: [r, h], F: [0, -F0]}", true, ""},
  {"force", "at", "angular", "e: {force: wheel, at: [r, h], F: [0, -F0]}", true, ""},
  {"friction", "mu", "energy", "e: {friction: block, mu: mu, normal: m*g}", true, ""},
  {"friction", "normal", "momentum", "e: {friction: block, mu: mu, normal: m*g}", true, ""},
  {"friction", "at", "momentum", "e: {friction: block, at: [x, 0], mu: mu, normal: m*g}", true, ""},
  {"friction", "direction", "energy", "e: {friction: block, mu: mu, normal: m*g, direction: negative}", false, "declares 'direction: negative'"},
  {"friction", "direction", "momentum", "e: {friction: block, mu: mu, normal: m*g, direction: negative}", false, "declares 'direction: negative'"},
  {"friction", "against", "energy", "e: {friction: block, mu: mu, normal: m*g, against: wheel}", false, "has no closed form along x"},
  {"friction_couple", "M", "energy", "e: {friction_couple: wheel, M: M0/10}", true, ""},
  {"friction_couple", "M", "angular", "e: {friction_couple: wheel, M: M0/10}", true, ""},
  {"friction_couple", "against", "energy", "e: {friction_couple: wheel, M: M0/10, against: block}", true, ""},
  {"friction_couple", "against", "angular", "e: {friction_couple: wheel, M: M0/10, against: wheel}", false, "acts against the body it turns"},
  {"friction_couple", "direction", "angular", "e: {friction_couple: wheel, M: M0/10, direction: negative}", false, "declares 'direction: negative'"},
  {"power", "P", "timed", "e: {power: wheel, P: P0}", true, "residuals"},
  {"power", "P", "angular", "e: {power: wheel, P: P0}", false, "turns with a couple that changes with the motion"},
  {"pin", "", "energy", "e: {pin: [C, wheel]}", true, ""},
  {"pin", "", "angular", "e: {pin: [C, wheel]}", true, ""},
  {"contact", "normal", "impact", "e: {contact: [W, block], normal: [1, 0], e: 0.5}", true, ""},
  {"contact", "e", "impact", "e: {contact: [W, block], normal: [1, 0], e: 1}", true, ""},
  {"contact", "tangential", "impact", "e: {contact: [W, block], normal: [1, 0], e: 0.5, tangential: stick}", true, "residuals"},
  {"contact", "e", "energy", "e: {contact: [W, block], normal: [1, 0], e: 0.5}", true, ""},
  {"contact", "lodges", "impact", "e: {contact: [W, block], normal: [1, 0], lodges: true}", true, "residuals"},
  {"contact", "lodges", "impact", "e: {contact: [W, block], normal: [1, 0], lodges: true, e: 0}", false, "'e' is not written beside it"},
  {"impulse", "J", "impact", "e: {impulse: block, J: [-J0, 0]}", true, ""},
  {"impulse", "J", "momentum", "e: {impulse: block, J: [J0, 0]}", true, ""},
  {"cord_pull", "P", "energy", "e: {cord_pull: [block, A], P: F0}", true, ""},
  {"cord_pull", "P", "momentum", "e: {cord_pull: [block, A], P: F0}", true, ""},
  {"constraint", "between", "energy", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]]}", true, ""},
  {"constraint", "at", "energy", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]]}", true, ""},
  // static friction: the block on its rail, pushed, drives the wheel on its hub (F = m a/2 = F0/3, N = m g)
  {"constraint", "mu_s", "energy", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]], mu_s: mu, normal: rail}\n"
                                   "  rail: {track: block, line: {through: [0, 0], along: [1, 0]}, pushes: up}\n  w: {gravity: g}\n  p: {force: block, F: [F0, 0]}\n  hub: {pin: [C, wheel]}", true, ""},
  {"constraint", "normal", "energy", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]], mu_s: mu/10, normal: rail}\n"
                                     "  rail: {track: block, line: {through: [0, 0], along: [1, 0]}, pushes: up}\n  w: {gravity: g}\n  p: {force: block, F: [F0, 0]}\n  hub: {pin: [C, wheel]}", false, "'e' slips at state '1'"},
  // mu_k: the friction once it slips (only a simulation goes past a slip): read with mu_s, refused without it
  {"constraint", "mu_k", "energy", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]], mu_s: mu, normal: rail, mu_k: mu/2}\n"
                                   "  rail: {track: block, line: {through: [0, 0], along: [1, 0]}, pushes: up}\n  w: {gravity: g}\n  p: {force: block, F: [F0, 0]}\n  hub: {pin: [C, wheel]}", true, ""},
  {"constraint", "mu_k", "energy", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]], mu_k: mu}", false, "nothing says when it slips"},
  {"constraint", "mu_s", "impact", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]], mu_s: mu, normal: rail}\n"
                                   "  rail: {track: block, line: {through: [0, 0], along: [1, 0]}, pushes: up}", false, "where kinergy does not check static friction"},
  {"track", "line", "energy", "e: {track: block, line: {through: [0, 0], along: [1, 0]}, pushes: up}", true, ""},
  {"track", "circle", "energy", "e: {track: block, circle: {centre: [0, 0], radius: R}, holds: both}", false, "off the circle"},
  {"track", "offset", "energy", "e: {track: block, line: {through: [0, -r/5], along: [1, 0]}, offset: r/5}", true, ""},
  {"track", "line", "momentum", "e: {track: block, line: {through: [0, 0], along: [1, 0]}, holds: both}", true, ""},
  // one-sided or both ways: a surface pushing the block up while a field lifts it would have to
  // pull (refused, at the state and over the duration); a guide holds it either way
  {"track", "pushes", "energy", "e: {track: block, line: {through: [0, 0], along: [1, 0]}, pushes: up}\n  w: {gravity: g}", true, ""},
  {"track", "pushes", "momentum", "e: {track: block, line: {through: [0, 0], along: [1, 0]}, pushes: up}\n  w: {gravity: g, direction: [0, 1]}", false, "would have to pull"},
  // e: how a body that has left the surface strikes it again (only a simulation has that): read
  // where the surface pushes, refused on a guide, which no body leaves
  {"track", "e", "energy", "e: {track: block, line: {through: [0, 0], along: [1, 0]}, pushes: up, e: 0.5}\n  w: {gravity: g, direction: [0, -1]}", true, ""},
  {"track", "e", "momentum", "e: {track: block, line: {through: [0, 0], along: [1, 0]}, holds: both, e: 0.5}", false, "a body never leaves it"},
  // a cord from O to the wheel's centre, which the coordinates keep at its length h: it holds, and
  // pulls no more than nothing holds it against (N = 0 >= 0); the wrong length is off its circle
  {"cord", "", "energy", "e: {cord: [O, wheel], length: h}", true, ""},
  {"cord", "length", "energy", "e: {cord: [O, wheel], length: h/2}", false, "off the circle"},
  {"cord", "e", "energy", "e: {cord: [O, wheel], length: h, e: 0}", true, ""},
  {"cord", "on", "energy", "e: {cord: [O, wheel], length: h, on: 2}", true, ""},
  {"cord", "off", "energy", "e: {cord: [O, wheel], length: h, off: 1}", true, ""},
  {"track", "holds", "momentum", "e: {track: block, line: {through: [0, 0], along: [1, 0]}, holds: both}\n  w: {gravity: g, direction: [0, 1]}", true, ""},
  // on and off, every kind's: switched where the analysis does not reach it, the effect is not
  // there (the simulation runs without it too); switched inside an energy analysis, its work is
  // taken over its part (no one simulation stands for that: residuals); inside a momentum
  // analysis, refused
  {"gravity", "off", "energy", "e: {gravity: g, direction: [1, 0], off: 2}", true, ""},
  {"gravity", "on", "energy", "e: {gravity: g, direction: [1, 0], on: 2}", true, ""},
  {"gravity", "off", "across", "e: {gravity: g, direction: [1, 0], off: 2}", true, "residuals"},
  {"spring", "off", "energy", "e: {spring: [block, A], k: k, free_length: a/2, off: 2}", true, ""},
  {"spring", "on", "across", "e: {spring: [block, A], k: k, free_length: a/2, on: 2}", true, "residuals"},
  {"torsion_spring", "off", "energy", "e: {torsion_spring: wheel, k: kt, off: 2}", true, ""},
  {"damper", "off", "energy", "e: {damper: [block, A], c: c, off: 1}", true, ""},
  {"torsion_damper", "on", "energy", "e: {torsion_damper: wheel, c: ct, on: 3}", true, ""},
  {"couple", "off", "energy", "e: {couple: wheel, M: M0, off: 2}", true, ""},
  {"couple", "on", "across", "e: {couple: wheel, M: M0, on: 2}", true, "residuals"},
  {"couple", "on", "angular", "e: {couple: wheel, M: M0, on: 2}", false, "switched on at state '2', inside this angular_momentum analysis"},
  {"force", "off", "momentum", "e: {force: block, F: [F0, 0], off: 2}", false, "switched off at state '2', inside this momentum analysis"},
  {"force", "on", "energy", "e: {force: block, F: [F0, 0], on: 2}", true, ""},
  {"friction", "on", "energy", "e: {friction: block, mu: mu, normal: m*g, on: 2}", true, ""},
  {"friction", "off", "across", "e: {friction: block, mu: mu, normal: m*g, off: 2}", true, "residuals"},
  {"friction_couple", "on", "energy", "e: {friction_couple: wheel, M: M0/10, on: 2}", true, ""},
  {"power", "off", "timed", "e: {power: wheel, P: P0, off: 2}", true, "residuals"},
  {"pin", "off", "energy", "e: {pin: [C, wheel], off: 2}", true, ""},
  {"contact", "off", "impact", "e: {contact: [W, block], normal: [1, 0], e: 0.5, off: before}", false, "is switched off at state 'before', so it does not act"},
  {"impulse", "on", "impact", "e: {impulse: block, J: [-J0, 0], on: before}", true, ""},
  {"cord_pull", "off", "energy", "e: {cord_pull: [block, A], P: F0, off: 2}", true, ""},
  {"constraint", "off", "energy", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]], off: 2}", false, "nonlinear in several unknowns"},
  {"constraint", "off", "across", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]], off: 2}", false, "switched off at state '2', inside this energy analysis"},
  {"track", "off", "energy", "e: {track: block, line: {through: [0, 0], along: [1, 0]}, holds: both, off: 2}", true, ""},
  {"track", "on", "energy", "e: {track: block, line: {through: [0, 0], along: [1, 0]}, pushes: up, on: 2}", true, ""},
  // least values and extremes (no one motion to simulate: confirmed by the residuals)
  {"friction", "mu", "least", "e: {friction: block, mu: mu, normal: m*g}", true, "residuals"},
  {"friction", "off", "least", "e: {friction: block, mu: mu, normal: m*g, off: 1}", false, "is reached for every value of 'u0'"},
  {"spring", "acts", "least", "e: {spring: [block, A], k: k, free_length: a/2, acts: tension}", true, "residuals"},
  {"gravity", "direction", "least", "e: {gravity: g, direction: [-1, 0]}", true, "residuals"},
  {"spring", "k", "extreme", "e: {spring: [block, A], k: k, free_length: 3*a/2}", true, "residuals"},
  {"force", "on", "extreme", "e: {force: block, F: [F0, 0], on: 2}", true, "residuals"},
  {"torsion_spring", "on", "energy", "e: {torsion_spring: wheel, k: kt, on: 2}", true, ""},
  {"torsion_damper", "off", "energy", "e: {torsion_damper: wheel, c: ct, off: 1}", true, ""},
  {"damper", "on", "energy", "e: {damper: [block, A], c: c, on: 3}", true, ""},
  {"friction_couple", "off", "energy", "e: {friction_couple: wheel, M: M0/10, off: 2}", true, ""},
  {"power", "on", "timed", "e: {power: wheel, P: P0, on: 2}", true, "residuals"},
  {"pin", "on", "energy", "e: {pin: [C, wheel], on: 2}", true, ""},
  {"cord_pull", "on", "energy", "e: {cord_pull: [block, A], P: F0, on: 2}", true, ""},
  {"impulse", "off", "impact", "e: {impulse: block, J: [-J0, 0], off: before}", false, "needs a contact or a given impulse"},
  {"contact", "on", "impact", "e: {contact: [W, block], normal: [1, 0], e: 0.5, on: before}", true, ""},
  {"constraint", "on", "energy", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]], on: 2}", false, "nonlinear in several unknowns"},
};
// clang-format on

const char* kHead = R"Y(title: option table
parameters: {m: 2 kg, r: 0.5 m, k: 10 N/m, kt: 2 N*m, g: 9.81 m/s^2, d: 0.2 m, t2: 0.2 s, M0: 3 N*m, F0: 5 N, mu: 0.3,
             c: 2 N*s/m, ct: 0.1 N*m*s, P0: 4 W, J0: 3 N*s, a: 1 m, h: 2 m, R: 1 m, v0: 2 m/s, w0: 3 rad/s}
points: {O: [0, 0], A: [-a, 0], C: [0, h], W: [0, 0]}
)Y";

/// The scene of a row: its context's bodies, constraints, states and analyses, with the row's effect
/// (and `analyses` in place of the context's, when given).
std::string scene_of(const Row& r, const std::string& analyses = "") {
  std::string s = kHead;
  const bool constraint_row = r.kind == "constraint";
  auto effect = "effects:\n  " + r.effect + "\n";
  if (r.context == "energy" || r.context == "across" || r.context == "timed") {
    s += "coordinates: {x: m, phi: rad}\n"
         "bodies:\n"
         "  block: {mass: m, inertia: particle, position: [x, 0]}\n"
         "  wheel: {mass: m, inertia: {disk: r}, position: [0, h], angle: phi}\n";
    if (!constraint_row) s += "constraints:\n  - x - r*phi = 0\n";
    s += effect;
    // (timed: a power drive's work is P times the time)
    if (r.context == "timed") s += "states:\n  1: {t: 0, x: 0, x_dot: v0}\n  2: {t: t2}\n  3: {t: 2*t2}\n";
    else s += "states:\n  1: {t: 0, x: 0, x_dot: v0}\n  2: {x: d}\n  3: {x: 2*d}\n";
    if (r.context != "across") s += "analyses:\n  - energy: {from: 1, to: 2}\n  - energy: {from: 2, to: 3}\n";
    else s += "analyses:\n  - energy: {from: 1, to: 3}\n";
    s += "find:\n  v3: {value: x_dot@3, root: positive, unit: m/s}\n";
  } else if (r.context == "least" || r.context == "extreme") {
    // the least speed at state 1 for which state 2 is reached (T@2 >= 0), or the greatest kinetic
    // energy over the positions of state 2: a parameter without a value in a state
    s = std::string(s).replace(s.find("J0: 3 N*s"), 9, "J0: 3 N*s, u0: m/s, p: m");
    s += "coordinates: {x: m, phi: rad}\n"
         "bodies:\n"
         "  block: {mass: m, inertia: particle, position: [x, 0]}\n"
         "  wheel: {mass: m, inertia: {disk: r}, position: [0, h], angle: phi}\n"
         "constraints:\n  - x - r*phi = 0\n";
    s += effect;
    if (r.context == "least") {
      s += "states:\n  1: {x: 0, x_dot: u0}\n  2: {x: d}\n";
      s += "analyses:\n  - energy: {from: 1, to: 2}\n";
      s += "find:\n  u0_min: {least: u0, reaches: 2, unit: m/s}\n";
    } else {
      s += "states:\n  1: {x: 0, x_dot: v0}\n  2: {x: p}\n";
      s += "analyses:\n  - energy: {from: 1, to: 2}\n";
      s += "find:\n  T_max: {value: T@2, max: p, over: [0, 4*d], unit: J}\n";
    }
  } else if (r.context == "momentum") {
    s += "coordinates: {x: m}\nbodies:\n  block: {mass: m, inertia: particle, position: [x, 0]}\n";
    s += effect;
    s += "states:\n  1: {t: 0, x: 0, x_dot: v0}\n  2: {t: t2}\n  3: {t: 2*t2}\n";
    s += "analyses:\n  - momentum: {from: 1, to: 3, along: x}\n";
    s += "find:\n  v3: {value: x_dot@3, unit: m/s}\n";
  } else if (r.context == "angular") {
    s += "coordinates: {phi: rad}\nbodies:\n  wheel: {mass: m, inertia: {disk: r}, position: [0, h], angle: phi}\n";
    s += effect;
    s += "states:\n  1: {t: 0, phi: 0, phi_dot: w0}\n  2: {t: t2}\n  3: {t: 2*t2}\n";
    s += "analyses:\n  - angular_momentum: {from: 1, to: 3, about: C}\n";
    s += "find:\n  w3: {value: phi_dot@3, unit: rad/s}\n";
  } else {  // impact: the block strikes the stop W (or is struck by a given impulse)
    s += "coordinates: {x: m, phi: rad}\n"
         "bodies:\n"
         "  block: {mass: m, inertia: particle, position: [x, 0]}\n"
         "  wheel: {mass: m, inertia: {disk: r}, position: [0, h], angle: phi}\n";
    s += effect;
    const bool contact = r.kind == "contact";
    if (!contact && r.kind != "impulse") s += "  stop: {contact: [W, block], normal: [1, 0], e: 0.5}\n";
    s += "states:\n  before: {t: 0, x: 0, x_dot: -v0, phi: 0, phi_dot: w0}\n  after: {}\n";
    s += std::string("analyses:\n  - impact: {from: before, to: after") + (contact ? ", contact: e" : r.kind == "impulse" ? "" : ", contact: stop") + "}\n";
    s += "find:\n  v: {value: x_dot@after, unit: m/s}\n";
  }
  if (!analyses.empty()) {
    const auto at = s.find("analyses:\n"), end = s.find("find:\n");
    s = s.substr(0, at) + "analyses:\n" + analyses + s.substr(end);
  }
  return s;
}

/// The keys a kind accepts, as its own error for an unknown key lists them.
std::set<std::string> keys_of(const std::string& kind) {
  const std::string t = std::string(kHead) + "coordinates: {x: m}\nbodies:\n  block: {mass: m, inertia: particle, position: [x, 0]}\n"
                        "effects:\n  e: {" + kind + ": block, zzqqzz: 1}\n";
  auto e = kt_errors::error_of(t);
  REQUIRE(e.has_value());
  std::smatch m;
  const std::string fix = e->fix();
  std::set<std::string> out;
  if (!std::regex_search(fix, m, std::regex("^use: (.*)$"))) return out;
  std::string list = m[1];
  std::regex item("[a-z_]+");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), item); it != std::sregex_iterator(); ++it)
    if (it->str() != kind) out.insert(it->str());
  return out;
}

}  // namespace

TEST_CASE("option table: every option of every effect kind is in the table, with on and off", "[options]") {
  std::map<std::string, std::set<std::string>> covered;
  for (auto& r : kTable) covered[r.kind].insert(r.option);
  for (auto& k : kinergy::model::effect_kinds()) {
    INFO("effect kind " << k.name);
    REQUIRE(covered.count(k.name));
    auto keys = keys_of(k.name);
    keys.insert("on");
    keys.insert("off");
    for (auto& key : keys) {
      INFO("option " << key);
      // a key every row of the kind writes (gravity's g, pin's points) may stand in the row of
      // the kind alone (""); on and off each have rows of their own
      CHECK((covered[k.name].count(key) || (covered[k.name].count("") && key != "on" && key != "off")));
    }
  }
}

/// A scene solved and confirmed, or the SceneError it is refused with.
static std::pair<std::optional<kinergy::Solution>, std::optional<kinergy::SceneError>> attempt(const std::string& text) {
  try {
    kinergy::Solution s = kinergy::solve_scene(kinergy::scene::load_string(text, "bad.yaml"));
    kinergy::confirm(s);
    return {std::move(s), std::nullopt};
  } catch (const kinergy::SceneError& e) {
    return {std::nullopt, e};
  }
}

TEST_CASE("option table: each row honoured (solved, confirmed by simulation) or refused at its line", "[options]") {
  for (auto& r : kTable) {
    const std::string text = scene_of(r);
    INFO(r.kind << " / " << (r.option.empty() ? "(the kind)" : r.option) << " / " << r.context << "\n" << text);
    auto [s, err] = attempt(text);
    if (r.honoured) {
      INFO("error: " << (err ? err->what() : ""));
      CHECK_FALSE(err.has_value());
      if (err) continue;
      CHECK(s->confirmed.size() == s->model.analyses.size());
      for (auto& c : s->confirmed) {
        INFO("confirmed by '" << kinergy::Confirmed::name(c.by) << "': " << c.note);
        if (r.phrase == "residuals") CHECK(c.by != kinergy::Confirmed::By::None);
        else CHECK(c.by == kinergy::Confirmed::By::Simulation);
      }
    } else {
      CHECK(err.has_value());
      if (!err) continue;
      INFO("error: " << err->what());
      CHECK_THAT(err->problem(), Catch::Contains(r.phrase));
      // at its line: the effect's, the analysis', or the option's own place
      // (or a result the scene cannot determine, at its line under find:)
      const int effect_line = kt_errors::at(text, r.effect).line, analysis_line = kt_errors::at(text, "analyses:").line + 1,
                find_line = kt_errors::at(text, "find:").line + 1;
      CHECK((err->pos().line == effect_line || err->pos().line == analysis_line || err->pos().line == analysis_line + 1 ||
             err->pos().line == find_line));
      kt_errors::check_form(*err, "bad.yaml");
    }
  }
}

namespace {

/// An option of an analysis kind, in a context of the table above with its analyses replaced.
struct AnalysisRow {
  std::string kind, option, context, effect, analyses;
  bool honoured;
  std::string phrase;
};

// clang-format off
const std::vector<AnalysisRow> kAnalysisTable = {
  {"energy", "bodies", "energy", "e: {constraint: \"x - r*phi = 0\", between: [block, wheel], at: [[x, 0], [0, h - r]]}",
   "  - energy: {from: 1, to: 2}\n  - energy: {from: 1, to: 2, bodies: [block]}\n  - energy: {from: 2, to: 3}\n", true, ""},
  {"momentum", "along", "momentum", "e: {force: block, F: [F0, 0]}", "  - momentum: {from: 1, to: 3, along: [1, 0]}\n", true, ""},
  {"momentum", "bodies", "momentum", "e: {force: block, F: [F0, 0]}", "  - momentum: {from: 1, to: 3, along: x, bodies: [block]}\n", true, ""},
  {"momentum", "conserved", "momentum", "e: {force: block, F: [F0, 0]}", "  - momentum: {from: 1, to: 3, along: x, conserved: true}\n", false, "is not conserved"},
  {"momentum", "conserved", "momentum", "e: {force: block, F: [0, F0]}", "  - momentum: {from: 1, to: 3, along: x, conserved: true}\n", true, ""},
  {"angular_momentum", "about", "angular", "e: {couple: wheel, M: M0}", "  - angular_momentum: {from: 1, to: 3, about: wheel}\n", true, ""},
  {"angular_momentum", "bodies", "angular", "e: {couple: wheel, M: M0}", "  - angular_momentum: {from: 1, to: 3, about: C, bodies: [wheel]}\n", true, ""},
  {"angular_momentum", "conserved", "angular", "e: {couple: wheel, M: M0}", "  - angular_momentum: {from: 1, to: 3, about: C, conserved: true}\n", false, "is not conserved"},
  {"angular_momentum", "conserved", "angular", "e: {pin: [C, wheel]}", "  - angular_momentum: {from: 1, to: 3, about: C, conserved: true}\n", true, ""},
  {"impact", "contact", "impact", "e: {contact: [W, block], normal: [1, 0], e: 0.5}", "  - impact: {from: before, to: after, contact: e}\n", true, ""},
  {"impact", "contacts", "impact", "e: {contact: [W, block], normal: [1, 0], e: 0.5}", "  - impact: {from: before, to: after, contacts: [e]}\n", true, ""},
  {"impact", "contact", "impact", "e: {contact: [W, block], normal: [1, 0], e: 0.5, off: before}", "  - impact: {from: before, to: after, contact: e}\n", false, "does not act in the impact"},
  {"kinetics", "at", "angular", "e: {pin: [C, wheel]}", "  - angular_momentum: {from: 1, to: 3, about: C}\n  - kinetics: {at: 1}\n", true, ""},
  {"kinetics", "at", "angular", "e: {pin: [C, wheel]}", "  - angular_momentum: {from: 1, to: 3, about: C}\n  - kinetics: {at: 4}\n", false, "no state named '4'"},
  {"kinetics", "bodies", "angular", "e: {pin: [C, wheel]}", "  - angular_momentum: {from: 1, to: 3, about: C}\n  - kinetics: {at: 1, bodies: [wheel]}\n", true, ""},
  {"kinetics", "bodies", "angular", "e: {pin: [C, wheel]}", "  - angular_momentum: {from: 1, to: 3, about: C}\n  - kinetics: {at: 3, bodies: [hub]}\n", false, "hub"},
};
// clang-format on

}  // namespace

TEST_CASE("option table: every option of every analysis kind, honoured or refused", "[options]") {
  // completeness: each key an analysis kind reads has a row
  std::map<std::string, std::set<std::string>> covered;
  for (auto& r : kAnalysisTable) covered[r.kind].insert(r.option);
  for (auto* k : kinergy::model::analysis_kinds()) {
    INFO("analysis kind " << k->name);
    for (auto& key : k->keys()) {
      INFO("option " << key);
      CHECK(covered[k->name].count(key));
    }
  }
  for (auto& r : kAnalysisTable) {
    // (the kind of the effect matters to the context: a constraint effect stands for the
    // coupling, a contact for the stop)
    const std::string kind = r.effect.find("{constraint:") != std::string::npos ? "constraint"
                             : r.effect.find("{contact:") != std::string::npos  ? "contact"
                                                                                 : "";
    const std::string text = scene_of(Row{kind, "", r.context, r.effect, r.honoured, r.phrase}, r.analyses);
    INFO(r.kind << " / " << r.option << "\n" << text);
    auto [s, err] = attempt(text);
    INFO("error: " << (err ? err->what() : ""));
    if (r.honoured) {
      CHECK_FALSE(err.has_value());
      if (err) continue;
      for (auto& c : s->confirmed) {
        INFO("confirmed by '" << kinergy::Confirmed::name(c.by) << "': " << c.note);
        // kinetics at a state: by the equations of motion there (no motion to run)
        CHECK((c.by == kinergy::Confirmed::By::Simulation || (c.by == kinergy::Confirmed::By::EquationsOfMotion && r.kind == "kinetics")));
      }
    } else {
      CHECK(err.has_value());
      if (!err) continue;
      CHECK_THAT(err->problem(), Catch::Contains(r.phrase));
      kt_errors::check_form(*err, "bad.yaml");
    }
  }
}
