/// @file sections.hpp  What an analysis kind writes its section of a derivation with (each kind's
/// section is in its own file under src/analyses/): the blocks of the page, the form its
/// expressions are shown in, and the notation of quantities at states.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "kinergy/emit/derive.hpp"
#include "kinergy/principles/kinetics.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"

namespace kinergy::emit {

/// A tagger for the equations of one part: prefix "E1" gives E1.1, E1.2, …; a bare prefix
/// ("C", "S") gives C1, C2, …
struct Tags {
  std::string prefix;
  bool dotted = true;
  int n = 0;
  Row row(std::vector<Math> sides) {
    std::string t = prefix + (dotted ? "." : "") + std::to_string(++n);
    return Row{std::move(sides), {}, t, "eq:" + t};
  }
};

/// Is the name all digits (a state "2", whose quantities take a subscript)?
bool digits_only(const std::string& s);
/// The digits as Unicode subscripts: "12" → "₁₂".
std::string subscript_digits(const std::string& s);
/// Plain-text quantity at a state: T₁, T(before), L_x₁.
std::string text_at(const std::string& base, const std::string& state);
/// TeX of an effect's, body's or state's name as an upright word.
std::string tex_word(const std::string& s);
/// "1 → 2".
std::string text_interval(const std::string& a, const std::string& b);
/// The subscript of a quantity over an interval: "1\to 2" (TeX), "₁→₂" (text).
std::string tex_interval_sub(const std::string& a, const std::string& b);
std::string text_interval_sub(const std::string& a, const std::string& b);

/// Words; an expression; fixed notation in both forms.
inline Span W(const std::string& s) { return Span::w(s); }
inline Span M(const GiNaC::ex& e) { return Span::m(Math::of(e)); }
inline Span N(const std::string& tex, const std::string& text) { return Span::m(Math::notation(tex, text)); }

/// "a, b and c".
std::string listed(const std::vector<std::string>& names);

class Sections {
public:
  virtual ~Sections() = default;

  /// The solution the derivation shows.
  virtual const Solution& solution() const = 0;

  // --- blocks, in the order they are written ---
  virtual void section(const std::string& title) = 0;
  virtual void subsection(const std::string& title) = 0;
  virtual void para(Spans sp) = 0;
  /// A figure, numbered in order (as `kinergy draw --figure N` finds it).
  virtual void figure(draw::Sheet sheet, const std::string& caption) = 0;
  /// The impulse–momentum diagram of `bodies` in analysis `a` showing `shown` (nothing when there
  /// is nothing to draw); `held`: the effects whose impulses its equations hold, each of which it
  /// must draw (checked: emit::check_diagram).
  virtual void momentum_figure(const model::Analysis& a, const std::vector<int>& bodies, const std::vector<principles::Shown>& shown,
                               const std::vector<std::string>& held, const std::string& caption) = 0;
  /// The free-body diagram of `body` at analysis `a`'s state equal to its kinetic diagram (nothing
  /// when there is nothing to draw).
  virtual void kinetic_figure(const model::Analysis& a, const principles::BodyAcceleration& acc, const std::vector<principles::BodyLoad>& loads,
                              const std::string& caption) = 0;
  /// Displayed equations (nothing when there are none).
  virtual void rows(std::vector<Row> r) = 0;
  /// Its equations' tag letter and what it stands for, in the legend (after the kinds' own: K
  /// kinematics, E energy, M momentum, I impact).
  virtual void legend(const std::string& letter, const std::string& meaning) = 0;
  /// The system's equation `q` is first shown here, under `tag` (the system section refers to it).
  virtual void remember(const principles::Equation& q, const std::string& tag) = 0;

  // --- forms ---
  /// An expression with the given state values put in, tidied but not factored (the terms of an
  /// energy or a momentum as a person adds them up).
  virtual GiNaC::ex sub(const GiNaC::ex& e) const = 0;
  /// Trigonometric and rational simplification, squares out of roots; not factored.
  virtual GiNaC::ex tidy(const GiNaC::ex& e) const = 0;

  /// Each side of an equation with the given values in and the tidy form.
  std::pair<GiNaC::ex, GiNaC::ex> sides(const principles::Equation& q) const { return {sub(q.lhs), sub(q.rhs)}; }
  /// The row of the system's equation `q`, tagged next by `tags` and remembered there.
  Row equation(Tags& tags, const principles::Equation& q);
  std::string state_name(int i) const { return solution().model.states[static_cast<std::size_t>(i)].name; }
  /// "a, b and c" of the analysis' bodies.
  std::string bodies(const model::Analysis& a) const;
};

}  // namespace kinergy::emit
