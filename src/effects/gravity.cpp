// Gravity: a uniform field g along a direction (−y by default), on every body with mass.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Gravity : public Effect {
public:
  ex g = 0, dir_x = 0, dir_y = -1;

  // the weight of each body: an arrow from its centre along g
  void draw(const Model& m, const At& at, Figure& f) const override {
    const double dx = at(dir_x), dy = at(dir_y), L = f.glyph() * 2.5;
    for (auto& b : m.bodies) {
      const double x = at(b.x), y = at(b.y);
      f.arrow(x, y, x + dx * L, y + dy * L, Ink::Force);
      f.label(x + dx * L, y + dy * L, "m g");
    }
  }

  bool conservative() const override { return true; }

  std::vector<int> bodies_acted(const Model& m) const override {
    std::vector<int> all;
    for (std::size_t b = 0; b < m.bodies.size(); ++b) all.push_back(static_cast<int>(b));
    return all;
  }

  ex potential(const Model& m) const override {
    // V = Σ m g h,  h = −(ĝ · r_G)  (height against the direction of gravity)
    ex V = 0;
    for (auto& b : m.bodies) V += -b.mass * g * (dir_x * b.x + dir_y * b.y);
    return V.expand();
  }

  principles::Work work_across(const Model& m, const Analysis& a, const Knowledge&) const override {
    // on the set's own bodies only: U = −Δ Σ_set m g h
    ex V = 0;
    for (int b : a.bodies) V += -m.bodies[b].mass * g * (dir_x * m.bodies[b].x + dir_y * m.bodies[b].y);
    principles::Work w;
    w.effect = name;
    w.U = model::trig_simplify(-(m.bind(V, a.to) - m.bind(V, a.from)));
    w.how = "U = -(change of m g h) of the bodies analysed";
    return w;
  }

  void pushes(const Model& m, const Analysis& a, const Knowledge&, std::vector<Push>& out) const override {
    // the weight m g ĝ of each body of the set, at its mass centre
    for (int b : a.bodies) {
      Push p;
      p.Fx = m.bodies[b].mass * g * dir_x;
      p.Fy = m.bodies[b].mass * g * dir_y;
      p.arm_x = m.bodies[b].x;
      p.arm_y = m.bodies[b].y;
      out.push_back(p);
    }
  }

  std::pair<ex, ex> impulse(const Model& m, int self, int ai) const override {
    const Analysis& a = m.analyses[ai];
    if (a.instant) return Effect::impulse(m, self, ai);
    // ∫ Σ m g ĝ dt over the analysis' bodies
    ex Fx = 0, Fy = 0;
    for (int b : a.bodies) {
      Fx += m.bodies[b].mass * g * dir_x;
      Fy += m.bodies[b].mass * g * dir_y;
    }
    return force_impulse(m, *this, Fx, Fy, a);
  }
};

}  // namespace

std::shared_ptr<Effect> read_gravity(EffectReader& r, const EffectDef& ed) {
  const Dimension L = Dimension::length(), T = Dimension::time();
  auto e = make<Gravity>(ed);
  r.only(ed, {"g", "direction"});
  scene::Node gnode = ed.arg.is_scalar() ? ed.arg : r.option(ed, "g", "g");
  if (ed.arg.is_scalar() && ed.options.get("g"))
    throw SceneError(ed.options.get("g")->pos, "gravity is given twice", "give 'g' once");
  e->g = r.quantity(r.text_of(gnode, "g", "g"), false, L / (T * T), "g", "g is an acceleration, e.g. 9.81 m/s^2");
  r.positive(e->g, gnode.pos, "g");
  if (auto* d = ed.options.get("direction")) {
    auto [dx, dy] = r.vec(*d, "direction", Dimension{}, false, "a direction is a pair of pure numbers");
    ex n2 = dx * dx + dy * dy;
    if (n2.is_zero()) throw SceneError(d->pos, "the direction of gravity is zero", "write e.g. [0, -1]");
    // ĝ = d / |d|
    e->dir_x = dx / sqrt(n2);
    e->dir_y = dy / sqrt(n2);
  }
  return e;
}

}  // namespace kinergy::effects
