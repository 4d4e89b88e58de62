// Angular impulse–momentum about a point P over a duration: Σ H_P₂ = Σ H_P₁ + Σ ∫M_P dt, about a
// fixed point, the mass centre of the one body analysed, or a place moving parallel to the mass
// centre; conservation when claimed.
#include "common.hpp"
#include "kinergy/model/simplify.hpp"

namespace kinergy::analyses {

namespace {

/// `about: {C: [x, y]}`: a named place, which may follow the motion (x, y of coordinates and t).
model::PointRef place(model::EffectReader& r, const scene::Node& n) {
  if (n.entries.size() != 1)
    throw SceneError(n.pos, "'about' as a place names one point and where it is", "write 'about: {C: [r, y]}'");
  const scene::Node& k = n.entries.front().first;
  const scene::Node& v = n.entries.front().second;
  model::PointRef p;
  p.text = k.scalar;
  if (r.model().body_index(p.text) >= 0 || r.model().fixed_points.count(p.text))
    throw SceneError(k.pos, "'" + p.text + "' already names a " + (r.model().body_index(p.text) >= 0 ? "body" : "fixed point"),
                     "give the place another name");
  std::tie(p.wx, p.wy) = r.vec(v, "about", units::Dimension::length(), true, "a place is a pair of lengths, e.g. [r, y]");
  return p;
}

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
    const model::PointRef about = ab->is_map() ? place(r, *ab) : r.point_ref(*ab, "about");
    a.options = model::About{about};
    // H_P₂ − H_P₁ = ∫M_P dt holds about a fixed point, or about the mass centre of the body
    auto [ax, ay] = m.position(about);
    bool fixed = true;  // a body point that the coordinates never move (a pulley's centre) is fixed too
    for (auto& co : m.coords) fixed = fixed && !ax.has(co.q) && !ay.has(co.q);
    fixed = fixed && !ax.has(m.t) && !ay.has(m.t);
    bool own_centre = about.body >= 0 && about.lx.is_zero() && about.ly.is_zero() && !about.world_place &&
                      a.bodies.size() == 1 && a.bodies[0] == about.body;
    // about a moving place P: dH_P/dt = ΣM_P − v_P × m v̄ (v̄ the set's mass centre), so the
    // balance holds where v_P ∥ v̄ at every position and rate (the point of a cable a drum climbs)
    if (!fixed && !own_centre && about.body < 0) {
      auto [Lx, Ly] = m.linear_momentum(a.bodies);
      if (principles::vanishes(m, m.rate(ax) * Ly - m.rate(ay) * Lx)) return;
      throw SceneError(ab->pos, "angular impulse-momentum about the place " + about.text + " = [" + model::text(ax) + ", " +
                                    model::text(ay) + "] does not hold: it moves, and not parallel to the mass centre of " +
                                    (a.bodies.size() == 1 ? "the body" : "the bodies") + " analysed (dH/dt = ΣM − v_P × m v̄)",
                       "take moments about a fixed point, the mass centre of the one body analysed, or a place that moves "
                       "parallel to the mass centre (the point of a cable level with a drum's centre)");
    }
    if (!fixed && !own_centre)
      throw SceneError(ab->pos, "angular impulse-momentum about '" + about.text + "' does not hold: that point moves",
                       "take moments about a fixed point (under 'points'), the mass centre of the one body analysed, or a "
                       "place that moves parallel to the mass centre ('about: {C: [x, y]}')");
  }

  bool takes_reactions() const override { return true; }
  bool gives_positions() const override { return true; }
};

}  // namespace

const model::AnalysisKind& angular_momentum() { return instance<AngularMomentum>(); }

}  // namespace kinergy::analyses
