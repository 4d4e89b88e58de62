// Work–energy between two states: T₁ + V₁ + Σ U₁→₂ = T₂ + V₂ (conservation when no work is done).
#include "common.hpp"
#include "kinergy/principles/momentum.hpp"

namespace kinergy::analyses {

namespace {

class Energy : public Balanced<principles::EnergyBalance, principles::energy> {
public:
  Energy() : Balanced("energy") {}

  bool impulsive() const override { return false; }  // energy alone keeps a motion going one way

  std::vector<std::string> keys() const override { return {"bodies"}; }

  /// Isolating a body set: each interaction across its boundary that does work on it (a tooth
  /// force, a cord's tension on a moving body) brings its average force F̄ as an unknown:
  /// U = F̄ × the distance its point moves along it.
  void read(model::EffectReader& r, const scene::AnalysisDef&, model::Analysis& a) const override {
    const model::Model& m = r.model();
    const std::string S1 = m.states[a.from].name, S2 = m.states[a.to].name;
    for (auto& e : m.effects) {
      auto rea = e.reaction(m);
      if (!rea || !principles::works_across(m, *rea, a.bodies)) continue;
      GiNaC::ex F = r.unknown("F_" + e.name + "[" + S1 + "," + S2 + "]", units::Dimension::mass() * units::Dimension::length() /
                                                                     (units::Dimension::time() * units::Dimension::time()));
      a.reactions[e.name] = {F};
      a.unknowns.push_back(F);
    }
  }
};

}  // namespace

const model::AnalysisKind& energy() { return instance<Energy>(); }

}  // namespace kinergy::analyses
