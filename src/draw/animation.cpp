// A motion drawn frame by frame: an SVG that plays by itself (SMIL), an HTML page with controls,
// or a GIF through gnuplot. Every frame is the scene drawn from the model at the frame's q, q̇, t.
#include "kinergy/draw/animation.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <unistd.h>

#include "kinergy/common/error.hpp"
#include "kinergy/common/process.hpp"
#include "kinergy/model/model.hpp"
#include "page.hpp"

namespace kinergy::draw {

using namespace GiNaC;
using namespace detail;

namespace {

constexpr int kWidth = 720, kHeight = 540;

// The frames drawn, and the page they share.
struct Drawn {
  std::vector<Figure> figs;
  std::vector<Layout> layouts;  // one transform for all (the same bounds); labels placed per frame
  double t0 = 0, t1 = 0;
};

Drawn draw_frames(const model::Model& m, const exmap& params, const Motion& motion) {
  if (motion.frames.empty()) throw InputError("the motion has no frames to draw", "simulate over a time span longer than zero");
  Drawn d;
  auto at_frame = [&](const Frame& fr) {
    At at;
    at.values = params;
    at.values[m.t] = fr.t;
    for (std::size_t i = 0; i < m.coords.size() && i < fr.q.size(); ++i) {
      at.values[m.coords[i].q] = fr.q[i];
      at.values[m.coords[i].qd] = i < fr.qd.size() ? fr.qd[i] : 0;
    }
    return at;
  };
  // one glyph size for the whole motion, from the box round a first drawing of every frame
  auto box = [&](double g) {
    d.figs.clear();
    Figure::Bounds all{0, 0, -1, -1};
    for (auto& fr : motion.frames) {
      d.figs.push_back(drawing(m, at_frame(fr), g));
      const Figure::Bounds b = d.figs.back().bounds(true);
      if (b.empty()) continue;
      if (all.empty()) all = b;
      all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1), std::max(all.y1, b.y1)};
    }
    return all;
  };
  Figure::Bounds all = box(glyph_for(m, at_frame(motion.frames.front())));
  if (!all.empty()) all = box(0.045 * std::max(all.x1 - all.x0, all.y1 - all.y0));
  // a page at least three quarters as wide as high: room for the time and the moments
  if (!all.empty() && all.x1 - all.x0 < 0.75 * (all.y1 - all.y0)) {
    const double cx = (all.x0 + all.x1) / 2, half = 0.375 * (all.y1 - all.y0);
    all.x0 = cx - half;
    all.x1 = cx + half;
  }
  for (auto& f : d.figs) d.layouts.push_back(lay_out({{&f, 0}}, kWidth, kHeight, all.empty() ? nullptr : &all));
  d.t0 = motion.frames.front().t;
  d.t1 = motion.frames.back().t;
  return d;
}

std::string seconds(double t) {
  std::ostringstream os;
  os << std::setprecision(4) << (std::fabs(t) < 1e-12 ? 0.0 : t);
  return os.str();
}

// The moment shown on frame i: the latest at or just before its time (a twentieth of the run, at
// least the frame itself), so that an impact stays in view for a moment.
std::vector<std::string> shown_moments(const Motion& motion, const Drawn& d, std::size_t i) {
  std::vector<std::string> out;
  const double t = motion.frames[i].t, keep = std::max((d.t1 - d.t0) / 20, 0.0);
  for (auto& mo : motion.moments)
    if (mo.t <= t && t <= mo.t + keep) out = {"t = " + seconds(mo.t) + " s: " + mo.what};
  return out;
}

// The frames as groups of one SVG; with `smil` each shows itself in its turn, looping.
std::string frames_svg(const Motion& motion, const Drawn& d, bool smil) {
  const Layout& L0 = d.layouts.front();
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << L0.width << "\" height=\"" << L0.height << "\" viewBox=\"0 0 " << L0.width << " "
    << L0.height << "\">\n";
  o << "<rect x=\"0\" y=\"0\" width=\"" << L0.width << "\" height=\"" << L0.height << "\" fill=\"white\"/>\n";
  const double span = d.t1 - d.t0;
  for (std::size_t i = 0; i < d.figs.size(); ++i) {
    const Layout& L = d.layouts[i];
    o << "<g data-frame=\"" << i << "\" data-t=\"" << n(motion.frames[i].t) << "\" display=\"" << (i == 0 ? "inline" : "none") << "\">\n";
    if (smil && span > 0) {
      // shown from its time to the next frame's, over a loop as long as the motion (real time)
      const double a = (motion.frames[i].t - d.t0) / span;
      const double b = i + 1 < d.figs.size() ? (motion.frames[i + 1].t - d.t0) / span : 1;
      o << "<animate attributeName=\"display\" calcMode=\"discrete\" repeatCount=\"indefinite\" dur=\"" << n(span) << "s\" ";
      if (i + 1 < d.figs.size()) o << "values=\"none;inline;none;none\" keyTimes=\"0;" << n(a) << ";" << n(b) << ";1\"/>\n";
      else o << "values=\"none;inline\" keyTimes=\"0;" << n(std::min(a, 1.0)) << "\"/>\n";
    }
    svg_world(o, d.figs[i], L.places[0], L.scale, "");
    o << "<g " << kLabelFont << ">\n";
    svg_labels(o, L);
    o << "<text x=\"10\" y=\"20\" font-weight=\"bold\">t = " << seconds(motion.frames[i].t) << " s</text>\n";
    int line = 0;
    for (auto& w : shown_moments(motion, d, i))
      o << "<text x=\"10\" y=\"" << 40 + 18 * line++ << "\" fill=\"#b8231f\">" << escape(w) << "</text>\n";
    o << "</g>\n</g>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace

std::string animation_svg(const model::Model& m, const exmap& params, const Motion& motion) {
  return frames_svg(motion, draw_frames(m, params, motion), true);
}

std::string animation_fragment(const model::Model& m, const exmap& params, const Motion& motion, const std::string& id) {
  const Drawn d = draw_frames(m, params, motion);
  std::ostringstream o;
  o << "<div class=\"kinergy-animation\" id=\"" << escape(id) << "\">\n<div class=\"stage\">\n" << frames_svg(motion, d, false) << "</div>\n"
    << "<div class=\"controls\"><button class=\"play\" type=\"button\">Pause</button>"
    << "<input class=\"slider\" type=\"range\" min=\"0\" max=\"" << d.figs.size() - 1 << "\" value=\"0\" step=\"1\" list=\"" << escape(id)
    << "-marks\"><span class=\"time\">t = " << seconds(d.t0) << " s</span></div>\n<datalist id=\"" << escape(id) << "-marks\">";
  // each moment marked on the slider at its frame (the first frame at or after it)
  for (auto& mo : motion.moments) {
    std::size_t k = 0;
    while (k + 1 < motion.frames.size() && motion.frames[k].t < mo.t) ++k;
    o << "<option value=\"" << k << "\"></option>";
  }
  o << "</datalist>\n<ul class=\"moments\">";
  for (auto& mo : motion.moments) o << "<li>t = " << seconds(mo.t) << " s: " << escape(mo.what) << "</li>";
  o << "</ul>\n<script>\n(function () {\n  const root = document.getElementById('" << escape(id) << "');\n  const times = [";
  for (std::size_t i = 0; i < motion.frames.size(); ++i) o << (i ? "," : "") << n(motion.frames[i].t);
  o << "];\n"
       "  const frames = root.querySelectorAll('.stage g[data-frame]');\n"
       "  const slider = root.querySelector('.slider'), play = root.querySelector('.play'), label = root.querySelector('.time');\n"
       "  let cur = 0, playing = true, start = null;\n"
       "  function show(i) {\n"
       "    frames[cur].setAttribute('display', 'none');\n"
       "    cur = i;\n"
       "    frames[cur].setAttribute('display', 'inline');\n"
       "    slider.value = i;\n"
       "    label.textContent = 't = ' + Number(times[i].toPrecision(4)) + ' s';\n"
       "  }\n"
       "  // the last frame at or before time t (times in order)\n"
       "  function frameAt(t) {\n"
       "    let lo = 0, hi = times.length - 1;\n"
       "    while (lo < hi) { const mid = (lo + hi + 1) >> 1; if (times[mid] <= t) lo = mid; else hi = mid - 1; }\n"
       "    return lo;\n"
       "  }\n"
       "  // real time: the frame of the time elapsed since the loop began\n"
       "  function tick(now) {\n"
       "    if (playing) {\n"
       "      const span = times[times.length - 1] - times[0];\n"
       "      if (start === null) start = now - (times[cur] - times[0]) * 1000;\n"
       "      let t = times[0] + (now - start) / 1000;\n"
       "      if (t > times[0] + span) { start = now; t = times[0]; }\n"
       "      show(frameAt(t));\n"
       "    }\n"
       "    requestAnimationFrame(tick);\n"
       "  }\n"
       "  function pause() { playing = false; play.textContent = 'Play'; }\n"
       "  play.addEventListener('click', function () { playing = !playing; start = null; play.textContent = playing ? 'Pause' : 'Play'; });\n"
       "  slider.addEventListener('input', function () { pause(); show(Number(slider.value)); });\n"
       "  // a page opened at #frame=K shows frame K, paused (a link to one instant)\n"
       "  const asked = /frame=([0-9]+)/.exec(window.location.hash);\n"
       "  if (asked && Number(asked[1]) < frames.length) { pause(); show(Number(asked[1])); }\n"
       "  window.kinergyAnimations = window.kinergyAnimations || {};\n"
       "  window.kinergyAnimations[root.id] = { show: function (i) { pause(); show(i); }, times: times };\n"
       "  requestAnimationFrame(tick);\n"
       "})();\n</script>\n</div>\n";
  return o.str();
}

const char* kAnimationStyle =
    ".kinergy-animation .stage svg{border:1px solid #ccc;max-width:100%;height:auto}"
    ".kinergy-animation .controls{margin:.6em 0;display:flex;gap:.8em;align-items:center}"
    ".kinergy-animation .slider{flex:1;max-width:560px}.kinergy-animation .moments{color:#b8231f}";

std::string animation_html(const model::Model& m, const exmap& params, const Motion& motion) {
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escape(motion.title) << "</title>\n"
    << "<style>body{font-family:'DejaVu Sans',sans-serif;margin:1.5em;color:#222}" << kAnimationStyle << "</style>\n</head>\n<body>\n"
    << "<h1 style=\"font-size:1.3em\">" << escape(motion.title) << "</h1>\n"
    << animation_fragment(m, params, motion, "animation")
    << "<script>window.kinergyShow = function (i) { window.kinergyAnimations.animation.show(i); };</script>\n</body>\n</html>\n";
  return o.str();
}

namespace {

// The frames through gnuplot's gif terminal: each frame's strokes as polylines by colour, its
// marks as points, its labels at their anchors.
std::string gnuplot_script(const Motion& motion, const Drawn& d, const std::string& out) {
  const Layout& L0 = d.layouts.front();
  // the world box the page shows: invert X = tx + s x, Y = ty − s y at the page's corners
  const auto& P = L0.places[0];
  const double x0 = (0 - P.tx) / L0.scale, x1 = (L0.width - P.tx) / L0.scale;
  const double y1 = (P.ty - 0) / L0.scale, y0 = (P.ty - L0.height) / L0.scale;
  // at most 150 frames, evenly in time: the last frame at or before each instant
  std::vector<std::size_t> pick;
  const std::size_t K = std::min<std::size_t>(150, motion.frames.size());
  for (std::size_t k = 0; k < K; ++k) {
    const double t = K == 1 ? d.t0 : d.t0 + (d.t1 - d.t0) * static_cast<double>(k) / static_cast<double>(K - 1);
    std::size_t i = 0;
    while (i + 1 < motion.frames.size() && motion.frames[i + 1].t <= t) ++i;
    if (pick.empty() || pick.back() != i) pick.push_back(i);
  }
  const int delay = std::max(2, static_cast<int>(std::lround(100 * (d.t1 - d.t0) / std::max<double>(1, static_cast<double>(pick.size())))));
  std::ostringstream o;
  o << "set terminal gif animate delay " << delay << " size " << L0.width << "," << L0.height << " font 'DejaVu Sans,9' background '#ffffff'\n"
    << "set output '" << out << "'\n"
    << "unset border\nunset tics\nunset key\nset margins 0,0,0,0\n"
    << "set xrange [" << n(x0) << ":" << n(x1) << "]\nset yrange [" << n(y0) << ":" << n(y1) << "]\n";
  for (std::size_t i : pick) {
    const Figure& f = d.figs[i];
    o << "unset label\n";
    o << "set label 1 't = " << seconds(motion.frames[i].t) << " s' at graph 0.015, graph 0.965\n";
    int id = 2, line = 1;
    for (auto& w : shown_moments(motion, d, i))
      o << "set label " << id++ << " '" << w << "' at graph 0.015, graph " << n(0.965 - 0.04 * line++) << " tc rgb '#b8231f'\n";
    for (auto& l : f.labels()) {
      if (!std::isfinite(l.x) || !std::isfinite(l.y)) continue;
      std::string text = l.text;
      std::replace(text.begin(), text.end(), '\'', ' ');
      o << "set label " << id++ << " '" << text << "' at " << n(l.x) << "," << n(l.y) << " offset 0.6,0.4\n";
    }
    // the strokes of each colour as one series of polylines (a blank line between them)
    std::vector<std::string> series, data;
    for (Ink ink : kInks) {
      std::ostringstream pts;
      for (auto& s : f.shapes()) {
        if (s.ink != ink || s.kind == Figure::Shape::Mark) continue;
        std::vector<std::pair<double, double>> line = s.pts;
        if (s.kind == Figure::Shape::Circle) {
          line.clear();
          for (int k = 0; k <= 48; ++k)
            line.push_back({s.pts[0].first + s.r * std::cos(k * 3.14159265358979323846 / 24), s.pts[0].second + s.r * std::sin(k * 3.14159265358979323846 / 24)});
        }
        if (s.kind == Figure::Shape::Polygon && !line.empty()) line.push_back(line.front());
        bool ok = !line.empty();
        for (auto& p : line) ok = ok && std::isfinite(p.first) && std::isfinite(p.second);
        if (!ok) continue;
        for (auto& p : line) pts << n(p.first) << " " << n(p.second) << "\n";
        pts << "\n";
        if ((s.kind == Figure::Shape::Arrow || s.kind == Figure::Shape::Arc) && line.size() >= 2) {
          // the head, drawn on the page and taken back to the world
          auto a = line[line.size() - 2], b = line.back();
          auto h = head_at(P.tx + L0.scale * a.first, P.ty - L0.scale * a.second, P.tx + L0.scale * b.first, P.ty - L0.scale * b.second);
          for (std::size_t k = 0; k <= h.size() && !h.empty(); ++k) {
            auto& q = h[k % h.size()];
            pts << n((q.first - P.tx) / L0.scale) << " " << n((P.ty - q.second) / L0.scale) << "\n";
          }
          pts << "\n";
        }
      }
      if (pts.str().empty()) continue;
      const Pen p = pen(ink);
      series.push_back("'-' with lines lc rgb '" + std::string(p.colour) + "' lw " + n(p.width / 1.2) + (p.dashed ? " dt 2" : ""));
      data.push_back(pts.str());
    }
    std::ostringstream marks;
    for (auto& s : f.shapes())
      if (s.kind == Figure::Shape::Mark && std::isfinite(s.pts[0].first) && std::isfinite(s.pts[0].second))
        marks << n(s.pts[0].first) << " " << n(s.pts[0].second) << "\n";
    if (!marks.str().empty()) {
      series.push_back("'-' with points pt 6 ps 0.7 lc rgb '#1f3b73'");
      data.push_back(marks.str());
    }
    if (series.empty()) {
      o << "plot 1/0\n";  // an empty frame: the page and its labels
      continue;
    }
    o << "plot ";
    for (std::size_t k = 0; k < series.size(); ++k) o << (k ? ", " : "") << series[k];
    o << "\n";
    for (auto& block : data) o << block << "e\n";
  }
  o << "unset output\n";
  return o.str();
}

}  // namespace

void write_animation(const model::Model& m, const exmap& params, const Motion& motion, const std::string& path) {
  namespace fs = std::filesystem;
  const std::string ext = fs::path(path).extension().string();
  if (ext != ".svg" && ext != ".html" && ext != ".gif")
    throw InputError("the animation '" + path + "' is not .svg, .html or .gif", "name it FILE.svg, FILE.html or FILE.gif");
  auto put = [&](const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
    if (!out) throw InputError("cannot write '" + p.string() + "'", "check the directory and its permissions");
  };
  if (ext == ".svg") return put(path, animation_svg(m, params, motion));
  if (ext == ".html") return put(path, animation_html(m, params, motion));
  // .gif: gnuplot in a private directory
  const Drawn d = draw_frames(m, params, motion);
  fs::path dir = fs::temp_directory_path() / ("kinergy-animate-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  put(dir / "frames.gp", gnuplot_script(motion, d, "animation.gif"));
  int rc = run_program(dir, {"gnuplot", "frames.gp"}, dir / "log.txt");
  std::error_code ec;
  if (rc == 0) {
    fs::copy_file(dir / "animation.gif", path, fs::copy_options::overwrite_existing, ec);
    if (ec) {
      fs::remove_all(dir, ec);
      throw InputError("cannot write '" + path + "'", "check the directory and its permissions");
    }
  }
  fs::remove_all(dir, ec);
  if (rc == 127) throw InputError("gnuplot is not installed, so the animation cannot be written as .gif", "install Debian's gnuplot-nox, or write FILE.html");
  if (rc != 0) throw InputError("gnuplot could not write the animation '" + path + "' (exit " + std::to_string(rc) + ")", "write FILE.html or FILE.svg instead");
}

}  // namespace kinergy::draw
