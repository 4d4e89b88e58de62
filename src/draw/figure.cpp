// A figure of the scene in world coordinates: its shapes and labels, and the scene drawn from the
// model (bodies by their inertia shapes, fixed points, effects, the coordinates' senses). Laid
// out on a page by layout.cpp, written as SVG and TikZ by sheet.cpp.
#include "kinergy/draw/figure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "kinergy/common/error.hpp"
#include "kinergy/common/markup.hpp"
#include "kinergy/draw/names.hpp"
#include "kinergy/model/inertia.hpp"
#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"
#include "connectors.hpp"
#include "page.hpp"

namespace kinergy::draw {

using namespace GiNaC;

namespace detail {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// numbers in the SVG: six significant digits, the same text on every machine
std::string n(double v) {
  if (std::fabs(v) < 1e-12) v = 0;
  std::ostringstream os;
  os << std::setprecision(6) << v;
  return os.str();
}

std::string escape(const std::string& s) { return xml_escape(s); }


Pen pen(Ink i) {
  switch (i) {
    case Ink::Body: return {"#1f3b73", 3.0, false};
    case Ink::Thin: return {"#1f3b73", 1.2, false};
    case Ink::Support: return {"#333333", 1.5, false};
    case Ink::Force: return {"#b8231f", 1.8, false};
    case Ink::Spring: return {"#2a7d2e", 1.5, false};
    case Ink::Track: return {"#777777", 1.2, true};
    case Ink::Hidden: return {"#999999", 1.0, true};
    case Ink::Momentum: return {"#6a1b9a", 2.2, false};
    case Ink::Dimension: return {"#777777", 0.8, false};
    case Ink::Sense: return {"#0b7a75", 1.4, false};
    case Ink::Cord: return {"#4a3b2a", 1.6, false};
    case Ink::Velocity: return {"#1565c0", 1.8, false};
  }
  return {"#000000", 1.0, false};
}

}  // namespace detail

using namespace detail;

void Figure::push(Shape s) {
  // a place without a value (a size of a parameter that has none) is not drawn: no NaN in a picture
  if (!std::isfinite(s.r)) return;
  for (auto& [x, y] : s.pts)
    if (!std::isfinite(x) || !std::isfinite(y)) return;
  s.owner = owner_;
  shapes_.push_back(std::move(s));
}

double At::operator()(const ex& e) const {
  try {
    ex v = e.subs(values).evalf();
    if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) return ex_to<numeric>(v).to_double();
  } catch (const std::exception&) {
  }
  return kNaN;
}

void Figure::line(double x1, double y1, double x2, double y2, Ink ink) { push({Shape::Line, {{x1, y1}, {x2, y2}}, 0, ink, false, "", ""}); }

void Figure::polyline(std::vector<std::pair<double, double>> pts, Ink ink, bool closed, bool filled) {
  push({closed ? Shape::Polygon : Shape::Polyline, std::move(pts), 0, ink, filled, "", ""});
}

void Figure::circle(double cx, double cy, double r, Ink ink, bool filled) { push({Shape::Circle, {{cx, cy}}, r, ink, filled, "", ""}); }

void Figure::arrow(double x1, double y1, double x2, double y2, Ink ink, double magnitude) {
  push({Shape::Arrow, {{x1, y1}, {x2, y2}}, 0, ink, false, "", "", magnitude});
}

void Figure::arc_arrow(double cx, double cy, double r, double a0, double a1, Ink ink) {
  // the arc as a polyline, its head drawn at the end when written
  std::vector<std::pair<double, double>> pts;
  const int k = 24;
  for (int i = 0; i <= k; ++i) {
    double a = a0 + (a1 - a0) * i / k;
    pts.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  push({Shape::Arc, std::move(pts), r, ink, false, "", ""});
}

void Figure::mark(double x, double y, const std::string& name, bool fixed) {
  push({Shape::Mark, {{x, y}}, 0, fixed ? Ink::Support : Ink::Thin, fixed, name, ""});
}

void Figure::ground(double x, double y, double dx, double dy) {
  // a short bar beyond the support with hatching behind it, drawn in the support's own axes:
  // along r = (−d_y, d_x), and "down" along d; (a, b) there is (x, y) + a r − b d
  const double g = glyph();
  auto at = [&](double a, double b) { return std::pair<double, double>{x + a * -dy - b * dx, y + a * dx - b * dy}; };
  auto seg = [&](double a0, double b0, double a1, double b1) {
    const auto p = at(a0, b0), q = at(a1, b1);
    line(p.first, p.second, q.first, q.second, Ink::Support);
  };
  seg(-g, -g * 0.8, g, -g * 0.8);
  for (int i = 0; i < 5; ++i) {
    const double a0 = -g + i * g / 2;
    seg(a0, -g * 0.8, a0 - g * 0.35, -g * 1.2);
  }
  polyline({at(0, 0), at(-g * 0.5, -g * 0.8), at(g * 0.5, -g * 0.8)}, Ink::Support, true);
}

void Figure::surface(double x1, double y1, double x2, double y2, double nx, double ny) {
  // the surface's edge, and short strokes behind it every half glyph, slanted back along it:
  // from p + s t̂ to p + s t̂ + 0.6 g (n̂ − 0.6 t̂)
  const double L = std::hypot(x2 - x1, y2 - y1), g = glyph();
  if (!(L > 0) || !std::isfinite(L)) return;
  const double tx = (x2 - x1) / L, ty = (y2 - y1) / L;
  line(x1, y1, x2, y2, Ink::Support);
  for (double s = 0.3 * g; s <= L; s += 0.5 * g) {
    const double px = x1 + s * tx, py = y1 + s * ty;
    line(px, py, px + 0.6 * g * (nx - 0.6 * tx), py + 0.6 * g * (ny - 0.6 * ty), Ink::Support);
  }
}

double Figure::reach(const std::string& owner, double x, double y, double nx, double ny) const {
  // the support function of the owner's shapes: max (p − o)·n over their points, (c − o)·n + r
  // for a circle (its dimension lines left out)
  double out = 0;
  for (const Shape& s : shapes_) {
    if (s.owner != owner || s.ink == Ink::Dimension) continue;  // the body, not its dimension lines
    if (s.kind == Shape::Circle) {
      out = std::max(out, (s.pts[0].first - x) * nx + (s.pts[0].second - y) * ny + s.r);
      continue;
    }
    for (auto& [px, py] : s.pts) out = std::max(out, (px - x) * nx + (py - y) * ny);
  }
  return std::isfinite(out) ? out : 0;
}

void Figure::round_surface(double cx, double cy, double r, bool outside) {
  // the circle, and strokes every half glyph round it on the ground's side, slanted as a
  // straight surface's are: from p to p + 0.6 g (±r̂ − 0.6 t̂)
  const double g = glyph();
  if (!(r > 0) || !std::isfinite(r)) return;
  circle(cx, cy, r, Ink::Support);
  const int k = std::max(12, static_cast<int>(2 * M_PI * r / (0.5 * g)));
  const double s = outside ? 1 : -1;
  for (int i = 0; i < k; ++i) {
    const double a = 2 * M_PI * i / k, c = std::cos(a), sn = std::sin(a);
    const double px = cx + r * c, py = cy + r * sn;
    line(px, py, px + 0.6 * g * (s * c + 0.6 * sn), py + 0.6 * g * (s * sn - 0.6 * c), Ink::Support);
  }
}

double Figure::ring(double cx, double cy, double r) {
  // out past each ring it comes within 0.4 glyph of (within 0.399, so that one just placed 0.4 out
  // is clear: r only grows, and each ring moves it once at most)
  const double g = glyph();
  for (std::size_t pass = 0; pass <= rings_.size(); ++pass) {
    bool moved = false;
    for (auto& [x, y, taken] : rings_)
      if (std::hypot(x - cx, y - cy) < 0.1 * g && std::fabs(taken - r) < 0.399 * g && taken + 0.4 * g > r) {
        r = taken + 0.4 * g;
        moved = true;
      }
    if (!moved) break;
  }
  rings_.push_back({cx, cy, r});
  return r;
}

bool Figure::has_circle(double cx, double cy, double r) const {
  for (const Shape& s : shapes_)
    if (s.kind == Shape::Circle && std::fabs(s.r - r) <= 1e-3 * r && std::hypot(s.pts[0].first - cx, s.pts[0].second - cy) <= 1e-3 * r) return true;
  return false;
}

void Figure::label(double x, double y, const std::string& text, const std::string& tex) {
  if (!std::isfinite(x) || !std::isfinite(y)) return;
  // the same name at the same place once ("O" of the ground and "O" of the bar pinned there)
  for (const Label& l : labels_)
    if (l.text == text && std::hypot(l.x - x, l.y - y) <= 0.25 * glyph()) return;
  labels_.push_back({x, y, text, tex});
}

void Figure::dimension(double x1, double y1, double x2, double y2, const std::string& text, const std::string& tex) {
  // offset to the right of 1 → 2 by two glyphs, with a tick at each end and the size in the middle
  const double d = std::hypot(x2 - x1, y2 - y1), g = glyph();
  if (!(d > 0) || !std::isfinite(d) || text.empty()) return;
  const double nx = (y2 - y1) / d, ny = -(x2 - x1) / d, o = 2 * g, t = 0.6 * g;
  line(x1 + nx * o, y1 + ny * o, x2 + nx * o, y2 + ny * o, Ink::Dimension);
  line(x1 + nx * (o - t), y1 + ny * (o - t), x1 + nx * (o + t), y1 + ny * (o + t), Ink::Dimension);
  line(x2 + nx * (o - t), y2 + ny * (o - t), x2 + nx * (o + t), y2 + ny * (o + t), Ink::Dimension);
  label((x1 + x2) / 2 + nx * o, (y1 + y2) / 2 + ny * o, text, tex);
}

double Figure::glyph() const { return glyph_; }

Figure::Bounds Figure::bounds(bool labels) const {
  const double inf = std::numeric_limits<double>::infinity();
  Bounds b{inf, inf, -inf, -inf};
  auto take = [&](double x, double y, double r) {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    b.x0 = std::min(b.x0, x - r), b.x1 = std::max(b.x1, x + r);
    b.y0 = std::min(b.y0, y - r), b.y1 = std::max(b.y1, y + r);
  };
  for (auto& s : shapes_)
    for (auto& p : s.pts) take(p.first, p.second, s.kind == Shape::Circle ? s.r : 0);
  if (labels)
    for (auto& l : labels_) take(l.x, l.y, 0);
  return b;
}

double Figure::extent() const {
  Bounds b = bounds();
  return b.empty() ? 0 : std::max(b.x1 - b.x0, b.y1 - b.y0);
}

std::string Figure::svg(int width) const { return Sheet(*this).svg(width); }


exmap with_samples(const model::Model& m, exmap values, std::string* stated) {
  auto number = [](const ex& e) {
    try {
      return is_a<numeric>(e.evalf());
    } catch (const std::exception&) {
      return false;
    }
  };
  exmap samples;
  for (auto& p : m.params) {
    auto it = values.find(p.sym);
    if (it != values.end() && number(it->second.subs(values))) continue;
    if (it != values.end() && p.unknown) continue;  // solved in terms of others: follows their samples
    samples[p.sym] = 1;
    if (stated) *stated += (stated->empty() ? "" : ", ") + p.name + " = 1" + (units::si_name(p.dim).empty() ? "" : " " + units::si_name(p.dim));
  }
  for (auto& [k, v] : values) v = v.subs(samples);
  for (auto& [k, v] : samples) values[k] = v;
  return values;
}

At state_values(const model::Model& m, const exmap& solved, const exmap& params, int state, const At* otherwise) {
  const model::State& S = m.states.at(static_cast<std::size_t>(state));
  At at;
  at.values = params;
  at.values[m.t] = 0;
  // a value at state `of`: given, or solved (closed forms may name other solved symbols)
  auto value_at = [&](const ex& sym, const model::State& of) {
    ex v = sym;
    for (int pass = 0; pass < 4; ++pass) {
      ex w = v.subs(of.given).subs(solved);
      if (w.is_equal(v)) break;
      v = w;
    }
    At p;
    p.values = params;
    return p(v);
  };
  auto value_of = [&](const ex& sym) { return value_at(sym, S); };
  for (auto& c : m.coords) {
    auto& [q, qd] = S.sym.at(c.name);
    double v = value_of(q);
    if (std::isnan(v) && otherwise) v = otherwise->values.count(c.q) ? otherwise->operator()(c.q) : v;
    if (std::isnan(v))
      throw SceneError(S.pos, "state '" + S.name + "' does not fix " + c.name + ", so it cannot be drawn",
                       "give " + c.name + " at that state, or draw another state with --state");
    at.values[c.q] = v;
    double r = value_of(qd);
    at.values[c.qd] = std::isnan(r) ? 0 : r;
  }
  if (double t = value_of(S.t); !std::isnan(t)) at.values[m.t] = t;
  // a contact that has closed in its impact draws its normal as it has turned since, with the
  // angle its surface had at the state it closed (Model::closed_normal)
  for (const model::Effect& e : m.effects) {
    const auto r = e.reaction(m);
    const int S2 = r && r->turns >= 0 ? m.closed_from(e) : -1;
    if (S2 < 0) continue;
    const ex sym = m.bind(m.bodies[static_cast<std::size_t>(r->turns)].angle, S2);
    if (const double x = value_at(sym, m.states[static_cast<std::size_t>(S2)]); !std::isnan(x) && is_a<symbol>(sym)) at.values[sym] = x;
  }
  return at;
}

namespace {

/// A name as a textbook writes it where it reads as a symbol (theta: θ, OA: O_A), else as it is.
Name identifier_label(const std::string& id) {
  if (auto n = textbook(id)) return *n;
  return {id, ""};
}

/// An expression's label: a parameter by its textbook name, anything else as written (2*r).
Name expression_label(const ex& e) {
  if (is_a<symbol>(e)) return identifier_label(ex_to<symbol>(e).get_name());
  return {model::text(e), ""};
}

/// A shape's frame: its centre (gx, gy) and turn phi; r = (gx, gy) + R(phi) (lx, ly).
struct Placed {
  double gx, gy, phi;
  std::pair<double, double> operator()(double lx, double ly) const {
    const double c = std::cos(phi), s = std::sin(phi);
    return {gx + c * lx - s * ly, gy + s * lx + c * ly};
  }
};

/// One shape drawn in its frame (model/inertia.hpp's outlines).
void outline(const At& at, const std::string& shape_name, const std::vector<ex>& sizes, const Placed& world, Figure& f, double rim) {
  const double gx = world.gx, gy = world.gy;
  const model::InertiaShape& shape = model::inertia_shape(shape_name);
  const double a = sizes.empty() ? 0 : at(sizes[0]);
  const double bb = sizes.size() > 1 ? at(sizes[1]) : a;
  switch (shape.outline) {
    case model::Outline::Bar: {
      auto [x1, y1] = world(-a / 2, 0);
      auto [x2, y2] = world(a / 2, 0);
      f.line(x1, y1, x2, y2, Ink::Body);
      break;
    }
    case model::Outline::Round:
    case model::Outline::Gyration: {
      // a wheel known by its radius of gyration k alone: its rim at `rim` (a cord's drum, a
      // pitch circle), else that of the uniform disk of that k, R = √2 k; k itself dashed. No
      // wheel's rim is inside k (k ≤ R, a thin ring's k = R): what acts inside it acts on a hub
      // or a drum, drawn as its own circle
      const bool gyration = shape.outline == model::Outline::Gyration;
      const double R = !gyration ? a : (rim >= a ? rim : std::sqrt(2.0) * a);
      f.circle(gx, gy, R, Ink::Body, true);
      if (gyration) f.circle(gx, gy, a, Ink::Hidden);
      if (gyration && rim > 0 && rim < a) f.circle(gx, gy, rim, Ink::Body);
      auto [x2, y2] = world(a, 0);
      f.line(gx, gy, x2, y2, Ink::Thin);  // the reference line: the body's angle
      break;
    }
    case model::Outline::Rect:
      f.polyline({world(-a / 2, -bb / 2), world(a / 2, -bb / 2), world(a / 2, bb / 2), world(-a / 2, bb / 2)}, Ink::Body, true, true);
      break;
    case model::Outline::EdgeOn: {
      // a plate seen edge-on: a thin rectangle along its axis, a glyph thick
      const double half = shape.span * a / 2, t = f.glyph() * 0.3;
      f.polyline({world(-half, -t), world(half, -t), world(half, t), world(-half, t)}, Ink::Body, true, true);
      break;
    }
    case model::Outline::Dot: {
      // a particle: a small block, turned with its angle
      const double g = f.glyph();
      f.polyline({world(-g, -g * 0.7), world(g, -g * 0.7), world(g, g * 0.7), world(-g, g * 0.7)}, Ink::Body, true, true);
      break;
    }
  }
}

/// A shape's given dimensions beside it: a rod's length and a plate's sides, a radius on its line.
void dimensions(const At& at, const std::string& shape_name, const std::vector<ex>& sizes, const Placed& world, Figure& f) {
  const model::InertiaShape& shape = model::inertia_shape(shape_name);
  const double a = sizes.empty() ? 0 : at(sizes[0]);
  const double bb = sizes.size() > 1 ? at(sizes[1]) : a;
  // (a parameter by its textbook name: kA as k_A)
  auto size_text = [&](std::size_t i) { return i < sizes.size() ? expression_label(sizes[i]) : Name{}; };
  switch (shape.outline) {
    case model::Outline::Bar: {
      auto [x1, y1] = world(-a / 2, 0);
      auto [x2, y2] = world(a / 2, 0);
      f.dimension(x1, y1, x2, y2, size_text(0).text, size_text(0).tex);
      break;
    }
    case model::Outline::Round:
    case model::Outline::Gyration: {
      auto [x2, y2] = world(a / 2, 0);
      const Name r = size_text(0);
      f.label(x2, y2, r.text, r.tex);
      break;
    }
    case model::Outline::Rect: {
      auto [x1, y1] = world(-a / 2, -bb / 2);
      auto [x2, y2] = world(a / 2, -bb / 2);
      auto [x3, y3] = world(a / 2, bb / 2);
      f.dimension(x1, y1, x2, y2, size_text(0).text, size_text(0).tex);
      if (sizes.size() > 1) f.dimension(x2, y2, x3, y3, size_text(1).text, size_text(1).tex);
      break;
    }
    case model::Outline::EdgeOn: {
      // its width (a rectangular plate), or its radius from the centre (a circular one)
      auto [x1, y1] = world(shape.span == 1 ? -a / 2 : 0, 0);
      auto [x2, y2] = world(a * (shape.span == 1 ? 0.5 : 1.0), 0);
      f.dimension(x1, y1, x2, y2, size_text(0).text, size_text(0).tex);
      break;
    }
    case model::Outline::Dot:
      break;
  }
}

}  // namespace

namespace {

/// Is body bi a particle (no outline of its own) that is a party of a contact: an impact's
/// ball, bullet or puck?
bool strikes_as_point(const model::Model& m, int bi) {
  const model::Body& b = m.bodies.at(static_cast<std::size_t>(bi));
  if (!b.drawn_shape.empty() || model::inertia_shape(b.shape).outline != model::Outline::Dot) return false;
  for (auto& e : m.effects)
    if (const auto r = e.reaction(m); r && r->kind == model::Reaction::Kind::Contact && (r->a.body == bi || r->b.body == bi)) return true;
  return false;
}

}  // namespace

std::optional<Name> body_label(const model::Body& b) {
  if (!b.label.empty()) return from_tex(b.label);
  return short_name(b.name);
}

Name point_label(const model::Model& m, const std::string& point) {
  if (const auto l = m.point_labels.find(point); l != m.point_labels.end()) return from_tex(l->second);
  const auto dot = point.rfind('.');
  return identifier_label(dot == std::string::npos ? point : point.substr(dot + 1));
}

Name coordinate_label(const model::Coordinate& c) { return c.label.empty() ? identifier_label(c.name) : from_tex(c.label); }

void body(const model::Model& m, const At& at, int bi, Figure& f, bool points, double rim) {
  const model::Body& b = m.bodies.at(static_cast<std::size_t>(bi));
  f.owned_by("body " + b.name);
  // the body by its shape, or each part of a composite body by its own: r = G + R(φ) (lx, ly)
  const double gx = at(b.x), gy = at(b.y);
  double phi = at(b.angle);
  // a particle drawn as a block whose turn is no coordinate's: its base along the way it moves (a
  // block on an incline lies on the slope), the first coordinate that moves it giving the way
  if (b.parts.empty() && b.drawn_shape.empty() && model::inertia_shape(b.shape).outline == model::Outline::Dot && b.angle.is_zero())
    for (auto& c : m.coords) {
      const double dx = at(b.x.diff(c.q)), dy = at(b.y.diff(c.q));
      if (!std::isfinite(dx) || !std::isfinite(dy) || std::hypot(dx, dy) <= 1e-12) continue;
      phi = std::atan2(dy, dx);
      // (upright where it may be: a turn in (−90°, 90°])
      if (phi > M_PI / 2 + 1e-9) phi -= M_PI;
      if (phi <= -M_PI / 2 + 1e-9) phi += M_PI;
      break;
    }
  const Placed world{gx, gy, phi};
  // each shape's frame: the body's own, or each part's at its centre and turn
  std::vector<std::tuple<const std::string*, const std::vector<ex>*, Placed>> shapes;
  // (`drawn_as`: a particle's or a flywheel's outline as the scene gives it, and a radius of
  // gyration's dashed circle as well)
  if (b.parts.empty() && !b.drawn_shape.empty()) {
    shapes.push_back({&b.drawn_shape, &b.drawn_sizes, Placed{gx, gy, phi}});
    if (b.shape == "gyration") f.circle(gx, gy, at(b.sizes[0]), Ink::Hidden);
  } else if (b.parts.empty() && strikes_as_point(m, bi)) {
    // a particle that strikes or is struck: a dot, as a textbook draws a point mass (a block of
    // its own would stand over what it meets at its centre)
    f.circle(gx, gy, 0.4 * f.glyph(), Ink::Body, true);
  } else if (b.parts.empty()) {
    shapes.push_back({&b.shape, &b.sizes, Placed{gx, gy, phi}});
  }
  for (auto& p : b.parts) {
    auto [px, py] = world(at(p.lx), at(p.ly));
    shapes.push_back({&p.shape, &p.sizes, Placed{px, py, phi + at(p.angle)}});
  }
  for (auto& [shape, sizes, placed] : shapes) outline(at, *shape, *sizes, placed, f, b.parts.empty() ? rim : 0);
  f.mark(gx, gy, b.name + ".G");
  // a body by its short name where it has one (gearA: A), else not named at its centre (a
  // textbook names a body by a letter, or not at all)
  if (const auto s = body_label(b)) f.label(gx, gy, s->text, s->tex);
  if (!points) return f.owned_by("");
  for (auto& [shape, sizes, placed] : shapes) dimensions(at, *shape, *sizes, placed, f);
  for (auto& [pn, lp] : b.points) {
    auto [px, py] = world(at(lp.first), at(lp.second));
    f.mark(px, py, b.name + "." + pn);
    const Name n = point_label(m, b.name + "." + pn);
    f.label(px, py, n.text, n.tex);
  }
  f.owned_by("");
}

namespace detail {

/// Angle coordinate c's positive sense as a curved arrow round the first body it turns (φ' ≠ 0):
/// about the point its turn leaves at rest, P = (x̄ − ∂ȳ/φ', ȳ + ∂x̄/φ') per unit of c, where P
/// is a fixed point of the scene (a pendulum's pin), else about the mass centre. False when c
/// turns no body.
bool turn_sense(const model::Model& m, const model::Coordinate& c, const At& at, const Name& q, Figure& f) {
  const double g = f.glyph();
  for (auto& b : m.bodies) {
    const double dx = at(b.x.diff(c.q)), dy = at(b.y.diff(c.q)), dphi = at(b.angle.diff(c.q)), gx = at(b.x), gy = at(b.y);
    if (!std::isfinite(gx) || !std::isfinite(gy) || !std::isfinite(dphi) || std::fabs(dphi) <= 1e-12) continue;
    double cx = gx, cy = gy;
    if (std::isfinite(dx) && std::isfinite(dy)) {
      const double px = gx - dy / dphi, py = gy + dx / dphi;
      for (auto& [pn, p] : m.fixed_points)
        if (std::hypot(at(p.first) - px, at(p.second) - py) <= 1e-6 * std::max(1.0, std::hypot(gx - px, gy - py))) cx = px, cy = py;
    }
    const double a0 = dphi > 0 ? 0.6 : 2.6, a1 = dphi > 0 ? 2.6 : 0.6, r = f.ring(cx, cy, 1.8 * g);
    f.arc_arrow(cx, cy, r, a0, a1, Ink::Sense);
    f.label(cx + r * std::cos(a1), cy + r * std::sin(a1), q.text, q.tex);
    return true;
  }
  return false;
}

// the scene drawn with glyphs of size g: bodies, fixed points, effects
Figure drawing(const model::Model& m, const At& at, double g, const std::vector<int>* bodies, const std::vector<std::string>* effects) {
  Figure f;
  f.set_glyph(g);
  // what the kinematics imply (cords, meshes, surfaces), read first: a wheel's rim may come from it
  const Implied imp = implied(m, at);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (bodies && std::find(bodies->begin(), bodies->end(), static_cast<int>(b)) == bodies->end()) continue;
    const auto rim = imp.rim.find(static_cast<int>(b));
    body(m, at, static_cast<int>(b), f, true, rim == imp.rim.end() ? 0 : rim->second);
  }
  for (auto& [pn, p] : m.fixed_points) {
    f.mark(at(p.first), at(p.second), pn, true);
    const Name n = point_label(m, pn);
    f.label(at(p.first), at(p.second), n.text, n.tex);
  }
  for (auto& e : m.effects) {
    if (effects && std::find(effects->begin(), effects->end(), e.name) == effects->end()) continue;
    f.owned_by(e.name);
    e.draw(m, at, f);
  }
  f.owned_by("");
  draw_implied(m, at, imp, f, bodies);
  // the positive sense of each coordinate, named as a textbook names it (θ, φ_A, x): an angle's as
  // a curved arrow round the first body it turns — about the fixed point the turn leaves at rest
  // (a pendulum's pin), else about the mass centre; a length's, or an angle's that turns no body,
  // as an arrow at the centre of the first body it moves, along ∂r̄/∂q
  for (auto& c : m.coords) {
    const Name q = coordinate_label(c);
    if (c.dim.dimensionless() && turn_sense(m, c, at, q, f)) continue;
    for (auto& b : m.bodies) {
      const double dx = at(b.x.diff(c.q)), dy = at(b.y.diff(c.q)), gx = at(b.x), gy = at(b.y);
      const double d = std::hypot(dx, dy);
      if (!std::isfinite(gx) || !std::isfinite(gy) || !std::isfinite(d) || d <= 1e-12) continue;
      const double ex = gx + 3 * g * dx / d, ey = gy + 3 * g * dy / d;
      f.arrow(gx, gy, ex, ey, Ink::Sense);
      f.label(ex, ey, q.text, q.tex);
      break;
    }
  }
  return f;
}

}  // namespace detail

double glyph_for(const model::Model& m, const At& at) {
  // glyphs (marks, arrows, ground) sized from the extent of a first drawing
  double extent = 0;
  for (auto& b : m.bodies)
    for (auto& sz : b.lengths()) extent = std::max(extent, std::fabs(at(sz)));
  const double first = drawing(m, at, 0.045 * (extent > 0 ? extent : 1)).extent();
  return 0.045 * (first > 0 ? first : 1);
}

Figure scene_at(const model::Model& m, const exmap& solved, const exmap& params, int state) {
  const At at = state_values(m, solved, params, state);
  Figure f = drawing(m, at, glyph_for(m, at));
  given_data(m, state, at, f);
  return f;
}

Figure first_drawable(const model::Model& m, const exmap& solved, const exmap& params, std::vector<std::string>& left_out) {
  std::optional<SceneError> first;
  for (std::size_t i = 0; i < m.states.size(); ++i) {
    try {
      return scene_at(m, solved, params, static_cast<int>(i));
    } catch (const SceneError& e) {
      if (!first) first = e;
      left_out.push_back(e.problem());
    }
  }
  if (first) throw *first;
  throw SceneError(m.analyses.empty() ? SourcePos{} : m.analyses.front().pos, "the scene has no states to draw", "add a state with every coordinate");
}

Sheet states_at(const model::Model& m, const exmap& solved, const exmap& params, const std::vector<int>& states,
                std::vector<std::string>* left_out) {
  std::vector<std::pair<int, At>> ats;
  double g = 0;
  for (int st : states) {
    try {
      ats.push_back({st, state_values(m, solved, params, st)});
    } catch (const SceneError& e) {
      if (!left_out) throw;
      left_out->push_back(e.problem());
      continue;
    }
    g = std::max(g, glyph_for(m, ats.back().second));
  }
  Sheet sheet;
  for (auto& [st, at] : ats) {
    Figure f = drawing(m, at, g);
    given_data(m, st, at, f);
    sheet.add(std::move(f), "state " + m.states.at(static_cast<std::size_t>(st)).name);
  }
  return sheet;
}

Sheet positions_with(const model::Model& m, const exmap& solved, const exmap& params, int from, int to, const std::vector<int>& bodies,
                     const std::vector<std::string>& effects) {
  // each state at its own positions; a coordinate one does not fix at the other's
  std::optional<At> a1, a2;
  try {
    a1 = state_values(m, solved, params, from);
  } catch (const SceneError&) {
  }
  a2 = state_values(m, solved, params, to, a1 ? &*a1 : nullptr);
  if (!a1) a1 = state_values(m, solved, params, from, &*a2);
  const double g = std::max(glyph_for(m, *a1), glyph_for(m, *a2));
  Sheet sheet;
  for (auto [st, at] : {std::pair<int, const At*>{from, &*a1}, {to, &*a2}}) {
    Figure f = drawing(m, *at, g, &bodies, &effects);
    given_data(m, st, *at, f, &bodies);
    sheet.add(std::move(f), "state " + m.states.at(static_cast<std::size_t>(st)).name);
  }
  return sheet;
}

}  // namespace kinergy::draw
