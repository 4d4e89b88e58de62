// The page a drawing is laid out on, shared by the figures (figure.cpp) and the animations
// (animation.cpp): the layout, the SVG writer of one figure's world, the scene's drawing.
#pragma once
#include <array>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "kinergy/draw/figure.hpp"
#include "glyphs.hpp"

namespace kinergy::draw::detail {

/// Numbers in the SVG: six significant digits, the same text on every machine.
std::string n(double v);
/// Text for XML.
std::string escape(const std::string& s);
/// Text for TeX's text mode.
std::string tex_escape(const std::string& s);

struct Pen {
  const char* colour;
  double width;  // pixels
  bool dashed;
};
Pen pen(Ink i);
/// Every ink, for writers that go through them all (TikZ's colours, gnuplot's series).
constexpr Ink kInks[] = {Ink::Body, Ink::Thin, Ink::Support, Ink::Force, Ink::Spring,
                         Ink::Track, Ink::Hidden, Ink::Momentum, Ink::Dimension, Ink::Sense, Ink::Cord, Ink::Velocity};

// A sheet laid out on the page (pixels, y down): one scale for every panel, each panel's world
// mapped by X = tx + s x, Y = ty − s y; labels placed off each other.
struct Layout {
  int page = 0;               // the width asked for (pixels)
  int width = 0, height = 0;  // the page's size: narrower than asked when the height bounds the scale
  double scale = 1;
  struct Place {
    double tx, ty, centre;  // transform, and the panel's middle on the page (x)
  };
  std::vector<Place> places;
  struct Box {
    double x0, y0, x1, y1;
  };
  struct Placed {
    Box box;  // the words' ink and a pixel round it
    const Figure::Label* label;
    double x, y;  // where the words start, on their baseline
  };
  std::vector<Placed> labels;
  /// Thin lines from an anchor to its label, where the label stands further out than a glyph.
  std::vector<std::array<double, 4>> leaders;
  double mid = 0, title_y = 0;
  std::vector<double> between_x;  // where the words after panel i go
  /// The boxes no label may take: each panel's title, and the words between panels ("+", "=").
  std::vector<Box> reserved;
  /// The size of the words on the page against the drawing's: 1 for SVG (13 px labels); larger
  /// where a document sets them at a size of its own (TikZ: 8 pt however small the drawing).
  double text = 1;
  /// TikZ: the size (pt) the document sets the words at, by which they are measured; 0 for SVG.
  double tex_pt = 0;
};

constexpr double kPad = 48, kGap = 120, kTitle = 26;
constexpr double kFont = 13, kCharWidth = 7.2;  // label font size and the width of a character (pixels)

/// Lay out figures side by side (each with its title's length, 0: none) at one scale, at most
/// `width` × `max_height` pixels; with `fixed`, every panel spans those world bounds (the frames
/// of an animation share the box round the whole motion). `after[i]`: the length of the words
/// after panel i (0: none), whose place no label takes.
Layout lay_out(const std::vector<std::pair<const Figure*, std::size_t>>& panels, int width, int max_height,
               const Figure::Bounds* fixed = nullptr, const std::vector<std::size_t>& after = {}, double text = 1, double tex_pt = 0);

/// The page width lay_out takes for `width` (0: its default for n panels).
int page_width(int width, std::size_t n);

/// The words between panels: font size and the page box of `length` characters at (x, mid).
constexpr double kSignFont = 28;
Layout::Box sign_box(double x, double mid, std::size_t length, double text = 1);

/// An arrowhead at page point b, pointing from page point a (page pixels).
std::vector<std::pair<double, double>> head_at(double xa, double ya, double xb, double yb);

/// A figure's world group (attributes `attrs` on it) and the placed labels of a layout.
void svg_world(std::ostringstream& o, const Figure& f, const Layout::Place& P, double scale, const std::string& attrs);
void svg_labels(std::ostringstream& o, const Layout& L);
extern const char* const kLabelFont;

/// The scene drawn at `at` with glyphs of size g: bodies, fixed points, effects, the coordinates'
/// senses. With `bodies` / `effects`, only those bodies (by index) and effects (by name).
Figure drawing(const model::Model& m, const At& at, double g, const std::vector<int>* bodies = nullptr,
               const std::vector<std::string>* effects = nullptr);

/// The data state `state` gives, drawn into its figure f (given.cpp): each given rate as an
/// arrow, or a curved arrow, with its value; each given coordinate that places the state as an
/// angle arc or a dimension line from where it is zero. Only on `bodies` when given.
void given_data(const model::Model& m, int state, const At& at, Figure& f, const std::vector<int>* bodies = nullptr);

}  // namespace kinergy::draw::detail
