/// @file simulate.hpp  Integrate the equations of motion of a scene in time: a compiled
/// right-hand side (every entry of M(q) and Q in one tape, sin/cos of each coordinate once),
/// Eigen's LDLᵀ for q̈, Boost.Odeint steppers, and the switching parts of the scene handled as
/// events located to the tolerance: contacts striking (the impact law with the scene's e) and
/// coming to rest, Coulomb friction stopping, sticking and breaking away.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/common/error.hpp"
#include "kinergy/model/model.hpp"
#include "kinergy/simulate/equations.hpp"

namespace kinergy::simulate {

enum class Method { Dopri5, Rkf78, BulirschStoer, Symplectic, Rk4 };

/// "dopri5", "rkf78", "bs", "symplectic", "rk4". @throws InputError naming the choices.
Method method_from_name(const std::string& s);
std::string method_name(Method m);

/// A failure while simulating (a singular mass matrix, a right-hand side that is undefined, a
/// method that does not fit the scene), with what would fix it.
class SimulationError : public std::runtime_error {
public:
  SimulationError(std::string what, std::string fix, SourcePos pos = {})
      : std::runtime_error(std::move(what)), fix_(std::move(fix)), pos_(std::move(pos)) {}
  const std::string& fix() const { return fix_; }
  const SourcePos& pos() const { return pos_; }  ///< the effect or state it is about (line 0: none)
private:
  std::string fix_;
  SourcePos pos_;
};

/// A rolling contact that slips in the run: holding it takes more friction than its μ_s allows
/// (`mu_s` on a constraint effect). The simulator does not switch it to sliding.
class SlipError : public SimulationError {
public:
  using SimulationError::SimulationError;
};

/// A body leaves a surface that can only push (a one-sided track): its normal force falls to
/// zero in the run. The simulator does not go on with the body free of it.
class ReleaseError : public SimulationError {
public:
  ReleaseError(std::string what, std::string fix, SourcePos pos, std::string effect, double t, const model::OneWay& w)
      : SimulationError(std::move(what), std::move(fix), std::move(pos)), effect_(std::move(effect)), t_(t), keeps_(w.keeps), verb_(w.verb), ask_(w.ask) {}
  const std::string& effect() const { return effect_; }  ///< the track
  double t() const { return t_; }                         ///< when, in s
  const std::string& keeps() const { return keeps_; }    ///< "keeps ball on 'dome'" (model::OneWay)
  const std::string& verb() const { return verb_; }      ///< "leaves", "goes slack"
  const std::string& ask() const { return ask_; }        ///< where: ["N(dome) = 0"]
private:
  std::string effect_;
  double t_;
  std::string keeps_, verb_, ask_;
};

struct Options {
  Method method = Method::Dopri5;
  double tol = 1e-10;        ///< absolute and relative tolerance of the adaptive methods
  double atol = -1;          ///< the absolute one apart (< 0: tol): a motion's own size times tol
  /// > 0: no adaptive step longer than this (a stop condition crossed twice within one long step
  /// — a ball passing a height just below its top and falling back through it — is not seen)
  double max_dt = 0;
  double step = 0;           ///< fixed step of symplectic and rk4 (0: span/10⁴)
  bool native = true;        ///< right-hand side as machine code (else the tape, same doubles)
  bool record = true;        ///< keep samples (every accepted step, or every `sample_dt`)
  /// stop where a rolling contact's mu_s no longer holds it, or a body leaves a surface that can
  /// only push (off: its accelerations at one state only)
  bool rolling_limits = true;
  /// With rolling_limits: a body that leaves a surface that can only push goes on free of it (a
  /// gap coordinate for each such surface whose body can be freed: the run's `model`), and strikes
  /// it again with the track's e; off, the run stops there with a ReleaseError (a check of an
  /// analysis that keeps the body on the surface: its first release already refutes it).
  bool follow_releases = true;
  /// > 0: samples at the regular times t₀ + k·sample_dt, from the integrator's steps by cubic
  /// Hermite interpolation (the state and its rate at both ends of the step: error O(h⁴)), and
  /// at each event exactly (an impact: the states before and after it, at the same time);
  /// 0: the accepted steps themselves.
  double sample_dt = 0;
  /// The effects that act (by index; empty: all): those switched on over the run.
  std::vector<bool> effects_on;
  std::size_t max_steps = 100'000'000;
  /// Called now and then with the fraction of the span done (a progress bar).
  std::function<void(double)> progress;
};

/// Positions and rates at an instant (SI values, the model's coordinate order).
struct State {
  double t = 0;
  std::vector<double> q, qd;
};

/// Where a run ends: at `until`, or earlier the first time `when` (an expression of the
/// coordinates, rates and t) crosses zero. `until` equal to the start time runs only what
/// happens at the start (given impulses, impacts of contacts touching and approaching).
struct Stop {
  double until = 0;
  std::optional<GiNaC::ex> when;
  bool impulses = true;  ///< apply the scene's given impulses at the start
};

struct Sample {
  double t;
  std::vector<double> q, qd;
  double T, V;
};

/// One impact: the contacts that struck, the approach and rebound speeds, and the kinetic energy
/// lost, ½ Σ P (v_n⁻ + v_n⁺) taken from the impulses (no difference of large numbers).
struct Impact {
  double t;
  std::vector<std::string> contacts;
  std::vector<double> vn_before, vn_after, impulse;
  double loss = 0;
  double T_before = 0, T_after = 0;
  bool comes_to_rest = false;  ///< the last bounce was too short to resolve: the contact rests
};

/// A switch of the run's contacts and friction at an instant: a body leaves a surface
/// ("leaves"), strikes one ("strikes"), comes to rest on it ("rests"), a contact lets go
/// ("lets go"), friction slips or sticks ("slips", "sticks").
struct Switch {
  double t = 0;
  std::string effect, kind;
  std::string text;  ///< as the log says it
};

struct Run {
  /// The model the run integrated when it is not the scene's own: the scene with a gap
  /// coordinate for each surface its bodies may leave (after the scene's coordinates, in each
  /// sample's q and q̇). Null: the scene's model.
  std::shared_ptr<const model::Model> model;
  std::vector<Switch> switches;    ///< in time order (also in `log`)
  std::vector<Sample> samples;     ///< accepted steps (when recording), and the end
  std::vector<Impact> impacts;
  std::vector<std::string> log;    ///< what switched and when (rest, stick, slip, release)
  std::vector<std::pair<std::string, double>> work;  ///< U of each non-conservative effect
  Sample end;
  bool stopped = false;            ///< `when` ended the run (not `until`)
  double E0 = 0, E1 = 0;           ///< T + V at the start and the end
  double impact_loss = 0;          ///< Σ energy lost in impacts
  double energy_scale = 0;         ///< max(|E₀|, largest T): the drift is relative to this
  /// (E₁ − E₀ − ΣU + Σ impact losses)/scale: the energy balance error of the integration.
  double drift = 0;
  bool conservative = false;       ///< no non-conservative effect and no impact
  std::size_t steps = 0, rejected = 0, rhs_calls = 0;
};

class Simulator {
public:
  /// Compile the equations of motion of `m` with the parameters at `values` (exact).
  /// @throws SceneError when a parameter has no value, SimulationError when the method does
  /// not fit the scene, std::runtime_error when no compiler is there for the native code.
  Simulator(const model::Model& m, const GiNaC::exmap& values, const Options& o);
  ~Simulator();
  Simulator(Simulator&&) noexcept;

  const Equations& equations() const;
  /// The model it integrates: the scene's, or with a gap coordinate for each surface that only
  /// pushes whose body it lets go (Options::follow_releases), after the scene's coordinates.
  const model::Model& model() const;
  /// State vector size (q, q̇, and the work of each non-conservative effect).
  std::size_t size() const;

  /// Integrate from s0 until stop. Applies the scene's given impulses at the start.
  Run run(const State& s0, const Stop& stop);

  /// dy/dt at y = [q, q̇, U…] (the current friction and contact modes), for benchmarks.
  void rhs(const double* y, double t, double* dydt);
  /// The modes at y, for the accelerations at a state (a kinetics check): every contact touching
  /// and at rest there (its gap and normal rate within 1e-9 of the positions' and rates' size)
  /// rests, held by its rows (a body resting on, or pivoting about, what it struck), and every
  /// kinetic friction that slips there opposes its slip at y (a block sliding in −x, a wheel
  /// turning clockwise against a bearing couple), not the run's first guess.
  void modes_at(const double* y, double t);

  struct Impl;  ///< compiled equations, modes and workspace (src/simulate/impl.hpp)

private:
  std::unique_ptr<Impl> p_;
};

}  // namespace kinergy::simulate
