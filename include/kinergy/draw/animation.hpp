/// @file animation.hpp  A motion drawn frame by frame from the model, as an SVG that plays by
/// itself, an HTML page with controls, or a GIF.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

namespace kinergy::model {
class Model;
}

namespace kinergy::draw {

/// One frame: the time, the coordinates and their rates there.
struct Frame {
  double t = 0;
  std::vector<double> q, qd;
};

/// What happens at an instant of the motion ("impact at floor"): marked where it happens.
struct Moment {
  double t = 0;
  std::string what;
};

struct Motion {
  std::string title;
  std::vector<Frame> frames;    ///< in time order (an impact's instant twice: before and after)
  std::vector<Moment> moments;  ///< impacts and the like
};

/// Every frame drawn from the model (bodies, points, effects) at one scale, fitted to the box round
/// the whole motion, in real time. An SVG whose frames take turns by SMIL (it loops in a browser;
/// a viewer without animation shows the first frame).
std::string animation_svg(const model::Model& m, const GiNaC::exmap& params, const Motion& motion);

/// A self-contained HTML page: the frames, play/pause, a time slider with the moments marked on
/// it and listed under it. Its script shows frame i on `kinergyShow(i)` (for tests).
std::string animation_html(const model::Model& m, const GiNaC::exmap& params, const Motion& motion);

/// The page's player alone, to set in another page (a worked solution): a div with id `id`; its
/// script registers `window.kinergyAnimations[id].show(i)`. Style it with `kAnimationStyle`.
std::string animation_fragment(const model::Model& m, const GiNaC::exmap& params, const Motion& motion, const std::string& id);
extern const char* kAnimationStyle;

/// Write to `path`: .svg, .html, or .gif (at most 150 frames, drawn by gnuplot's gif terminal).
/// @throws InputError for another extension, a missing gnuplot or a failed write.
void write_animation(const model::Model& m, const GiNaC::exmap& params, const Motion& motion, const std::string& path);

}  // namespace kinergy::draw
