// A couple M on a body (constant, or a function of the coordinates and t); with `against: B`, a
// couple between two bodies: M on the first, −M on B (a motor between its rotor and its frame).
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Couple : public BodyEffect {
public:
  ex M = 0;
  std::optional<int> other;  ///< `against`: the body that takes −M

  // M on its body, from outside the bodies (or −M on the body it acts against)
  std::vector<model::Load> loads(const Model& m) const override { return {with_symbol(couple_on(m, body, M, other), load_symbol(*this, "M", M))}; }

  // a curved arrow round the body's centre in the sense of M (counterclockwise when positive)
  void draw(const Model& m, const At& at, Figure& f) const override { draw_turning(m, at, f, body, at(M), Ink::Force, draw::from_tex(load_symbol(*this, "M", M))); }
};

}  // namespace

std::shared_ptr<Effect> read_couple(EffectReader& r, const EffectDef& ed) {
  auto e = make<Couple>(ed);
  r.only(ed, {"M", "against"});
  e->body = r.body_ref(ed.arg, ed.kind);
  e->other = against(r, ed, e->body);
  e->M = r.quantity(r.text_of(r.option(ed, "M", "M0"), "M", "M0"), true, energy_dim(), "M",
                    "a couple is in N·m (or lb·ft)");
  return e;
}

}  // namespace kinergy::effects
