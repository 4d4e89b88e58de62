// Viscous torsion damper: a couple −c (ω₁ − ω₂) on one body, or between two.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class TorsionDamper : public Effect {
public:
  int body = -1, body2 = -1;
  ex c = 0;

  // the couple −c (ω₁ − ω₂) on the body, its reaction on the second (or the ground)
  std::vector<model::Load> loads(const Model& m) const override {
    ex w = m.omega(body) - (body2 >= 0 ? m.omega(body2) : ex(0));
    return {with_symbol(couple_on(m, body, -c * w, body2), load_symbol(*this, "M"))};
  }

  // an arc round the (first) body's centre
  void draw(const Model& m, const At& at, Figure& f) const override { draw_turning(m, at, f, body, 0, Ink::Hidden, value_label(c, "c"), 1.3, true); }

};

}  // namespace

std::shared_ptr<Effect> read_torsion_damper(EffectReader& r, const EffectDef& ed) {
  auto e = make<TorsionDamper>(ed);
  r.only(ed, {"c"});
  std::tie(e->body, e->body2) = r.one_or_two_bodies(ed, "a torsion damper");
  e->c = r.quantity(r.text_of(r.option(ed, "c", "c_t"), "c", "c_t"), false, energy_dim() * Dimension::time(), "c",
                    "a torsional damping coefficient is in N*m*s/rad");
  r.positive(e->c, r.option(ed, "c", "c").pos, "the torsional damping coefficient");
  return e;
}

}  // namespace kinergy::effects
