// A friction couple M on a body (a bearing, a brake): −M against its turning; with `against: B`,
// between two bodies (a shell dropped on a turntable, a clutch): against their relative turning,
// on each equal and opposite.
#include "common.hpp"

namespace kinergy::effects {

namespace {

class FrictionCouple : public BodyEffect {
public:
  ex M = 0;

  // an arc round the body's centre: a bearing's or a brake's friction couple
  void draw(const Model& m, const At& at, Figure& f) const override { draw_turning(m, at, f, body, 0, Ink::Support, draw::from_tex(load_symbol(*this, "M", M)), 1.2, true); }
  std::optional<int> direction;  ///< the sign of the rotation it opposes, if declared
  std::optional<int> other;      ///< `against`: the body it turns against (else the ground)

  // M against the body's turning relative to the other (or the ground: a bearing, a brake's
  // frame), its reaction on that
  std::vector<model::Load> loads(const Model& m) const override {
    model::Load l = couple_on(m, body, 0, other ? *other : -1);
    l.kind = model::Load::Kind::Turn;
    l.size = M;
    l.direction = direction;
    l.symbol = load_symbol(*this, "M", M);
    return {l};
  }

};

}  // namespace

std::shared_ptr<Effect> read_friction_couple(EffectReader& r, const EffectDef& ed) {
  auto e = make<FrictionCouple>(ed);
  r.only(ed, {"M", "direction", "against"});
  e->body = r.body_ref(ed.arg, ed.kind);
  e->other = against(r, ed, e->body);
  e->M = non_negative(r, ed, "M", "M0", energy_dim(), "a couple is in N·m (or lb·ft)", "a friction couple");
  e->direction = r.direction_of(ed);
  return e;
}

}  // namespace kinergy::effects
