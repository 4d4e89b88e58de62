// A figure of the scene in world coordinates, fitted to a page and written as SVG.
#include "kinergy/draw/figure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include <unistd.h>

#include "kinergy/common/error.hpp"
#include "kinergy/common/markup.hpp"
#include "kinergy/common/process.hpp"
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

void Sheet::add(Figure f, std::string title, std::string title_tex) { panels_.push_back({std::move(f), std::move(title), std::move(title_tex), "", ""}); }

void Sheet::then(std::string text, std::string tex) {
  if (panels_.empty()) return;
  panels_.back().after = std::move(text);
  panels_.back().after_tex = std::move(tex);
}

namespace detail {


// Does the segment (x0, y0)–(x1, y1) pass through the box? (Liang–Barsky clipping.)
bool crosses(const std::array<double, 4>& seg, const Layout::Box& b) {
  double t0 = 0, t1 = 1;
  const double dx = seg[2] - seg[0], dy = seg[3] - seg[1];
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {seg[0] - b.x0, b.x1 - seg[0], seg[1] - b.y0, b.y1 - seg[1]};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return false;
      continue;
    }
    const double r = q[k] / p[k];
    if (p[k] < 0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
    if (t0 > t1) return false;
  }
  return true;
}

int page_width(int width, std::size_t n) { return width > 0 ? width : n <= 1 ? 640 : static_cast<int>(std::min<std::size_t>(1200, 400 * n)); }

Layout::Box sign_box(double x, double mid, std::size_t length, double text) {
  // (drawn centred at x on the baseline mid + 9: a "+" or "=" of 28 px is about 17 px wide, and
  // stands from 19 px above the baseline to 1 below; a few pixels of room kept round it)
  const double half = text * (0.6 * kSignFont * static_cast<double>(std::max<std::size_t>(length, 1)) / 2 + 4);
  return {x - half, mid - text * 13, x + half, mid + text * 12};
}

using Segment = std::array<double, 4>;

/// The page segments (pixels, y down) of everything panel P's figure strokes: lines, outlines,
/// arcs and hatching as drawn, a circle by 32 chords, an arrow's head as its triangle, a marked
/// point as the square round its marker.
std::vector<Segment> page_strokes(const Figure& f, const Layout::Place& P, double s) {
  std::vector<Segment> out;
  auto X = [&](double x) { return P.tx + s * x; };
  auto Y = [&](double y) { return P.ty - s * y; };
  auto finite = [](const Segment& g) { return std::isfinite(g[0]) && std::isfinite(g[1]) && std::isfinite(g[2]) && std::isfinite(g[3]); };
  auto add = [&](const Segment& g) {
    if (finite(g)) out.push_back(g);
  };
  for (auto& sh : f.shapes()) {
    if (sh.pts.empty()) continue;
    if (sh.kind == Figure::Shape::Circle || sh.kind == Figure::Shape::Mark) {
      // (a marker: 3.2 px and its 1.2 px stroke, on the page whatever the scale)
      const double cx = X(sh.pts[0].first), cy = Y(sh.pts[0].second), r = sh.kind == Figure::Shape::Mark ? 3.8 : s * sh.r;
      if (sh.kind == Figure::Shape::Mark) {
        add({cx - r, cy - r, cx + r, cy - r}), add({cx + r, cy - r, cx + r, cy + r});
        add({cx + r, cy + r, cx - r, cy + r}), add({cx - r, cy + r, cx - r, cy - r});
        continue;
      }
      for (int k = 0; k < 32; ++k)
        add({cx + r * std::cos(k * M_PI / 16), cy + r * std::sin(k * M_PI / 16), cx + r * std::cos((k + 1) * M_PI / 16), cy + r * std::sin((k + 1) * M_PI / 16)});
      continue;
    }
    for (std::size_t k = 0; k + 1 < sh.pts.size(); ++k) add({X(sh.pts[k].first), Y(sh.pts[k].second), X(sh.pts[k + 1].first), Y(sh.pts[k + 1].second)});
    if (sh.kind == Figure::Shape::Polygon && sh.pts.size() > 2) add({X(sh.pts.back().first), Y(sh.pts.back().second), X(sh.pts[0].first), Y(sh.pts[0].second)});
    if ((sh.kind == Figure::Shape::Arrow || sh.kind == Figure::Shape::Arc) && sh.pts.size() >= 2) {
      const auto& a = sh.pts[sh.pts.size() - 2];
      const auto& b = sh.pts.back();
      const auto h = head_at(X(a.first), Y(a.second), X(b.first), Y(b.second));
      for (std::size_t k = 0; k < h.size(); ++k) add({h[k].first, h[k].second, h[(k + 1) % h.size()].first, h[(k + 1) % h.size()].second});
    }
  }
  return out;
}

/// A label's words measured as the page sets them (pixels): SVG's DejaVu Sans, or TeX at
/// L.tex_pt (a point is 13 L.text / tex_pt pixels: 13 px is where SVG's words stand).
Extent measured(const Layout& L, const Figure::Label& l) {
  if (L.tex_pt <= 0) return svg_extent(l.text);
  const Extent e = l.tex.empty() ? tex_text_extent(l.text, L.tex_pt) : tex_extent(l.tex, L.tex_pt);
  const double px = kFont * L.text / L.tex_pt;
  return {px * e.width, px * e.above, px * e.below};
}

namespace {

bool overlaps(const Layout::Box& a, const Layout::Box& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

// The places tried for a box w × h round the anchor (ax, ay), nearest first: the twelve of a
// textbook's habit (right and above first), then rings further out (to 290 px) in 16 or 32 directions.
std::vector<Layout::Box> places_round(double ax, double ay, double w, double h, double u) {
  std::vector<Layout::Box> out;
  const std::pair<double, double> habit[] = {{6, -4}, {6, 4}, {-6, -4}, {-6, 4}, {0, -6}, {0, 6}, {12, -14}, {-12, 14}, {12, 14}, {-12, -14}, {12, 0}, {-12, 0}};
  // (dx, dy): the box's corner nearest the anchor that far from it, the box beyond
  for (auto& [dx, dy] : habit) {
    const double x0 = dx > 0 ? ax + dx * u : dx < 0 ? ax + dx * u - w : ax - w / 2;
    const double y0 = dy > 0 ? ay + dy * u : dy < 0 ? ay + dy * u - h : ay - h / 2;
    out.push_back({x0, y0, x0 + w, y0 + h});
  }
  for (double d : {3.0, 8.0, 14.0, 20.0, 28.0, 36.0, 46.0, 58.0, 72.0, 90.0, 110.0, 135.0, 165.0, 200.0, 240.0, 290.0}) {
    const int K = d < 20 ? 16 : 32;
    for (int k = 0; k < K; ++k) {
      // from the upper right round through above, left, below
      const double a = M_PI / 4 + k * 2 * M_PI / K, c = std::cos(a), sn = -std::sin(a);
      const double cx = ax + c * (d * u + w / 2), cy = ay + sn * (d * u + h / 2);
      out.push_back({cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2});
    }
  }
  return out;
}

}  // namespace

/// The labels of the panels placed on the page (L.labels), off the titles (widths tw) and the
/// words between panels (lengths after), off each other and off every stroke: the nearest place
/// round the anchor free of all; where none is, the place free of words and page edge that
/// crosses the fewest strokes. A label set further out than a glyph gets a leader to its anchor.
void place_labels(Layout& L, const std::vector<std::pair<const Figure*, std::size_t>>& panels, const std::vector<double>& tw,
                  const std::vector<std::size_t>& after) {
  const std::size_t n = panels.size();
  const double text = L.text;
  for (std::size_t i = 0; i < n; ++i) {
    if (tw[i] > 0)
      L.reserved.push_back({L.places[i].centre - (tw[i] - 12 * text) / 2 - 2, L.title_y - 13 * text, L.places[i].centre + (tw[i] - 12 * text) / 2 + 2,
                            L.title_y + 4 * text});
    if (i < after.size() && after[i] > 0 && i + 1 < n) L.reserved.push_back(sign_box(L.between_x[i], L.mid, after[i], text));
  }
  std::vector<Layout::Box> taken = L.reserved;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Segment> strokes = page_strokes(*panels[i].first, L.places[i], L.scale);
    const auto& P = L.places[i];
    for (auto& l : panels[i].first->labels()) {
      const double u = text, m = 2;  // (room round the ink: a stroke's half width and a pixel)
      const Extent e = measured(L, l);
      const double w = e.width + 2 * m, h = e.above + e.below + 2 * m;
      const double ax = P.tx + L.scale * l.x, ay = P.ty - L.scale * l.y;
      const auto places = places_round(ax, ay, w, h, u);
      // only the strokes that come near the places tried
      Layout::Box reach{ax - 292 * u - w, ay - 292 * u - h, ax + 292 * u + w, ay + 292 * u + h};
      std::vector<Segment> near;
      for (auto& sg : strokes)
        if (crosses(sg, reach)) near.push_back(sg);
      // a leader from the anchor to the box's nearest point, stopped short of both, where the box
      // stands further out than a glyph
      auto leader_to = [&](const Layout::Box& b) -> std::optional<Segment> {
        const double qx = std::clamp(ax, b.x0, b.x1), qy = std::clamp(ay, b.y0, b.y1), d = std::hypot(qx - ax, qy - ay);
        if (!(d > 16 * u)) return std::nullopt;
        const double ux = (qx - ax) / d, uy = (qy - ay) / d;
        return Segment{ax + 5 * ux, ay + 5 * uy, qx - 2 * ux, qy - 2 * uy};
      };
      std::size_t best = places.size(), fewest = std::numeric_limits<std::size_t>::max();
      for (std::size_t k = 0; k < places.size() && fewest > 0; ++k) {
        const auto& b = places[k];
        const auto leader = leader_to(b);
        bool clash = b.x0 < 0 || b.x1 > L.width || b.y0 < 0 || b.y1 > L.height;
        for (auto& t : taken) clash = clash || overlaps(b, t) || (leader && crosses(*leader, t));
        if (clash) continue;
        std::size_t crossed = 0;
        for (auto& sg : near) crossed += crosses(sg, b) ? 1 : 0;
        if (crossed < fewest) best = k, fewest = crossed;
      }
      Layout::Box box = best < places.size() ? places[best] : places[0];
      if (best == places.size()) {
        // no place free of the others on the page: at least on the page
        box.x0 = std::clamp(box.x0, 0.0, std::max(0.0, L.width - w)), box.x1 = box.x0 + w;
        box.y0 = std::clamp(box.y0, 0.0, std::max(0.0, L.height - h)), box.y1 = box.y0 + h;
      }
      taken.push_back(box);
      L.labels.push_back({box, &l, box.x0 + m, box.y1 - m - e.below});
      if (const auto leader = leader_to(box)) {
        L.leaders.push_back(*leader);
        strokes.push_back(*leader);
      }
    }
  }
}

Layout lay_out(const std::vector<std::pair<const Figure*, std::size_t>>& panels, int width, int max_height, const Figure::Bounds* fixed,
               const std::vector<std::size_t>& after, double text, double tex_pt) {
  Layout L;
  L.text = text;
  L.tex_pt = tex_pt;
  const double pad = kPad * text;  // (a margin for the labels at the edge, as large as they are)
  const std::size_t n = panels.size();
  width = page_width(width, n);
  L.page = width;
  bool titles = false;
  for (auto& p : panels) titles = titles || p.second > 0;
  std::vector<Figure::Bounds> bs;
  double sum_w = 0, max_h = 0;
  for (auto& p : panels) {
    Figure::Bounds b = fixed ? *fixed : p.first->bounds(true);
    if (b.empty()) b = {-1, -1, 1, 1};
    double w = std::max(b.x1 - b.x0, 1e-9), h = std::max(b.y1 - b.y0, 1e-9);
    // a degenerate extent (all on one line): give it the other's size
    if (w < h * 0.05) w = h * 0.5;
    if (h < w * 0.05) h = w * 0.5;
    const double cx = (b.x0 + b.x1) / 2, cy = (b.y0 + b.y1) / 2;
    bs.push_back({cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2});
    sum_w += w;
  }
  // one vertical place for every panel: the same height in the world at the same height on the
  // page — unless that would make the page half as tall again as the tallest panel needs (a block
  // far up an incline at one state): then each panel centred on its own
  double gy0 = bs.empty() ? 0 : bs[0].y0, gy1 = bs.empty() ? 0 : bs[0].y1, own_h = 0;
  for (auto& b : bs) gy0 = std::min(gy0, b.y0), gy1 = std::max(gy1, b.y1), own_h = std::max(own_h, b.y1 - b.y0);
  const bool aligned = fixed || gy1 - gy0 <= 1.5 * own_h;
  max_h = aligned ? gy1 - gy0 : own_h;
  const double gaps = kGap * static_cast<double>(n > 0 ? n - 1 : 0);
  const double title_h = titles ? kTitle * text : 0;
  // each panel as wide as its drawing, or its title when that is wider: the scale s solves
  // Σ max(w_i s, t_i) = the width available (a few rounds of fixing the panels their titles hold)
  std::vector<double> tw;
  for (auto& p : panels) tw.push_back(p.second > 0 ? text * (kCharWidth * static_cast<double>(p.second) + 12) : 0);
  const double avail = width - 2 * pad - gaps;
  L.scale = avail / sum_w;
  for (int round = 0; round < 4; ++round) {
    double fixed = 0, free_w = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = bs[i].x1 - bs[i].x0;
      if (tw[i] > w * L.scale) fixed += tw[i];
      else free_w += w;
    }
    if (free_w > 0 && avail - fixed > 0) L.scale = (avail - fixed) / free_w;
  }
  L.scale = std::min(L.scale, (max_height - 2 * pad - title_h) / max_h);
  std::vector<double> slot;
  double slots = 0;
  for (std::size_t i = 0; i < n; ++i) {
    slot.push_back(std::max((bs[i].x1 - bs[i].x0) * L.scale, tw[i]));
    slots += slot.back();
  }
  L.width = static_cast<int>(std::ceil(slots + 2 * pad + gaps - 1e-6));
  L.height = static_cast<int>(std::ceil(max_h * L.scale + 2 * pad + title_h - 1e-6));
  L.mid = pad + max_h * L.scale / 2;
  L.title_y = pad + max_h * L.scale + pad / 2 + 8 * text;
  double left = pad;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& b = bs[i];
    const double w = slot[i], cx = (b.x0 + b.x1) / 2, cy = aligned ? (gy0 + gy1) / 2 : (b.y0 + b.y1) / 2;
    // X = left + w/2 + s (x − cx), Y = mid − s (y − cy)
    L.places.push_back({left + w / 2 - L.scale * cx, L.mid + L.scale * cy, left + w / 2});
    L.between_x.push_back(left + w + kGap / 2);
    left += w + kGap;
  }
  place_labels(L, panels, tw, after);
  return L;
}

// an arrowhead 11 px long and 8 px wide at page point b, pointing from page point a
std::vector<std::pair<double, double>> head_at(double xa, double ya, double xb, double yb) {
  double d = std::hypot(xb - xa, yb - ya);
  if (!(d > 0)) return {};
  const double ux = (xb - xa) / d, uy = (yb - ya) / d, L = 11, B = 4;
  return {{xb, yb}, {xb - L * ux - B * uy, yb - L * uy + B * ux}, {xb - L * ux + B * uy, yb - L * uy - B * ux}};
}

// text for TeX's text mode
std::string tex_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '_': case '#': case '%': case '&': case '$': case '{': case '}': o += std::string("\\") + c; break;
      case '~': o += "\\textasciitilde{}"; break;
      case '^': o += "\\textasciicircum{}"; break;
      case '\\': o += "\\textbackslash{}"; break;
      default: o += c;
    }
  }
  return o;
}

}  // namespace detail

namespace detail {

// One figure's world group: metres, y up, mapped to the page by P; strokes keep their page width.
void svg_world(std::ostringstream& o, const Figure& f, const Layout::Place& P, double scale, const std::string& attrs) {
  auto stroke = [&](Ink ink, bool filled) {
    Pen p = pen(ink);
    // widths in page pixels, written in metres (the group's scale makes them pixels again)
    std::string s = " fill=\"" + std::string(filled ? p.colour : "none") + "\" stroke=\"" + p.colour + "\" stroke-width=\"" +
                    n(p.width / scale) + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
    if (p.dashed) s += " stroke-dasharray=\"" + n(6 / scale) + " " + n(4 / scale) + "\"";
    return s;
  };
  o << "<g data-world=\"metres\"" << attrs << " transform=\"matrix(" << n(scale) << " 0 0 " << n(-scale) << " " << n(P.tx) << " " << n(P.ty)
    << ")\">\n";
  auto head = [&](double xa, double ya, double xb, double yb, Ink ink) {
    // the head drawn on the page, written back in world coordinates
    auto h = head_at(P.tx + scale * xa, P.ty - scale * ya, P.tx + scale * xb, P.ty - scale * yb);
    if (h.empty()) return;
    o << "<polygon points=\"";
    for (std::size_t i = 0; i < h.size(); ++i) o << (i ? " " : "") << n((h[i].first - P.tx) / scale) << "," << n((P.ty - h[i].second) / scale);
    o << "\"" << stroke(ink, true) << "/>\n";
  };
  for (auto& s : f.shapes()) {
    switch (s.kind) {
      case Figure::Shape::Line:
      case Figure::Shape::Arrow:
        o << "<line x1=\"" << n(s.pts[0].first) << "\" y1=\"" << n(s.pts[0].second) << "\" x2=\"" << n(s.pts[1].first) << "\" y2=\""
          << n(s.pts[1].second) << "\"" << stroke(s.ink, false) << "/>\n";
        if (s.kind == Figure::Shape::Arrow) head(s.pts[0].first, s.pts[0].second, s.pts[1].first, s.pts[1].second, s.ink);
        break;
      case Figure::Shape::Circle:
        o << "<circle cx=\"" << n(s.pts[0].first) << "\" cy=\"" << n(s.pts[0].second) << "\" r=\"" << n(s.r) << "\""
          << stroke(s.ink, s.filled) << (s.filled ? " fill-opacity=\"0.15\"" : "") << "/>\n";
        break;
      case Figure::Shape::Polygon:
      case Figure::Shape::Polyline:
      case Figure::Shape::Arc: {
        o << (s.kind == Figure::Shape::Polygon ? "<polygon" : "<polyline") << " points=\"";
        for (std::size_t i = 0; i < s.pts.size(); ++i) o << (i ? " " : "") << n(s.pts[i].first) << "," << n(s.pts[i].second);
        o << "\"" << stroke(s.ink, s.filled) << (s.filled ? " fill-opacity=\"0.15\"" : "") << "/>\n";
        if (s.kind == Figure::Shape::Arc && s.pts.size() >= 2)
          head(s.pts[s.pts.size() - 2].first, s.pts[s.pts.size() - 2].second, s.pts.back().first, s.pts.back().second, s.ink);
        break;
      }
      case Figure::Shape::Mark:
        o << "<circle data-name=\"" << escape(s.id) << "\" cx=\"" << n(s.pts[0].first) << "\" cy=\"" << n(s.pts[0].second) << "\" r=\""
          << n(3.2 / scale) << "\" fill=\"" << (s.filled ? "#333333" : "white") << "\" stroke=\"" << pen(s.ink).colour
          << "\" stroke-width=\"" << n(1.2 / scale) << "\"/>\n";
        break;
    }
  }
  o << "</g>\n";
}

/// The label's text for SVG: a subscript kSubFont px, its baseline kSubDrop px lower (as
/// svg_extent measures it), the words after it back on the line.
std::string svg_label_text(const std::string& text) {
  // (each space as a no-break space: SVG drops a space that begins or ends a tspan)
  auto escape = [](const std::string& t) {
    std::string o = detail::escape(t);
    for (std::size_t at; (at = o.find(' ')) != std::string::npos;) o.replace(at, 1, "&#160;");
    return o;
  };
  std::string out;
  bool down = false;
  for (auto& [part, sub] : label_parts(text)) {
    if (sub) {
      out += "<tspan dy=\"" + n(down ? 0 : kSubDrop) + "\" font-size=\"" + n(kSubFont) + "\">" + escape(part) + "</tspan>";
    } else if (down) {
      // back on the line; the spaces that begin the words as a shift (rsvg drops a space at the
      // start of a tspan, even a no-break one), as wide as svg_extent measures them
      const std::size_t lead = std::min(part.find_first_not_of(' '), part.size());
      const std::string dx = lead > 0 ? " dx=\"" + n(svg_extent(part.substr(0, lead)).width) + "\"" : "";
      out += "<tspan" + dx + " dy=\"" + n(-kSubDrop) + "\">" + escape(part.substr(lead)) + "</tspan>";
    } else {
      out += escape(part);
    }
    down = sub;
  }
  return out;
}

/// The same for TeX's text mode: "W_cart" as W$_{\mathrm{cart}}$.
std::string tex_label_text(const std::string& text) {
  std::string out;
  for (auto& [part, sub] : label_parts(text)) out += sub ? "$_{\\mathrm{" + tex_escape(part) + "}}$" : tex_escape(part);
  return out;
}

void svg_labels(std::ostringstream& o, const Layout& L) {
  for (auto& ld : L.leaders)
    o << "<line x1=\"" << n(ld[0]) << "\" y1=\"" << n(ld[1]) << "\" x2=\"" << n(ld[2]) << "\" y2=\"" << n(ld[3]) << "\" stroke=\"" << pen(Ink::Thin).colour
      << "\" stroke-width=\"0.8\" data-leader=\"1\"/>\n";
  for (auto& pl : L.labels) o << "<text x=\"" << n(pl.x) << "\" y=\"" << n(pl.y) << "\">" << svg_label_text(pl.label->text) << "</text>\n";
}

extern const char* const kLabelFont = "font-family=\"DejaVu Sans, sans-serif\" font-size=\"13\" fill=\"#222222\"";

}  // namespace detail

detail::Layout Sheet::layout(int width, int max_height, double width_cm) const {
  std::vector<std::pair<const Figure*, std::size_t>> ps;
  std::vector<std::size_t> after;
  for (auto& p : panels_) {
    ps.push_back({&p.figure, p.title.size()});
    after.push_back(p.after.size());
  }
  if (width_cm <= 0) return lay_out(ps, width, max_height, nullptr, after, 1, 0);
  const auto [pt, text] = tikz_text(width_cm, width);
  return lay_out(ps, width, max_height, nullptr, after, text, pt);
}

std::pair<double, double> Sheet::tikz_text(double width_cm, int width) const {
  // SVG's 13 px labels at the picture's scale would be font_pt; the 11 pt document sets them at
  // 9 pt (\footnotesize; 10 pt, \small, where the picture is large enough), and the layout makes
  // room for that size
  const double k = width_cm / page_width(width, panels_.size()), font_pt = kFont * k * 28.4527;
  const double set = font_pt < 10 ? 9 : 10;
  return {set, set / font_pt};
}

Sheet::TextLayout Sheet::text_boxes(int width, int max_height, double width_cm) const {
  const Layout L = layout(width, max_height, width_cm);
  TextLayout out{static_cast<double>(L.width), static_cast<double>(L.height), {}};
  for (auto& pl : L.labels) out.boxes.push_back({pl.box.x0, pl.box.y0, pl.box.x1, pl.box.y1, pl.label->text, true});
  for (auto& r : L.reserved) out.boxes.push_back({r.x0, r.y0, r.x1, r.y1, "", false});
  return out;
}

std::string Sheet::svg(int width, int max_height) const {
  const Layout L = layout(width, max_height, 0);
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << L.width << "\" height=\"" << L.height << "\" viewBox=\"0 0 " << L.width
    << " " << L.height << "\">\n";
  o << "<rect x=\"0\" y=\"0\" width=\"" << L.width << "\" height=\"" << L.height << "\" fill=\"white\"/>\n";
  for (std::size_t pi = 0; pi < panels_.size(); ++pi)
    svg_world(o, panels_[pi].figure, L.places[pi], L.scale, panels_.size() > 1 ? " data-panel=\"" + std::to_string(pi) + "\"" : "");
  o << "<g " << kLabelFont << ">\n";
  svg_labels(o, L);
  for (std::size_t pi = 0; pi < panels_.size(); ++pi) {
    const auto& p = panels_[pi];
    if (!p.title.empty())
      o << "<text x=\"" << n(L.places[pi].centre) << "\" y=\"" << n(L.title_y) << "\" text-anchor=\"middle\" font-style=\"italic\">"
        << escape(p.title) << "</text>\n";
    if (!p.after.empty())
      o << "<text x=\"" << n(L.between_x[pi]) << "\" y=\"" << n(L.mid + 9) << "\" text-anchor=\"middle\" font-size=\"28\">" << escape(p.after)
        << "</text>\n";
  }
  o << "</g>\n</svg>\n";
  return o.str();
}

std::string Sheet::tikz(double width_cm, int width, int max_height) const {
  const Layout L = layout(width, max_height, width_cm);
  // page pixels → centimetres, y up: (k X, k (H − Y)); numbers to 1/1000 cm, the same text everywhere
  const double k = width_cm / L.page;
  auto c = [](double v) {
    std::ostringstream os;
    os << std::fixed << std::setprecision(3) << (std::fabs(v) < 5e-4 ? 0.0 : v);
    return os.str();
  };
  auto pt = [&](double X, double Y) { return "(" + c(k * X) + "," + c(k * (L.height - Y)) + ")"; };
  // each pen's colour as a TikZ colour named by its value ("k1f3b73"), defined once from pen()
  auto colour = [](Ink i) { return "k" + std::string(pen(i).colour + 1); };
  auto style = [&](Ink ink, bool filled) {
    Pen p = pen(ink);
    std::string s = "draw=" + std::string(colour(ink)) + ",line width=" + c(k * p.width) + "cm,line cap=round,line join=round";
    if (filled) s += ",fill=" + std::string(colour(ink)) + ",fill opacity=0.15";
    if (p.dashed) s += ",dash pattern=on " + c(6 * k) + "cm off " + c(4 * k) + "cm";
    return s;
  };
  // labels and titles at 9 pt (\footnotesize of the 11 pt document), or 10 pt (\small), whatever
  // the picture's scale (the layout made room for them)
  const std::string font = tikz_text(width_cm, width).first < 10 ? "\\footnotesize" : "\\small";
  std::ostringstream o;
  o << "\\begin{tikzpicture}\n"
    ;
  std::vector<std::string> defined;
  for (Ink ink : kInks) {
    const std::string name = colour(ink);
    if (std::find(defined.begin(), defined.end(), name) != defined.end()) continue;
    defined.push_back(name);
    o << "\\definecolor{" << name << "}{HTML}{" << (pen(ink).colour + 1) << "}";
  }
  o << "\n"
    << "\\path[use as bounding box] (0,0) rectangle " << pt(L.width, 0) << ";\n";
  for (std::size_t pi = 0; pi < panels_.size(); ++pi) {
    const auto& P = L.places[pi];
    auto X = [&](double x) { return P.tx + L.scale * x; };
    auto Y = [&](double y) { return P.ty - L.scale * y; };
    auto path = [&](const std::vector<std::pair<double, double>>& pts) {
      std::string s;
      for (std::size_t i = 0; i < pts.size(); ++i) s += (i ? " -- " : "") + pt(X(pts[i].first), Y(pts[i].second));
      return s;
    };
    auto head = [&](std::pair<double, double> a, std::pair<double, double> b, Ink ink) {
      auto h = head_at(X(a.first), Y(a.second), X(b.first), Y(b.second));
      if (h.empty()) return;
      Pen p = pen(ink);
      o << "\\filldraw[draw=" << colour(ink) << ",fill=" << colour(ink) << ",line width=" << c(k * p.width) << "cm,line join=round] "
        << pt(h[0].first, h[0].second) << " -- " << pt(h[1].first, h[1].second) << " -- " << pt(h[2].first, h[2].second) << " -- cycle;\n";
    };
    for (auto& s : panels_[pi].figure.shapes()) {
      bool finite = true;
      for (auto& q : s.pts) finite = finite && std::isfinite(q.first) && std::isfinite(q.second);
      if (!finite || s.pts.empty()) continue;
      switch (s.kind) {
        case Figure::Shape::Line:
        case Figure::Shape::Arrow:
        case Figure::Shape::Polyline:
        case Figure::Shape::Arc:
          o << "\\draw[" << style(s.ink, false) << "] " << path(s.pts) << ";\n";
          if (s.kind == Figure::Shape::Arrow || s.kind == Figure::Shape::Arc)
            if (s.pts.size() >= 2) head(s.pts[s.pts.size() - 2], s.pts.back(), s.ink);
          break;
        case Figure::Shape::Polygon:
          o << "\\draw[" << style(s.ink, s.filled) << "] " << path(s.pts) << " -- cycle;\n";
          break;
        case Figure::Shape::Circle:
          if (!(s.r > 0) || !std::isfinite(s.r)) break;
          o << "\\draw[" << style(s.ink, s.filled) << "] " << pt(X(s.pts[0].first), Y(s.pts[0].second)) << " circle (" << c(k * L.scale * s.r)
            << "cm);\n";
          break;
        case Figure::Shape::Mark:
          o << "\\filldraw[draw=" << colour(s.ink) << ",fill=" << (s.filled ? colour(Ink::Support) : std::string("white")) << ",line width=" << c(k * 1.2)
            << "cm] " << pt(X(s.pts[0].first), Y(s.pts[0].second)) << " circle (" << c(k * 3.2) << "cm);\n";
          break;
      }
    }
  }
  for (auto& ld : L.leaders)
    o << "\\draw[draw=" << colour(Ink::Thin) << ",line width=" << c(k * 0.8) << "cm] " << pt(ld[0], ld[1]) << " -- " << pt(ld[2], ld[3]) << ";\n";
  for (auto& pl : L.labels) {
    const std::string body = pl.label->tex.empty() ? tex_label_text(pl.label->text) : "$" + pl.label->tex + "$";
    o << "\\node[anchor=base west,inner sep=0pt,font=" << font << "] at " << pt(pl.x, pl.y) << " {" << body << "};\n";
  }
  for (std::size_t pi = 0; pi < panels_.size(); ++pi) {
    const auto& p = panels_[pi];
    if (!p.title.empty())
      o << "\\node[anchor=base,inner sep=0pt,font=" << font << "\\itshape] at " << pt(L.places[pi].centre, L.title_y) << " {"
        << (p.title_tex.empty() ? tex_escape(p.title) : p.title_tex) << "};\n";
    if (!p.after.empty())
      o << "\\node[anchor=center,inner sep=0pt,font=\\Large] at " << pt(L.between_x[pi], L.mid) << " {$"
        << (p.after_tex.empty() ? p.after : p.after_tex) << "$};\n";
  }
  o << "\\end{tikzpicture}\n";
  return o.str();
}

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

void write(const Sheet& sheet, const std::string& path) {
  namespace fs = std::filesystem;
  const std::string ext = fs::path(path).extension().string();
  if (ext != ".svg" && ext != ".pdf" && ext != ".png" && ext != ".tex")
    throw InputError("the drawing '" + path + "' is not .svg, .pdf, .png or .tex", "name it FILE.svg, FILE.pdf, FILE.png or FILE.tex");
  const std::string svg = ext == ".tex" ? sheet.tikz(16) : sheet.svg();
  auto put = [&](const fs::path& p) {
    std::ofstream out(p, std::ios::binary);
    out << svg;
    if (!out) throw InputError("cannot write '" + p.string() + "'", "check the directory and its permissions");
  };
  if (ext == ".svg" || ext == ".tex") return put(path);
  // .pdf, .png: the SVG through rsvg-convert, in a private directory
  fs::path dir = fs::temp_directory_path() / ("kinergy-draw-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  put(dir / "figure.svg");
  const fs::path target = fs::absolute(path);
  int rc = run_program(dir, {"rsvg-convert", "--format", ext.substr(1), "--output", target.string(), "figure.svg"}, dir / "log.txt");
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (rc == 127)
    throw InputError("rsvg-convert is not installed, so the drawing cannot be written as " + ext,
                     "install Debian's librsvg2-bin (bash .ci/setup --deps), or write FILE.svg");
  if (rc != 0) throw InputError("rsvg-convert could not write '" + path + "' (exit " + std::to_string(rc) + ")", "check the directory and its permissions");
}

}  // namespace kinergy::draw
