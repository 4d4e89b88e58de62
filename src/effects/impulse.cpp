// A given impulse J (a blow) at a body point: it acts only in impacts.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Impulse : public Effect {
public:
  model::Blow j;
  std::vector<int> bodies_acted(const Model&) const override { return bodies_of({j.at.body}); }

  const model::Blow* blow() const override { return &j; }

  // (switched off, or not yet on, over the analysis: it does not strike there)
  std::pair<ex, ex> impulse(const Model& m, int, int ai) const override {
    if (activity(m.analyses[static_cast<std::size_t>(ai)]) == Activity::None) return {0, 0};
    return {j.Jx, j.Jy};
  }

  std::pair<ex, ex> impact_impulse_on(const Model& m, int body, int ai) const override {
    if (j.at.body != body || activity(m.analyses[static_cast<std::size_t>(ai)]) == Activity::None) return {0, 0};
    return {j.Jx, j.Jy};
  }

  void pushes(const Model& m, const Analysis& a, const Knowledge&, std::vector<Push>& out) const override {
    if (!acts_on(a, j.at.body)) return;
    Push p;  // the impulse itself (no time integral)
    p.Rx = j.Jx;
    p.Ry = j.Jy;
    p.unknown = true;
    auto [x, y] = m.position(j.at);
    p.arm_x = x;
    p.arm_y = y;
    out.push_back(p);
  }

  void motion(const Model& m, int self, simulate::Equations& eq) const override {
    // P_i = J · ∂r_P/∂q_i
    simulate::ImpulseTerm im{self, {}};
    for (auto& co : m.coords) {
      auto [dx, dy] = m.position_derivative(j.at, co.q);
      im.P.push_back(model::trig_simplify(j.Jx * dx + j.Jy * dy));
    }
    eq.impulses.push_back(im);
  }
};

}  // namespace

std::shared_ptr<Effect> read_impulse(EffectReader& r, const EffectDef& ed) {
  auto e = make<Impulse>(ed);
  r.only(ed, {"J"});
  e->j.at = r.point_ref(ed.arg, ed.kind);
  if (e->j.at.body < 0)
    throw SceneError(ed.arg.pos, "an impulse acts on a body, but '" + ed.arg.scalar + "' is a fixed point",
                     "name body.point or a body (its mass centre)");
  auto [jx, jy] = r.vec(r.option(ed, "J", "[J0, 0]"), "J", force_dim() * Dimension::time(), false,
                        "an impulse is in N*s (or lb*s)");
  e->j.Jx = jx;
  e->j.Jy = jy;
  return e;
}

}  // namespace kinergy::effects
