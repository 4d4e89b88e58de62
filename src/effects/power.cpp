// A power drive: a motor delivering power P to a body (the couple P/ω).
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Power : public BodyEffect {
public:
  ex P = 0;

  // a curved arrow round the body's centre: the drive (in the sense of the motion it drives)
  void draw(const Model& m, const At& at, Figure& f) const override { draw_turning(m, at, f, body, 1, Ink::Force, name + " (P)"); }

  ex power(const Model&) const override { return P; }

  principles::Work work(const Model& m, int s1, int s2, const Knowledge&) const override {
    // U = P (t₂ − t₁)
    principles::Work w;
    w.effect = name;
    w.U = P * (m.states[s2].t - m.states[s1].t);
    w.how = "U = P (t2 - t1)";
    return w;
  }

  void pushes(const Model&, const Analysis& a, const Knowledge&, std::vector<Push>&) const override {
    if (!on(a)) return;
    throw SceneError(pos, "a power drive '" + name + "' has no impulse of its own",
                     "give the drive as a couple or a force, or use an energy analysis");
  }

  void motion(const Model& m, int self, simulate::Equations& eq) const override {
    // the couple P/ω on the body: Q_i = (P/ω) ∂φ/∂q_i
    simulate::ForceTerm f{self, {}, false, P, ""};
    f.singular = " (power drive '" + name + "' gives the couple P/omega: it is infinite at omega = 0)";
    ex w = m.omega(body);
    for (auto& co : m.coords) f.Q.push_back(P * m.bodies[body].angle.diff(co.q) / w);
    eq.forces.push_back(f);
  }

  std::string start_problem(const Model& m, const GiNaC::exmap& at) const override {
    // its couple P/ω is infinite at ω = 0
    ex w = m.omega(body).subs(at).evalf();
    if (GiNaC::is_a<GiNaC::numeric>(w) && GiNaC::ex_to<GiNaC::numeric>(w).is_zero())
      return "power drive '" + name + "' starts from rest, where its couple P/omega is infinite";
    return "";
  }
};

}  // namespace

std::shared_ptr<Effect> read_power(EffectReader& r, const EffectDef& ed) {
  auto e = make<Power>(ed);
  r.only(ed, {"P"});
  e->body = r.body_ref(ed.arg, ed.kind);
  e->P = r.quantity(r.text_of(r.option(ed, "P", "P0"), "P", "P0"), false, energy_dim() / Dimension::time(), "P",
                    "a power is in W (or hp)");
  return e;
}

}  // namespace kinergy::effects
