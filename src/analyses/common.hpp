// What every analysis kind shares (private to src/analyses): its balance kept in the solution, the
// balance's equations joining the system, its section of the derivation.
#pragma once
#include "kinergy/emit/sections.hpp"
#include "kinergy/problem.hpp"

namespace kinergy::analyses {

/// The principle that turns an analysis into its balance.
template <class B>
using Principle = B (*)(const model::Model&, const model::Analysis&, const principles::Knowledge&);

/// What writes an analysis' section of the derivation from its balance B (`k`: its number).
template <class B>
using Section = void (*)(emit::Sections&, int k, const model::Analysis&, const B&);

/// The section of a linear or an angular momentum analysis (momentum_section.cpp).
void momentum_section(emit::Sections& w, int k, const model::Analysis& a, const principles::MomentumBalance& mb);

/// An analysis kind whose balance B is made by `principle` and shown by `section`.
template <class B, Principle<B> principle, Section<B> section>
class Balanced : public model::AnalysisKind {
public:
  using AnalysisKind::AnalysisKind;

  void equations(const model::Model& m, const model::Analysis& a, const principles::Knowledge& k, Solution& s) const override {
    auto b = std::make_shared<const B>(principle(m, a, k));
    for (auto& e : b->equations()) s.equations.push_back(e);
    s.balances.push_back(std::move(b));
  }

  void derive(emit::Sections& w, int k, const model::Analysis& a, const Solution& s) const override {
    section(w, k, a, *s.balance<B>(static_cast<std::size_t>(k - 1)));
  }
};

/// The one instance of analysis kind K (what the table of kinds holds).
template <class K>
const model::AnalysisKind& instance() {
  static const K kind;
  return kind;
}

}  // namespace kinergy::analyses
