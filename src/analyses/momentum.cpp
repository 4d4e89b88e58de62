// Linear impulse–momentum of a body set over a duration: Σ m v̄₂·n = Σ m v̄₁·n + Σ ∫F·n dt, along
// x and y, or along one direction (`along`); conservation when claimed (`conserved: true`).
#include "kinergy/model/simplify.hpp"
#include "common.hpp"

namespace kinergy::analyses {

namespace {

using GiNaC::ex;

class Momentum : public Balanced<principles::MomentumBalance, principles::linear_momentum, momentum_section> {
public:
  Momentum() : Balanced("momentum") {}

  std::vector<std::string> keys() const override { return {"bodies", "along", "conserved"}; }

  void read(model::EffectReader& r, const scene::AnalysisDef& ad, model::Analysis& a) const override {
    const scene::Node* al = ad.options.get("along");
    if (!al) return;
    model::Along along;
    if (al->is_scalar() && (al->scalar == "x" || al->scalar == "y")) {
      along.nx = al->scalar == "x" ? 1 : 0;
      along.ny = al->scalar == "y" ? 1 : 0;
      along.name = al->scalar;
    } else {
      auto [nx, ny] = r.vec(*al, "along", units::Dimension{}, false, "a direction is a pair of pure numbers");
      ex n2 = nx * nx + ny * ny;
      if (n2.is_zero()) throw SceneError(al->pos, "the direction is zero", "write x, y or [nx, ny]");
      // n̂ = n / |n|
      along.nx = nx / sqrt(n2);
      along.ny = ny / sqrt(n2);
      along.name = "[" + model::text(nx) + ", " + model::text(ny) + "]";
    }
    a.options = along;
  }

  bool takes_reactions() const override { return true; }
  bool gives_positions() const override { return true; }
};

}  // namespace

const model::AnalysisKind& momentum() { return instance<Momentum>(); }

}  // namespace kinergy::analyses
