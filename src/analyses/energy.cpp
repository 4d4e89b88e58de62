// Work–energy between two states: T₁ + V₁ + Σ U₁→₂ = T₂ + V₂ (conservation when no work is done).
#include "kinergy/emit/sections.hpp"
#include "kinergy/problem.hpp"

namespace kinergy::analyses {

namespace {

class Energy : public model::AnalysisKind {
public:
  Energy() : AnalysisKind("energy") {}

  bool impulsive() const override { return false; }  // energy alone keeps a motion going one way

  int equations(const model::Model& m, const model::Analysis& a, const principles::Knowledge& k, Solution& s) const override {
    s.balances.push_back(principles::energy(m, a, k));
    s.equations.push_back(s.balances.back().equation);
    return static_cast<int>(s.balances.size()) - 1;
  }

  void derive(emit::Sections& w, int k, const model::Analysis& a, const Solution& s, int part) const override {
    w.energy(k, a, s.balances[static_cast<std::size_t>(part)]);
  }
};

}  // namespace

const model::AnalysisKind& energy() {
  static const Energy kind;
  return kind;
}

}  // namespace kinergy::analyses
