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
      // W, with the body's short name (or its name) as a subscript where the scene has several (W_A)
      const auto s = draw::body_label(b);
      const draw::Name w = m.bodies.size() > 1 ? (s ? draw::subscripted({"W", "W"}, *s) : draw::subscripted({"W", "W"}, b.name))
                                               : draw::Name{"W", "W"};
      f.label(x + dx * L, y + dy * L, w.text, w.tex);
    }
  }

  // the weight m g ĝ of each body at its mass centre (the earth is not a body of the scene)
  std::vector<model::Load> loads(const Model& m) const override {
    std::vector<model::Load> out;
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      const ex W = m.bodies[b].mass * g;
      out.push_back(force_at(centre_of(m, static_cast<int>(b)), W * dir_x, W * dir_y));
      out.back().symbol = "W";  // a weight
    }
    return out;
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
};

}  // namespace

std::shared_ptr<Effect> read_gravity(EffectReader& r, const EffectDef& ed) {
  const Dimension L = Dimension::length(), T = Dimension::time();
  auto e = make<Gravity>(ed);
  e->has_potential = true;
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
