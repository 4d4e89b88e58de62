// Linear spring between two points: V = ½ k (|r_A − r_B| − L₀)².
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Spring : public Effect {
public:
  PointRef a, b;
  ex k = 0, free = 0;
  std::vector<int> bodies_acted(const Model&) const override { return bodies_of({a.body, b.body}); }

  bool conservative() const override { return true; }

  ex potential(const Model& m) const override {
    // V = ½ k (|r_A − r_B| − L₀)²
    auto [xa, ya] = m.position(a);
    auto [xb, yb] = m.position(b);
    ex d2 = model::trig_simplify(pow(xa - xb, 2) + pow(ya - yb, 2));
    if (free.is_zero()) return k * d2 / 2;
    return k * pow(m.spring_length(d2) - free, 2) / 2;
  }

  void pushes(const Model&, const Analysis& an, const Knowledge&, std::vector<Push>&) const override {
    refuse_elastic_push(*this, acts_on(an, a.body), acts_on(an, b.body));
  }
};

}  // namespace

std::shared_ptr<Effect> read_spring(EffectReader& r, const EffectDef& ed) {
  auto e = make<Spring>(ed);
  r.only(ed, {"k", "free_length"});
  std::tie(e->a, e->b) = two_points(r, ed, "a spring joins two points", "write 'spring: [A, bar.B]'");
  const scene::Node& kn = r.option(ed, "k", "k");
  e->k = r.quantity(r.text_of(kn, "k", "k"), false, force_dim() / Dimension::length(), "k",
                    "a spring constant is in N/m (or lb/ft)");
  r.positive(e->k, kn.pos, "the spring constant");
  if (auto* f = ed.options.get("free_length")) {
    e->free = r.quantity(r.text_of(*f, "free_length", "L0"), false, Dimension::length(), "free_length",
                         "a free length is a length");
    r.positive(e->free, f->pos, "the free length", true);
  }
  return e;
}

}  // namespace kinergy::effects
