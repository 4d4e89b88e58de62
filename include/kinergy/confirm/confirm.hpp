/// @file confirm.hpp  Every answer confirmed a second way before it is printed: each analysis of
/// a solved scene run as a simulation of the same scene (simulate/check.hpp) and compared with the
/// closed form; where no simulation stands for it (a state placed by a parameter without a value,
/// an effect switched inside it, a scene the simulator cannot run), the equations' residuals at
/// the chosen solution at 50 digits. `solve`, `verify`, `derive`, batch and the Python module
/// confirm by default; `--no-confirm` (confirm=False) skips it.
#pragma once
#include "kinergy/confirm/check.hpp"
#include "kinergy/problem.hpp"

namespace kinergy {

/// Relative agreement a simulation must reach with the closed form (integrated at 1e-10).
constexpr double kConfirmSimulation = 1e-8;
/// A difference that stays above kConfirmSimulation when integrated at 1e-13 is still accepted up
/// to this: what doubles can tell of a tiny rate among large positions (near a turning point, a
/// nearly balanced Atwood machine); a wrong model or a wrong root differs by far more.
constexpr double kConfirmFloor = 1e-6;
/// Relative size a residual may have at the solution (numeric roots are refined to 40 digits).
constexpr double kConfirmResidual = 1e-25;

/// Closed forms in parameters without values are confirmed at this many sampled values of them,
/// drawn from at most kSampleCandidates candidates (those where the solution's conditions fail
/// are passed over without a solve), the scene solved at no more than kSampleSolves of them.
constexpr int kSamples = 3;
constexpr int kSampleCandidates = 256;
constexpr int kSampleSolves = 32;

/// Kinetics at a state against the simulator's equations of motion there (Kane's form, compiled
/// apart): the largest relative difference of the accelerations q̈ (relative to their own size,
/// or q̇² where they vanish), which one, and whether it is within kConfirmSimulation and every
/// equation the kinetics did not solve holds at the solution at 50 digits (`what` says which does
/// not). @throws SceneError when a q̈ has no value at the solution.
struct KineticsCheck {
  double worst = 0;
  std::string what;
  bool ok = false;
};
KineticsCheck check_kinetics(const Solution& s, int analysis);

/// Is run `c` of analysis `a` no second opinion rather than a disagreement? A run that does not
/// reach the end of an analysis over impulses: the scene's effects alone may not take the motion
/// there (a person walking on a turntable, balls drawn in by a mechanism a conservation claim
/// leaves out). (An energy analysis has every effect that works: there it is a disagreement.)
/// One rule for solve's confirmation and `simulate --check`.
bool no_second_opinion(const model::Analysis& a, const simulate::LegCheck& c);

/// Confirm every analysis of `s`, in order (fills s.confirmed).
/// @throws SceneError at the analysis whose second way disagrees, showing both numbers.
void confirm(Solution& s);

}  // namespace kinergy
