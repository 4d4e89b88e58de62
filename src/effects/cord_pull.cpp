// A cord pulled with a constant force P: from point A it runs straight to point B (a small
// guide or pulley, or a point of another body) and pulls A toward B (and B toward A). The cord's
// length between them is L = |r_A − r_B|, and the pull does the work U = P (L₁ − L₂): it is
// conservative, V = P L.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class CordPull : public Effect {
public:
  PointRef a, b;
  ex P = 0;

  // the cord from A to B, and the pull on A as an arrow toward B
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto p = joined(m, at, a, b);
    if (!p) return;
    const auto [x1, y1, x2, y2] = *p;
    f.line(x1, y1, x2, y2, Ink::Thin);
    const double L = std::hypot(x2 - x1, y2 - y1), g = f.glyph() * 3;
    if (L > 0) f.arrow(x1, y1, x1 + (x2 - x1) / L * std::min(g, L), y1 + (y2 - y1) / L * std::min(g, L), Ink::Force);
    const draw::Name n = draw::from_tex(load_symbol(*this, "T"));
    f.label(x1, y1, n.text, n.tex);
  }
  // on A: P toward B, F = P (r_B − r_A)/L; −F on B
  std::vector<model::Load> loads(const Model& m) const override {
    auto [xa, ya] = m.position(a);
    auto [xb, yb] = m.position(b);
    ex L = m.spring_length(model::trig_simplify(pow(xa - xb, 2) + pow(ya - yb, 2)));
    return {with_symbol(force_at(a, P * (xb - xa) / L, P * (yb - ya) / L, b), load_symbol(*this, "T"))};
  }

  ex potential(const Model& m) const override {
    // V = P |r_A − r_B|  (the work of the pull is −ΔV = P (L₁ − L₂))
    auto [xa, ya] = m.position(a);
    auto [xb, yb] = m.position(b);
    return P * m.spring_length(model::trig_simplify(pow(xa - xb, 2) + pow(ya - yb, 2)));
  }
};

}  // namespace

std::shared_ptr<Effect> read_cord_pull(EffectReader& r, const EffectDef& ed) {
  auto e = make<CordPull>(ed);
  e->has_potential = true;
  r.only(ed, {"P"});
  std::tie(e->a, e->b) = two_points(r, ed, "a cord pull runs between two points",
                                     "write 'cord_pull: [collar, D]' (the point pulled, then the guide)");
  if (e->a.body < 0 && e->b.body < 0)
    throw SceneError(ed.arg.pos, "cord pull '" + ed.name + "' runs between two fixed points; it moves nothing",
                     "make the first point a body point, e.g. 'cord_pull: [collar, D]'");
  const scene::Node& pn = r.option(ed, "P", "P0");
  e->P = r.quantity(r.text_of(pn, "P", "P0"), false, force_dim(), "P", "a pull is a force, in N (or lb)");
  r.positive(e->P, pn.pos, "the pull of the cord");
  return e;
}

}  // namespace kinergy::effects
