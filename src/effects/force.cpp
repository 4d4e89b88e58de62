// A force F at a body point (or at a world place on a body), constant or a function of the
// coordinates and t.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Force : public Effect {
public:
  PointRef a;
  ex Fx = 0, Fy = 0;
  std::vector<int> bodies_acted(const Model&) const override { return bodies_of({a.body}); }

  ex generalized_force(const Model& m, std::size_t i) const override {
    auto [dx, dy] = m.position_derivative(a, m.coords[i].q);  // Q_i = F · ∂r_P/∂q_i
    return Fx * dx + Fy * dy;
  }

  ex power(const Model& m) const override {
    auto [vx, vy] = m.velocity(a);  // P = F · v
    return Fx * vx + Fy * vy;
  }

  principles::Work work(const Model& m, int s1, int s2, const Knowledge& k) const override {
    return principles::generalized_force_work(m, *this, "force", "U = integral of F . dr", s1, s2, &k);
  }

  void pushes(const Model& m, const Analysis& an, const Knowledge&, std::vector<Push>& out) const override {
    if (!acts_on(an, a.body)) return;
    Push p;
    p.Fx = Fx;
    p.Fy = Fy;
    auto [x, y] = m.position(a);
    p.arm_x = x;
    p.arm_y = y;
    out.push_back(p);
  }

  std::pair<ex, ex> impulse(const Model& m, int self, int ai) const override {
    const Analysis& an = m.analyses[ai];
    if (an.instant) return Effect::impulse(m, self, ai);
    return force_impulse(m, *this, Fx, Fy, an);  // ∫F dt
  }

  void motion(const Model& m, int self, simulate::Equations& eq) const override {
    eq.forces.push_back(simulate::force_term(m, *this, self));
  }

  // an arrow along F ending at its point, 3 glyphs long, labelled with its name
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto [x, y] = at.point(m.position(a));
    const double fx = at(Fx), fy = at(Fy), F = std::hypot(fx, fy);
    if (!(F > 0)) return;
    const double L = f.glyph() * 3;
    f.arrow(x - fx / F * L, y - fy / F * L, x, y, Ink::Force);
    f.label(x - fx / F * L, y - fy / F * L, name);
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
