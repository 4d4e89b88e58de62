// A track: a point that the coordinates keep on a fixed line or circle (a collar on a guide, a
// pin in a slot, a block on a smooth surface, a ball in a bowl), declared so that it is checked
// and its normal reaction can be an unknown. Like a pin, a support the coordinates imply: it does
// no work, and in a momentum analysis across it its reaction along the track's normal n̂ is an
// unknown N (the impulse N n̂).
//
// One-sided or both ways: a surface can only push (a floor, a wall, a dome, an incline under a
// block: `pushes: up`, `pushes: outward`), a guide holds both ways (a slot, a collar on a rod, a
// bead on a wire: `holds: both`); a round body at an `offset` rests on the surface on its side.
// The scene says which: no default turns a dome into a guide. A one-sided track's N is positive
// when it pushes (its direction n̂ is the way it pushes), and N ≥ 0 is checked wherever it acts.
//
// Checked: the point's distance to the track, d = (r_P − r_0)·n̂ for a line through r_0, or
// |r_P − c| − R for a circle, less the declared offset (`offset: r`: the centre of a round body
// of radius r touching the surface — a wheel on a floor, a ball inside a bowl with offset −r),
// vanishes for every value of the coordinates (random samples) when the scene has no
// constraints, and at every state once the states are solved.

#include "common.hpp"
#include "kinergy/model/inertia.hpp"
#include <map>

#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/roots.hpp"
#include "kinergy/numeric/trace.hpp"

namespace kinergy::effects {

namespace {

/// The points of a body's outline that reach furthest (a rod's ends, a plate's corners, a disk's
/// rim at 24 places), with the body's size, at the values `num` gives: (x, y, size). A particle,
/// and a wheel known by its radius of gyration alone, have none.
template <class Num>
std::vector<std::array<double, 3>> outline_points(const model::Body& B, Num num) {
  std::vector<std::array<double, 3>> out;
  const double gx = num(B.x), gy = num(B.y), phi = num(B.angle);
  auto shape_points = [&](const std::string& shape, const std::vector<ex>& sizes, double cx, double cy, double turn) {
    if (shape.empty() || sizes.empty()) return;
    const model::InertiaShape& s = model::inertia_shape(shape);
    const double a = num(sizes[0]), b = sizes.size() > 1 ? num(sizes[1]) : a, c = std::cos(turn), d = std::sin(turn);
    auto put = [&](double lx, double ly, double size) { out.push_back({cx + c * lx - d * ly, cy + d * lx + c * ly, size}); };
    switch (s.outline) {
      case model::Outline::Bar:
        put(-a / 2, 0, a), put(a / 2, 0, a);
        break;
      case model::Outline::EdgeOn:
        put(s.span == 1 ? -a / 2 : -a, 0, a), put(s.span == 1 ? a / 2 : a, 0, a);
        break;
      case model::Outline::Rect:
        for (int i : {-1, 1})
          for (int j : {-1, 1}) put(i * a / 2, j * b / 2, std::max(a, b));
        break;
      case model::Outline::Round:
        for (int k = 0; k < 24; ++k) put(a * std::cos(k * M_PI / 12), a * std::sin(k * M_PI / 12), 2 * a);
        break;
      default:
        break;
    }
  };
  if (B.parts.empty()) shape_points(B.shape, B.sizes, gx, gy, phi);
  for (auto& part : B.parts) {
    const double lx = num(part.lx), ly = num(part.ly);
    shape_points(part.shape, part.sizes, gx + std::cos(phi) * lx - std::sin(phi) * ly, gy + std::sin(phi) * lx + std::cos(phi) * ly,
                 phi + num(part.angle));
  }
  return out;
}

class Track : public Effect {
public:
  PointRef p;
  bool circle = false;
  ex x0 = 0, y0 = 0;  ///< a point of the line, or the circle's centre
  ex tx = 0, ty = 0;  ///< the line's direction (unit)
  ex R = 0;           ///< the circle's radius
  ex offset = 0;      ///< the point's distance from the surface (on the normal's side; circle: outward)
  /// One-sided: the sign σ of the way it pushes against the geometric normal (k × t̂ of a line,
  /// outward for a circle); 0: a guide that holds both ways.
  int pushes = 0;
  /// A cord from a fixed point (`cord: [O, bob]`, `length: l`): the circle of radius l about O,
  /// pulling the point inward (pushes = −1), its N the cord's tension.
  bool cord = false;
  /// The restitution when a body that has left the surface strikes it again (`e:`; only a
  /// simulation has such a strike): without it, such a strike is an error that asks for it.
  ex e = 0;
  bool e_given = false;
  std::string shape;  ///< "the line through [..] along [..]", "the circle of centre [..] and radius R"
  SourcePos arg_pos;  ///< where its point is named


  // N n̂ on the point: the coordinates keep it on the track; one-sided, n̂ = σ × the geometric
  // normal, the way the surface pushes (N ≥ 0)
  std::optional<model::Reaction> reaction(const Model& m) const override {
    auto [nx, ny] = normal(m);
    // one-sided: the way it pushes; a guide: outward (a circle), or its line's normal taken up (or,
    // across a vertical line, along +x) — the sign rule, whatever way `along` is written
    const int s = pushes ? pushes : circle ? 1 : axis_sense(m, nx, ny);
    model::Reaction r = model::Reaction::track(p, s * nx, s * ny);
    r.one_sided = pushes != 0;
    r.pulls = cord;
    r.gap = s * distance(m);
    if (r.one_sided) r.e = e_given ? e : ex(-1);
    return r;
  }

  /// The unit normal n̂ at the point (generic): the line's normal k × t̂, or the circle's radius.
  std::pair<ex, ex> normal(const Model& m) const {
    if (!circle) return {-ty, tx};
    auto [x, y] = m.position(p);
    return {(x - x0) / (R + offset), (y - y0) / (R + offset)};  // the point keeps to radius R + offset
  }

  /// Signed distance of the point from where the track keeps it (generic):
  ///   line: (r_P − r_0)·n̂ − offset, n̂ = k × t̂;   circle: |r_P − c| − (R + offset)
  ex distance(const Model& m) const {
    auto [x, y] = m.position(p);
    if (!circle) return model::trig_simplify((x - x0) * -ty + (y - y0) * tx - offset);
    return sqrt(pow(x - x0, 2) + pow(y - y0, 2)) - (R + offset);
  }

  // the surface or guide (draw::line_support): under a round body at its offset, hatched on the
  // ground's side; else the surface the loads press the body onto, or a guide through the point.
  // A circle: the surface of radius R, hatched on the side away from the body (outside a bowl
  // the body is in, inside a dome it is on); a guide circle where there is no offset.
  void draw(const Model& m, const At& at, Figure& f) const override {
    auto [px, py] = at.point(m.position(p));
    const double off = at(offset);
    if (cord) {
      // the cord itself, from its anchor to the point (straight while taut)
      f.line(at(x0), at(y0), px, py, Ink::Cord);
      const draw::Name n = draw::from_tex(load_symbol(*this, "T"));
      f.label(0.5 * (at(x0) + px), 0.5 * (at(y0) + py), n.text, n.tex);
      return;
    }
    // a body off the surface (a simulation that has let it go): the surface and its name where
    // the coordinates would keep the point, its foot, not at the body
    if (const double d = at(distance(m)); std::isfinite(d) && std::fabs(d) > 1e-9 * (1 + std::hypot(px, py))) {
      if (circle) {
        const double cx = at(x0), cy = at(y0), k = (at(R) + off) / std::hypot(px - cx, py - cy);
        px = cx + k * (px - cx);
        py = cy + k * (py - cy);
      } else {
        px -= d * -at(ty);
        py -= d * at(tx);
      }
    }
    if (circle) {
      const double cx = at(x0), cy = at(y0), r = at(R);
      if (!pushes) f.circle(cx, cy, r, Ink::Support);
      else f.round_surface(cx, cy, r, pushes < 0);  // pushing inward: the body inside, the ground outside
    } else {
      draw::line_support(m, at, f, p.body, px, py, at(tx), at(ty), std::isfinite(off) ? off : 0, pushes);
    }
    // (not named: its hatching says it is a surface, as a textbook draws one)
  }

  std::string off_track(const Model& m, const GiNaC::exmap& at) const {
    ex d = distance(m);
    ex v;
    try {
      v = d.subs(at).evalf();
    } catch (const std::exception&) {
      return "";  // undefined there: nothing to tell
    }
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return "";
    // off, against the size of the positions themselves (a scene may be a millimetre across)
    auto [x, y] = m.position(p);
    ex scale = sqrt(pow(x, 2) + pow(y, 2) + pow(x0, 2) + pow(y0, 2) + pow(R, 2) + pow(offset, 2));
    auto s = numerics::evaluate(scale, at, 30);
    GiNaC::numeric dv = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(v));
    // the choice reads the sign of s·10⁻⁹ − |d| (noted for a sweep: numeric/trace.hpp)
    if (s && numerics::tracing()) numerics::note(scale * GiNaC::numeric(1, 1000000000) - abs(d), *s * GiNaC::numeric(1, 1000000000) - dv);
    if (!s || dv <= *s * GiNaC::numeric(1, 1000000000)) return "";
    return numerics::format(dv, 6) + " m";
  }

  // for every value of the coordinates, when no constraint relates them (else: at the states)
  void check(const Model& m, int state, const GiNaC::exmap& values) const override {
    if (state < 0) check_everywhere(m);
    else check_at(m, state, values);
  }

  void check_everywhere(const Model& m) const {
    if (!m.constraints.empty()) return;
    for (GiNaC::exmap& at : random_positions(m, m.numeric_environment(), 4242)) {
      // (a sweep's trace takes the sample's coordinates as the numbers they are here)
      GiNaC::exmap probe;
      if (numerics::tracing()) {
        probe[m.t] = at[m.t];
        for (auto& c : m.coords) probe[c.q] = at[c.q];
      }
      const numerics::TraceForms traced(probe);
      std::string off = off_track(m, at);
      if (off.empty()) continue;
      std::string where;
      for (auto& c : m.coords)
        where += (where.empty() ? "" : ", ") + c.name + " = " + numerics::format(GiNaC::ex_to<GiNaC::numeric>(at[c.q]), 4);
      throw SceneError(arg_pos, "track '" + name + "': " + p.text + " is " + off + " off " + shape + " at " + where,
                       "fix the body's position/angle or the point so that " + p.text + " stays on its track for every value "
                       "of the coordinates");
    }
  }

  void check_at(const Model& m, int state, const GiNaC::exmap& values) const {
    GiNaC::exmap at = values;
    for (auto& c : m.coords) {
      auto it = values.find(m.states[state].sym.at(c.name).first);
      if (it == values.end()) return;  // not fixed at this state
      at[c.q] = it->second;
    }
    at[m.t] = values.count(m.states[state].t) ? values.at(m.states[state].t) : ex(0);
    // (the coordinates are this state's: a sweep's trace follows them to their forms)
    GiNaC::exmap here;
    if (numerics::tracing()) {
      here[m.t] = values.count(m.states[state].t) ? ex(m.states[state].t) : ex(0);
      for (auto& c : m.coords) here[c.q] = m.states[state].sym.at(c.name).first;
    }
    const numerics::TraceForms traced(here);
    std::string off = off_track(m, at);
    if (!off.empty())
      throw SceneError(pos, "track '" + name + "': " + p.text + " is " + off + " off " + shape + " at state '" +
                                m.states[state].name + "'",
                       "fix the body's position/angle, the point or the track so that " + p.text + " stays on it");
    check_pose(m, state, at);
  }

  // A surface that only pushes holds a body by one of its points (a rod's end on a floor): the
  // rest of the body stays on the side it pushes toward — at no outline point is
  //   (r − r₀)·n̂ < 0   (n̂ the way it pushes)
  // by more than a millionth of the body's size. (A body held by its mass centre is drawn with
  // the surface at its edge: nothing to tell.)
  void check_pose(const Model& m, int state, const GiNaC::exmap& at) const {
    if (!pushes || circle || p.body < 0 || p.ground || (p.lx.is_zero() && p.ly.is_zero() && !p.world_place)) return;
    const model::Body& B = m.bodies[static_cast<std::size_t>(p.body)];
    auto num = [&](const ex& e) {
      try {
        const ex v = e.subs(at).evalf();
        return GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real() ? GiNaC::ex_to<GiNaC::numeric>(v).to_double()
                                                                                          : std::nan("");
      } catch (const std::exception&) {
        return std::nan("");
      }
    };
    const double nx = pushes * -num(ty), ny = pushes * num(tx), n = std::hypot(nx, ny), X0 = num(x0), Y0 = num(y0);
    double deepest = 0, size = 0, wx = 0, wy = 0;
    for (auto [px, py, extent] : outline_points(B, num)) {
      const double depth = ((px - X0) * nx + (py - Y0) * ny) / n;
      size = std::max(size, extent);
      if (std::isfinite(depth) && depth < deepest) deepest = depth, wx = px, wy = py;
    }
    if (!(deepest < -1e-6 * size)) return;
    // (a place a rounding's width from 0 is 0)
    if (std::fabs(wx) < 1e-12 * size) wx = 0;
    if (std::fabs(wy) < 1e-12 * size) wy = 0;
    throw SceneError(pos, "track '" + name + "' only pushes, and at state '" + m.states[state].name + "' " + B.name + " reaches " +
                              numerics::g_text(-deepest, 4) + " m through it (at [" +
                              numerics::g_text(wx, 4) + ", " +
                              numerics::g_text(wy, 4) + "]): a body rests on a surface, it does not pass through it",
                     "give state '" + m.states[state].name + "' a position with " + B.name + " on the side '" + name +
                         "' pushes it to (an angle the other way, or the surface's 'pushes' turned round)");
  }
};

}  // namespace

namespace {

/// `pushes:` or `holds: both` (or, with an `offset`, the side the round body is on): what the
/// track can do, as the sign σ of its push against the geometric normal n̂ (0: both ways).
/// `side`: the sign of the offset (the side of the surface a round body is on), 0 without one.
void read_sidedness(EffectReader& r, const EffectDef& ed, Track& e, int side) {
  const scene::Node* pushes = ed.options.get("pushes");
  const scene::Node* holds = ed.options.get("holds");
  const std::string fix = e.circle ? "write 'pushes: outward' (a surface the body is on: a dome), 'pushes: inward' (a surface the body is in: a "
                                     "bowl, a loop) or 'holds: both' (a guide: a bead on a wire, a pin in a curved slot)"
                                   : "write 'pushes: up' (or down, left, right, or a direction [nx, ny] across the line: the way the surface "
                                     "pushes the body) or 'holds: both' (a guide: a collar on a rod, a pin in a slot)";
  if (pushes && holds)
    throw SceneError(holds->pos, "track '" + ed.name + "' says both 'pushes' and 'holds'", "keep one: " + fix);
  if (holds) {
    if (!holds->is_scalar() || holds->scalar != "both")
      throw SceneError(holds->pos, "'holds' of track '" + ed.name + "' is 'both' (a guide that holds both ways), not '" + holds->scalar + "'",
                       "write 'holds: both', or 'pushes: ...' for a surface that can only push");
    e.pushes = 0;
    return;
  }
  if (!pushes) {
    // a round body at an offset rests on the surface on its side (it can only push it away)
    if (side != 0) {
      e.pushes = side;
      return;
    }
    throw SceneError(ed.pos, "track '" + ed.name + "' does not say whether it can only push (a surface) or holds both ways (a guide)", fix);
  }
  int sigma = 0;
  if (e.circle) {
    if (!pushes->is_scalar() || (pushes->scalar != "outward" && pushes->scalar != "inward"))
      throw SceneError(pushes->pos, "a circular track pushes 'outward' (away from its centre) or 'inward', not " +
                                        (pushes->is_scalar() ? "'" + pushes->scalar + "'" : std::string("a direction")),
                       fix);
    sigma = pushes->scalar == "outward" ? 1 : -1;
  } else {
    // up, down, left, right, or [nx, ny]: along the line's normal n̂ = k × t̂ or against it
    ex dx, dy;
    static const std::map<std::string, std::pair<int, int>> words{{"up", {0, 1}}, {"down", {0, -1}}, {"left", {-1, 0}}, {"right", {1, 0}}};
    if (pushes->is_scalar()) {
      auto w = words.find(pushes->scalar);
      if (w == words.end())
        throw SceneError(pushes->pos, "'pushes' of track '" + ed.name + "' is up, down, left, right or a direction [nx, ny], not '" +
                                          pushes->scalar + "'",
                         fix);
      dx = w->second.first;
      dy = w->second.second;
    } else {
      std::tie(dx, dy) = r.vec(*pushes, "pushes", units::Dimension{}, false, "a direction is a pair of pure numbers: [0, 1]");
    }
    const ex nx = -e.ty, ny = e.tx;
    const ex cross = model::trig_simplify(dx * ny - dy * nx), dot = model::trig_simplify(dx * nx + dy * ny);
    auto c = r.value_of(cross, pushes->pos, "the direction the track pushes");
    auto d = r.value_of(dot, pushes->pos, "the direction the track pushes");
    // across the line: |d × n̂| small against |d|
    auto len = r.value_of(model::trig_simplify(dx * dx + dy * dy), pushes->pos, "the direction the track pushes");
    if (!c || !d || !len || len->is_zero())
      throw SceneError(pushes->pos, "the direction track '" + ed.name + "' pushes needs a value (its parameters have none)",
                       "give the direction as up, down, left or right, or in parameters that have values");
    if (!cross.is_zero() && GiNaC::abs(*c) > GiNaC::sqrt(*len) * numerics::tenth(9))
      throw SceneError(pushes->pos, "track '" + ed.name + "' pushes along its line's normal, and " +
                                        (pushes->is_scalar() ? "'" + pushes->scalar + "'" : std::string("this direction")) + " is not across " + e.shape,
                       "give the direction across the line, the way the surface pushes the body");
    sigma = d->is_positive() ? 1 : -1;
  }
  // a round body at an offset rests on its own side: the surface pushes it that way
  if (side != 0 && sigma != side)
    throw SceneError(pushes->pos, "track '" + ed.name + "' pushes the round body toward the surface, but its offset puts the body on the other side",
                     "the surface pushes the body away from itself: turn 'pushes' round, or leave it out (the offset says it)");
  e.pushes = sigma;
}

/// `e`: how a body that has left the surface (a slack cord's point) rebounds when it strikes it
/// again (the cord snaps taut), v_n⁺ = −e v_n⁻, from 0 to 1; only a simulation has such a strike.
void read_restitution(EffectReader& r, const EffectDef& ed, const scene::Node& en, Track& e, const std::string& kind, const std::string& range) {
  e.e = r.quantity(r.text_of(en, "e", "0.5"), false, units::Dimension{}, "e", "a coefficient of restitution is a pure number from 0 to 1");
  auto v = r.value_of(e.e, en.pos, "the coefficient of restitution");
  if (v && (v->is_negative() || *v > 1))
    throw SceneError(en.pos, "the coefficient of restitution of " + kind + " '" + ed.name + "' is " + numerics::format(*v, 6) + ", not from 0 to 1",
                     "give e from " + range);
  e.e_given = true;
}

}  // namespace

std::shared_ptr<Effect> read_track(EffectReader& r, const EffectDef& ed) {
  auto e = make<Track>(ed);
  e->has_potential = true;  // V = 0: a smooth track does no work
  r.only(ed, {"line", "circle", "offset", "pushes", "holds", "e"});
  e->p = r.point_ref(ed.arg, ed.kind);
  e->arg_pos = ed.arg.pos;
  if (e->p.body < 0)
    throw SceneError(ed.arg.pos, "a track holds a point of a body, but '" + ed.arg.scalar + "' is a fixed point",
                     "name body.point or a body (its mass centre)");
  const scene::Node* line = ed.options.get("line");
  const scene::Node* circle = ed.options.get("circle");
  if ((line != nullptr) == (circle != nullptr))
    throw SceneError(ed.pos, "track '" + ed.name + "' needs one shape: 'line' or 'circle'",
                     "write 'line: {through: [0, 0], along: [1, 0]}' or 'circle: {centre: [0, 0], radius: R}'");
  auto text_of_vec = [](const scene::Node& n) { return "[" + n.items[0].scalar + ", " + n.items[1].scalar + "]"; };
  const units::Dimension L = units::Dimension::length();
  if (line) {
    if (!line->is_map() || !line->get("through") || !line->get("along"))
      throw SceneError(line->pos, "'line' is given by a point and a direction", "write 'line: {through: [0, 0], along: [1, 0]}'");
    std::tie(e->x0, e->y0) = r.vec(*line->get("through"), "through", L, false, "a point of the line is a pair of lengths");
    auto [dx, dy] = r.vec(*line->get("along"), "along", units::Dimension{}, false, "a direction is a pair of pure numbers");
    ex len2 = model::trig_simplify(pow(dx, 2) + pow(dy, 2));
    auto lv = r.value_of(len2, line->get("along")->pos, "the direction of the line");
    if (len2.is_zero() || (lv && lv->is_zero()))
      throw SceneError(line->get("along")->pos, "the direction of the line of track '" + ed.name + "' is zero", "write e.g. [1, 0]");
    ex len = model::root_simplify(sqrt(len2));
    e->tx = dx / len;
    e->ty = dy / len;
    e->shape = "the line through " + text_of_vec(*line->get("through")) + " along " + text_of_vec(*line->get("along"));
  } else {
    if (!circle->is_map() || !circle->get("centre") || !circle->get("radius"))
      throw SceneError(circle->pos, "'circle' is given by its centre and radius", "write 'circle: {centre: [0, 0], radius: R}'");
    e->circle = true;
    std::tie(e->x0, e->y0) = r.vec(*circle->get("centre"), "centre", L, false, "a centre is a pair of lengths");
    const scene::Node& rn = *circle->get("radius");
    e->R = r.quantity(r.text_of(rn, "radius", "R"), false, L, "radius", "a radius is a length");
    r.positive(e->R, rn.pos, "the radius of track '" + ed.name + "'");
    e->shape = "the circle of centre " + text_of_vec(*circle->get("centre")) + " and radius " + rn.scalar;
  }
  int side = 0;  // the sign of the offset: the side of the surface a round body is on
  if (auto* o = ed.options.get("offset")) {
    e->offset = r.quantity(r.text_of(*o, "offset", "r"), false, L, "offset", "an offset is a length (the radius of the round body)");
    e->shape += " at distance " + o->scalar;
    // a round body on the offset's side: the surface can only push it that way
    if (auto v = numerics::evaluate(e->offset, r.model().numeric_environment(), 30); v && !v->is_zero()) side = v->is_positive() ? 1 : -1;
    if (e->circle) {
      auto rv = r.value_of(e->R + e->offset, o->pos, "the radius of the circle the point keeps to");
      if (rv && !rv->is_positive())
        throw SceneError(o->pos, "track '" + ed.name + "': the offset " + o->scalar + " leaves no circle for the point (R + offset = " +
                                     numerics::format(*rv, 6) + " m)",
                         "a ball of radius r inside a bowl of radius R has offset -r with r < R");
    }
  }
  read_sidedness(r, ed, *e, side);
  if (auto* en = ed.options.get("e")) {
    if (!e->pushes)
      throw SceneError(en->pos, "track '" + ed.name + "' holds both ways, so a body never leaves it to strike it again: 'e' has no use here",
                       "leave 'e' out, or say 'pushes: ...' for a surface that can only push");
    read_restitution(r, ed, *en, *e, "track", "0 (the body lands and stays) to 1 (it rebounds with its speed)");
  }
  return e;
}

// A cord from a fixed point O to a point of a body, of length l: while taut it keeps the point on
// the circle of radius l about O and pulls it toward O with its tension N ≥ 0; it goes slack where
// N falls to zero (a bob whirled too slowly in a vertical circle). A track that can only pull.
std::shared_ptr<Effect> read_cord(EffectReader& r, const EffectDef& ed) {
  auto e = make<Track>(ed);
  e->has_potential = true;  // V = 0: a taut cord of fixed length does no work
  r.only(ed, {"length", "e"});
  auto [anchor, p] = two_points(r, ed, "a cord runs from a fixed point to a point of a body", "write 'cord: [O, bob]' (the fixed point, then the body's point)");
  if (anchor.body >= 0 || anchor.world_place)
    throw SceneError(ed.arg.pos, "cord '" + ed.name + "' is tied to a moving body at '" + anchor.text + "'; a cord here runs from a fixed point",
                     "write the fixed point first: 'cord: [O, bob]'");
  if (p.body < 0 || p.world_place)
    throw SceneError(ed.arg.pos, "cord '" + ed.name + "' holds a point of a body, but '" + p.text + "' is not one", "name body.point or a body (its mass centre)");
  e->p = p;
  e->arg_pos = ed.arg.pos;
  e->circle = true;
  e->cord = true;
  e->pushes = -1;  // its pull is toward the anchor
  e->x0 = anchor.wx;
  e->y0 = anchor.wy;
  const scene::Node& ln = r.option(ed, "length", "l");
  e->R = r.quantity(r.text_of(ln, "length", "l"), false, units::Dimension::length(), "length", "a cord's length is a length");
  r.positive(e->R, ln.pos, "the length of cord '" + ed.name + "'");
  e->shape = "the circle of radius " + ln.scalar + " about " + anchor.text + " (the cord taut)";
  if (auto* en = ed.options.get("e")) read_restitution(r, ed, *en, *e, "cord", "0 (the cord stays taut when it straightens) to 1");
  return e;
}

}  // namespace kinergy::effects
