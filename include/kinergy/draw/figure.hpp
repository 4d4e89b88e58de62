/// @file figure.hpp  A figure in world coordinates (metres, y up), fitted to a page and written
/// as SVG: the scene's bodies, points and effects drawn at a state.
#pragma once
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/draw/names.hpp"

namespace kinergy::model {
class Model;
struct Body;
struct Coordinate;
}

namespace kinergy::draw {

namespace detail {
struct Layout;
}

/// Numbers of expressions at one state: coordinates, rates, time and parameters substituted.
struct At {
  GiNaC::exmap values;
  double operator()(const GiNaC::ex& e) const;  ///< NaN where e has no real value there
  std::pair<double, double> point(const std::pair<GiNaC::ex, GiNaC::ex>& p) const { return {(*this)(p.first), (*this)(p.second)}; }
};

/// What a stroke is for: its colour and weight follow.
enum class Ink { Body, Thin, Support, Force, Spring, Track, Hidden, Momentum, Dimension, Sense, Cord, Velocity };

class Figure {
public:
  struct Shape {
    enum Kind { Line, Circle, Polygon, Polyline, Arrow, Arc, Mark } kind;
    std::vector<std::pair<double, double>> pts;  ///< world coordinates (Arc: centre, then (r, a0..a1) in pts[1], pts[2])
    double r = 0;
    Ink ink = Ink::Body;
    bool filled = false;
    std::string id;  ///< data-name of a marked point, for reading positions back
    std::string owner;  ///< what it draws: an effect's name, or an implied connector's ("cord drum-load")
    /// An arrow drawn to its figure's scale: the size it stands for (a momentum's, an impulse's);
    /// NaN for an arrow that shows a direction only.
    double magnitude = std::numeric_limits<double>::quiet_NaN();
  };
  struct Label {
    double x, y;  ///< the anchor, world coordinates
    std::string text;
    std::string tex;  ///< the same in TeX's math mode (empty: the text, escaped)
  };
  /// The box round everything drawn (world coordinates); empty when nothing finite is.
  struct Bounds {
    double x0, y0, x1, y1;
    bool empty() const { return !(x0 <= x1); }
  };

  void line(double x1, double y1, double x2, double y2, Ink ink = Ink::Body);
  void polyline(std::vector<std::pair<double, double>> pts, Ink ink, bool closed = false, bool filled = false);
  void circle(double cx, double cy, double r, Ink ink = Ink::Body, bool filled = false);
  /// An arrow from (x1, y1) to (x2, y2), its head at the end; `magnitude`: the size it stands for,
  /// where it is drawn to the figure's scale.
  void arrow(double x1, double y1, double x2, double y2, Ink ink = Ink::Force, double magnitude = std::numeric_limits<double>::quiet_NaN());
  /// A curved arrow round (cx, cy) of radius r from angle a0 to a1 (rad), its head at a1.
  void arc_arrow(double cx, double cy, double r, double a0, double a1, Ink ink = Ink::Force);
  /// A named point: a small marker of fixed size on the page, its world place kept as data.
  void mark(double x, double y, const std::string& name, bool fixed = false);
  /// Hatched ground at a fixed support at (x, y), on the side (dx, dy) points to (a unit
  /// vector; below by default).
  void ground(double x, double y, double dx = 0, double dy = -1);
  /// A surface along the segment 1 → 2 (a floor, an incline, a wall), hatched on the side
  /// (nx, ny) points to (a unit vector: the ground's side, away from what rests on it).
  void surface(double x1, double y1, double x2, double y2, double nx, double ny);
  /// A round surface of radius r about (cx, cy): a bowl (hatched outside, `outside`) or a dome
  /// (hatched inside).
  void round_surface(double cx, double cy, double r, bool outside);
  /// Whom the shapes drawn from now on belong to (an effect's name; "" for the bodies).
  void owned_by(std::string owner) { owner_ = std::move(owner); }
  /// How far the shapes of `owner` reach from (x, y) along the unit vector (nx, ny) (0 when none
  /// do): where a body's edge is, for the floor under it.
  double reach(const std::string& owner, double x, double y, double nx, double ny) const;
  /// A radius for one more curved arrow round (cx, cy), at least r: clear by 0.4 glyph of those
  /// already taken round that centre (a couple, a bearing's friction and the sense of the
  /// coordinate at one hub), and taken.
  double ring(double cx, double cy, double r);
  /// Is there a circle of radius r round (cx, cy) already (within a thousandth of r)?
  bool has_circle(double cx, double cy, double r) const;
  /// A label at (x, y); not repeated where one with the same text is already within a quarter
  /// glyph of it (a point of the ground and a body's point pinned there, both named O).
  void label(double x, double y, const std::string& text, const std::string& tex = "");
  /// A dimension: the size `text` of the segment 1 → 2, on a thin line beside it (to its right)
  /// with a tick at each end.
  void dimension(double x1, double y1, double x2, double y2, const std::string& text, const std::string& tex = "");

  /// A length that reads as "small" in this figure (for glyphs whose size the scene does not set).
  double glyph() const;
  void set_glyph(double g) { glyph_ = g; }

  /// The whole figure as an SVG document `width` pixels wide (height from the extent), the world
  /// drawn in a group whose transform maps metres to pixels (y flipped); labels kept off each other.
  std::string svg(int width = 640) const;

  const std::vector<Shape>& shapes() const { return shapes_; }
  const std::vector<Label>& labels() const { return labels_; }
  /// The box round the shapes (and the labels' anchors, with `labels`).
  Bounds bounds(bool labels = false) const;
  /// The larger side of the box around everything drawn (0 when nothing is).
  double extent() const;

private:
  std::vector<Shape> shapes_;
  std::vector<Label> labels_;
  double glyph_ = 0.05;
  std::string owner_;
  std::vector<std::array<double, 3>> rings_;  ///< the curved arrows' centres and radii (ring())
  void push(Shape s);
};

/// Figures side by side at one scale, each with a title under it and words between them: the
/// scene at several states, or an impulse–momentum diagram (momenta + impulses = momenta).
class Sheet {
public:
  Sheet() = default;
  explicit Sheet(Figure f) { add(std::move(f)); }
  /// A panel; `title` under it (plain text, and in TeX's text mode when `title_tex` is set).
  void add(Figure f, std::string title = "", std::string title_tex = "");
  /// Words between the last panel added and the next ("+", "="), plain and in TeX's math mode.
  void then(std::string text, std::string tex);
  /// What a caption should say of the drawing (its scale, the arrows not drawn to it); "" when
  /// nothing.
  std::string note;

  /// An SVG document at most `width` pixels wide and `max_height` high; each panel's world in its
  /// own group (data-world="metres", data-panel="i") whose transform maps metres to pixels.
  /// (`width` 0: 640 for one panel, more for several.)
  std::string svg(int width = 0, int max_height = 1600) const;
  /// The same drawing as a TikZ picture `width_cm` wide (at most), for pdflatex: the page laid out
  /// as for svg(width, max_height), at width_cm / width centimetres a pixel.
  std::string tikz(double width_cm, int width = 0, int max_height = 1600) const;
  std::size_t size() const { return panels_.size(); }
  const Figure& panel(std::size_t i) const { return panels_.at(i).figure; }

  /// A box of words on the page as svg(width, max_height) lays it out (pixels, y down): a label
  /// (its text), or a place no label may take (a panel's title, the words between panels).
  struct TextBox {
    double x0, y0, x1, y1;
    std::string text;
    bool label;
  };
  /// The page's size and its boxes of words (`width_cm` > 0: as tikz(width_cm, width,
  /// max_height) lays it out, its words at 8 or 9 pt).
  struct TextLayout {
    double width = 0, height = 0;
    std::vector<TextBox> boxes;
  };
  TextLayout text_boxes(int width = 0, int max_height = 1600, double width_cm = 0) const;

private:
  detail::Layout layout(int width, int max_height, double width_cm) const;
  /// TikZ's size for the words (pt) at width_cm, and that size against SVG's 13 px labels at
  /// the picture's scale.
  std::pair<double, double> tikz_text(double width_cm, int width) const;
  struct Panel {
    Figure figure;
    std::string title, title_tex, after, after_tex;
  };
  std::vector<Panel> panels_;
};

/// The values to draw with: `values` (the parameters', the solved unknowns') and, for each
/// parameter that has no number there (a scene solved in closed form), the sample value 1 in SI
/// units, said in `stated` ("L = 1 m, s = 1 m"; empty when none) so that the drawing says what it
/// shows.
GiNaC::exmap with_samples(const model::Model& m, GiNaC::exmap values, std::string* stated);

/// The values of a state for drawing: its coordinates and rates (given, or solved in `solved`),
/// its time, and the parameters. A coordinate the state does not fix takes its value in
/// `otherwise` (a diagram drawn at the positions of the other state) when that is given.
/// @throws SceneError when the state does not fix a coordinate (and `otherwise` is null).
At state_values(const model::Model& m, const GiNaC::exmap& solved, const GiNaC::exmap& params, int state, const At* otherwise = nullptr);

/// How figures name a body: its `label:`, else its short name (gearA: A); none for a word alone.
std::optional<Name> body_label(const model::Body& b);
/// How figures name a point ("O", "bar.A": the name after the dot) and a coordinate: its
/// `label:`, else its name as a textbook writes it (OA: O_A, theta: θ).
Name point_label(const model::Model& m, const std::string& point);
Name coordinate_label(const model::Coordinate& c);

/// Body b by its inertia shape at `at`: a bar, a disk with its reference line, a plate, a
/// block; its mass centre and (with `points`) its named points marked and labelled. A wheel known
/// by its radius of gyration alone is drawn with its rim at `rim` (0: at √2 k). Its shapes are
/// owned by "body NAME".
void body(const model::Model& m, const At& at, int b, Figure& f, bool points = true, double rim = 0);

/// What holds body b's point (px, py) on the line along the unit (ux, uy) (a track, or what the
/// coordinates imply): with `offset` ≠ 0 a round body's surface, at the foot (px, py) − offset n̂
/// (n̂ = k × u), its ground beyond; at offset 0 the surface its weight presses it onto (and its
/// other given loads to the same side), at its edge there; else a guide through the point (a
/// collar's rod). `pushes` (±1): a surface that pushes the body along ±n̂, through the point
/// (or at the body's edge the other way), its ground behind it; 0: as the loads say.
void line_support(const model::Model& m, const At& at, Figure& f, int b, double px, double py, double ux, double uy, double offset,
                  int pushes = 0);

/// The rim of each wheel known only by its radius of gyration, where the kinematics give it one
/// at `at` (a cord's drum, a mesh's pitch circle): for drawing it as the scene drawing does.
std::map<int, double> wheel_rims(const model::Model& m, const At& at);

/// A glyph size that suits a drawing of these bodies at `at`: from a first drawing's extent.
double glyph_for(const model::Model& m, const At& at);

/// The scene at state `state` (coordinates and rates given or solved in `solved`), drawn from
/// the model: each body by its inertia shape, its named points, the fixed points, and each
/// effect as it draws itself. @throws SceneError when the state does not fix a coordinate.
Figure scene_at(const model::Model& m, const GiNaC::exmap& solved, const GiNaC::exmap& params, int state);

/// The scene at the first state that fixes every coordinate (given or solved): what `draw`
/// shows without a state named. Each state before it is left out, and why is added to
/// `left_out`. @throws the first state's SceneError where no state can be drawn.
Figure first_drawable(const model::Model& m, const GiNaC::exmap& solved, const GiNaC::exmap& params, std::vector<std::string>& left_out);

/// The scene at each of `states` side by side, at one scale and with one glyph size, each titled
/// "state NAME". A state that does not fix a coordinate is left out, and why is added to
/// `left_out`; without `left_out` it throws that SceneError.
Sheet states_at(const model::Model& m, const GiNaC::exmap& solved, const GiNaC::exmap& params, const std::vector<int>& states,
                std::vector<std::string>* left_out = nullptr);

/// The bodies `bodies` at states `from` and `to` side by side, with only the effects named in
/// `effects` (those that do work over an energy analysis). A coordinate one state does not fix
/// takes the other's value. @throws SceneError when neither fixes it.
Sheet positions_with(const model::Model& m, const GiNaC::exmap& solved, const GiNaC::exmap& params, int from, int to,
                     const std::vector<int>& bodies, const std::vector<std::string>& effects);

/// Write the drawing to `path`: .svg as it is, .pdf or .png converted by rsvg-convert (Debian
/// librsvg2-bin), .tex as a TikZ picture to \input in a document that loads tikz.
/// @throws InputError for another extension, a missing converter or a failed write.
void write(const Sheet& s, const std::string& path);

}  // namespace kinergy::draw
