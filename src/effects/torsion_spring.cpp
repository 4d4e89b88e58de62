// Torsion spring on a body (or between two): V = ½ k (φ − φ₀)².
#include "common.hpp"

namespace kinergy::effects {

namespace {

class TorsionSpring : public Effect {
public:
  int body = -1, body2 = -1;
  ex k = 0, free = 0;

  // a coil round the pin the (first) body turns about (its centre when it has none)
  void draw(const Model& m, const At& at, Figure& f) const override { draw_turning(m, at, f, body, 0, Ink::Spring, value_label(k, "k"), 1.0, true); }
  // the couple −k (φ₁ − φ₂ − φ₀) on the body, its reaction on the second (or the ground)
  std::vector<model::Load> loads(const Model& m) const override {
    ex phi = m.bodies[body].angle - (body2 >= 0 ? m.bodies[body2].angle : ex(0));
    return {with_symbol(couple_on(m, body, -k * (phi - free), body2), load_symbol(*this, "M"))};
  }

  ex potential(const Model& m) const override {
    // V = ½ k (φ − φ₀)²,  φ the body's angle (or relative to a second body)
    ex phi = m.bodies[body].angle - (body2 >= 0 ? m.bodies[body2].angle : ex(0));
    return k * pow(phi - free, 2) / 2;
  }
};

}  // namespace

std::shared_ptr<Effect> read_torsion_spring(EffectReader& r, const EffectDef& ed) {
  auto e = make<TorsionSpring>(ed);
  e->has_potential = true;
  r.only(ed, {"k", "free_angle"});
  std::tie(e->body, e->body2) = r.one_or_two_bodies(ed, "a torsion spring");
  e->k = r.quantity(r.text_of(r.option(ed, "k", "k_t"), "k", "k_t"), false, energy_dim(), "k",
                    "a torsional constant is in N·m/rad");
  r.positive(e->k, r.option(ed, "k", "k").pos, "the torsional constant");
  if (auto* f = ed.options.get("free_angle"))
    e->free = r.quantity(r.text_of(*f, "free_angle", "0"), false, Dimension{}, "free_angle",
                         "an angle is a pure number (rad)");
  return e;
}

}  // namespace kinergy::effects
