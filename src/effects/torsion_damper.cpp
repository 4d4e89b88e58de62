// Viscous torsion damper: a couple −c (ω₁ − ω₂) on one body, or between two.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class TorsionDamper : public Effect {
public:
  int body = -1, body2 = -1;
  ex c = 0;

  // an arc round the (first) body's centre
  void draw(const Model& m, const At& at, Figure& f) const override { draw_turning(m, at, f, body, 0, Ink::Hidden, name, 1.3); }
  std::vector<int> bodies_acted(const Model&) const override { return bodies_of({body, body2}); }

  /// φ₁ − φ₂ (the body's angle alone when there is no second body)
  ex relative_angle(const Model& m) const {
    return m.bodies[body].angle - (body2 >= 0 ? m.bodies[body2].angle : ex(0));
  }

  ex power(const Model& m) const override {
    // P = −c (ω₁ − ω₂)²
    ex w = m.omega(body) - (body2 >= 0 ? m.omega(body2) : ex(0));
    return model::collect_simplify(-c * w * w, m.rates());
  }

  principles::Work work(const Model& m, int s1, int s2, const Knowledge&) const override {
    refuse_speed_dependent_work(m, *this, s1, s2);
  }

  void pushes(const Model&, const Analysis& a, const Knowledge&, std::vector<Push>&) const override {
    refuse_elastic_push(*this, acts_on(a, body), acts_on(a, body2));
  }

  void motion(const Model& m, int self, simulate::Equations& eq) const override {
    // couple −c (ω₁ − ω₂) on the body (and its reaction on the second),
    // Q_i = −c (ω₁ − ω₂) ∂(φ₁ − φ₂)/∂q_i
    ex rel = relative_angle(m);
    ex w = m.rate(rel);
    std::vector<ex> Q;
    for (auto& co : m.coords) Q.push_back(model::collect_simplify(-c * w * rel.diff(co.q), m.rates()));
    eq.forces.push_back(simulate::force_term(m, self, Q, false));
  }
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
