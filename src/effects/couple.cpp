// A couple M on a body (constant, or a function of the coordinates and t).
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Couple : public BodyEffect {
public:
  ex M = 0;

  // Q_i = M ∂φ/∂q_i
  ex generalized_force(const Model& m, std::size_t i) const override { return M * m.bodies[body].angle.diff(m.coords[i].q); }

  ex power(const Model& m) const override { return M * m.omega(body); }  // P = M ω

  principles::Work work(const Model& m, int s1, int s2, const Knowledge& k) const override {
    return principles::generalized_force_work(m, *this, "couple", "U = integral of M dphi", s1, s2, &k);
  }

  // a curved arrow round the body's centre in the sense of M (counterclockwise when positive)
  void draw(const Model& m, const At& at, Figure& f) const override { draw_turning(m, at, f, body, at(M), Ink::Force, name); }

  void pushes(const Model&, const Analysis& a, const Knowledge&, std::vector<Push>& out) const override {
    if (!on(a)) return;
    Push p;
    p.M = M;
    out.push_back(p);
  }

  void motion(const Model& m, int self, simulate::Equations& eq) const override {
    eq.forces.push_back(simulate::force_term(m, *this, self));
  }
};

}  // namespace

std::shared_ptr<Effect> read_couple(EffectReader& r, const EffectDef& ed) {
  auto e = make<Couple>(ed);
  r.only(ed, {"M"});
  e->body = r.body_ref(ed.arg, ed.kind);
  e->M = r.quantity(r.text_of(r.option(ed, "M", "M0"), "M", "M0"), true, energy_dim(), "M",
                    "a couple is in N·m (or lb·ft)");
  return e;
}

}  // namespace kinergy::effects
