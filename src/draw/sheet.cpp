// A sheet of figures written out: SVG (each panel's world in metres, its labels on the page),
// a TikZ picture for pdflatex, and files through rsvg-convert.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include <unistd.h>

#include "kinergy/common/error.hpp"
#include "kinergy/common/process.hpp"
#include "kinergy/draw/figure.hpp"
#include "page.hpp"

namespace kinergy::draw {

using namespace detail;

void Sheet::add(Figure f, std::string title, std::string title_tex) { panels_.push_back({std::move(f), std::move(title), std::move(title_tex), "", ""}); }

void Sheet::then(std::string text, std::string tex) {
  if (panels_.empty()) return;
  panels_.back().after = std::move(text);
  panels_.back().after_tex = std::move(tex);
}

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
