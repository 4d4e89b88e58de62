// Linear spring between two points: V = ½ k (|r_A − r_B| − L₀)².
#include <algorithm>
#include <functional>
#include <optional>

#include "common.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/trace.hpp"

namespace kinergy::effects {

namespace {

class Spring : public Effect {
public:
  PointRef a, b;
  ex k = 0, free = 0;
  /// 0: pushes and pulls; −1: only when compressed (a bumper, a stop, a launcher left behind);
  /// +1: only when stretched (an elastic cord)
  int side = 0;
  /// Its stretch δ = |r_A − r_B| − L₀ (generic).
  ex stretch(const Model& m) const {
    auto [xa, ya] = m.position(a);
    auto [xb, yb] = m.position(b);
    ex d2 = model::trig_simplify(pow(xa - xb, 2) + pow(ya - yb, 2));
    return m.spring_length(d2) - free;
  }

  // on A: F = −k f(δ) (r_A − r_B)/L, L = |r_A − r_B|, f(δ) = δ, or (δ + σ|δ|)/2 when it acts only
  // stretched (σ = 1) or compressed (σ = −1); −F on B
  std::vector<model::Load> loads(const Model& m) const override {
    auto [xa, ya] = m.position(a);
    auto [xb, yb] = m.position(b);
    ex L = m.spring_length(model::trig_simplify(pow(xa - xb, 2) + pow(ya - yb, 2)));
    ex d = L - free;
    ex f = side == 0 ? d : (d + side * abs(d)) / 2;
    return {with_symbol(force_at(a, -k * f * (xa - xb) / L, -k * f * (ya - yb) / L, b), load_symbol(*this, "F"))};
  }

  ex potential(const Model& m) const override {
    if (side != 0) return 0;  // one-sided: no potential of q alone (its work is taken part by part)
    // V = ½ k (|r_A − r_B| − L₀)²
    auto [xa, ya] = m.position(a);
    auto [xb, yb] = m.position(b);
    ex d2 = model::trig_simplify(pow(xa - xb, 2) + pow(ya - yb, 2));
    if (free.is_zero()) return k * d2 / 2;
    return k * pow(m.spring_length(d2) - free, 2) / 2;
  }

  /// Is it engaged at state s (its δ of the acting sign)? nothing when δ there is not known yet.
  std::optional<bool> engaged(const Model& m, int s, const std::function<std::optional<GiNaC::numeric>(const ex&)>& value) const {
    auto d = value(m.bind(stretch(m), s));
    if (!d) return std::nullopt;
    return side < 0 ? d->is_negative() : d->is_positive();
  }

  /// Engaged at the two states of an energy analysis, as its equation takes it: where δ is known
  /// beforehand, from δ; where not, the opposite of the other state (a body meets the spring
  /// part-way, or leaves it behind). @throws SceneError when neither state tells.
  std::pair<bool, bool> engagement(const Model& m, int s1, int s2, const Knowledge& k) const {
    auto value = [&](const ex& e) { return k.value(e); };
    auto e1 = engaged(m, s1, value), e2 = engaged(m, s2, value);
    if (!e1 && !e2)
      throw SceneError(pos, "spring '" + name + "' acts only when " + (side < 0 ? "compressed" : "stretched") +
                                ", and neither state '" + m.states[s1].name + "' nor '" + m.states[s2].name + "' tells whether it is",
                       "give the position at one of the two states");
    if (!e1) e1 = !*e2;
    if (!e2) e2 = !*e1;
    return {*e1, *e2};
  }

  // U = V(s₁) − V(s₂), V = ½ k δ² where it is engaged and 0 where not: the integral of its force
  // over the part of the motion where it acts
  principles::Work work(const Model& m, int s1, int s2, const Knowledge& k) const override {
    if (side == 0) return Effect::work(m, s1, s2, k);
    auto [e1, e2] = engagement(m, s1, s2, k);
    ex V = this->k * pow(stretch(m), 2) / 2;  // (k here is the knowledge: the stiffness is this->k)
    principles::Work w;
    w.effect = name;
    w.U = (e1 ? m.bind(V, s1) : ex(0)) - (e2 ? m.bind(V, s2) : ex(0));
    w.ends_only = true;
    // what the equation took at each state, σ δ ≥ 0 where engaged and −σ δ ≥ 0 where not (σ = −1
    // acting compressed): with parameters without values, stated with the closed forms (the
    // launcher is left behind only where the block gets past its free length); with numbers,
    // check() below says it first
    const char* acting = side < 0 ? "compressed" : "stretched";
    for (auto [st, en] : {std::pair{s1, e1}, std::pair{s2, e2}})
      w.holds.push_back({(en ? side : -side) * m.bind(stretch(m), st),
                         "spring '" + name + "' was taken as " + (en ? "" : "not ") + acting + " at state '" + m.states[st].name +
                             "', but the solution puts it {} m the other way there",
                         "give the position at state '" + m.states[st].name + "' so that it is known whether the spring acts there", pos,
                         "spring '" + name + "' is " + (en ? "" : "not ") + acting + " at state '" + m.states[st].name + "'"});
    w.how = "U = V(" + m.states[s1].name + ") - V(" + m.states[s2].name + "), V = k*delta^2/2 where it is " +
            (side < 0 ? "compressed" : "stretched") + " (at " + (e1 && e2 ? "both states" : e1 ? "state " + m.states[s1].name : e2 ? "state " + m.states[s2].name : "neither state") + "), else 0";
    return w;
  }

  // the states solved as the energy equations took them: engaged where assumed
  void check(const Model& m, int s, const GiNaC::exmap& values) const override {
    if (s < 0 || side == 0) return;
    Knowledge before(m);
    for (auto& an : m.analyses) {
      if (an.type->impulsive() || (an.from != s && an.to != s) || activity(an) == Activity::None) continue;
      // an energy analysis with parameters without values states its engagement (work's holds),
      // not judged at the sample values that stand in for them
      if (!an.type->at_state() && m.unvalued()) continue;
      auto [e1, e2] = engagement(m, an.from, an.to, before);
      bool assumed = an.from == s ? e1 : e2;
      auto value = [&](const ex& e) -> std::optional<GiNaC::numeric> {
        try {
          // (the stretch's sign a choice reads: noted for a sweep, numeric/trace.hpp)
          return numerics::noted(e, values);
        } catch (const std::exception&) {
        }
        return std::nullopt;
      };
      auto actual = engaged(m, s, value);
      if (!actual || *actual == assumed) continue;
      auto d = value(m.bind(stretch(m), s));
      throw SceneError(pos, "spring '" + name + "' was taken as " + (assumed ? "" : "not ") + (side < 0 ? "compressed" : "stretched") +
                                " at state '" + m.states[s].name + "', but the solution puts its stretch there at " +
                                numerics::format(*d, 6) + " m" + (assumed ? ": the motion does not reach it" : ": it does act there"),
                       assumed ? "the body stops (or turns) before the spring: remove it from this analysis ('off:'), or check the state"
                               : "give the position at state '" + m.states[s].name + "' so that it is known whether the spring acts there");
    }
  }

  // a zigzag from P1 to P2: straight ends, eight teeth between, its name at the middle
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto [x1, y1] = at.point(m.position(a));
    auto [x2, y2] = at.point(m.position(b));
    const double L = std::hypot(x2 - x1, y2 - y1);
    if (!(L > 0)) return;
    const double ux = (x2 - x1) / L, uy = (y2 - y1) / L, w = std::min(f.glyph() * 0.5, L / 6);
    std::vector<std::pair<double, double>> pts{{x1, y1}, {x1 + ux * L * 0.15, y1 + uy * L * 0.15}};
    for (int i = 1; i <= 8; ++i) {
      const double s = 0.15 + 0.7 * (i - 0.5) / 8, side = (i % 2 ? 1 : -1) * w;
      pts.push_back({x1 + ux * L * s - uy * side, y1 + uy * L * s + ux * side});
    }
    pts.push_back({x1 + ux * L * 0.85, y1 + uy * L * 0.85});
    pts.push_back({x2, y2});
    f.polyline(pts, Ink::Spring);
    const draw::Name kn = value_label(k, "k");  // (by its stiffness, as a textbook labels a spring)
    f.label((x1 + x2) / 2, (y1 + y2) / 2, kn.text, kn.tex);
  }
};

}  // namespace

std::shared_ptr<Effect> read_spring(EffectReader& r, const EffectDef& ed) {
  auto e = make<Spring>(ed);
  e->has_potential = true;  // V = ½ k δ² (one-sided: none of q alone, below)
  r.only(ed, {"k", "free_length", "acts"});
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
  if (auto* acts = ed.options.get("acts")) {
    if (!acts->is_scalar() || (acts->scalar != "compression" && acts->scalar != "tension" && acts->scalar != "both"))
      throw SceneError(acts->pos, "'acts' must be compression, tension or both",
                       "write 'acts: compression' for a bumper or a launcher the body leaves");
    e->side = acts->scalar == "compression" ? -1 : acts->scalar == "tension" ? 1 : 0;
    e->has_potential = e->side == 0;
    if (e->side != 0 && e->free.is_zero())
      throw SceneError(acts->pos, "a spring that acts only in " + acts->scalar + " needs its free length",
                       "add 'free_length: L0'");
  }
  return e;
}

}  // namespace kinergy::effects
