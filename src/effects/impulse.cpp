// A given impulse J (a blow) at a body point: it acts only in impacts.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Impulse : public Effect {
public:
  model::Blow j;

  // J at its point, in the impacts it takes part in
  const model::Blow* blow() const override { return &j; }
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
