// Linear impulse–momentum of a body set over a duration: Σ m v̄₂·n = Σ m v̄₁·n + Σ ∫F·n dt, along
// x and y, or along one direction (`along`); conservation when claimed (`conserved: true`).
#include "kinergy/emit/sections.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/problem.hpp"

namespace kinergy::analyses {

namespace {

using GiNaC::ex;

class Momentum : public model::AnalysisKind {
public:
  Momentum() : AnalysisKind("momentum") {}

  std::vector<std::string> keys() const override { return {"bodies", "along", "conserved"}; }

  void read(model::EffectReader& r, const scene::AnalysisDef& ad, model::Analysis& a) const override {
    const scene::Node* al = ad.options.get("along");
    if (!al) return;
    a.has_along = true;
    if (al->is_scalar() && (al->scalar == "x" || al->scalar == "y")) {
      a.nx = al->scalar == "x" ? 1 : 0;
      a.ny = al->scalar == "y" ? 1 : 0;
      a.along_name = al->scalar;
    } else {
      auto [nx, ny] = r.vec(*al, "along", units::Dimension{}, false, "a direction is a pair of pure numbers");
      ex n2 = nx * nx + ny * ny;
      if (n2.is_zero()) throw SceneError(al->pos, "the direction is zero", "write x, y or [nx, ny]");
      // n̂ = n / |n|
      a.nx = nx / sqrt(n2);
      a.ny = ny / sqrt(n2);
      a.along_name = "[" + model::text(nx) + ", " + model::text(ny) + "]";
    }
  }

  bool takes_reactions() const override { return true; }

  int equations(const model::Model& m, const model::Analysis& a, const principles::Knowledge& k, Solution& s) const override {
    s.momenta.push_back(principles::linear_momentum(m, a, k));
    for (auto& c : s.momenta.back().components) s.equations.push_back(c.equation);
    return static_cast<int>(s.momenta.size()) - 1;
  }

  void derive(emit::Sections& w, int k, const model::Analysis& a, const Solution& s, int part) const override {
    w.momentum(k, a, s.momenta[static_cast<std::size_t>(part)]);
  }
};

}  // namespace

const model::AnalysisKind& momentum() {
  static const Momentum kind;
  return kind;
}

}  // namespace kinergy::analyses
