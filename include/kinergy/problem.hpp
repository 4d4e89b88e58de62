/// @file problem.hpp  The whole pipeline for one scene: model, equations, solution, results.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/model/model.hpp"
#include "kinergy/numeric/ball.hpp"
#include "kinergy/principles/kinetics.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/solve/solver.hpp"

namespace kinergy {

/// A number for a result, and how it was obtained.
struct Value {
  GiNaC::numeric v;       ///< in the display unit; its rounding to the digits asked is right
  enum class How { Exact, Double, Precise, Zero } how = How::Exact;
  long working = 0;       ///< Precise: the working precision (decimal digits) that settled the digits
  double bound = 0;       ///< Double: |error| bound of the double; Zero: |value| bound
  /// Precise, Zero: proven by ball arithmetic; the exact value lies in [lo, hi]. Not proven: two
  /// working precisions of CLN agreed (a form with a number found numerically in it).
  bool proven = false;
  GiNaC::numeric lo, hi;
  std::string note() const;  ///< "exact", "double, |error| ≤ 4.4e-16", "proven: ball radius 2.1e-52", …
  /// The ball as the JSON prints it: a midpoint of digits + 10 significant digits, and a radius
  /// of two digits rounded up that covers the ball and the midpoint's rounding (empty when not proven).
  std::pair<std::string, std::string> ball(int digits) const;
};

/// A named result of a scene.
struct Result {
  std::string name;
  SourcePos pos;
  GiNaC::ex closed;                 ///< closed form in the parameters
  bool closed_form = true;          ///< false when a numeric root was needed
  std::optional<GiNaC::numeric> si; ///< value in SI units (when every parameter has a value)
  units::Dimension dim;
  std::string unit;                 ///< display unit
  /// For an extreme: how it was found (the stationary condition, the second-order check, the ends).
  std::string extreme_note;
  GiNaC::ex extreme_of;  ///< the expression made greatest or least (of the parameter)
  std::string extreme_what = "of the parameter";  ///< what extreme_of is, for the derivation
  GiNaC::ex unit_factor = 1;        ///< SI value / unit_factor = value in the display unit
  /// A result that holds numbers found as roots (an unknown found by a numeric root, a value
  /// solved from one, an extreme at a stationary point found numerically): the same value as an
  /// expression of those roots (SI; in the parameters and the roots' unknowns), and each root's
  /// equation and bracket. Its digits are then proven by ball arithmetic to any number.
  GiNaC::ex of_roots;
  std::vector<numerics::RootOf> roots;
  /// Value in the display unit with `digits` correct significant digits (working precision
  /// raised until stable). @returns nothing when parameters lack values.
  std::optional<GiNaC::numeric> value(const GiNaC::exmap& env, int digits) const;
  /// The value, right when rounded to `digits` significant digits. With `prefer_double`, the compiled
  /// double evaluator decides when its error bound fixes every one of those digits; otherwise
  /// (or when it cannot) CLN with working precision raised until the digits settle.
  /// @throws SceneError when more digits are asked of a numeric root than it was refined to.
  std::optional<Value> evaluate(const GiNaC::exmap& env, int digits, bool prefer_double) const;
};

/// Significant digits a numeric root (no closed form) is refined to.
constexpr int kRootDigits = 35;

/// How one analysis was confirmed a second way (kinergy/confirm.hpp), or why it could not be.
struct Confirmed {
  int analysis = -1;
  /// How: by a simulation of the same scene, by the equations' residuals at the solution at 50
  /// digits, by the equations of motion at a state (kinetics), or not at all (`note` says why).
  /// Shared: a batch request that differs from an earlier one only in parameter values, whose
  /// solution (confirmed there) is shown to hold at these values (batch/carry.hpp).
  enum class By { None, Simulation, Residuals, EquationsOfMotion, Shared };
  By by = By::None;
  /// Its name in JSON and the Python module: "simulation", "residuals", "equations of motion",
  /// "shared solution", "".
  static std::string name(By b);
  double difference = 0;  ///< the largest relative difference found
  double tolerance = 0;   ///< what it was checked against
  std::string note;       ///< how the simulation stood for the analysis (a nudge), or why none could
  /// Closed forms in parameters without values: those parameters ("m, L, theta0"), confirmed at
  /// each of `samples` ("m = 1.37 kg, L = 0.842 m, theta0 = 1.05") as a numeric scene is; `by`
  /// is the weakest way any sample was confirmed, `difference` the largest.
  std::string sampled;
  std::vector<std::string> samples;
  /// Its simulation did not reach the analysis' end (no_second_opinion): no second opinion.
  bool unreached = false;
};

struct Solution {
  model::Model model;
  /// Each analysis's balance (its kind's type: principles::EnergyBalance, MomentumBalance,
  /// ImpactBalance), in the order of model.analyses.
  std::vector<std::shared_ptr<const principles::Balance>> balances;
  /// The balance of analysis `ai` when it is of type B (nullptr when it is another kind's).
  template <class B>
  const B* balance(std::size_t ai) const {
    return ai < balances.size() ? dynamic_cast<const B*>(balances[ai].get()) : nullptr;
  }
  /// The balances of type B, in order.
  template <class B>
  std::vector<const B*> balances_of() const {
    std::vector<const B*> out;
    for (std::size_t i = 0; i < balances.size(); ++i)
      if (const B* b = balance<B>(i)) out.push_back(b);
    return out;
  }
  std::vector<principles::Equation> equations;  ///< every equation solved, in order
  /// Of the balances' reserves, those solved (a result was not determined without them).
  std::vector<principles::Equation> drawn_on;
  /// Is `e` one of the reserve equations solved?
  bool drew_on(const principles::Equation& e) const;
  solve::Branch branch;                         ///< the chosen solution
  std::vector<Result> results;
  /// Each analysis confirmed a second way, in order (empty: not asked, `--no-confirm`).
  std::vector<Confirmed> confirmed;
  /// The scene as written (its parameters' texts, points and units: what a derivation quotes).
  scene::SceneDef scene;
  /// What the solution takes for granted that holds a parameter without a value, so that it
  /// cannot be checked here (e ≥ 0, bound to the solution): stated with the closed forms, which
  /// hold only where it does (a friction's sense: mA − mu mB ≥ 0).
  std::vector<principles::Condition> valid_where;
  /// The static friction rolling contacts state (|F| ≤ μ_s |N|, principles::static_friction_limits),
  /// at the states of the analyses they act in: checked on the solution (or stated in valid_where).
  std::vector<principles::FrictionLimit> friction_limits;
  /// The analyses over an interval along which that friction changes with the motion: the
  /// confirmation checks them along the simulated motion.
  std::vector<int> friction_along;
  /// Surfaces that can only push whose normal force Newton's law does not give in closed form
  /// (principles::one_sided_limits): "'floor' during …: why". N ≥ 0 is then not checked at
  /// the states, only along the motion where a simulation confirms it.
  std::vector<std::string> one_sided_unchecked;
};

/// Every parameter's number: the given values, and the solved values of unknown parameters (for
/// drawing and simulating the solved scene).
GiNaC::exmap parameter_values(const Solution& s);

/// The first condition of s.valid_where that fails at the model's numeric environment (its
/// parameters' values, and samples for those without): where the choices made there lie outside
/// the solution's domain, or a sample of them does. nullptr where every one holds.
const principles::Condition* failing_condition(const Solution& s);

/// Does solution `at` hold at its model's parameter values (samples for those without)? Every
/// condition it states for values it could not check (valid_where) met, every result a real
/// number, every analysis forward in time. `why`: the first that fails.
bool admissible(const Solution& at, std::string& why);

/// Sample values of parameters without values a solve tries its choices at (Model::sample): at
/// most kSolveSamples solves, among the first kSampleSearch samples.
constexpr int kSolveSamples = 24;
constexpr int kSampleSearch = 256;

/// Solve a scene. @throws SceneError (bad scene, no solution, ambiguous roots).
Solution solve_scene(const scene::SceneDef& def);
Solution solve_file(const std::string& path);

}  // namespace kinergy
