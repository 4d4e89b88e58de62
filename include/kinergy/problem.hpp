/// @file problem.hpp  The whole pipeline for one scene: model, equations, solution, results.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/model/model.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/solve/solver.hpp"

namespace kinergy {

/// A named result of a scene.
struct Result {
  std::string name;
  SourcePos pos;
  GiNaC::ex closed;                 ///< closed form in the parameters
  bool closed_form = true;          ///< false when a numeric root was needed
  std::optional<GiNaC::numeric> si; ///< value in SI units (when every parameter has a value)
  units::Dimension dim;
  std::string unit;                 ///< display unit
  GiNaC::ex unit_factor = 1;        ///< SI value / unit_factor = value in the display unit
  /// Value in the display unit with `digits` correct significant digits (working precision
  /// raised until stable). @returns nothing when parameters lack values.
  std::optional<GiNaC::numeric> value(const GiNaC::exmap& env, int digits) const;
};

struct Solution {
  model::Model model;
  std::vector<principles::EnergyBalance> balances;     ///< energy analyses, in order
  std::vector<principles::MomentumBalance> momenta;    ///< momentum and angular momentum analyses
  std::vector<principles::ImpactBalance> impacts;      ///< impact analyses
  std::vector<principles::Equation> equations;  ///< every equation solved, in order
  solve::Branch branch;                         ///< the chosen solution
  std::vector<Result> results;
};

/// Solve a scene. @throws SceneError (bad scene, no solution, ambiguous roots).
Solution solve_scene(const scene::SceneDef& def);
Solution solve_file(const std::string& path);

}  // namespace kinergy
