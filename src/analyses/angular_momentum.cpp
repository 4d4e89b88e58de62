// Angular impulse–momentum about a point P over a duration: Σ H_P₂ = Σ H_P₁ + Σ ∫M_P dt, about a
// fixed point or the mass centre of the one body analysed; conservation when claimed.
#include "common.hpp"

namespace kinergy::analyses {

namespace {

class AngularMomentum : public Balanced<principles::MomentumBalance, principles::angular_momentum, momentum_section> {
public:
  AngularMomentum() : Balanced("angular_momentum") {}

  std::vector<std::string> keys() const override { return {"bodies", "about", "conserved"}; }

  void read(model::EffectReader& r, const scene::AnalysisDef& ad, model::Analysis& a) const override {
    const model::Model& m = r.model();
    const scene::Node* ab = ad.options.get("about");
    if (!ab)
      throw SceneError(ad.pos, "angular_momentum needs the point 'about' which moments are taken",
                       "write 'about: O' (a fixed point) or 'about: disk' (its mass centre)");
    const model::PointRef about = r.point_ref(*ab, "about");
    a.options = model::About{about};
    // H_P₂ − H_P₁ = ∫M_P dt holds about a fixed point, or about the mass centre of the body
    bool fixed = about.body < 0;
    if (!fixed) {  // a body point that the coordinates never move (a pulley's centre) is fixed too
      auto [ax, ay] = m.position(about);
      fixed = true;
      for (auto& co : m.coords) fixed = fixed && !ax.has(co.q) && !ay.has(co.q);
      fixed = fixed && !ax.has(m.t) && !ay.has(m.t);
    }
    bool own_centre = about.body >= 0 && about.lx.is_zero() && about.ly.is_zero() && !about.world_place &&
                      a.bodies.size() == 1 && a.bodies[0] == about.body;
    if (!fixed && !own_centre)
      throw SceneError(ab->pos, "angular impulse-momentum about '" + ab->scalar + "' does not hold: that point moves",
                       "take moments about a fixed point (under 'points') or about the mass centre of the one body analysed");
  }

  bool takes_reactions() const override { return true; }
  bool gives_positions() const override { return true; }
};

}  // namespace

const model::AnalysisKind& angular_momentum() { return instance<AngularMomentum>(); }

}  // namespace kinergy::analyses
