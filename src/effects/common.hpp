// Pieces several effect kinds share (private to src/effects).
#pragma once
#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <initializer_list>
#include <memory>
#include <random>
#include <vector>

#include "kinergy/common/error.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/draw/names.hpp"
#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"

namespace kinergy::effects {

using draw::At;
using draw::Figure;
using draw::Ink;

using GiNaC::ex;
using model::Analysis;
using model::Effect;
using model::EffectReader;
using model::Model;
using model::PointRef;
using principles::Knowledge;
using principles::Push;
using scene::EffectDef;
using units::Dimension;

/// A new effect of kind T named and placed as its definition.
template <class T>
std::shared_ptr<T> make(const EffectDef& ed) {
  auto e = std::make_shared<T>();
  e->name = ed.name;
  e->kind = ed.kind;
  e->pos = ed.pos;
  return e;
}

/// The units of the chapter: force F, energy (or moment) E.
inline Dimension force_dim() {
  return Dimension::mass() * Dimension::length() / (Dimension::time() * Dimension::time());
}
inline Dimension energy_dim() { return force_dim() * Dimension::length(); }

/// `KIND: [A, B]`: the two points an element joins (refused with `problem` and `fix` otherwise).
inline std::pair<PointRef, PointRef> two_points(EffectReader& r, const EffectDef& ed, const std::string& problem,
                                                const std::string& fix) {
  if (!ed.arg.is_list() || ed.arg.items.size() != 2) throw SceneError(ed.arg.pos, problem, fix);
  PointRef a = r.point_ref(ed.arg.items[0], ed.kind);
  return {a, r.point_ref(ed.arg.items[1], ed.kind)};
}

/// The option `key` as a quantity of dimension `d` that must be zero or positive (`what` names it).
inline ex non_negative(EffectReader& r, const EffectDef& ed, const std::string& key, const std::string& example,
                       const Dimension& d, const std::string& fix, const std::string& what) {
  const scene::Node& n = r.option(ed, key, example);
  ex v = r.quantity(r.text_of(n, key, example), false, d, key, fix);
  r.positive(v, n.pos, what, true);
  return v;
}

/// The bodies among these parties (a fixed party is no body), each once.
inline std::vector<int> bodies_of(std::initializer_list<int> parties) {
  std::vector<int> out;
  for (int b : parties)
    if (b >= 0 && std::find(out.begin(), out.end(), b) == out.end()) out.push_back(b);
  return out;
}

/// `n` positions drawn at random over the `base` values (each coordinate in [−3, 3], t in [0, 6]),
/// from `seed`: the same ones on every run. What a declared geometry (a pin, a track) must hold at.
inline std::vector<GiNaC::exmap> random_positions(const Model& m, const GiNaC::exmap& base, unsigned seed, int n = 5) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<GiNaC::exmap> out;
  for (int i = 0; i < n; ++i) {
    GiNaC::exmap at = base;
    for (auto& c : m.coords) at[c.q] = GiNaC::numeric(u(rng));
    at[m.t] = GiNaC::numeric(u(rng) + 3);
    out.push_back(at);
  }
  return out;
}

/// The sense a support's force along a line is counted in (the sign rule, docs/scene-format.md
/// "Signs of forces"): +1 when (ux, uy) points up (+y), or — a horizontal line — along +x; −1
/// otherwise: a friction up an incline, a cord's pull up, a push to the right along a floor. A
/// line that turns with the motion is taken as it lies where the coordinates are zero (or, where
/// it is not defined there, at the first of a few fixed places).
inline int axis_sense(const Model& m, const ex& ux, const ex& uy) {
  const GiNaC::exmap env = m.numeric_environment();
  for (double q : {0.0, 0.1, 0.3, 0.7}) {
    GiNaC::exmap at = env;
    for (auto& c : m.coords) {
      at[c.q] = GiNaC::numeric(q);
      at[c.qd] = 0;
    }
    at[m.t] = 0;
    try {
      const ex x = ux.subs(at).evalf(), y = uy.subs(at).evalf();
      if (!GiNaC::is_a<GiNaC::numeric>(x) || !GiNaC::is_a<GiNaC::numeric>(y)) continue;
      const double dx = GiNaC::ex_to<GiNaC::numeric>(x).to_double(), dy = GiNaC::ex_to<GiNaC::numeric>(y).to_double();
      if (!std::isfinite(dx) || !std::isfinite(dy) || std::hypot(dx, dy) < 1e-9) continue;
      return std::abs(dy) > 1e-9 * std::hypot(dx, dy) ? (dy > 0 ? 1 : -1) : (dx > 0 ? 1 : -1);
    } catch (const std::exception&) {  // (a division by zero there: the next place)
    }
  }
  return 1;
}

/// How figures and diagrams name an effect's force or couple (issue 47), in TeX: the scene's
/// `label:`, else the parameter that is its size, where it is one (a couple M: Mc → M_{c}), else
/// the effect's own name where it reads as a symbol (P, F1), else the symbol of its kind (`kind`:
/// P a force, M a couple, T a cord's pull, F a spring's or a friction's force). Figures show it
/// through draw::from_tex.
inline std::string load_symbol(const Effect& e, const std::string& kind, const ex& size = 0) {
  if (!e.label.empty()) return e.label;
  if (GiNaC::is_a<GiNaC::symbol>(size))
    if (auto n = draw::textbook(GiNaC::ex_to<GiNaC::symbol>(size).get_name())) return n->tex;
  if (auto n = draw::textbook(e.name)) return n->tex;
  return kind;
}

/// `l` named by `symbol` (what figures and diagrams write for it).
inline model::Load with_symbol(model::Load l, std::string symbol) {
  l.symbol = std::move(symbol);
  return l;
}

/// A label for an expression (a spring's stiffness, a damper's constant): the textbook name of
/// a parameter, the symbol `otherwise` for anything else.
inline draw::Name value_label(const ex& v, const std::string& otherwise) {
  if (GiNaC::is_a<GiNaC::symbol>(v))
    if (auto n = draw::textbook(GiNaC::ex_to<GiNaC::symbol>(v).get_name())) return *n;
  return {otherwise, otherwise};
}

/// Is body b (≥ 0) in the analysis' set?
inline bool acts_on(const Analysis& a, int b) { return b >= 0 && principles::in_set(a.bodies, b); }

/// Body b's mass centre as a place loads act at (−1: the ground).
inline PointRef centre_of(const Model& m, int b) {
  PointRef p;
  p.body = b;
  p.ground = b < 0;
  p.text = b >= 0 ? m.bodies[static_cast<std::size_t>(b)].name : "ground";
  return p;
}

/// A couple M on body b; with `other` ≥ 0 (or the ground, −1, when `reacted`), −M on that one.
inline model::Load couple_on(const Model& m, int b, const ex& M, std::optional<int> other = std::nullopt) {
  model::Load l;
  l.at = centre_of(m, b);
  l.M = M;
  if (other) l.partner = centre_of(m, *other);
  return l;
}

/// The body a couple acts against (`against: B`: it takes −M), checked to be another body; none
/// when the option is absent.
inline std::optional<int> against(EffectReader& r, const EffectDef& ed, int body) {
  const scene::Node* n = ed.options.get("against");
  if (!n) return std::nullopt;
  const int b = r.body_ref(*n, "against");
  if (b == body)
    throw SceneError(n->pos, ed.kind + " '" + ed.name + "' acts against the body it turns", "name the other body, which takes the opposite couple");
  return b;
}

/// A force F at point `at`; with a partner, −F at that point (an interaction).
inline model::Load force_at(const PointRef& at, const ex& Fx, const ex& Fy, std::optional<PointRef> partner = std::nullopt) {
  model::Load l;
  l.at = at;
  l.Fx = Fx;
  l.Fy = Fy;
  l.partner = std::move(partner);
  return l;
}

/// An effect on one body (a couple, a friction couple, a drive).
class BodyEffect : public Effect {
public:
  int body = -1;
};

// --- pictures ----------------------------------------------------------------------------

/// Where body b is pinned to a fixed point (a pin effect with a fixed party), at `at`; nothing
/// when it is not.
inline std::optional<std::pair<double, double>> fixed_pin(const Model& m, const At& at, int body) {
  for (auto& e : m.effects) {
    const auto r = e.reaction(m);
    if (!r || r->kind != model::Reaction::Kind::Pin) continue;
    if ((r->a.body == body && r->b.body < 0) || (r->b.body == body && r->a.body < 0))
      return at.point(m.position(r->a.body == body ? r->a : r->b));
  }
  return std::nullopt;
}

/// A curved arrow round body b's centre, counterclockwise when sense > 0 (clockwise < 0, no
/// head when 0), `glyphs` glyphs out, labelled: a couple, a torsion spring, a power drive. With
/// `at_pin`, round the fixed pin the body turns about, where it has one (a torsion spring, a
/// bearing's friction act there).
inline void draw_turning(const Model& m, const At& at, Figure& f, int body, double sense, Ink ink, const draw::Name& label,
                         double glyphs = 1.6, bool at_pin = false) {
  const auto& B = m.bodies[static_cast<std::size_t>(body)];
  const auto pin = at_pin ? fixed_pin(m, at, body) : std::nullopt;
  const double x = pin ? pin->first : at(B.x), y = pin ? pin->second : at(B.y), r = f.ring(x, y, f.glyph() * glyphs);
  if (sense > 0) f.arc_arrow(x, y, r, -0.6, 3.6, ink);
  else if (sense < 0) f.arc_arrow(x, y, r, 3.6, -0.6, ink);
  else {
    std::vector<std::pair<double, double>> pts;
    for (int i = 0; i <= 24; ++i) pts.push_back({x + r * std::cos(-0.6 + 4.2 * i / 24), y + r * std::sin(-0.6 + 4.2 * i / 24)});
    f.polyline(pts, ink);
  }
  f.label(x + r * std::cos(2.2), y + r * std::sin(2.2), label.text, label.tex);
}

/// The two points an effect joins, when both have a place (a party on the ground has none).
inline std::optional<std::array<double, 4>> joined(const Model& m, const At& at, const PointRef& a, const PointRef& b) {
  if (a.ground || b.ground) return std::nullopt;
  auto [x1, y1] = at.point(m.position(a));
  auto [x2, y2] = at.point(m.position(b));
  if (std::isnan(x1) || std::isnan(y1) || std::isnan(x2) || std::isnan(y2)) return std::nullopt;
  return std::array<double, 4>{x1, y1, x2, y2};
}

}  // namespace kinergy::effects
