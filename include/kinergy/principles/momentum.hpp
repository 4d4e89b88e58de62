/// @file momentum.hpp  Impulse and momentum between two states, and impacts.
#pragma once
#include <string>
#include <vector>

#include "kinergy/principles/principles.hpp"

namespace kinergy::principles {

/// One external impulse in a component equation.
struct ImpulseTerm {
  std::string effect;
  ex value;
  std::string how;  ///< "∫F dt", "unknown pin reaction", …
};

/// The equations of one momentum analysis, component by component.
struct MomentumBalance {
  struct Component {
    std::string name;  ///< "x", "y", "along (nx, ny)", "moment about O"
    ex before, after;  ///< momentum (or angular momentum) at the two states
    std::vector<ImpulseTerm> impulses;
    Equation equation;
  };
  std::vector<Component> components;
  bool conserved = false;
};

/// Linear impulse–momentum Σ m v̄₂·n = Σ m v̄₁·n + Σ ∫F·n dt for the analysis' bodies.
/// @throws SceneError when an impulse cannot be taken, or a conservation claim is false.
MomentumBalance linear_momentum(const model::Model& m, const model::Analysis& a, const Knowledge& k);

/// Angular impulse–momentum Σ H_P₂ = Σ H_P₁ + Σ ∫M_P dt.
MomentumBalance angular_momentum(const model::Model& m, const model::Analysis& a, const Knowledge& k);

/// The equations of an impact: generalized impulse–momentum along each coordinate (pins and
/// constraints carry workless impulsive reactions), restitution and stick conditions at each
/// contact, positions unchanged.
struct ImpactBalance {
  std::vector<Equation> momentum;     ///< one per coordinate
  std::vector<Equation> restitution;  ///< one per contact (and stick conditions)
  std::vector<Equation> positions;    ///< q_after = q_before
};

ImpactBalance impact(const model::Model& m, const model::Analysis& a, const Knowledge& k);

}  // namespace kinergy::principles
