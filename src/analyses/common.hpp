// What every analysis kind shares (private to src/analyses): its balance kept in the solution's
// list for its kind, the balance's equations joining the system, its section of the derivation.
#pragma once
#include "kinergy/emit/sections.hpp"
#include "kinergy/problem.hpp"

namespace kinergy::analyses {

/// The equations of a balance, in the order they join the system.
std::vector<principles::Equation> equations_of(const principles::EnergyBalance& b);
std::vector<principles::Equation> equations_of(const principles::MomentumBalance& b);
std::vector<principles::Equation> equations_of(const principles::ImpactBalance& b);

/// The principle that turns an analysis into its balance.
template <class B>
using Principle = B (*)(const model::Model&, const model::Analysis&, const principles::Knowledge&);

/// An analysis kind whose balance B, made by `principle`, is kept in `Solution::*list`.
template <class B, std::vector<B> Solution::*list, Principle<B> principle>
class Balanced : public model::AnalysisKind {
public:
  using AnalysisKind::AnalysisKind;

  int equations(const model::Model& m, const model::Analysis& a, const principles::Knowledge& k, Solution& s) const override {
    auto& kept = s.*list;
    kept.push_back(principle(m, a, k));
    for (auto& e : equations_of(kept.back())) s.equations.push_back(e);
    return static_cast<int>(kept.size()) - 1;
  }

  void derive(emit::Sections& w, int k, const model::Analysis& a, const Solution& s, int part) const override {
    w.section(k, a, (s.*list)[static_cast<std::size_t>(part)]);
  }
};

/// The one instance of analysis kind K (what the table of kinds holds).
template <class K>
const model::AnalysisKind& instance() {
  static const K kind;
  return kind;
}

}  // namespace kinergy::analyses
