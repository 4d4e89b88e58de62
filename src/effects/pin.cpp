// A pin: two points that the coordinates keep together (a support the scene names, so that
// its reaction can be asked for). It does no work; its reaction is an unknown of a momentum
// analysis across it, and in an impact the pinned body's momentum change less the other impulses.
#include "common.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::effects {

namespace {

class Pin : public Effect {
public:
  PointRef a, b;

  // R on A, −R on B: the coordinates keep them together
  std::optional<model::Reaction> reaction(const Model&) const override { return model::Reaction::pin(a, b); }

  // a joint: a ring at the pinned point, on hatched ground when one side is a fixed point
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto [x, y] = at.point(m.position(b.body >= 0 ? b : a));
    f.circle(x, y, f.glyph() * 0.45, Ink::Support);
    if (a.body >= 0 && b.body >= 0) return;
    // the ground below the pin, as the ground is; above it where the pinned body hangs from it
    // (its mass centre within 60° of straight below the pin), so that the hatching does not cross it
    const int body = a.body >= 0 ? a.body : b.body;
    double dy = -1;
    if (body >= 0) {
      const model::Body& B = m.bodies[static_cast<std::size_t>(body)];
      const double ux = x - at(B.x), uy = y - at(B.y), d = std::hypot(ux, uy);
      if (d > 0.5 * f.glyph() && std::isfinite(d) && uy / d > 0.5) dy = 1;
      // a wheel on an axle at its centre: a post from the axle down to ground beyond its rim,
      // not hatching inside the wheel
      const double rim = f.reach("body " + B.name, x, y, 0, -1);
      if (d <= 0.5 * f.glyph() && rim > 1.5 * f.glyph()) {
        const double yg = y - rim - 0.5 * f.glyph();
        f.line(x, y, x, yg, Ink::Support);
        return f.ground(x, yg, 0, -1);
      }
    }
    f.ground(x, y, 0, dy);
  }
};

// A pin declares that two points coincide for every value of the coordinates.
void check_pin(const Model& m, const Pin& e, const SourcePos& pos) {
  auto [xa, ya] = m.position(e.a);
  auto [xb, yb] = m.position(e.b);
  ex dx = model::trig_simplify(xa - xb), dy = model::trig_simplify(ya - yb);
  if (dx.is_zero() && dy.is_zero()) return;
  for (const GiNaC::exmap& at : random_positions(m, m.parameter_values(), 12345)) {
    ex gx, gy;
    try {
      gx = dx.subs(at).evalf();
      gy = dy.subs(at).evalf();
    } catch (const std::exception&) {
      continue;  // undefined at this sample position: try another
    }
    if (!GiNaC::is_a<GiNaC::numeric>(gx) || !GiNaC::is_a<GiNaC::numeric>(gy)) return;  // symbolic parameters: trust it
    // how far apart, in CLN's numbers (a point 1e400 m away is no double)
    const GiNaC::numeric& nx = GiNaC::ex_to<GiNaC::numeric>(gx);
    const GiNaC::numeric& ny = GiNaC::ex_to<GiNaC::numeric>(gy);
    const GiNaC::numeric d = GiNaC::sqrt(nx * nx + ny * ny);
    // apart, against the size of the positions themselves (a scene may be a millimetre across)
    if (!numerics::negligible(dx, at).value_or(true) || !numerics::negligible(dy, at).value_or(true))
      throw SceneError(pos, "pin '" + e.name + "': " + e.a.text + " and " + e.b.text +
                                " do not coincide (apart by " + numerics::format(d, 6) + " m at some position)",
                       "fix the body's position/angle or the point so the pinned points stay together");
  }
}

}  // namespace

std::shared_ptr<Effect> read_pin(EffectReader& r, const EffectDef& ed) {
  auto e = make<Pin>(ed);
  e->has_potential = true;  // V = 0: it does no work
  r.only(ed, {});
  std::tie(e->a, e->b) = two_points(r, ed, "a pin joins two points", "write 'pin: [O, bar.O]'");
  check_pin(r.model(), *e, ed.arg.pos);
  return e;
}

}  // namespace kinergy::effects
