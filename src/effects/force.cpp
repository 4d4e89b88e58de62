// A force F at a body point (or at a world place on a body), constant or a function of the
// coordinates and t.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Force : public Effect {
public:
  PointRef a;
  ex Fx = 0, Fy = 0;
  // F at its point, from outside the bodies
  std::vector<model::Load> loads(const Model&) const override {
    return {with_symbol(force_at(a, Fx, Fy), load_symbol(*this, "P"))};
  }

  // an arrow along F ending at its point, 3 glyphs long, labelled with its name; where F is
  // zero at this state (a bumper not yet touched), a ring at its point, "name = 0"
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto [x, y] = at.point(m.position(a));
    const double fx = at(Fx), fy = at(Fy), F = std::hypot(fx, fy);
    if (F == 0) {
      f.circle(x, y, 0.3 * f.glyph(), Ink::Force);
      const draw::Name n = draw::from_tex(load_symbol(*this, "P"));
      return f.label(x, y, n.text + " = 0", n.tex + " = 0");
    }
    if (!(F > 0)) return;
    const double L = f.glyph() * 3;
    f.arrow(x - fx / F * L, y - fy / F * L, x, y, Ink::Force);
    const draw::Name n = draw::from_tex(load_symbol(*this, "P"));
    f.label(x - fx / F * L, y - fy / F * L, n.text, n.tex);
  }
};

}  // namespace

std::shared_ptr<Effect> read_force(EffectReader& r, const EffectDef& ed) {
  auto e = make<Force>(ed);
  r.only(ed, {"F", "at"});
  e->a = r.acting_point(ed);
  auto [fx, fy] = r.vec(r.option(ed, "F", "[0, -P]"), "F", force_dim(), true, "a force is in N (or lb)");
  e->Fx = fx;
  e->Fy = fy;
  return e;
}

}  // namespace kinergy::effects
