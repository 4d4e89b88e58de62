// A friction couple M on a body (a bearing, a brake): −M against its turning.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class FrictionCouple : public BodyEffect {
public:
  ex M = 0;

  // an arc round the body's centre: a bearing's or a brake's friction couple
  void draw(const Model& m, const At& at, Figure& f) const override { draw_turning(m, at, f, body, 0, Ink::Support, name, 1.2); }
  std::optional<int> direction;  ///< the sign of the rotation it opposes, if declared

  ex power(const Model& m) const override { return -M * abs(m.omega(body)); }  // P = −M |ω|

  principles::Work work(const Model& m, int s1, int s2, const Knowledge& k) const override {
    // angle turned: dℓ/ds = |∂φ/∂s| along the path
    auto turned = [&](const principles::Path& p) {
      ex phi = m.bodies[body].angle.subs(p.q_of_s);
      return sqrt(model::trig_simplify(pow(phi.diff(m.coords[p.s].q), 2)));
    };
    return principles::friction_work(m, *this, direction, M, turned, "U = -M * angle turned", s1, s2, k);
  }

  void pushes(const Model& m, const Analysis& a, const Knowledge& k, std::vector<Push>& out) const override {
    if (!on(a)) return;
    Push p;
    p.M = -M * principles::motion_direction(m, *this, direction, m.omega(body), a, k, "rotation", &p.holds);
    out.push_back(p);
  }

  void motion(const Model& m, int self, simulate::Equations& eq) const override {
    eq.friction.push_back({self, true, simulate::linear_rate(m, m.omega(body)), {}, M});
  }
};

}  // namespace

std::shared_ptr<Effect> read_friction_couple(EffectReader& r, const EffectDef& ed) {
  auto e = make<FrictionCouple>(ed);
  r.only(ed, {"M", "direction"});
  e->body = r.body_ref(ed.arg, ed.kind);
  e->M = non_negative(r, ed, "M", "M0", energy_dim(), "a couple is in N·m (or lb·ft)", "a friction couple");
  e->direction = r.direction_of(ed);
  return e;
}

}  // namespace kinergy::effects
