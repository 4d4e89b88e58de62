/// @file check.hpp  A solved scene's states as numbers, and its closed forms checked against a
/// simulation: each analysis from state S1 to S2 run from S1 until S2 is reached (its instant,
/// or the first time a coordinate given at S2 reaches its value), the simulated positions and
/// rates compared with the solution's.
#pragma once
#include <string>
#include <vector>

#include "kinergy/draw/animation.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace kinergy::simulate {

/// Parameter symbol → exact value, with the values solved for (`unknown` parameters).
GiNaC::exmap simulation_values(const Solution& s);

/// State `index` of a solved scene as numbers; NaN where the solution leaves a value open.
State state_values(const Solution& s, int index);
/// The same from a model's given values and `solved` (state symbol → value; empty for a scene
/// without analyses), the parameters at `params`.
State state_values(const model::Model& m, const GiNaC::exmap& solved, const GiNaC::exmap& params, int index);

/// One analysis as a simulation: from one state to another.
struct Leg {
  int analysis = -1, from = -1, to = -1;
  State start, expect;   ///< expect: NaN where the solution does not fix the value
  Stop stop;
  std::string target;    ///< how the end is found ("t = 2 s", "yA reaches -1.5")
  std::string why_not;   ///< empty when the leg can be simulated
};

std::vector<Leg> legs(const Solution& s);

struct LegCheck {
  Leg leg;
  Run run;
  double worst = 0;          ///< largest relative difference, simulated against closed form
  std::string worst_what;    ///< which value, in words (for people: decisions read `outcome`)
  /// What the comparison came to: values compared (within tolerance or not: `ok`, `worst`); the
  /// run ended at another time than the solution's; the run did not reach the leg's end; the
  /// solution fixes no value at the end to compare.
  enum class Outcome { Compared, WrongTime, NotReached, NothingToCompare };
  Outcome outcome = Outcome::Compared;
  bool ok = false;
  /// How the run was made to stand for the analysis, when not as it is ("nudged: …": released
  /// at rest on an equilibrium, as a textbook means "given a slight nudge"; "run for … s").
  std::string note;
};

/// Run a leg and compare its end with the closed-form state; passes when every known value
/// agrees within `tolerance` relative to its scale. The integration's absolute tolerance is
/// o.tol times the motion's own size (a swing of 1e-6 rad is integrated to 1e-6 of o.tol), so
/// the comparison is relative for small motions too. A run that does not reach the leg's end
/// is run again: longer (up to 10⁴ times the first estimate), and — when it started at rest and
/// did not move, an equilibrium the closed form leaves as "released" — nudged toward the end
/// with a rate whose kinetic energy is 10⁻²⁰ of the one at the end (said in `note`).
LegCheck check_leg(const Solution& s, const Leg& leg, const Options& o, double tolerance);

/// A run as a motion to draw: its samples as frames, its impacts as moments ("impact at floor").
draw::Motion motion_of(const Run& r, const std::string& title);

/// The motion of each analysis that can be simulated (each leg), from its first state until its
/// second is reached, at `samples` regular times and every impact: the animations of a worked
/// solution. Analyses without duration (impacts) and legs that cannot run are left out.
std::vector<draw::Motion> motions(const Solution& s, int samples);

/// Does a run from state `start` begin with the scene's given impulses? They act at the state an
/// impact analysis starts from (or, without analyses, at the start), not again from a later state.
bool impulses_at(const model::Model& m, int start);

/// A run from state `start` (at s0) to time `until` that follows the effects switched on and off
/// at states (`on: S`, `off: S`): it runs with the effects acting after the start state until the
/// next state where one switches is reached — found as a check's leg finds its end (the state's
/// time, or the first time a value given there is reached) — switches them, and goes on. The
/// runs are joined (works summed; each switch in the log). `impulses`: apply the scene's given
/// impulses at the start. @throws SceneError when a switching state cannot be found in a run.
Run run_following(const model::Model& m, const GiNaC::exmap& solved, const GiNaC::exmap& params, int start, const State& s0,
                  double until, const Options& o, bool impulses);

}  // namespace kinergy::simulate
