// A figure of the scene in world coordinates, fitted to a page and written as SVG.
#include "kinergy/draw/figure.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include <unistd.h>

#include "kinergy/common/error.hpp"
#include "kinergy/common/process.hpp"
#include "kinergy/model/inertia.hpp"
#include "kinergy/model/model.hpp"

namespace kinergy::draw {

using namespace GiNaC;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// numbers in the SVG: six significant digits, the same text on every machine
std::string n(double v) {
  if (std::fabs(v) < 1e-12) v = 0;
  std::ostringstream os;
  os << std::setprecision(6) << v;
  return os.str();
}

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else o += c;
  }
  return o;
}

struct Pen {
  const char* colour;
  double width;  // pixels
  bool dashed;
};

Pen pen(Ink i) {
  switch (i) {
    case Ink::Body: return {"#1f3b73", 3.0, false};
    case Ink::Thin: return {"#1f3b73", 1.2, false};
    case Ink::Support: return {"#333333", 1.5, false};
    case Ink::Force: return {"#b8231f", 1.8, false};
    case Ink::Spring: return {"#2a7d2e", 1.5, false};
    case Ink::Track: return {"#777777", 1.2, true};
    case Ink::Hidden: return {"#999999", 1.0, true};
  }
  return {"#000000", 1.0, false};
}

}  // namespace

double At::operator()(const ex& e) const {
  try {
    ex v = e.subs(values).evalf();
    if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) return ex_to<numeric>(v).to_double();
  } catch (const std::exception&) {
  }
  return kNaN;
}

void Figure::line(double x1, double y1, double x2, double y2, Ink ink) { shapes_.push_back({Shape::Line, {{x1, y1}, {x2, y2}}, 0, ink, false, ""}); }

void Figure::polyline(std::vector<std::pair<double, double>> pts, Ink ink, bool closed, bool filled) {
  shapes_.push_back({closed ? Shape::Polygon : Shape::Polyline, std::move(pts), 0, ink, filled, ""});
}

void Figure::circle(double cx, double cy, double r, Ink ink, bool filled) { shapes_.push_back({Shape::Circle, {{cx, cy}}, r, ink, filled, ""}); }

void Figure::arrow(double x1, double y1, double x2, double y2, Ink ink) { shapes_.push_back({Shape::Arrow, {{x1, y1}, {x2, y2}}, 0, ink, false, ""}); }

void Figure::arc_arrow(double cx, double cy, double r, double a0, double a1, Ink ink) {
  // the arc as a polyline, its head drawn at the end when written
  std::vector<std::pair<double, double>> pts;
  const int k = 24;
  for (int i = 0; i <= k; ++i) {
    double a = a0 + (a1 - a0) * i / k;
    pts.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  shapes_.push_back({Shape::Arc, std::move(pts), r, ink, false, ""});
}

void Figure::mark(double x, double y, const std::string& name, bool fixed) {
  shapes_.push_back({Shape::Mark, {{x, y}}, 0, fixed ? Ink::Support : Ink::Thin, fixed, name});
}

void Figure::ground(double x, double y) {
  // a short bar under the support with hatching below it
  const double g = glyph();
  line(x - g, y - g * 0.8, x + g, y - g * 0.8, Ink::Support);
  for (int i = 0; i < 5; ++i) {
    double x0 = x - g + i * g / 2;
    line(x0, y - g * 0.8, x0 - g * 0.35, y - g * 1.2, Ink::Support);
  }
  polyline({{x, y}, {x - g * 0.5, y - g * 0.8}, {x + g * 0.5, y - g * 0.8}}, Ink::Support, true);
}

void Figure::label(double x, double y, const std::string& text) { labels_.push_back({x, y, text}); }

double Figure::glyph() const { return glyph_; }

double Figure::extent() const {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (auto& s : shapes_)
    for (auto& p : s.pts) {
      if (!std::isfinite(p.first) || !std::isfinite(p.second)) continue;
      const double r = s.kind == Shape::Circle ? s.r : 0;
      x0 = std::min(x0, p.first - r), x1 = std::max(x1, p.first + r);
      y0 = std::min(y0, p.second - r), y1 = std::max(y1, p.second + r);
    }
  return std::isfinite(x0) ? std::max(x1 - x0, y1 - y0) : 0;
}

std::string Figure::svg(int width) const {
  // the extent of everything drawn (world)
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  auto take = [&](double x, double y, double r = 0) {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    x0 = std::min(x0, x - r);
    x1 = std::max(x1, x + r);
    y0 = std::min(y0, y - r);
    y1 = std::max(y1, y + r);
  };
  for (auto& s : shapes_)
    for (auto& p : s.pts) take(p.first, p.second, s.kind == Shape::Circle ? s.r : 0);
  for (auto& l : labels_) take(l.x, l.y);
  if (!std::isfinite(x0)) x0 = y0 = -1, x1 = y1 = 1;
  double w = std::max(x1 - x0, 1e-9), h = std::max(y1 - y0, 1e-9);
  // a degenerate extent (all on one line): give it the other's size
  if (w < h * 0.05) w = h * 0.5;
  if (h < w * 0.05) h = w * 0.5;
  const double pad = 48;
  const double scale = (width - 2 * pad) / w;
  const int height = static_cast<int>(std::ceil(h * scale + 2 * pad));
  const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  // world → page: X = W/2 + s (x − cx), Y = H/2 − s (y − cy)
  const double tx = width / 2.0 - scale * cx, ty = height / 2.0 + scale * cy;
  auto X = [&](double x) { return tx + scale * x; };
  auto Y = [&](double y) { return ty - scale * y; };
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << " "
    << height << "\">\n";
  o << "<rect x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"white\"/>\n";
  // the world group: metres, y up; strokes keep their page width
  o << "<g data-world=\"metres\" transform=\"matrix(" << n(scale) << " 0 0 " << n(-scale) << " " << n(tx) << " " << n(ty) << ")\">\n";
  auto stroke = [&](Ink ink, bool filled) {
    Pen p = pen(ink);
    // widths in page pixels, written in metres (the group's scale makes them pixels again)
    std::string s = " fill=\"" + std::string(filled ? p.colour : "none") + "\" stroke=\"" + p.colour + "\" stroke-width=\"" +
                    n(p.width / scale) + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
    if (p.dashed) s += " stroke-dasharray=\"" + n(6 / scale) + " " + n(4 / scale) + "\"";
    return s;
  };
  auto head = [&](double xa, double ya, double xb, double yb, Ink ink) {
    // an arrowhead 11 px long at (xb, yb), pointing from a to b
    double d = std::hypot(xb - xa, yb - ya);
    if (!(d > 0)) return;
    double ux = (xb - xa) / d, uy = (yb - ya) / d, L = 11 / scale, B = 4 / scale;
    o << "<polygon points=\"" << n(xb) << "," << n(yb) << " " << n(xb - L * ux - B * uy) << "," << n(yb - L * uy + B * ux) << " "
      << n(xb - L * ux + B * uy) << "," << n(yb - L * uy - B * ux) << "\"" << stroke(ink, true) << "/>\n";
  };
  for (auto& s : shapes_) {
    switch (s.kind) {
      case Shape::Line:
        o << "<line x1=\"" << n(s.pts[0].first) << "\" y1=\"" << n(s.pts[0].second) << "\" x2=\"" << n(s.pts[1].first) << "\" y2=\""
          << n(s.pts[1].second) << "\"" << stroke(s.ink, false) << "/>\n";
        break;
      case Shape::Circle:
        o << "<circle cx=\"" << n(s.pts[0].first) << "\" cy=\"" << n(s.pts[0].second) << "\" r=\"" << n(s.r) << "\""
          << stroke(s.ink, s.filled) << (s.filled ? " fill-opacity=\"0.15\"" : "") << "/>\n";
        break;
      case Shape::Polygon:
      case Shape::Polyline:
      case Shape::Arc: {
        o << (s.kind == Shape::Polygon ? "<polygon" : "<polyline") << " points=\"";
        for (std::size_t i = 0; i < s.pts.size(); ++i) o << (i ? " " : "") << n(s.pts[i].first) << "," << n(s.pts[i].second);
        o << "\"" << stroke(s.ink, s.filled) << (s.filled ? " fill-opacity=\"0.15\"" : "") << "/>\n";
        if (s.kind == Shape::Arc && s.pts.size() >= 2)
          head(s.pts[s.pts.size() - 2].first, s.pts[s.pts.size() - 2].second, s.pts.back().first, s.pts.back().second, s.ink);
        break;
      }
      case Shape::Arrow:
        o << "<line x1=\"" << n(s.pts[0].first) << "\" y1=\"" << n(s.pts[0].second) << "\" x2=\"" << n(s.pts[1].first) << "\" y2=\""
          << n(s.pts[1].second) << "\"" << stroke(s.ink, false) << "/>\n";
        head(s.pts[0].first, s.pts[0].second, s.pts[1].first, s.pts[1].second, s.ink);
        break;
      case Shape::Mark:
        o << "<circle data-name=\"" << escape(s.id) << "\" cx=\"" << n(s.pts[0].first) << "\" cy=\"" << n(s.pts[0].second) << "\" r=\""
          << n(3.2 / scale) << "\" fill=\"" << (s.filled ? "#333333" : "white") << "\" stroke=\"" << pen(s.ink).colour
          << "\" stroke-width=\"" << n(1.2 / scale) << "\"/>\n";
        break;
    }
  }
  o << "</g>\n";
  // labels on the page, kept off each other: the first free place around the anchor
  struct Box {
    double x0, y0, x1, y1;
  };
  std::vector<Box> taken;
  o << "<g font-family=\"DejaVu Sans, sans-serif\" font-size=\"13\" fill=\"#222222\">\n";
  for (auto& l : labels_) {
    const double bw = 7.2 * static_cast<double>(l.text.size()) + 2, bh = 15;
    const double ax = X(l.x), ay = Y(l.y);
    const std::pair<double, double> tries[] = {{8, -6}, {8, 16}, {-8 - bw, -6}, {-8 - bw, 16}, {-bw / 2, -12}, {-bw / 2, 24},
                                               {14, -20}, {-14 - bw, 30}, {14, 30}, {-14 - bw, -20}};
    Box best{ax + 8, ay - 6 - bh, ax + 8 + bw, ay - 6};
    for (auto& [dx, dy] : tries) {
      Box b{ax + dx, ay + dy - bh + 3, ax + dx + bw, ay + dy + 3};
      bool clash = b.x0 < 0 || b.x1 > width || b.y0 < 0 || b.y1 > height;
      for (auto& t : taken) clash = clash || (b.x0 < t.x1 && t.x0 < b.x1 && b.y0 < t.y1 && t.y0 < b.y1);
      if (!clash) {
        best = b;
        break;
      }
    }
    taken.push_back(best);
    o << "<text x=\"" << n(best.x0 + 1) << "\" y=\"" << n(best.y1 - 3) << "\">" << escape(l.text) << "</text>\n";
  }
  o << "</g>\n</svg>\n";
  return o.str();
}

Figure scene_at(const model::Model& m, const exmap& solved, const exmap& params, int state) {
  const model::State& S = m.states.at(static_cast<std::size_t>(state));
  At at;
  at.values = params;
  at.values[m.t] = 0;
  // a state value: given, or solved (closed forms may name other solved symbols)
  auto value_of = [&](const ex& sym) {
    ex v = sym;
    for (int pass = 0; pass < 4; ++pass) {
      ex w = v.subs(S.given).subs(solved);
      if (w.is_equal(v)) break;
      v = w;
    }
    At p;
    p.values = params;
    return p(v);
  };
  for (auto& c : m.coords) {
    auto& [q, qd] = S.sym.at(c.name);
    double v = value_of(q);
    if (std::isnan(v))
      throw SceneError(S.pos, "state '" + S.name + "' does not fix " + c.name + ", so it cannot be drawn",
                       "give " + c.name + " at that state, or draw another state with --state");
    at.values[c.q] = v;
    double r = value_of(qd);
    at.values[c.qd] = std::isnan(r) ? 0 : r;
  }
  if (double t = value_of(S.t); !std::isnan(t)) at.values[m.t] = t;
  // drawn twice: glyphs (marks, arrows, ground) sized from the extent of the first drawing
  auto drawing = [&](double glyph) {
    Figure f;
    f.set_glyph(glyph);
    // the bodies by their shapes: r = G + R(φ) (lx, ly)
    for (auto& b : m.bodies) {
      const double gx = at(b.x), gy = at(b.y), phi = at(b.angle), c = std::cos(phi), s = std::sin(phi);
      auto world = [&](double lx, double ly) { return std::pair<double, double>{gx + c * lx - s * ly, gy + s * lx + c * ly}; };
      const model::InertiaShape& shape = model::inertia_shape(b.shape);
      const double a = b.sizes.empty() ? 0 : at(b.sizes[0]);
      switch (shape.outline) {
        case model::Outline::Bar: {
          auto [x1, y1] = world(-a / 2, 0);
          auto [x2, y2] = world(a / 2, 0);
          f.line(x1, y1, x2, y2, Ink::Body);
          break;
        }
        case model::Outline::Round:
        case model::Outline::Gyration: {
          if (shape.outline == model::Outline::Round) f.circle(gx, gy, a, Ink::Body, true);
          else f.circle(gx, gy, a, Ink::Hidden);  // the radius of gyration, not the rim
          auto [x2, y2] = world(a, 0);
          f.line(gx, gy, x2, y2, Ink::Thin);  // the reference line: the body's angle
          break;
        }
        case model::Outline::Rect: {
          const double bb = b.sizes.size() > 1 ? at(b.sizes[1]) : a;
          f.polyline({world(-a / 2, -bb / 2), world(a / 2, -bb / 2), world(a / 2, bb / 2), world(-a / 2, bb / 2)}, Ink::Body, true, true);
          break;
        }
        case model::Outline::Dot: {
          // a particle: a small block, turned with its angle
          const double g = f.glyph();
          f.polyline({world(-g, -g * 0.7), world(g, -g * 0.7), world(g, g * 0.7), world(-g, g * 0.7)}, Ink::Body, true, true);
          break;
        }
      }
      f.mark(gx, gy, b.name + ".G");
      f.label(gx, gy, b.name);
      for (auto& [pn, lp] : b.points) {
        auto [px, py] = world(at(lp.first), at(lp.second));
        f.mark(px, py, b.name + "." + pn);
        f.label(px, py, pn);
      }
    }
    for (auto& [pn, p] : m.fixed_points) {
      f.mark(at(p.first), at(p.second), pn, true);
      f.label(at(p.first), at(p.second), pn);
    }
    for (auto& e : m.effects) e.draw(m, at, f);
    return f;
  };
  double extent = 0;
  for (auto& b : m.bodies)
    for (auto& sz : b.sizes) extent = std::max(extent, std::fabs(at(sz)));
  const double first = drawing(0.045 * (extent > 0 ? extent : 1)).extent();
  return drawing(0.045 * (first > 0 ? first : 1));
}

void write(const Figure& f, const std::string& path) {
  namespace fs = std::filesystem;
  const std::string ext = fs::path(path).extension().string();
  if (ext != ".svg" && ext != ".pdf" && ext != ".png")
    throw InputError("the drawing '" + path + "' is not .svg, .pdf or .png", "name it FILE.svg, FILE.pdf or FILE.png");
  const std::string svg = f.svg();
  auto put = [&](const fs::path& p) {
    std::ofstream out(p, std::ios::binary);
    out << svg;
    if (!out) throw InputError("cannot write '" + p.string() + "'", "check the directory and its permissions");
  };
  if (ext == ".svg") return put(path);
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
