// The figures of a worked solution: the scene at its states, and impulse–momentum diagrams.
#include "figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "kinergy/common/error.hpp"
#include "kinergy/draw/names.hpp"
#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"

namespace kinergy::emit {

using namespace GiNaC;

exmap figure_values(const Solution& s, std::string* samples) { return draw::with_samples(s.model, parameter_values(s), samples); }

std::vector<draw::Sheet> state_sheets(const Solution& s, std::vector<std::string>& left_out) {
  const model::Model& m = s.model;
  const exmap values = figure_values(s);
  std::vector<draw::Sheet> out;
  for (std::size_t first = 0; first < m.states.size(); first += 3) {
    std::vector<int> row;
    for (std::size_t i = first; i < std::min(first + 3, m.states.size()); ++i) row.push_back(static_cast<int>(i));
    draw::Sheet sheet = draw::states_at(m, s.branch.sol, values, row, &left_out);
    if (sheet.size() > 0) out.push_back(std::move(sheet));
  }
  return out;
}

namespace {

/// A body as a subscript: its label or short name (gearA: A), else its name (m_A, W_rod, N_disk).
draw::Name body_sub(const model::Model& m, int b) {
  const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
  if (const auto s = draw::body_label(B)) return *s;
  return {B.name, "\\mathrm{" + tex_text(B.name) + "}"};
}

/// The names of the loads one figure draws (issue 47): each by its symbol (W, N, F, P, M, T), with
/// a subscript only where two of one kind meet in the figure — the body's short name where one
/// effect acts on several of its bodies (W_A, W_B), the effect's name where several effects share
/// a symbol (F_rolling, F_table).
class LoadNames {
public:
  struct Load {
    std::string effect, symbol;
    int body;
  };
  LoadNames(const model::Model& m, std::vector<Load> loads) : m_(m), loads_(std::move(loads)) {}

  draw::Name operator()(const std::string& effect, int body) const {
    const Load* me = nullptr;
    for (auto& l : loads_)
      if (l.effect == effect && l.body == body) me = &l;
    if (!me) return {effect, "\\mathrm{" + tex_text(effect) + "}"};
    bool effects = false, bodies = false;  // several effects with its symbol; this effect on several bodies
    for (auto& l : loads_) {
      if (l.symbol != me->symbol) continue;
      effects = effects || l.effect != effect;
      bodies = bodies || (l.effect == effect && l.body != body);
    }
    // (a symbol is TeX: a scene's `label:`, or a letter with its subscript)
    const draw::Name base = draw::from_tex(me->symbol);
    draw::Name sub{effects ? effect : "", effects ? "\\mathrm{" + tex_text(effect) + "}" : ""};
    if (bodies && body >= 0) {
      const draw::Name b = body_sub(m_, body);
      sub = sub.text.empty() ? b : draw::Name{sub.text + "," + b.text, sub.tex + "," + b.tex};
    }
    return draw::subscripted(base, sub);
  }

private:
  const model::Model& m_;
  std::vector<Load> loads_;
};

// What the diagram needs to put numbers on its arrows' directions.
struct Diagram {
  const Solution& s;
  const model::Model& m;
  const model::Analysis& a;
  const std::vector<int>& bodies;
  const TexSymbols* names;
  exmap params;
  draw::At at1, at2;
  double g = 0, len = 0;  // glyph, and the length every arrow is drawn with (directions only)
  std::map<int, double> rims = {};  // a wheel known by k: its rim as the scene drawing has it (a pitch circle)
  // One scale for the arrows of an impulse–momentum equation (0: each as long as `len`): the
  // length per unit of momentum or impulse, so that the drawn sum closes. What a first drawing
  // finds (the sizes), and what the caption says of the arrows not drawn to it.
  double scale = 0;
  mutable std::vector<double> seen = {};
  mutable std::vector<std::string> lengthened = {}, direction_only = {}, negative = {};
  mutable std::string about = "";  // what the arrow being drawn stands for, as a caption says it

  // `what` added to `list` once
  static void once(std::vector<std::string>& list, const std::string& what) {
    if (std::find(list.begin(), list.end(), what) == list.end()) list.push_back(what);
  }

  // what the caption says of the scale and of the arrows not drawn to it (empty when nothing)
  std::string note() const {
    if (!(scale > 0) && direction_only.empty()) return "";
    auto list = [](const std::vector<std::string>& v) {
      std::string out;
      for (std::size_t i = 0; i < v.size(); ++i) out += (i == 0 ? "" : i + 1 == v.size() ? " and " : ", ") + v[i];
      return out;
    };
    std::string out = scale > 0 ? "Momenta and impulses are drawn to one scale, each arrow as long as its size." : "";
    if (!lengthened.empty()) out += " Too short at that scale, drawn longer: " + list(lengthened) + ".";
    if (!direction_only.empty()) out += std::string(out.empty() ? "" : " ") + "Drawn by direction only (its size not known alone): " + list(direction_only) + ".";
    if (!negative.empty())
      out += " " + list(negative) + (negative.size() > 1 ? " come" : " comes") + " out negative: drawn in the sense the equations take, " +
             (negative.size() > 1 ? "they act" : "it acts") + " the other way.";
    return out;
  }

  void body(draw::Figure& f, const draw::At& at, int b) const {
    const auto r = rims.find(b);
    draw::body(m, at, b, f, false, r == rims.end() ? 0 : r->second);
  }

  bool in_set(int b) const { return b < 0 || std::find(bodies.begin(), bodies.end(), b) != bodies.end(); }

  // the value of an expression of state symbols: given and solved values put in, then the parameters
  double solved(const ex& e) const {
    ex v = e;
    for (int pass = 0; pass < 6; ++pass) {
      ex w = v.subs(m.states[static_cast<std::size_t>(a.from)].given).subs(m.states[static_cast<std::size_t>(a.to)].given).subs(s.branch.sol);
      if (w.is_equal(v)) break;
      v = w;
    }
    draw::At p;
    p.values = params;
    return p(v);
  }

  // an arrow from (x, y) along (dx, dy), labelled, standing for a size `magnitude`: drawn to the
  // diagram's scale where it has one (at least a glyph long, else said), else `len` long; false
  // when it has no direction
  bool arrow(draw::Figure& f, double x, double y, double dx, double dy, draw::Ink ink, const std::string& text, const std::string& tex,
             double magnitude = std::numeric_limits<double>::quiet_NaN()) const {
    const double d = std::hypot(dx, dy);
    if (!(d > 0) || !std::isfinite(d) || !std::isfinite(x) || !std::isfinite(y)) return false;
    const bool sized = std::isfinite(magnitude) && magnitude > 0;
    if (sized) seen.push_back(magnitude);
    double length = len, to_scale = std::numeric_limits<double>::quiet_NaN();
    if (scale > 0 && sized) {
      // length = scale × size, down to a glyph (so that its direction still shows)
      length = scale * magnitude;
      if (length < g) {
        length = g;
        once(lengthened, about.empty() ? text : about);
      } else {
        to_scale = magnitude;
      }
    } else if (!sized) {
      once(direction_only, about.empty() ? text : about);
    }
    const double ex_ = x + length * dx / d, ey = y + length * dy / d;
    f.arrow(x, y, ex_, ey, ink, to_scale);
    f.label(ex_, ey, text, tex);
    return true;
  }

  // where a load on body b at (x, y) is drawn: there; but on a particle whose drawing it is off
  // (the friction of a block on the cart it rides, acting at the block), at the particle's edge
  // toward it — a particle's loads act through its centre, only their directions matter
  std::pair<double, double> on_body(const draw::Figure& f, const draw::At& at, int b, double x, double y) const {
    if (b < 0 || !m.bodies[static_cast<std::size_t>(b)].inertia.is_zero()) return {x, y};
    const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
    const double gx = at(B.x), gy = at(B.y), d = std::hypot(x - gx, y - gy);
    if (!(d > 0) || !std::isfinite(d)) return {x, y};
    const double r = f.reach("body " + B.name, gx, gy, (x - gx) / d, (y - gy) / d);
    return d > r ? std::pair{gx + r * (x - gx) / d, gy + r * (y - gy) / d} : std::pair{x, y};
  }

  // a load that is zero (at both states): a ring at its point, "name = 0"
  void zero(draw::Figure& f, double x, double y, const std::string& text, const std::string& tex) const {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    f.circle(x, y, 0.35 * g, draw::Ink::Force);
    f.label(x, y, text + " = 0", tex + " = 0");
  }

  // a curved arrow round (x, y) in the sense of w (counterclockwise when positive), labelled
  void turning(draw::Figure& f, double x, double y, double w, draw::Ink ink, const std::string& text, const std::string& tex) const {
    if (!(std::fabs(w) > 0) || !std::isfinite(w) || !std::isfinite(x) || !std::isfinite(y)) return;
    const double r = f.ring(x, y, 2.2 * g), pi = 3.14159265358979323846;
    const double a0 = w > 0 ? -pi / 4 : pi, a1 = w > 0 ? pi : -pi / 4;
    f.arc_arrow(x, y, r, a0, a1, ink);
    f.label(x + r * std::cos(a1), y + r * std::sin(a1), text, tex);
  }

  void about_point(draw::Figure& f, const draw::At& at) const {
    if (!a.about() || m.body_index(a.about()->text) >= 0) return;
    auto [x, y] = at.point(m.position(*a.about()));
    if (std::isfinite(x) && std::isfinite(y)) {
      f.mark(x, y, a.about()->text, a.about()->body < 0);
      const draw::Name n = draw::point_label(m, a.about()->text);
      f.label(x, y, n.text, n.tex);
    }
  }

  // |m v̄| of body b at a state (NaN where it has no value)
  double momentum(const draw::At& at, int b) const {
    const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
    return std::fabs(at(B.mass)) * std::hypot(at(m.rate(B.x)), at(m.rate(B.y)));
  }

  // |∫F dt| over the analysis of a known force (NaN where it changes with the motion, or is a
  // support's whose size no equation gives): F Δt for a constant F, else its integral in t
  double impulse_size(const principles::Push& p) const {
    if (p.assumed || !principles::motion_free(m, p.Fx) || !principles::motion_free(m, p.Fy)) return std::numeric_limits<double>::quiet_NaN();
    const auto Ix = principles::over_duration(m, p.Fx, a), Iy = principles::over_duration(m, p.Fy, a);
    if (!Ix || !Iy) return std::numeric_limits<double>::quiet_NaN();
    return std::hypot(solved(*Ix), solved(*Iy));
  }

  // momenta at a state: m v̄ at each mass centre, its arrow at the diagram's one scale, Ī ω round
  // it; with several bodies each label carries its body's name (m_A v̄_A)
  draw::Figure momenta(const draw::At& at) const {
    draw::Figure f;
    f.set_glyph(g);
    for (int b : bodies) {
      body(f, at, b);
      const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
      const double x = at(B.x), y = at(B.y);
      const double p = momentum(at, b);  // (its arrow to the diagram's scale)
      about = "the momentum of " + B.name;
      const draw::Name sub = bodies.size() > 1 ? body_sub(m, b) : draw::Name{};
      const draw::Name ms = draw::subscripted({"m", "m"}, sub), vs = draw::subscripted({"v\u0304", "\\bar{v}"}, sub);
      arrow(f, x, y, at(m.rate(B.x)), at(m.rate(B.y)), draw::Ink::Momentum, ms.text + " " + vs.text, ms.tex + vs.tex, p);
      if (at(B.inertia) > 0) {
        const draw::Name Is = draw::subscripted({"I\u0304", "\\bar{I}"}, sub), ws = draw::subscripted({"\u03c9", "\\omega"}, sub);
        turning(f, x, y, at(m.omega(b)), draw::Ink::Momentum, Is.text + " " + ws.text, Is.tex + ws.tex);
      }
    }
    about = "";
    about_point(f, at);
    return f;
  }

  // a push's symbol: its load's (W, F, P, M, T), N for an implied support ("N_disk", the
  // principles' name), R for a pin's known impulse, J for a blow
  static std::string push_symbol(const std::string& effect, const principles::Push& p) {
    if (!p.symbol.empty()) return p.symbol;
    if (effect.rfind("N_", 0) == 0) return "N";
    if (p.unknown) return p.reaction ? "R" : "J";
    return "";
  }

  // the impulses on the bodies over the analysis, drawn on them at its first state
  draw::Figure impulses(const std::vector<principles::Shown>& shown) const {
    draw::Figure f;
    f.set_glyph(g);
    for (int b : bodies) body(f, at1, b);
    std::vector<LoadNames::Load> drawn;
    for (auto& [effect, p] : shown)
      if (in_set(p.body) && !push_symbol(effect, p).empty()) drawn.push_back({effect, push_symbol(effect, p), p.body});
    const LoadNames names_of(m, drawn);
    for (auto& [effect, p] : shown) {
      if (!in_set(p.body)) continue;
      f.owned_by(effect);  // (what the check of the diagram against its equations reads)
      about = "the impulse of " + effect;
      const auto [x, y] = on_body(f, at1, p.body, at1(p.arm_x), at1(p.arm_y));
      // each by its symbol, subscripted only where two of a kind meet in the diagram
      const draw::Name named = names_of(effect, p.body);
      const std::string word = named.tex, said = named.text;
      if (p.unknown) {
        // an unknown impulse made of unknowns (R = Σ u ∂R/∂u): one arrow along each ∂R/∂u, named by u
        std::vector<symbol> us;
        ex restx = p.Rx, resty = p.Ry;
        for (const ex& u : a.unknowns)
          if (is_a<symbol>(u) && (p.Rx.has(u) || p.Ry.has(u))) {
            us.push_back(ex_to<symbol>(u));
            restx -= u * p.Rx.diff(us.back());
            resty -= u * p.Ry.diff(us.back());
          }
        const bool made_of_unknowns = !us.empty() && expand(restx).is_zero() && expand(resty).is_zero();
        if (made_of_unknowns)
          for (const symbol& u : us) {
            // named as written, without the states an impulse is bound to ("J_hit[before,after]"),
            // in the sense the equations take it, as long as its solved size (said where negative)
            const double dx = at1(p.Rx.diff(u)), dy = at1(p.Ry.diff(u)), v = solved(u);
            const std::string name = plain_name(model::text(u));
            arrow(f, x, y, dx, dy, draw::Ink::Force, name, latex(u, names), std::fabs(v) * std::hypot(dx, dy));
            if (v < 0 && scale > 0) once(negative, name);
          }
        // a known impulse (given, or a pin's: the momentum change less the others): along its solved
        // value (a pin's as ∫R dt); a ring at its point where it is zero (a pin struck at the
        // centre of percussion)
        else {
          const std::string t = p.reaction ? "\u222b" + said + " dt" : said, tx = p.reaction ? "\\int " + word + "\\,dt" : word;
          const double jx = solved(p.Rx), jy = solved(p.Ry);
          if (!arrow(f, x, y, jx, jy, draw::Ink::Force, t, tx, std::hypot(jx, jy))) zero(f, x, y, t, tx);
        }
        continue;
      }
      if (!p.M.is_zero()) {
        // a couple: round the mass centre of the body it turns
        int b = -1;
        if (int ei = m.effect_index(effect); ei >= 0)
          for (int x2 : m.effects[static_cast<std::size_t>(ei)].bodies_acted(m))
            if (in_set(x2)) b = x2;
        if (b >= 0) {
          const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
          double Mv = at1(p.M);
          if (!(std::fabs(Mv) > 0)) Mv = at2(p.M);
          turning(f, at1(B.x), at1(B.y), Mv, draw::Ink::Force, (p.M.has(m.t) ? "\u222b" + said + " dt" : said + " \u0394t"),
                  p.M.has(m.t) ? "\\int " + word + "\\,dt" : word + "\\,\\Delta t");
        }
      }
      if (p.Fx.is_zero() && p.Fy.is_zero()) continue;
      // a force: along its direction at the first state (at the second when it is zero there)
      const bool varies = p.Fx.has(m.t) || p.Fy.has(m.t) || p.assumed;
      const std::string text = varies ? "\u222b" + said + " dt" : said + " \u0394t";
      const std::string tex = varies ? "\\int " + word + "\\,dt" : word + "\\,\\Delta t";
      const double size = impulse_size(p);
      if (!arrow(f, x, y, at1(p.Fx), at1(p.Fy), draw::Ink::Force, text, tex, size)) {
        const auto [x2, y2] = on_body(f, at2, p.body, at2(p.arm_x), at2(p.arm_y));
        if (!arrow(f, x2, y2, at2(p.Fx), at2(p.Fy), draw::Ink::Force, text, tex, size)) zero(f, x, y, said, word);
      }
    }
    f.owned_by("");
    about = "";
    about_point(f, at1);
    return f;
  }

  // the forces and couples on body b at the state, as the free-body diagram shows them
  draw::Figure free_body(int b, const std::vector<principles::BodyLoad>& loads) const {
    draw::Figure f;
    f.set_glyph(g);
    body(f, at1, b);
    const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
    std::vector<LoadNames::Load> drawn;
    for (auto& l : loads)
      if (l.body == b && !l.unknown && !l.symbol.empty()) drawn.push_back({l.effect, l.symbol, b});
    const LoadNames names_of(m, drawn);
    for (auto& l : loads) {
      if (l.body != b) continue;
      f.owned_by(l.effect);
      const auto [x, y] = on_body(f, at1, b, solved(l.x), solved(l.y));
      // each by its symbol (W, F, P, M), subscripted only where two of a kind meet on the body
      const draw::Name named = names_of(l.effect, b);
      const std::string word = named.tex, said = named.text;
      if (!l.M.is_zero()) turning(f, at1(B.x), at1(B.y), solved(l.M), draw::Ink::Force, said, word);
      if (l.Fx.is_zero() && l.Fy.is_zero()) continue;
      if (l.unknown) {
        // a reaction: one arrow along each of its unknowns' directions (F = Σ u ∂F/∂u), named by u
        for (const ex& u : a.unknowns)
          if (is_a<symbol>(u) && (l.Fx.has(u) || l.Fy.has(u))) {
            arrow(f, x, y, solved(l.Fx.diff(ex_to<symbol>(u))), solved(l.Fy.diff(ex_to<symbol>(u))), draw::Ink::Force,
                  plain_name(model::text(u)), latex(u, names));
          }
        continue;
      }
      arrow(f, x, y, solved(l.Fx), solved(l.Fy), draw::Ink::Force, said, word);
    }
    f.owned_by("");
    return f;
  }

  // m ā at the mass centre along the acceleration solved, Ī α round it
  draw::Figure kinetic(const principles::BodyAcceleration& acc) const {
    const int b = acc.body;
    draw::Figure f;
    f.set_glyph(g);
    body(f, at1, b);
    const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
    const double x = at1(B.x), y = at1(B.y);
    arrow(f, x, y, solved(acc.ax), solved(acc.ay), draw::Ink::Momentum, "m a\u0304", "m\\bar{a}");
    if (at1(B.inertia) > 0) turning(f, x, y, solved(acc.alpha), draw::Ink::Momentum, "I\u0304 \u03b1", "\\bar{I}\\alpha");
    return f;
  }
};

}  // namespace

/// What a panel draws, to tell two alike: its marks where they are (to the micrometre), and the
/// owner, kind and ink of every other stroke, and its labels' words — not the glyph size, which
/// differs between sheets of the same drawing.
std::string panel_print(const draw::Figure& f) {
  std::vector<std::string> parts;
  for (const auto& s : f.shapes()) {
    if (s.kind == draw::Figure::Shape::Mark && !s.pts.empty()) {
      char buf[96];
      std::snprintf(buf, sizeof buf, " %.6f %.6f", s.pts[0].first, s.pts[0].second);
      parts.push_back("mark " + s.id + buf);
    } else {
      parts.push_back("shape " + std::to_string(static_cast<int>(s.kind)) + " " + std::to_string(static_cast<int>(s.ink)) + " " + s.owner);
    }
  }
  for (const auto& l : f.labels()) parts.push_back("label " + l.text);
  std::sort(parts.begin(), parts.end());
  std::string out;
  for (auto& x : parts) out += x + "\n";
  return out;
}

std::vector<std::string> outside_supports(const model::Model& m, const std::vector<int>& bodies) {
  auto in = [&](int b) { return b >= 0 && std::find(bodies.begin(), bodies.end(), b) != bodies.end(); };
  std::vector<std::string> out;
  for (auto& e : m.effects) {
    const auto r = e.reaction(m);
    if (!r || r->kind == model::Reaction::Kind::Contact) continue;  // (a contact acts in its impacts only: among the terms there)
    if (in(r->a.body) != in(r->b.body)) out.push_back(e.name);
  }
  return out;
}

void check_diagram(const draw::Sheet& sheet, std::size_t panel, const std::vector<std::string>& held, const std::string& what) {
  std::string missing;
  for (const std::string& e : held) {
    const auto& shapes = sheet.panel(panel).shapes();
    if (std::none_of(shapes.begin(), shapes.end(), [&](const draw::Figure::Shape& sh) { return sh.owner == e; }))
      missing += (missing.empty() ? "'" : ", '") + e + "'";
  }
  if (!missing.empty())
    throw std::logic_error("the " + what + " does not draw " + missing + ", which its equations hold (or which acts on it from outside its set)");
}

std::optional<draw::Sheet> kinetic_diagram(const Solution& s, const model::Analysis& a, const principles::BodyAcceleration& acc,
                                           const std::vector<principles::BodyLoad>& loads, const TexSymbols* names) {
  const int body = acc.body;
  const model::Model& m = s.model;
  const std::vector<int> bodies{body};
  Diagram d{s, m, a, bodies, names, figure_values(s), {}, {}};
  try {
    d.at1 = draw::state_values(m, s.branch.sol, d.params, a.from);
  } catch (const SceneError&) {
    return std::nullopt;
  }
  d.at2 = d.at1;
  d.rims = draw::wheel_rims(m, d.at1);
  d.g = draw::glyph_for(m, d.at1);
  d.len = 5 * d.g;
  draw::Sheet sheet;
  sheet.add(d.free_body(body, loads), "free-body diagram");
  sheet.then("=", "=");
  sheet.add(d.kinetic(acc), "kinetic diagram");
  // every load of its equations on the body (a force or a couple), and its supports from outside
  std::vector<std::string> held = outside_supports(m, bodies);
  for (auto& l : loads)
    if (l.body == body && !(l.Fx.is_zero() && l.Fy.is_zero() && l.M.is_zero()) && std::find(held.begin(), held.end(), l.effect) == held.end())
      held.push_back(l.effect);
  check_diagram(sheet, 0, held, "free-body diagram of " + m.bodies[static_cast<std::size_t>(body)].name);
  return sheet;
}

std::optional<draw::Sheet> momentum_diagram(const Solution& s, const model::Analysis& a, const std::vector<int>& bodies,
                                            const std::vector<principles::Shown>& shown, const std::vector<std::string>& held,
                                            const TexSymbols* names) {
  const model::Model& m = s.model;
  Diagram d{s, m, a, bodies, names, figure_values(s), {}, {}};
  // each state at its own positions; a coordinate one of them does not fix (an angle the problem
  // never needs) at the other's
  std::optional<draw::At> a1, a2;
  try {
    a1 = draw::state_values(m, s.branch.sol, d.params, a.from);
  } catch (const SceneError&) {
  }
  try {
    a2 = draw::state_values(m, s.branch.sol, d.params, a.to, a1 ? &*a1 : nullptr);
    if (!a1) a1 = draw::state_values(m, s.branch.sol, d.params, a.from, &*a2);
  } catch (const SceneError&) {
    return std::nullopt;
  }
  d.at1 = *a1;
  d.at2 = *a2;
  d.rims = draw::wheel_rims(m, d.at1);
  d.g = std::max(draw::glyph_for(m, d.at1), draw::glyph_for(m, d.at2));
  d.len = 5 * d.g;
  const std::string S1 = m.states[static_cast<std::size_t>(a.from)].name, S2 = m.states[static_cast<std::size_t>(a.to)].name;
  auto panels = [&] {
    draw::Sheet sheet;
    sheet.add(d.momenta(d.at1), "momenta at " + S1);
    sheet.then("+", "+");
    sheet.add(d.impulses(shown), a.instant() ? "impulses in the impact" : "impulses from " + S1 + " to " + S2);
    sheet.then("=", "=");
    sheet.add(d.momenta(d.at2), "momenta at " + S2);
    return sheet;
  };
  // one scale for the momenta and impulses of the equation, so that the drawn sum closes: the
  // largest 1.4 times the diagram's length (a first drawing finds the sizes)
  (void)panels();
  const double largest = d.seen.empty() ? 0 : *std::max_element(d.seen.begin(), d.seen.end());
  if (largest > 0) d.scale = 1.4 * d.len / largest;
  d.lengthened.clear();
  d.direction_only.clear();
  d.negative.clear();
  draw::Sheet sheet = panels();
  sheet.note = d.note();
  std::vector<std::string> all = held;
  for (auto& e : outside_supports(m, bodies))
    if (std::find(all.begin(), all.end(), e) == all.end()) all.push_back(e);
  std::string names_of;
  for (int b : bodies) names_of += (names_of.empty() ? "" : ", ") + m.bodies[static_cast<std::size_t>(b)].name;
  check_diagram(sheet, 1, all, "impulse-momentum diagram of " + names_of + " from state " + S1 + " to " + S2);
  return sheet;
}

}  // namespace kinergy::emit
