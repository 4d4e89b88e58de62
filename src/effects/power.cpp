// A power drive: a motor delivering power P to a body (the couple P/ω).
#include "common.hpp"

namespace kinergy::effects {

namespace {

class Power : public BodyEffect {
public:
  ex P = 0;

  // the couple P/ω on the body, its reaction on the ground (the drive's frame)
  std::vector<model::Load> loads(const Model& m) const override {
    model::Load l = couple_on(m, body, P / m.omega(body), -1);
    l.singular = "power drive '" + name + "' gives the couple P/omega: it is infinite at omega = 0";
    l.symbol = load_symbol(*this, "M");  // (a drive's couple)
    return {l};
  }

  // a curved arrow round the body's centre: the drive (in the sense of the motion it drives)
  void draw(const Model& m, const At& at, Figure& f) const override { draw_turning(m, at, f, body, 1, Ink::Force, draw::from_tex(load_symbol(*this, "P", P))); }
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
