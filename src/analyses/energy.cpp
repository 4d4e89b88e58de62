// Work–energy between two states: T₁ + V₁ + Σ U₁→₂ = T₂ + V₂ (conservation when no work is done).
#include "common.hpp"

namespace kinergy::analyses {

namespace {

class Energy : public Balanced<principles::EnergyBalance, &Solution::balances, principles::energy> {
public:
  Energy() : Balanced("energy") {}

  bool impulsive() const override { return false; }  // energy alone keeps a motion going one way
};

}  // namespace

const model::AnalysisKind& energy() { return instance<Energy>(); }

}  // namespace kinergy::analyses
