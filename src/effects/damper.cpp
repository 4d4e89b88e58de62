// Viscous damper between two points: a force c·(rate of its length) along its line.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Damper : public Effect {
public:
  PointRef a, b;
  ex c = 0;

  // a dashpot: a line between its points with a cylinder (an open box) at the middle
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto p = joined(m, at, a, b);
    if (!p) return;
    const double x1 = (*p)[0], y1 = (*p)[1], x2 = (*p)[2], y2 = (*p)[3];
    const double L = std::hypot(x2 - x1, y2 - y1);
    if (!(L > 0)) return;
    const double ux = (x2 - x1) / L, uy = (y2 - y1) / L, w = std::min(f.glyph() * 0.6, L / 5);
    auto at_s = [&](double s, double side) { return std::pair<double, double>{x1 + ux * L * s - uy * side, y1 + uy * L * s + ux * side}; };
    f.polyline({{x1, y1}, at_s(0.45, 0)}, Ink::Spring);
    f.polyline({at_s(0.35, w), at_s(0.6, w), at_s(0.6, -w), at_s(0.35, -w)}, Ink::Spring);  // the cylinder, open at its left
    f.polyline({at_s(0.45, w * 0.8), at_s(0.45, -w * 0.8)}, Ink::Spring);                     // the piston
    f.polyline({at_s(0.6, 0), {x2, y2}}, Ink::Spring);
    const draw::Name cn = value_label(c, "c");  // (by its constant)
    f.label((x1 + x2) / 2, (y1 + y2) / 2, cn.text, cn.tex);
  }

  /// d = r_B − r_A
  std::pair<ex, ex> span(const Model& m) const {
    auto [xa, ya] = m.position(a);
    auto [xb, yb] = m.position(b);
    return {xb - xa, yb - ya};
  }

  // along the line of its ends, d = r_B − r_A: the force on A is c (d·ḋ/|d|²) d (−that on B),
  // the rate of its length d·ḋ/|d| times c, along the unit vector d/|d| (no root: it appears twice)
  std::vector<model::Load> loads(const Model& m) const override {
    auto [dx, dy] = span(m);
    ex dd = model::collect_simplify(m.rate(dx) * dx + m.rate(dy) * dy, m.rates());
    ex d2 = model::trig_simplify(dx * dx + dy * dy);
    return {with_symbol(force_at(a, c * dd / d2 * dx, c * dd / d2 * dy, b), load_symbol(*this, "F"))};
  }

};

}  // namespace

std::shared_ptr<Effect> read_damper(EffectReader& r, const EffectDef& ed) {
  auto e = make<Damper>(ed);
  r.only(ed, {"c"});
  std::tie(e->a, e->b) = two_points(r, ed, "a damper joins two points", "write 'damper: [A, bar.B]'");
  e->c = r.quantity(r.text_of(r.option(ed, "c", "c"), "c", "c"), false,
                    force_dim() * Dimension::time() / Dimension::length(), "c",
                    "a damping coefficient is in N*s/m (or lb*s/ft)");
  r.positive(e->c, r.option(ed, "c", "c").pos, "the damping coefficient");
  return e;
}

}  // namespace kinergy::effects
