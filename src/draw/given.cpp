// The data a state gives, drawn as a textbook draws it (issue 47): a given rate as an arrow beside
// the body it moves (a curved arrow round a body it turns) with its value, and a given coordinate
// that places the state as an angle arc, or a dimension line, from where that coordinate is zero.
#include <algorithm>
#include <cmath>

#include "kinergy/model/model.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/units/units.hpp"
#include "page.hpp"

namespace kinergy::draw::detail {

using GiNaC::ex;

namespace {

/// How body b moves per unit of coordinate q at `at`: its mass centre along (dx, dy), its turn dφ.
struct Moved {
  const model::Body* body = nullptr;
  double dx = 0, dy = 0, dphi = 0;
  double speed() const { return std::hypot(dx, dy); }
};

/// The body coordinate c moves (among `bodies`, all when null): for a turn, the first it turns;
/// for a move, the first whose centre it moves one for one (a block, not a pulley at half the
/// rate), else the first it moves at all.
Moved moved_by(const model::Model& m, const model::Coordinate& c, const At& at, bool turn, const std::vector<int>* bodies) {
  Moved first;
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    if (bodies && std::find(bodies->begin(), bodies->end(), static_cast<int>(i)) == bodies->end()) continue;
    const model::Body& b = m.bodies[i];
    Moved mo{&b, at(b.x.diff(c.q)), at(b.y.diff(c.q)), at(b.angle.diff(c.q))};
    if (!std::isfinite(mo.dx) || !std::isfinite(mo.dy) || !std::isfinite(mo.dphi) || !std::isfinite(at(b.x)) || !std::isfinite(at(b.y))) continue;
    if (turn && std::fabs(mo.dphi) > 1e-12) return mo;
    if (!turn && std::fabs(mo.speed() - 1) < 1e-9) return mo;
    if (!first.body && (turn ? std::fabs(mo.dphi) > 1e-12 : mo.speed() > 1e-12)) first = mo;
  }
  return first;
}

/// A given value as a textbook labels it beside a drawing that shows its sense: `symbol` (v, ω,
/// θ) = its size with its unit ("v = 2 m/s", an angle in degrees "θ = 30°"), or its parameter's
/// name where it is one (v_1 = 6 m/s); the name alone where the parameter has no number (a
/// closed form drawn at sample values) or a negative one (the drawing shows which way).
Name value_label(const model::Model& m, const Name& symbol, const ex& given, double value, const std::string& unit, bool angle) {
  const double size = std::fabs(value);
  const std::string digits = numerics::g_text(angle ? size * 180 / M_PI : size, 4);
  const Name number = angle ? Name{digits + "\u00b0", digits + "^\\circ"} : Name{digits + " " + unit, digits + "\\,\\mathrm{" + unit + "}"};
  Name name = symbol;
  if (GiNaC::is_a<GiNaC::symbol>(given))
    if (const auto n = textbook(GiNaC::ex_to<GiNaC::symbol>(given).get_name())) {
      name = *n;
      bool known = false;
      for (const auto& p : m.params) known = known || (p.sym.is_equal(given) && p.value);
      if (!known || value < 0) return name;
    }
  const std::string tex = name.tex.empty() ? name.text : name.tex;
  return {name.text + " = " + number.text, tex + " = " + number.tex};
}

/// A given rate q̇ = v: an arrow beside the body's centre along its motion (the side away from
/// the ground where there is a choice), clear of its outline; or a curved arrow round its centre
/// in the sense it turns, out past the arcs already there.
void given_rate(const model::Coordinate& c, const Moved& mo, double v, const Name& label, const At& at, Figure& f) {
  const double g = f.glyph(), gx = at(mo.body->x), gy = at(mo.body->y);
  if (std::fabs(mo.dphi) > 1e-12 && c.dim.dimensionless()) {
    // ω = φ' q̇: counter-clockwise where positive; below the centre (the sense arcs are above)
    const bool ccw = v * mo.dphi > 0;
    const double r = f.ring(gx, gy, 2.2 * g), a0 = ccw ? 3.8 : 5.6, a1 = ccw ? 5.6 : 3.8;
    f.arc_arrow(gx, gy, r, a0, a1, Ink::Velocity);
    f.label(gx + r * std::cos(a1), gy + r * std::sin(a1), label.text, label.tex);
    return;
  }
  const double d = mo.speed(), s = v > 0 ? 1 : -1;
  const double ux = s * mo.dx / d, uy = s * mo.dy / d;
  double nx = -uy, ny = ux;
  if (ny < -1e-9 || (std::fabs(ny) <= 1e-9 && nx < 0)) nx = -nx, ny = -ny;
  const double off = f.reach("body " + mo.body->name, gx, gy, nx, ny) + 0.8 * g;
  const double x0 = gx + nx * off - 1.5 * g * ux, y0 = gy + ny * off - 1.5 * g * uy;
  const double x1 = gx + nx * off + 1.5 * g * ux, y1 = gy + ny * off + 1.5 * g * uy;
  f.arrow(x0, y0, x1, y1, Ink::Velocity);
  f.label(x1, y1, label.text, label.tex);
}

/// A given angle q = θ that turns the body by Δφ from where q is zero: an arc about the point the
/// turn leaves at rest (a pivot; the centre of a body turning about it), from a dashed line where
/// q is zero to the body's line now.
void given_angle(const Moved& mo, double turned, const Name& label, const At& at, Figure& f) {
  const double g = f.glyph(), gx = at(mo.body->x), gy = at(mo.body->y);
  // the point at rest: v̄ = φ' k × (r̄ − P), so P = r̄ + (−dȳ, dx̄)·(−1/φ')… = (x̄ − dȳ/φ', ȳ + dx̄/φ')
  const bool spins = mo.speed() < 1e-9;
  const double px = spins ? gx : gx - mo.dy / mo.dphi, py = spins ? gy : gy + mo.dx / mo.dphi;
  const double arm = std::hypot(gx - px, gy - py);
  const double a1 = spins ? at(mo.body->angle) : std::atan2(gy - py, gx - px), a0 = a1 - turned;
  const double r = spins ? f.ring(px, py, 2.6 * g) : std::clamp(0.45 * arm, 2.0 * g, 6.0 * g);
  const double reach = spins ? r + g : std::max(arm, r + g);
  f.line(px, py, px + reach * std::cos(a0), py + reach * std::sin(a0), Ink::Hidden);
  std::vector<std::pair<double, double>> arc;
  for (int k = 0; k <= 24; ++k) {
    const double a = a0 + (a1 - a0) * k / 24;
    arc.push_back({px + r * std::cos(a), py + r * std::sin(a)});
  }
  f.polyline(arc, Ink::Dimension);
  const double am = (a0 + a1) / 2;
  f.label(px + r * std::cos(am), py + r * std::sin(am), label.text, label.tex);
}

/// Is a given value plain data, as a problem states it — a number, or a parameter (its negative):
/// not a value that follows from others (φ̇ = −v_1/r of a wheel rolling, x = −√(h(2r − h)) at a
/// step's edge), which the drawing leaves to the words.
bool plain(const ex& given) {
  if (GiNaC::is_a<GiNaC::numeric>(given) || GiNaC::is_a<GiNaC::symbol>(given)) return true;
  if (GiNaC::is_a<GiNaC::mul>(given) && given.nops() == 2)
    return (GiNaC::is_a<GiNaC::numeric>(given.op(0)) && GiNaC::is_a<GiNaC::symbol>(given.op(1))) ||
           (GiNaC::is_a<GiNaC::numeric>(given.op(1)) && GiNaC::is_a<GiNaC::symbol>(given.op(0)));
  // a number however written (an angle in degrees: a multiple of π)
  return GiNaC::is_a<GiNaC::numeric>(given.evalf());
}

}  // namespace

void given_data(const model::Model& m, int state, const At& at, Figure& f, const std::vector<int>* bodies) {
  const model::State& S = m.states.at(static_cast<std::size_t>(state));
  for (const auto& c : m.coords) {
    const auto sym = S.sym.find(c.name);
    if (sym == S.sym.end()) continue;
    const bool angle = c.dim.dimensionless();
    // the rate, where the state gives one and it is not zero
    if (const auto r = S.given.find(sym->second.second); r != S.given.end() && plain(r->second)) {
      const double v = at(r->second);
      const Moved mo = moved_by(m, c, at, angle, bodies);
      const Moved moving = mo.body ? mo : moved_by(m, c, at, false, bodies);
      const std::string unit = angle ? "rad/s" : units::si_name(c.dim) + "/s";
      // (ω for a turn, v for a move)
      const bool turns = moving.body && std::fabs(moving.dphi) > 1e-12 && angle;
      const Name symbol = turns ? Name{"\u03c9", "\\omega"} : Name{"v", "v"};
      if (moving.body && std::isfinite(v) && std::fabs(v) > 1e-12) given_rate(c, moving, v, value_label(m, symbol, r->second, v, unit, false), at, f);
    }
    // the coordinate, where the state gives it and it is not zero
    const auto q = S.given.find(sym->second.first);
    if (q == S.given.end() || !plain(q->second)) continue;
    const double value = at(q->second);
    if (!std::isfinite(value) || std::fabs(value) < 1e-12) continue;
    At zero = at;
    zero.values[c.q] = 0;
    const Moved mo = moved_by(m, c, at, angle, bodies);
    if (!mo.body) continue;
    const Name label = value_label(m, coordinate_label(c), q->second, value, units::si_name(c.dim), angle);
    if (angle && std::fabs(mo.dphi) > 1e-12) {
      const double turned = at(mo.body->angle) - zero(mo.body->angle);
      // (a turn of a revolution or more — a flywheel after n turns — has no arc to show it)
      if (std::isfinite(turned) && std::fabs(turned) > 1e-9 && std::fabs(turned) < 2 * M_PI - 1e-9) given_angle(mo, turned, label, at, f);
      continue;
    }
    // a length: from the mass centre where q is zero to where it is now
    const double x0 = zero(mo.body->x), y0 = zero(mo.body->y), x1 = at(mo.body->x), y1 = at(mo.body->y);
    if (std::isfinite(x0) && std::isfinite(y0) && std::hypot(x1 - x0, y1 - y0) > 1e-9) f.dimension(x0, y0, x1, y1, label.text, label.tex);
  }
}

}  // namespace kinergy::draw::detail
