// Kinetic friction μN at a sliding point (a known normal force), against the sliding.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Friction : public Effect {
public:
  PointRef a;
  ex mu = 0, normal = 0;
  std::optional<int> direction;  ///< the sign of the motion it opposes, if declared
  std::vector<int> bodies_acted(const Model&) const override { return bodies_of({a.body}); }

  ex power(const Model& m) const override {
    // P = −μ N |v_P|
    auto [vx, vy] = m.velocity(a);
    return -mu * normal * sqrt(model::trig_simplify(vx * vx + vy * vy));
  }

  principles::Work work(const Model& m, int s1, int s2, const Knowledge& k) const override {
    // distance slid: dℓ/ds = |∂r_P/∂s|, the velocity at ṡ = 1 with the others following
    auto slid = [&](const principles::Path& p) {
      const GiNaC::symbol& s = m.coords[p.s].q;
      auto [x, y] = m.velocity(a);
      GiNaC::exmap rates;
      for (std::size_t j = 0; j < m.coords.size(); ++j) {
        ex qj = j == p.s ? ex(s) : m.coords[j].q.subs(p.q_of_s);
        rates[m.coords[j].qd] = qj.diff(s);
      }
      ex vx = x.subs(rates).subs(p.q_of_s), vy = y.subs(rates).subs(p.q_of_s);
      return sqrt(model::trig_simplify(vx * vx + vy * vy));
    };
    return principles::friction_work(m, *this, direction, mu * normal, slid, "U = -mu N * distance", s1, s2, k);
  }

  void pushes(const Model& m, const Analysis& an, const Knowledge& k, std::vector<Push>& out) const override {
    if (!acts_on(an, a.body)) return;
    // kinetic friction −μN û against the sliding velocity of the point at the first state
    auto [vx, vy] = m.velocity(a);
    ex ux, uy;
    bool x0 = principles::vanishes(m, vy), y0 = principles::vanishes(m, vx);
    if (x0 && !y0) {
      ux = principles::motion_direction(m, *this, direction, vx, an, k, "sliding");
      uy = 0;
    } else if (y0 && !x0) {
      ux = 0;
      uy = principles::motion_direction(m, *this, direction, vy, an, k, "sliding");
    } else {
      throw SceneError(pos, "friction '" + name + "' slides along a changing direction; its impulse needs the motion in time",
                       "use friction whose contact slides along a fixed line (x or y)");
    }
    Push p;
    p.Fx = -mu * normal * ux;
    p.Fy = -mu * normal * uy;
    auto [x, y] = m.position(a);
    p.arm_x = x;
    p.arm_y = y;
    out.push_back(p);
  }

  void motion(const Model& m, int self, simulate::Equations& eq) const override {
    // the slip velocity of the material point under the friction
    auto [vx, vy] = m.velocity(a);
    eq.friction.push_back({self, false, simulate::linear_rate(m, vx), simulate::linear_rate(m, vy), mu * normal});
  }
};

}  // namespace

std::shared_ptr<Effect> read_friction(EffectReader& r, const EffectDef& ed) {
  auto e = make<Friction>(ed);
  r.only(ed, {"mu", "normal", "at", "direction"});
  e->a = r.acting_point(ed);
  e->mu = non_negative(r, ed, "mu", "mu_k", Dimension{}, "a friction coefficient is a pure number", "the friction coefficient");
  e->normal = non_negative(r, ed, "normal", "m*g", force_dim(), "a normal force is in N (or lb)", "the normal force");
  e->direction = r.direction_of(ed);
  return e;
}

}  // namespace kinergy::effects
