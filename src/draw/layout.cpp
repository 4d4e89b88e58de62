// The page a sheet is laid out on: one scale for its panels, and each label placed off every
// stroke and every other word, measured from the fonts' metrics (glyphs.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "kinergy/draw/figure.hpp"
#include "page.hpp"

namespace kinergy::draw {

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

}  // namespace kinergy::draw
