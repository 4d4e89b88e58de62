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
    return principles::generalized_force_work(m, *this, "couple", "U = integral of M dphi", s1, s2, k.fewer_switches);
  }

  // a curved arrow round the body's centre in the sense of M (counterclockwise when positive)
  void draw(const Model& m, const At& at, Figure& f) const override {
    const auto& B = m.bodies[static_cast<std::size_t>(body)];
    const double x = at(B.x), y = at(B.y), M0 = at(M), r = f.glyph() * 1.6;
    if (M0 > 0) f.arc_arrow(x, y, r, -0.6, 3.6, Ink::Force);
    else if (M0 < 0) f.arc_arrow(x, y, r, 3.6, -0.6, Ink::Force);
    f.label(x + r * std::cos(2.2), y + r * std::sin(2.2), name);
  }

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
