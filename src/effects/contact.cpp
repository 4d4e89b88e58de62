// A contact: two parties (body points, bodies, fixed points or the ground) that may strike along
// a normal n̂ (from the first into the second) with restitution e, smooth or rough.
#include <cmath>

#include "kinergy/draw/figure.hpp"

#include "common.hpp"

namespace kinergy::effects {

namespace {

class Contact : public Effect {
public:
  PointRef a, b;   ///< parties: body points, bodies, fixed points or ground
  ex nx = 0, ny = 0;  ///< unit normal from a into b
  ex e = 0;           ///< coefficient of restitution
  bool stick = false;  ///< rough: no sliding after the impact
  std::vector<std::size_t> holds;  ///< plastic and rough: r_b − r_a = 0 (x, y) once it has struck
  int turns = -1;                  ///< the body whose surface it is (its n̂ turns with it), −1: fixed
  bool lodged = false;             ///< `lodges: true`: b embeds in a, held both ways from its impact on

  /// J n̂ + Jt t̂ on b, −that on a, in impacts
  std::optional<model::Reaction> reaction(const Model&) const override;
  void draw(const Model& m, const draw::At& at, draw::Figure& f) const override;
};

std::optional<model::Reaction> Contact::reaction(const Model&) const {
  model::Reaction r = model::Reaction::contact(a, b, nx, ny, e, stick);
  r.holds = holds;
  r.turns = turns;
  r.lodged = lodged;
  return r;
}

// the contact: its surface (a line across n̂ through the first party's point, hatched when that
// party is fixed) and n̂ as a short arrow from there into the second party
void Contact::draw(const Model& m, const draw::At& at, draw::Figure& f) const {
  // the surface is the plane through party a perpendicular to n̂ (the simulator's gap is measured
  // from it; the ground's plane passes through the origin): drawn where party b's point projects
  // onto it, r = r_b − ((r_b − r_a)·n̂) n̂, the normal from there
  auto [xa, ya] = at.point(m.position(a));
  auto [xb, yb] = at.point(m.position(b));
  // (one that has closed in its impact: its normal as it has turned with its surface since;
  // where the angle it closed at is not known, an animation's frame: as written)
  auto [enx, eny] = m.closed_normal(*this);
  if (std::isnan(at(enx)) || std::isnan(at(eny))) enx = nx, eny = ny;
  const double len = std::hypot(at(enx), at(eny));
  const double ux = at(enx) / len, uy = at(eny) / len, g = f.glyph();
  const double gap = (xb - xa) * ux + (yb - ya) * uy;
  const double x = xb - gap * ux, y = yb - gap * uy;
  // a fixed party's surface is the ground: hatched behind it (against n̂); between bodies, dashed
  if (a.body < 0) f.surface(x - uy * g * 3, y + ux * g * 3, x + uy * g * 3, y - ux * g * 3, -ux, -uy);
  else f.line(x - uy * g * 3, y + ux * g * 3, x + uy * g * 3, y - ux * g * 3, draw::Ink::Track);
  f.arrow(x, y, x + ux * g * 2, y + uy * g * 2, draw::Ink::Thin);
  f.label(x + ux * g * 2, y + uy * g * 2, "n", "\\mathbf{n}");
}

}  // namespace

std::shared_ptr<Effect> read_contact(EffectReader& r, const EffectDef& ed) {
  auto c = make<Contact>(ed);
  if (!ed.arg.is_list() || ed.arg.items.size() != 2)
    throw SceneError(ed.arg.pos, "a contact names two parties",
                     "write 'contact: [ball, bar.Q]' (body points, bodies, fixed points or ground)");
  r.only(ed, {"normal", "e", "tangential", "surface", "lodges"});
  c->a = r.party(ed.arg.items[0]);
  c->b = r.party(ed.arg.items[1]);
  if (c->a.body < 0 && c->b.body < 0)
    throw SceneError(ed.arg.pos, "contact '" + ed.name + "' joins two fixed parties; nothing can strike",
                     "make at least one party a body or a body point");
  const scene::Node& nn = r.option(ed, "normal", "[0, 1]");
  auto [nx, ny] = r.vec(nn, "normal", Dimension{}, false, "a normal is a direction: a pair of pure numbers");
  ex n2 = model::trig_simplify(nx * nx + ny * ny);
  auto nv = r.value_of(n2, nn.pos, "the normal of '" + ed.name + "'");
  if (n2.is_zero() || (nv && nv->is_zero()))
    throw SceneError(nn.pos, "the normal of contact '" + ed.name + "' is zero", "write a direction, e.g. [0, 1]");
  // n̂ = n / |n|
  c->nx = nx / sqrt(n2);
  c->ny = ny / sqrt(n2);
  // `lodges: true`: b embeds in a (a bullet in a block) — plastic (e = 0) and rough, and it holds
  // both ways from then on; e and tangential are then not written
  if (const scene::Node* lo = ed.options.get("lodges")) {
    if (!lo->is_scalar() || (lo->scalar != "true" && lo->scalar != "false"))
      throw SceneError(lo->pos, "'lodges' must be true or false", "write 'lodges: true' for a body that embeds in the other (a bullet in a block)");
    c->lodged = lo->scalar == "true";
    for (const char* k : {"e", "tangential"})
      if (const scene::Node* x = ed.options.get(k); x && c->lodged)
        throw SceneError(x->pos, std::string("contact '") + ed.name + "' lodges, which is e: 0 and tangential: stick already; '" + k + "' is not written beside it",
                         std::string("remove '") + k + "'");
  }
  const scene::Node& en = c->lodged ? ed.arg : r.option(ed, "e", "0.5");
  c->e = c->lodged ? ex(0) : r.quantity(r.text_of(en, "e", "0.5"), false, Dimension{}, "e", "a coefficient of restitution is a pure number");
  if (auto v = r.value_of(c->e, en.pos, "the coefficient of restitution"); v && (v->is_negative() || *v > 1))
    throw SceneError(r.value_place(c->e, en.pos),
                     "the coefficient of restitution of '" + ed.name + "' is " + model::text(*v) + ", outside [0, 1]",
                     std::string("give ") +
                         (GiNaC::is_a<GiNaC::symbol>(c->e) ? "'" + model::text(c->e) + "' a value" : std::string("e")) +
                         " between 0 (plastic: the parties move together) and 1 (elastic)");
  if (c->lodged) c->stick = true;
  if (auto* tg = ed.options.get("tangential")) {
    if (!tg->is_scalar() || (tg->scalar != "stick" && tg->scalar != "smooth"))
      throw SceneError(tg->pos, "'tangential' must be stick or smooth",
                       "write 'tangential: stick' for a rough contact that does not slide after the impact");
    c->stick = tg->scalar == "stick";
  }
  // plastic and rough (e = 0, stick): once it has struck, the parties move together at the point —
  // a pin that can only push along n̂ (a wheel pivoting about the corner it struck):
  //   x_b − x_a = 0,  y_b − y_a = 0   from the state its impact ends at (Model::closed_from)
  const auto ev = r.value_of(c->e, en.pos, "the coefficient of restitution");
  const bool stays = c->stick && ev && ev->is_zero() && c->a.body != c->b.body && !c->a.ground && !c->b.ground;
  if (c->lodged && !stays)
    throw SceneError(ed.arg.pos, "contact '" + ed.name + "' lodges: one body embeds in another at a point, and its parties are not two (a body and another body or a fixed point)",
                     "name a body or body point on each side, or a fixed point: 'contact: [block, bullet]' (the ground is a line, not a point to embed at)");
  const scene::Node* sn = ed.options.get("surface");
  if (sn) {
    if (!stays)
      throw SceneError(sn->pos, "contact '" + ed.name + "': 'surface' says whose surface the normal is, which matters only for a contact that stays closed after its impact, and this one " +
                                    (c->stick ? "rebounds (e > 0)" : "is smooth (it slides after the impact)"),
                       "leave 'surface' out, or make the contact plastic and rough: 'e: 0, tangential: stick' (a wheel that strikes a corner and pivots about it)");
    const scene::Text who = r.text_of(*sn, "surface", "wheel");
    const auto of = [&](const PointRef& p) { return p.body >= 0 ? r.model().bodies[static_cast<std::size_t>(p.body)].name : std::string("ground"); };
    if (who.s != of(c->a) && who.s != of(c->b))
      throw SceneError(sn->pos, "contact '" + ed.name + "': 'surface: " + who.s + "' is not a party's: the surface is " + of(c->a) + "'s or " + of(c->b) + "'s",
                       "write 'surface: " + of(c->b) + "' where the other party is a corner on its surface (a wheel's rim on a step's edge: its normal turns with the wheel), "
                       "'surface: " + of(c->a) + "' for the other way round");
    const PointRef& p = who.s == of(c->a) ? c->a : c->b;
    c->turns = p.body;
  } else {
    c->turns = c->a.body;  // the surface through party a (the normal points from it into b)
  }
  if (stays) {
    auto [xa, ya] = r.model().position(c->a);
    auto [xb, yb] = r.model().position(c->b);
    c->holds.push_back(r.relation(xb - xa, ed.arg.pos));
    c->holds.push_back(r.relation(yb - ya, ed.arg.pos));
  }
  return c;
}


}  // namespace kinergy::effects
