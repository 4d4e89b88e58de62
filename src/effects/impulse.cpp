// A given impulse J (a blow) at a body point: it acts only in impacts.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Impulse : public Effect {
public:
  model::Blow j;

  // J at its point, in the impacts it takes part in
  const model::Blow* blow() const override { return &j; }

  // the blow: an arrow along J ending at its point, 3 glyphs long (a ring there where J's
  // direction is not known at these values), labelled with its name
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto [x, y] = at.point(m.position(j.at));
    const double jx = at(j.Jx), jy = at(j.Jy), J = std::hypot(jx, jy), L = 3 * f.glyph();
    if (!(J > 0)) {
      f.circle(x, y, 0.3 * f.glyph(), Ink::Force);
      const draw::Name n = draw::from_tex(load_symbol(*this, "J"));
      return f.label(x, y, n.text, n.tex);
    }
    f.arrow(x - jx / J * L, y - jy / J * L, x, y, Ink::Force);
    const draw::Name n = draw::from_tex(load_symbol(*this, "J"));
    f.label(x - jx / J * L, y - jy / J * L, n.text, n.tex);
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
