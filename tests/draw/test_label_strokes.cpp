// Nothing over a stroke (issue 47): every label of every figure of every derivation, read back
// from the SVG and the TikZ kinergy writes (not from its layout), against every stroke drawn
// there: outlines, arrows and their heads, arcs, cords, hatching, dimension lines, markers,
// leaders. A label's box is its words' ink as the fonts' metrics give it (DejaVu Sans for SVG,
// Computer Modern for TikZ; the second checked against TeX itself in test_glyphs.cpp).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../../src/draw/glyphs.hpp"
#include "each_figure.hpp"

namespace {

using Seg = std::array<double, 4>;
struct Box {
  double x0, y0, x1, y1;
  std::string text;
};

// Does the segment meet the box's inside? (Clipped to the box, Liang–Barsky: the part of the
// segment in [x0, x1] × [y0, y1] is not empty.)
bool meets(const Seg& s, const Box& b) {
  double t0 = 0, t1 = 1;
  const double dx = s[2] - s[0], dy = s[3] - s[1];
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {s[0] - b.x0, b.x1 - s[0], s[1] - b.y0, b.y1 - s[1]};
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

std::vector<std::pair<double, double>> numbers_in(const std::string& points) {
  std::vector<std::pair<double, double>> out;
  std::istringstream in(points);
  std::string pair;
  while (in >> pair) {
    const auto c = pair.find(',');
    out.push_back({std::stod(pair.substr(0, c)), std::stod(pair.substr(c + 1))});
  }
  return out;
}

void chords(std::vector<Seg>& out, double cx, double cy, double r) {
  for (int k = 0; k < 64; ++k)
    out.push_back({cx + r * std::cos(k * M_PI / 32), cy + r * std::sin(k * M_PI / 32), cx + r * std::cos((k + 1) * M_PI / 32),
                   cy + r * std::sin((k + 1) * M_PI / 32)});
}

std::string attr(const std::string& tag, const std::string& name) {
  std::smatch m;
  if (std::regex_search(tag, m, std::regex("\\s" + name + "=\"([^\"]*)\""))) return m[1];
  return "";
}

/// The strokes (page pixels) and labels of an SVG kinergy wrote.
void read_svg(const std::string& svg, std::vector<Seg>& strokes, std::vector<Box>& labels) {
  static const std::regex group("<g data-world=\"metres\"[^>]*transform=\"matrix\\(([^ ]+) 0 0 ([^ ]+) ([^ ]+) ([^ ]+)\\)\">([^]*?)</g>");
  static const std::regex element("<(line|polyline|polygon|circle)\\b[^>]*>");
  for (auto g = std::sregex_iterator(svg.begin(), svg.end(), group); g != std::sregex_iterator(); ++g) {
    const double s = std::stod((*g)[1]), sy = std::stod((*g)[2]), tx = std::stod((*g)[3]), ty = std::stod((*g)[4]);
    auto P = [&](double x, double y) { return std::pair<double, double>{tx + s * x, ty + sy * y}; };
    const std::string body = (*g)[5];
    for (auto e = std::sregex_iterator(body.begin(), body.end(), element); e != std::sregex_iterator(); ++e) {
      const std::string tag = (*e)[0], kind = (*e)[1];
      if (kind == "line") {
        auto a = P(std::stod(attr(tag, "x1")), std::stod(attr(tag, "y1"))), b = P(std::stod(attr(tag, "x2")), std::stod(attr(tag, "y2")));
        strokes.push_back({a.first, a.second, b.first, b.second});
      } else if (kind == "circle") {
        auto c = P(std::stod(attr(tag, "cx")), std::stod(attr(tag, "cy")));
        // (the stroke's half width outside the radius)
        chords(strokes, c.first, c.second, s * std::stod(attr(tag, "r")) + s * std::stod(attr(tag, "stroke-width")) / 2);
      } else {
        auto pts = numbers_in(attr(tag, "points"));
        for (std::size_t k = 0; k + 1 < pts.size() + (kind == "polygon" ? 1 : 0); ++k) {
          auto a = P(pts[k].first, pts[k].second), b = P(pts[(k + 1) % pts.size()].first, pts[(k + 1) % pts.size()].second);
          strokes.push_back({a.first, a.second, b.first, b.second});
        }
      }
    }
  }
  // the labels' group: leaders, and the words that have no text-anchor (titles and signs do)
  static const std::regex leader("<line [^>]*data-leader[^>]*>");
  for (auto e = std::sregex_iterator(svg.begin(), svg.end(), leader); e != std::sregex_iterator(); ++e) {
    const std::string tag = (*e)[0];
    strokes.push_back({std::stod(attr(tag, "x1")), std::stod(attr(tag, "y1")), std::stod(attr(tag, "x2")), std::stod(attr(tag, "y2"))});
  }
  static const std::regex text("<text x=\"([^\"]+)\" y=\"([^\"]+)\">(.*?)</text>");
  static const std::regex sub("<tspan dy=\"[^\"]*\" font-size=\"10\">([^<]*)</tspan>"), back("<tspan dy=\"[^\"]*\">([^<]*)</tspan>"),
      shifted("<tspan dx=\"[^\"]*\" dy=\"[^\"]*\">([^<]*)</tspan>");
  for (auto t = std::sregex_iterator(svg.begin(), svg.end(), text); t != std::sregex_iterator(); ++t) {
    // (a shift dx back on the line stands for a space, as svg_label_text writes it)
    std::string words = std::regex_replace(std::regex_replace(std::regex_replace(std::string((*t)[3]), sub, "_$1"), back, "$1"), shifted, " $1");
    for (auto [from, to] : {std::pair<std::string, std::string>{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#160;", " "}, {"&amp;", "&"}})
      for (std::size_t at; (at = words.find(from)) != std::string::npos;) words.replace(at, from.size(), to);
    const double x = std::stod((*t)[1]), y = std::stod((*t)[2]);
    const auto e = kinergy::draw::detail::svg_extent(words);
    labels.push_back({x, y - e.above, x + e.width, y + e.below, words});
  }
}

/// The strokes and labels of a TikZ picture kinergy wrote, in centimetres (y up).
void read_tikz(const std::string& tikz, std::vector<Seg>& strokes, std::vector<Box>& labels) {
  static const std::regex draw("\\\\(?:draw|filldraw)\\[[^\\]]*\\] ([^;]*);");
  static const std::regex point("\\(([-0-9.]+),([-0-9.]+)\\)( circle \\(([-0-9.]+)cm\\))?");
  for (auto d = std::sregex_iterator(tikz.begin(), tikz.end(), draw); d != std::sregex_iterator(); ++d) {
    const std::string path = (*d)[1];
    std::vector<std::pair<double, double>> pts;
    for (auto p = std::sregex_iterator(path.begin(), path.end(), point); p != std::sregex_iterator(); ++p) {
      if ((*p)[3].matched) {
        chords(strokes, std::stod((*p)[1]), std::stod((*p)[2]), std::stod((*p)[4]));
        continue;
      }
      pts.push_back({std::stod((*p)[1]), std::stod((*p)[2])});
    }
    if (path.find("cycle") != std::string::npos && !pts.empty()) pts.push_back(pts.front());
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) strokes.push_back({pts[k].first, pts[k].second, pts[k + 1].first, pts[k + 1].second});
  }
  static const std::regex node("\\\\node\\[anchor=base west,inner sep=0pt,font=\\\\(footnotesize|small)\\] at \\(([-0-9.]+),([-0-9.]+)\\) \\{(.*)\\};");
  for (auto nd = std::sregex_iterator(tikz.begin(), tikz.end(), node); nd != std::sregex_iterator(); ++nd) {
    const double pt = (*nd)[1] == "small" ? 10 : 9, x = std::stod((*nd)[2]), y = std::stod((*nd)[3]), cm = 1 / 28.4527;
    const std::string body = (*nd)[4];
    const bool math = body.size() > 1 && body.front() == '$' && body.back() == '$' && body.find('$', 1) == body.size() - 1;
    // (text mode: W$_{\mathrm{cart}}$ read back as W_cart)
    const std::string plain = std::regex_replace(body, std::regex("\\$_\\{\\\\mathrm\\{([^}]*)\\}\\}\\$"), "_$1");
    const auto e = math ? kinergy::draw::detail::tex_extent(body.substr(1, body.size() - 2), pt) : kinergy::draw::detail::tex_text_extent(plain, pt);
    // (y up: the box from y − below to y + above)
    labels.push_back({x, y - cm * e.below, x + cm * e.width, y + cm * e.above, body});
  }
}

/// Each label over a stroke or another label, in words.
void faults_of(const std::vector<Seg>& strokes, const std::vector<Box>& labels, double room, const std::string& where, std::vector<std::string>& out) {
  for (std::size_t i = 0; i < labels.size(); ++i) {
    // (the box shrunk by `room`: a stroke may graze its words' outermost ink)
    const Box b{labels[i].x0 + room, labels[i].y0 + room, labels[i].x1 - room, labels[i].y1 - room, ""};
    for (auto& s : strokes)
      if (meets(s, b)) {
        std::ostringstream o;
        o << where << ": '" << labels[i].text << "' at (" << b.x0 << ", " << b.y0 << ")–(" << b.x1 << ", " << b.y1 << ") over the stroke (" << s[0]
          << ", " << s[1] << ")–(" << s[2] << ", " << s[3] << ")";
        out.push_back(o.str());
        break;
      }
    for (std::size_t j = i + 1; j < labels.size(); ++j)
      if (b.x0 < labels[j].x1 && labels[j].x0 < b.x1 && b.y0 < labels[j].y1 && labels[j].y0 < b.y1)
        out.push_back(where + ": '" + labels[i].text + "' over '" + labels[j].text + "'");
  }
}

}  // namespace

TEST_CASE("every figure of every derivation, as written in SVG and TikZ: no label over a stroke or another label", "[draw][derive][labels][strokes]") {
  int figures = 0, labels = 0;
  std::vector<std::string> faults;
  kt::each_figure([&](const std::string& file, int k, const kinergy::emit::Block& b) {
    ++figures;
    const bool several = b.sheet->size() > 1;
    const std::string where = file.substr(file.rfind('/') + 1) + " figure " + std::to_string(k);
    {
      std::vector<Seg> strokes;
      std::vector<Box> boxes;
      read_svg(b.sheet->svg(kinergy::emit::html_figure_width(*b.sheet)), strokes, boxes);
      labels += static_cast<int>(boxes.size());
      faults_of(strokes, boxes, 0.3, where + " (SVG)", faults);
    }
    {
      // as derive_latex asks for it
      std::vector<Seg> strokes;
      std::vector<Box> boxes;
      read_tikz(b.sheet->tikz(several ? 15.5 : 10.5, 0, several ? 560 : 520), strokes, boxes);
      labels += static_cast<int>(boxes.size());
      faults_of(strokes, boxes, 0.3 / 37.8, where + " (TikZ)", faults);
    }
  });
  INFO(figures << " figures, " << labels << " labels, " << faults.size() << " faults");
  for (std::size_t i = 0; i < faults.size() && i < 60; ++i) UNSCOPED_INFO(faults[i]);
  CHECK(faults.empty());
  CHECK(figures >= 150);
  CHECK(labels >= 3000);
}
