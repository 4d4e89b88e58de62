/// @file analysis.hpp  An analysis kind as a type: what it reads, the unknowns it brings, the
/// equations it contributes, its section of the derivation.
///
/// Each kind (energy, momentum, angular_momentum, impact) is one class in its own file under
/// src/analyses/, registered by name in src/analyses/registry.cpp (the one table of analyses).
#pragma once
#include <string>
#include <vector>

#include "kinergy/model/effect.hpp"

namespace kinergy {
struct Solution;
}
namespace kinergy::emit {
class Sections;
}
namespace kinergy::solve {
struct Branch;
}

namespace kinergy::model {

class AnalysisKind {
public:
  std::string name;
  explicit AnalysisKind(std::string n) : name(std::move(n)) {}
  virtual ~AnalysisKind() = default;

  /// Is it taken at one state (`at`: kinetics at an instant) rather than between two (`from`,
  /// `to`)? Its analysis then has from = to = that state.
  virtual bool at_state() const { return false; }
  /// The option keys it takes besides `from` and `to` (or `at`).
  virtual std::vector<std::string> keys() const { return {}; }
  /// Read its own options (the builder has read from, to, bodies and conserved); add the
  /// unknowns it brings through `r.unknown`.
  virtual void read(EffectReader&, const scene::AnalysisDef&, Analysis&) const {}
  /// Over a duration with the impulses of supports across its body set (pin reactions)?
  virtual bool takes_reactions() const { return false; }
  /// Does it balance impulses (so `impulse(effect, S1, S2)` refers to it, and a motion may
  /// reverse between its states)? Work–energy does not.
  virtual bool impulsive() const { return true; }
  /// Over a duration, does its balance integrate once more to the positions at its ends, where
  /// its pushes are known functions of time (momentum: Σ m r̄ moves with L; a body turning about a
  /// fixed axis: I φ with H)? It does so for the positions a result asks for (positions_asked).
  virtual bool gives_positions() const { return false; }
  /// Does it take no time (an impact: positions and t do not change, impulses are impulsive)?
  virtual bool instant() const { return false; }
  /// Add its balance (Solution::balances) and its equations to the solution.
  virtual void equations(const Model& m, const Analysis& a, const Knowledge& k, Solution& s) const = 0;
  /// Check the chosen solution (`given`: the states' given values; `env`: the parameters').
  /// @throws SceneError when it is physically impossible for this analysis.
  virtual void check(const Model&, const Analysis&, const GiNaC::exmap& /*given*/, const solve::Branch&,
                     const GiNaC::exmap& /*env*/) const {}
  /// Write its section of the derivation (`k`: its number, from 1; its balance is s.balances[k − 1]).
  virtual void derive(emit::Sections& w, int k, const Analysis& a, const Solution& s) const = 0;
};

/// The table of analysis kinds (src/analyses/registry.cpp).
const std::vector<const AnalysisKind*>& analysis_kinds();

}  // namespace kinergy::model
