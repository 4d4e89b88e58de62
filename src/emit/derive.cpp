// The worked solution of a scene, step by step, as a document model that the text and LaTeX
// writers print: the problem, the given data, the kinematics, each principle applied, the
// system, its solution in closed form and the numbers with units.
#include "kinergy/emit/derive.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "figures.hpp"
#include "kinergy/emit/sections.hpp"
#include "kinergy/model/inertia.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/units/units.hpp"
#include "kinergy/verify/verify.hpp"

namespace kinergy::emit {

using namespace GiNaC;

namespace {

// ---------------------------------------------------------------------------------------------
// small helpers

std::string subscript_digits(const std::string& s) {
  static const char* sub[] = {"\u2080", "\u2081", "\u2082", "\u2083", "\u2084",
                              "\u2085", "\u2086", "\u2087", "\u2088", "\u2089"};
  std::string o;
  for (char c : s) o += sub[c - '0'];
  return o;
}

bool digits_only(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

/// Plain-text quantity at a state: T₁, T(before), L_x₁.
std::string text_at(const std::string& base, const std::string& state) {
  if (digits_only(state)) return base + subscript_digits(state);
  return base + "(" + state + ")";
}

/// TeX of an effect's, body's or state's name as an upright word.
std::string tex_word(const std::string& s) { return "\\mathrm{" + tex_text(s) + "}"; }

/// "1 → 2" in both forms.
std::string text_interval(const std::string& a, const std::string& b) { return a + " \u2192 " + b; }

std::string tex_interval_sub(const std::string& a, const std::string& b) {
  auto one = [](const std::string& s) { return digits_only(s) || s.size() == 1 ? s : "\\mathrm{" + s + "}"; };
  return one(a) + "\\to " + one(b);
}

std::string text_interval_sub(const std::string& a, const std::string& b) {
  if (digits_only(a) && digits_only(b)) return subscript_digits(a) + "\u2192" + subscript_digits(b);
  return "(" + a + "\u2192" + b + ")";
}

/// The symbols of an expression, in a fixed order (by their plain text).
void symbols_in(const ex& e, std::vector<ex>& out) {
  if (is_a<symbol>(e)) {
    if (std::find_if(out.begin(), out.end(), [&](const ex& x) { return x.is_equal(e); }) == out.end()) out.push_back(e);
    return;
  }
  // an integral's variable is bound inside it: only its integrand's other symbols and its ends
  if (numerics::is_integral(e)) {
    std::vector<ex> inner;
    symbols_in(e.op(0), inner);
    for (auto& x : inner)
      if (!x.is_equal(e.op(1))) symbols_in(x, out);
    symbols_in(e.op(2), out);
    symbols_in(e.op(3), out);
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) symbols_in(e.op(i), out);
}

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

class Builder : public Sections {
public:
  Builder(const Solution& s, const scene::SceneDef& def, const DeriveOptions& o)
      : s_(s), m_(s.model), def_(def), o_(o), given_(s.model.given_values()), tag_of_(s.equations.size()) {}

  Derivation run() {
    d_.title = m_.title;
    d_.description = m_.description;
    d_.file = m_.file;
    values();
    clashing_names();
    given();
    kinematics();
    states();
    // each analysis writes its own section
    for (std::size_t i = 0; i < m_.analyses.size() && i < s_.balances.size(); ++i)
      m_.analyses[i].type->derive(*this, static_cast<int>(i) + 1, m_.analyses[i], s_);
    system();
    solution();
    results();
    if (o_.checks) checks();
    return d_;
  }

private:
  const Solution& s_;
  const model::Model& m_;
  const scene::SceneDef& def_;
  DeriveOptions o_;
  Derivation d_;
  exmap given_;
  std::vector<std::string> tag_of_;  ///< tag of each equation of s_.equations where first shown
  int figures_ = 0;

  // --- blocks -----------------------------------------------------------------------------

  void section(const std::string& t) { d_.blocks.push_back({Block::Kind::Section, t, {}, {}, {}, {}, nullptr}); }
  void subsection(const std::string& t) { d_.blocks.push_back({Block::Kind::Subsection, t, {}, {}, {}, {}, nullptr}); }
  void para(Spans sp) { d_.blocks.push_back({Block::Kind::Paragraph, "", std::move(sp), {}, {}, {}, nullptr}); }
  void figure(draw::Sheet sheet, const std::string& caption) {
    // numbered in order, as `kinergy draw --figure N` finds them
    ++figures_;
    Block b{Block::Kind::Figure, "Figure " + std::to_string(figures_) + ": " + caption, {}, {}, {}, {}, nullptr};
    b.sheet = std::make_shared<const draw::Sheet>(std::move(sheet));
    d_.blocks.push_back(std::move(b));
  }
  void rows(std::vector<Row> r) {
    if (!r.empty()) d_.blocks.push_back({Block::Kind::Equations, "", {}, std::move(r), {}, {}, nullptr});
  }

  static Span W(const std::string& s) { return Span::w(s); }
  static Span M(const ex& e) { return Span::m(Math::of(e)); }
  static Span N(const std::string& tex, const std::string& text) { return Span::m(Math::notation(tex, text)); }

  /// An expression with the given state values put in, tidied (as it was, if that fails).
  /// An expression with the given state values put in, tidied but not factored (the terms of
  /// an energy or a momentum as a person adds them up).
  ex sub(const ex& e) const {
    try {
      return tidy(e.subs(given_));
    } catch (const std::exception&) {
      return e;
    }
  }

  /// Trigonometric and rational simplification, squares out of roots; not factored (factor()
  /// picks its form by GiNaC's term order, and a sum of energies reads better expanded).
  ex tidy(const ex& e) const {
    try {
      return model::root_simplify(model::tidy(model::tidy_function_arguments(e)));
    } catch (const std::exception&) {
      return e;
    }
  }

  /// The engine's form of a solved value (as problem.cpp makes a result): tidy, then numerator
  /// and denominator factored when that is shorter.
  ex final_form(const ex& e) const {
    try {
      return model::factored(model::root_simplify(model::tidy(model::tidy_function_arguments(e))));
    } catch (const std::exception&) {
      return e;
    }
  }

  /// Each side of an equation with the given values in and the tidy form.
  std::pair<ex, ex> sides(const principles::Equation& q) const { return {sub(q.lhs), sub(q.rhs)}; }

  /// The equation of the system that a principle's equation is (same sides and label).
  int index_of(const principles::Equation& q) const {
    for (std::size_t i = 0; i < s_.equations.size(); ++i) {
      const auto& e = s_.equations[i];
      if (e.label == q.label && e.lhs.is_equal(q.lhs) && e.rhs.is_equal(q.rhs)) return static_cast<int>(i);
    }
    return -1;
  }

  void remember(const principles::Equation& q, const std::string& tag) {
    int i = index_of(q);
    if (i >= 0 && tag_of_[static_cast<std::size_t>(i)].empty()) tag_of_[static_cast<std::size_t>(i)] = tag;
  }

  std::string state_name(int i) const { return m_.states[static_cast<std::size_t>(i)].name; }

  // --- the parameters' values, as written ----------------------------------------------------

  void values() {
    for (auto& pd : def_.parameters) {
      const model::Parameter* p = m_.parameter(pd.name);
      if (!p || !p->value || p->unknown) continue;
      std::string t = pd.value.s;
      std::size_t i = t.find_first_not_of(' ');
      if (i == std::string::npos) continue;
      std::size_t j = i;
      numeric v;
      try {
        if (!units::parse_decimal(t, j, v)) continue;
      } catch (const std::exception&) {
        continue;
      }
      std::string number = t.substr(i, j - i);
      std::string unit;
      try {
        unit = units::parse_quantity(t).unit.text;
      } catch (const std::exception&) {
        continue;
      }
      d_.values_text[p->sym] = number + (unit.empty() ? "" : " " + unit);
      bool atomic = (unit.empty() || unit == "deg") && number[0] != '-' && number[0] != '+';
      d_.values_tex[p->sym] = {tex_quantity(number, unit), atomic};
    }
  }

  /// A state symbol whose TeX name is that of a parameter (theta@2 and theta2 are both
  /// \theta_{2}) is written (\theta)_{2}.
  void clashing_names() {
    std::set<std::string> taken;
    for (auto& p : m_.params) taken.insert(tex_name(ex_to<symbol>(p.sym).get_name()));
    for (auto& st : m_.states)
      for (auto& [q, syms] : st.sym)
        for (const ex& x : {ex(syms.first), ex(syms.second)}) {
          std::string name = ex_to<symbol>(x).get_name();
          std::string tex = tex_name(name);
          if (!taken.count(tex)) continue;
          std::string base = tex_name(name.substr(0, name.find('@')));
          d_.names[x] = {"(" + base + ")_{" + (digits_only(st.name) ? st.name : "\\mathrm{" + st.name + "}") + "}", true};
        }
  }

  // --- given ----------------------------------------------------------------------------------

  void given() {
    section("Given");
    Block t{Block::Kind::Table, "", {}, {}, {"Symbol", "Value", "Unit"}, {}, nullptr};
    for (auto& pd : def_.parameters) {
      const model::Parameter* p = m_.parameter(pd.name);
      if (!p) continue;
      units::Quantity q;
      try {
        q = units::parse_quantity(pd.value.s);
      } catch (const std::exception&) {
        continue;
      }
      std::string unit_tex = q.unit.text == "deg" ? "{}^{\\circ}" : tex_unit(q.unit.text);
      std::string unit_text = q.unit.text.empty() ? "\u2014" : q.unit.text;
      Spans value;
      if (p->unknown) value = {W("unknown")};
      else if (!q.has_number) value = {W("symbolic")};
      else {
        std::string t = pd.value.s;
        std::size_t i = t.find_first_not_of(' '), j = i;
        numeric v;
        units::parse_decimal(t, j, v);
        std::string number = t.substr(i, j - i);
        value = {N(tex_number(number), number)};
      }
      t.cells.push_back({{M(p->sym)}, value, {N(unit_tex.empty() ? "\\text{---}" : unit_tex, unit_text)}});
    }
    if (!t.cells.empty()) d_.blocks.push_back(t);
    else para({W("No parameters.")});
    if (!m_.fixed_points.empty()) {
      Spans sp{W("Fixed points: ")};
      bool first = true;
      for (auto& pd : def_.points) {
        auto it = m_.fixed_points.find(pd.name);
        if (it == m_.fixed_points.end()) continue;
        if (!first) sp.push_back(W(", "));
        first = false;
        sp.push_back(N(tex_name(pd.name), pd.name));
        sp.push_back(W(" at "));
        sp.push_back(N("(" + latex(tidy(it->second.first)) + ", " + latex(tidy(it->second.second)) + ")",
                       "(" + plain(tidy(it->second.first)) + ", " + plain(tidy(it->second.second)) + ")"));
      }
      sp.push_back(W("."));
      para(sp);
    }
  }

  // --- kinematics -----------------------------------------------------------------------------

  void kinematics() {
    section("Kinematics");
    {
      Spans sp{W(m_.coords.size() == 1 ? "Generalized coordinate " : "Generalized coordinates ")};
      for (std::size_t i = 0; i < m_.coords.size(); ++i) {
        if (i) sp.push_back(W(i + 1 == m_.coords.size() ? " and " : ", "));
        sp.push_back(M(m_.coords[i].q));
        std::string u = i < def_.coordinates.size() ? def_.coordinates[i].unit.s : "";
        if (!u.empty()) sp.push_back(W(" (" + u + ")"));
      }
      sp.push_back(W(m_.coords.size() == 1 ? ", its rate " : ", their rates "));
      for (std::size_t i = 0; i < m_.coords.size(); ++i) {
        if (i) sp.push_back(W(", "));
        sp.push_back(M(m_.coords[i].qd));
      }
      sp.push_back(W(". Velocities are the time derivatives of the positions, "));
      sp.push_back(N("\\bar{v} = \\sum_i \\frac{\\partial \\bar{r}}{\\partial q_i}\\dot{q}_i", "v = Σ ∂r/∂q q_dot"));
      sp.push_back(W(", and the kinetic energy of a body is "));
      sp.push_back(N("T = \\frac{1}{2} m \\bar{v}^{2} + \\frac{1}{2} \\bar{I} \\omega^{2}", "T = m*v^2/2 + I*omega^2/2"));
      sp.push_back(W("."));
      para(sp);
    }
    Tags tags{"K", false};
    for (std::size_t bi = 0; bi < m_.bodies.size(); ++bi) {
      const auto& b = m_.bodies[bi];
      const scene::BodyDef* bd = nullptr;
      for (auto& x : def_.bodies)
        if (x.name == b.name) bd = &x;
      std::string kind = bd ? bd->inertia.kind : "";
      bool particle = b.inertia.is_zero() && b.angle.is_zero();
      Spans sp{W("Body " + b.name + ": mass "), M(b.mass)};
      if (particle) {
        sp.push_back(W(", a particle."));
      } else {
        std::string words = kind.empty() ? "" : model::inertia_shape(kind).words;
        sp.push_back(W(!words.empty() ? ", " + words + ", " : ", "));
        sp.push_back(Span::m(Math::named("\\bar{I}", "I", tidy(b.inertia))));
        sp.push_back(W("."));
      }
      para(sp);
      std::vector<Row> r;
      ex vx = tidy(m_.rate(b.x)), vy = tidy(m_.rate(b.y));
      Row pos = tags.row({Math::notation("\\bar{x}", "x_G"), Math::of(tidy(b.x))});
      pos.also.push_back({Math::notation("\\bar{y}", "y_G"), Math::of(tidy(b.y))});
      r.push_back(pos);
      Row vel = tags.row({Math::notation("\\bar{v}_{x}", "vx_G"), Math::of(vx)});
      vel.also.push_back({Math::notation("\\bar{v}_{y}", "vy_G"), Math::of(vy)});
      r.push_back(vel);
      if (!particle) r.push_back(tags.row({Math::notation("\\omega", "omega"), Math::of(tidy(m_.omega(static_cast<int>(bi))))}));
      r.push_back(tags.row({Math::notation("T_{" + tex_word(b.name) + "}", "T(" + b.name + ")"),
                            Math::of(tidy(m_.kinetic_energy(static_cast<int>(bi))))}));
      rows(r);
    }
    if (!m_.constraints.empty()) {
      para({W(m_.constraints.size() == 1 ? "The constraint holds at every instant, and so does its rate:"
                                         : "The constraints hold at every instant, and so do their rates:")});
      std::vector<Row> r;
      for (auto& [c, pos] : m_.constraints) {
        Row row = tags.row({Math::of(tidy(c)), Math::of(0)});
        ex rate = model::trig_simplify(m_.rate(c));
        if (!rate.is_zero()) row.also.push_back({Math::of(tidy(rate)), Math::of(0)});
        r.push_back(row);
      }
      rows(r);
    }
    if (m_.bodies.size() > 1) {
      para({W("The kinetic energy of the system is the sum, "), N("T = \\sum T_{b}", "T = Σ T(body)"), W(":")});
      rows({tags.row({Math::notation("T", "T"), Math::of(tidy(m_.kinetic_energy()))})});
    }
  }

  // --- states ---------------------------------------------------------------------------------

  void states() {
    section("States");
    for (std::size_t si = 0; si < m_.states.size(); ++si) {
      const auto& st = m_.states[si];
      Spans sp{W("State " + st.name + ": ")};
      std::vector<ex> known, unknown;
      for (auto& c : m_.coords) {
        auto& [q, qd] = st.sym.at(c.name);
        (st.given.count(q) ? known : unknown).push_back(q);
        (st.given.count(qd) ? known : unknown).push_back(qd);
      }
      (st.given.count(st.t) ? known : unknown).push_back(st.t);
      bool any = false;
      for (auto& x : known) {
        if (any) sp.push_back(W(", "));
        any = true;
        sp.push_back(Span::m(Math::equation(x, tidy(st.given.at(x)))));
      }
      if (!any) sp.push_back(W("nothing given"));
      for (auto& [w, pos] : st.where) {
        sp.push_back(W("; where "));
        sp.push_back(Span::m(Math::equation(tidy(w), 0)));
      }
      // only what some equation uses is worth naming as unknown
      std::vector<ex> used;
      for (auto& x : unknown)
        for (auto& q : s_.equations)
          if (q.lhs.has(x) || q.rhs.has(x)) {
            used.push_back(x);
            break;
          }
      if (!used.empty()) {
        sp.push_back(W("; unknown: "));
        for (std::size_t i = 0; i < used.size(); ++i) {
          if (i) sp.push_back(W(", "));
          sp.push_back(M(used[i]));
        }
      }
      sp.push_back(W("."));
      para(sp);
    }
    // the scene at each state, from its model with the solved values
    std::vector<std::string> left_out;
    std::vector<draw::Sheet> sheets = state_sheets(s_, left_out);
    for (std::size_t i = 0; i < sheets.size(); ++i)
      figure(std::move(sheets[i]), "The scene at its states, drawn from the model with the solved values" +
                                       std::string(sheets.size() > 1 ? " (" + std::to_string(i + 1) + " of " + std::to_string(sheets.size()) + ")" : "") + ".");
    for (auto& why : left_out) para({W("Not drawn: " + why + ".")});
  }

  // --- energy ---------------------------------------------------------------------------------

  void section(int k, const model::Analysis& a, const principles::EnergyBalance& b) override {
    const std::string S1 = state_name(a.from), S2 = state_name(a.to);
    section(std::string(b.conservative ? "Conservation of energy" : "Work and energy") + ", states " + text_interval(S1, S2));
    Tags tags{"E" + std::to_string(k)};
    auto T = [&](const std::string& S) { return Math::notation(tex_at("T", S), text_at("T", S)); };
    auto V = [&](const std::string& S) { return Math::notation(tex_at("V", S), text_at("V", S)); };
    std::string U_tex = "U_{" + tex_interval_sub(S1, S2) + "}", U_text = "U" + text_interval_sub(S1, S2);

    // the positions at the two states with the effects that do work between them
    try {
      std::string names;
      for (std::size_t i = 0; i < b.working.size(); ++i)
        names += (i ? (i + 1 == b.working.size() ? " and " : ", ") : "") + b.working[i];
      figure(draw::positions_with(m_, s_.branch.sol, parameter_values(s_), a.from, a.to, a.bodies, b.working),
             "Positions at " + S1 + " and " + S2 + (names.empty() ? ", with no effect doing work" : ", with the effects that do work: " + names) + ".");
    } catch (const SceneError&) {
      // a state neither fixes: the states' figure says which
    }
    // which effects store energy (those whose V the balance holds)
    const std::vector<std::string>& potentials = b.stored;
    Spans intro;
    if (b.conservative) {
      intro = {W("No non-conservative effect does work between states " + S1 + " and " + S2 + ", so "),
               N(tex_at("T", S1) + " + " + tex_at("V", S1) + " = " + tex_at("T", S2) + " + " + tex_at("V", S2),
                 text_at("T", S1) + " + " + text_at("V", S1) + " = " + text_at("T", S2) + " + " + text_at("V", S2)),
               W(".")};
    } else {
      intro = {W("The principle of work and energy between states " + S1 + " and " + S2 + ": "),
               N(tex_at("T", S1) + " + " + tex_at("V", S1) + " + " + U_tex + " = " + tex_at("T", S2) + " + " + tex_at("V", S2),
                 text_at("T", S1) + " + " + text_at("V", S1) + " + " + U_text + " = " + text_at("T", S2) + " + " +
                     text_at("V", S2)),
               W(", where "), N(U_tex, U_text), W(" is the work of the non-conservative effects.")};
    }
    if (a.bodies.size() != m_.bodies.size()) {
      std::string set;
      for (std::size_t i = 0; i < a.bodies.size(); ++i)
        set += std::string(i ? (i + 1 == a.bodies.size() ? " and " : ", ") : "") + m_.bodies[a.bodies[i]].name;
      intro.insert(intro.begin(), W("Bodies: " + set + ", isolated from the rest: T is their kinetic energy, and the rest acts on them "
                                    "through the effects that cross the boundary. "));
    }
    if (!potentials.empty()) {
      std::string list;
      for (std::size_t i = 0; i < potentials.size(); ++i)
        list += std::string(i ? (i + 1 == potentials.size() ? " and " : ", ") : "") + potentials[i];
      intro.push_back(W(" The potential energy V is that of " + list + "."));
    }
    para(intro);
    para({W("At state " + S1 + ", with the values given there:")});
    std::vector<Row> r;
    r.push_back(tags.row({T(S1), Math::of(sub(b.at_from.T))}));
    r.push_back(tags.row({V(S1), Math::of(sub(b.at_from.V))}));
    rows(r);
    if (!b.works.empty()) {
      para({W(b.works.size() == 1 ? "The work of the non-conservative effect:" : "The work of each non-conservative effect:")});
      r.clear();
      for (auto& w : b.works)
        r.push_back(tags.row({Math::notation(U_tex + "^{" + tex_word(w.effect) + "}", U_text + "(" + w.effect + ")"),
                              Math::of(sub(w.U))}));
      rows(r);
      Spans how;
      for (std::size_t i = 0; i < b.works.size(); ++i) {
        const auto& w = b.works[i];
        if (w.how.empty()) continue;
        how.push_back(W(std::string(how.empty() ? "" : "; ") + w.effect + ": " + w.how));
      }
      if (!how.empty()) {
        how.insert(how.begin(), W("How each work is taken: "));
        how.push_back(W("."));
        para(how);
      }
    }
    para({W("At state " + S2 + ":")});
    r.clear();
    r.push_back(tags.row({T(S2), Math::of(sub(b.at_to.T))}));
    r.push_back(tags.row({V(S2), Math::of(sub(b.at_to.V))}));
    rows(r);
    para({W(b.conservative ? "So the energy equation reads:" : "So the work\u2013energy equation reads:")});
    auto [lhs, rhs] = sides(b.equation);
    Row eq = tags.row({Math::of(lhs), Math::of(rhs)});
    remember(b.equation, eq.tag);
    rows({eq});
  }

  // --- momentum -------------------------------------------------------------------------------

  std::string about_tex(const std::string& about) const {
    std::string p = about;
    if (auto dot = p.find('.'); dot != std::string::npos) return tex_name(p.substr(dot + 1));
    if (m_.body_index(p) >= 0) return "G";
    return tex_name(p);
  }

  void section(int k, const model::Analysis& a, const principles::MomentumBalance& mb) override {
    const std::string S1 = state_name(a.from), S2 = state_name(a.to);
    bool angular = mb.angular;
    std::string bodies;
    for (std::size_t i = 0; i < a.bodies.size(); ++i)
      bodies += std::string(i ? (i + 1 == a.bodies.size() ? " and " : ", ") : "") + m_.bodies[static_cast<std::size_t>(a.bodies[i])].name;
    std::string what = angular ? (mb.conserved ? "Conservation of angular momentum" : "Angular impulse and momentum")
                               : (mb.conserved ? "Conservation of linear momentum" : "Linear impulse and momentum");
    std::string about = !angular ? "" : m_.body_index(a.about()->text) >= 0 ? "the mass centre of " + a.about()->text : a.about()->text;
    std::string where = angular ? " about " + about : (a.along() ? " along " + a.along()->name : "");
    section(what + where + ", states " + text_interval(S1, S2));
    Tags tags{"M" + std::to_string(k)};
    std::string dt_tex = "\\int_{" + (digits_only(S1) ? "t_{" + S1 + "}" : "t_{\\mathrm{" + S1 + "}}") + "}^{" +
                         (digits_only(S2) ? "t_{" + S2 + "}" : "t_{\\mathrm{" + S2 + "}}") + "}";
    if (angular) {
      std::string P = about_tex(a.about()->text);
      std::string H = "H_{" + P + "}";
      para({W("Bodies: " + bodies + ". The angular momentum about " + about + " is "),
            N(H + " = \\sum \\left(\\bar{I}\\omega + (\\bar{r} - r_{" + P + "})\\times m\\bar{v}\\right)",
              "H = Σ (I*omega + (r_G - r_" + a.about()->text + ") × m*v)"),
            W(", and "),
            mb.conserved ? N(tex_at(H, S1) + " = " + tex_at(H, S2), text_at("H", S1) + " = " + text_at("H", S2))
                         : N(tex_at(H, S1) + " + \\sum " + dt_tex + " M_{" + P + "}\\,dt = " + tex_at(H, S2),
                             text_at("H", S1) + " + Σ ∫M dt = " + text_at("H", S2)),
            W(mb.conserved ? " when no effect has a moment about " + about + "." : ".")});
    } else {
      para({W("Bodies: " + bodies + ". The linear momentum is "), N("L = \\sum m\\bar{v}", "L = Σ m*v"), W(", and "),
            mb.conserved ? N(tex_at("L", S1) + " = " + tex_at("L", S2), text_at("L", S1) + " = " + text_at("L", S2))
                         : N(tex_at("L", S1) + " + \\sum " + dt_tex + " F\\,dt = " + tex_at("L", S2),
                             text_at("L", S1) + " + Σ ∫F dt = " + text_at("L", S2)),
            W(mb.conserved ? " along a direction in which no effect has an impulse" : ""),
            W(mb.components.size() > 1 ? ". Component by component:" : ".")});
    }
    if (auto sheet = momentum_diagram(s_, a, a.bodies, mb.shown, &d_.names))
      figure(std::move(*sheet), "Impulse-momentum diagram of " + bodies + ": the momenta at " + S1 + ", plus the impulses from " + S1 +
                                    " to " + S2 + ", equal the momenta at " + S2 + ".");
    for (auto& c : mb.components) {
      std::string base_tex, base_text, comp;
      if (angular) {
        base_tex = "H_{" + about_tex(a.about()->text) + "}";
        base_text = "H";
        comp = "about " + about;
      } else {
        std::string n = c.name == "x" || c.name == "y" ? c.name : "n";
        base_tex = "L_{" + n + "}";
        base_text = "L_" + n;
        comp = "along " + (c.name == "x" || c.name == "y" ? c.name : c.name + " (n)");
      }
      if (mb.components.size() > 1) subsection("Component " + comp);
      std::vector<Row> r;
      r.push_back(tags.row({Math::notation(tex_at(base_tex, S1), text_at(base_text, S1)), Math::of(sub(c.before))}));
      Spans unknowns;
      for (auto& imp : c.impulses) {
        ex v = sub(imp.value);
        bool reaction = imp.kind == principles::ImpulseTerm::Kind::Reaction;
        std::string F = angular ? "M" : "F";
        std::string sub_ = angular ? "_{" + about_tex(a.about()->text) + "}" : "_{" + std::string(c.name == "x" || c.name == "y" ? c.name : "n") + "}";
        if (reaction) {
          unknowns.push_back(W(std::string(unknowns.empty() ? "" : "; ") + imp.effect + ": " + imp.how + " "));
          unknowns.push_back(M(v));
          continue;
        }
        if (imp.kind == principles::ImpulseTerm::Kind::Given) {
          r.push_back(tags.row({Math::notation("J" + sub_ + "^{" + tex_word(imp.effect) + "}", "J(" + imp.effect + ")"), Math::of(v)}));
          continue;
        }
        r.push_back(tags.row({Math::notation(dt_tex + " " + F + sub_ + "^{" + tex_word(imp.effect) + "}\\,dt",
                                             "∫" + F + " dt (" + imp.effect + ")"),
                              Math::of(v)}));
      }
      r.push_back(tags.row({Math::notation(tex_at(base_tex, S2), text_at(base_text, S2)), Math::of(sub(c.after))}));
      rows(r);
      if (!unknowns.empty()) {
        unknowns.insert(unknowns.begin(), W("Unknown impulses: "));
        unknowns.push_back(W("."));
        para(unknowns);
      }
      if (mb.conserved)
        para({W("No effect acting on " + bodies + " has an impulse " + comp + " between states " + S1 + " and " + S2 +
                " (each effect was checked), so the " + std::string(angular ? "angular" : "linear") + " momentum " + comp +
                " is conserved:")});
      else if (c.impulses.empty())
        para({W("No impulse acts " + comp + ", so the " + std::string(angular ? "angular" : "linear") + " momentum " + comp +
                " does not change:")});
      else
        para({W("So:")});
      auto [lhs, rhs] = sides(c.equation);
      Row eq = tags.row({Math::of(lhs), Math::of(rhs)});
      remember(c.equation, eq.tag);
      rows({eq});
    }
  }

  // --- impact ---------------------------------------------------------------------------------

  void section(int k, const model::Analysis& a, const principles::ImpactBalance& ib) override {
    const std::string SB = state_name(a.from), SA = state_name(a.to);
    section("Impact, " + text_interval(SB, SA));
    Tags tags{"I" + std::to_string(k)};
    Spans intro{W("During the impact the positions and the time do not change (the state " + SA +
                  " has the positions of " + SB + "), and only impulsive forces act: ")};
    bool any = false;
    for (int ci : a.struck()->contacts) {
      const auto e = m_.contact(ci);
      if (any) intro.push_back(W("; "));
      any = true;
      intro.push_back(W("the contact " + e.name + " between " + e.a.text + " and " + e.b.text + ", normal "));
      intro.push_back(N("n = \\left(" + latex(tidy(e.nx)) + ", " + latex(tidy(e.ny)) + "\\right)",
                        "n = (" + plain(tidy(e.nx)) + ", " + plain(tidy(e.ny)) + ")"));
      intro.push_back(W(" from the first into the second, coefficient of restitution "));
      intro.push_back(M(e.e));
      auto it = a.struck()->impulses.find(e.name);
      if (it != a.struck()->impulses.end()) {
        intro.push_back(W(", impulse "));
        intro.push_back(M(it->second.first));
        intro.push_back(W(" along n"));
        if (e.stick) {
          intro.push_back(W(" and "));
          intro.push_back(M(it->second.second));
          intro.push_back(W(" along the tangent (rough: no sliding after)"));
        }
      }
    }
    for (auto& e : m_.effects)
      if (const model::Blow* g = e.blow()) {
        if (any) intro.push_back(W("; "));
        any = true;
        intro.push_back(W("the given impulse " + e.name + " at " + g->at.text + ", "));
        intro.push_back(N("\\left(" + latex(tidy(g->Jx)) + ", " + latex(tidy(g->Jy)) + "\\right)",
                          "(" + plain(tidy(g->Jx)) + ", " + plain(tidy(g->Jy)) + ")"));
      }
    if (!any) intro.push_back(W("none"));
    intro.push_back(W(". Pins and constraints carry workless impulsive reactions; gravity, springs, couples and "
                      "forces are not impulsive."));
    para(intro);
    // each body the impact moves: momenta before + impulses on it = momenta after
    for (std::size_t b = 0; b < m_.bodies.size(); ++b) {
      bool struck = false;
      for (auto& sh : ib.shown) struck = struck || sh.push.body == static_cast<int>(b);
      if (!struck) continue;
      if (auto sheet = momentum_diagram(s_, a, {static_cast<int>(b)}, ib.shown, &d_.names))
        figure(std::move(*sheet), "Impulse-momentum diagram of " + m_.bodies[b].name + " in the impact: its momenta before (" + SB +
                                      "), plus the impulses on it, equal its momenta after (" + SA + ").");
    }
    if (!ib.momentum.empty()) {
      para({W("Impulse and momentum along each coordinate q (its generalized momentum changes by the generalized "
              "impulse), "),
            N("\\sum_{b}\\left(m\\,\\Delta\\bar{v}\\cdot\\frac{\\partial\\bar{r}}{\\partial q} + \\bar{I}\\,\\Delta\\omega\\,"
              "\\frac{\\partial\\phi}{\\partial q}\\right) = \\sum J\\cdot\\frac{\\partial r}{\\partial q}",
              "Σ (m Δv·∂r_G/∂q + I Δω ∂φ/∂q) = Σ J·∂r/∂q"),
            W(":")});
      std::vector<Row> r;
      std::vector<std::string> conserved;
      Spans order{W("In order, along ")};
      for (std::size_t i = 0; i < ib.momentum.size(); ++i) {
        const auto& q = ib.momentum[i];
        auto [lhs, rhs] = sides(q);
        Row row = tags.row({Math::of(lhs), Math::of(rhs)});
        remember(q, row.tag);
        if (i) order.push_back(W(i + 1 == ib.momentum.size() ? " and " : ", "));
        order.push_back(M(m_.coords[static_cast<std::size_t>(ib.along[i])].q));
        if (rhs.is_zero()) conserved.push_back(row.tag);
        r.push_back(row);
      }
      order.push_back(W(":"));
      para(order);
      rows(r);
      if (!conserved.empty()) {
        std::string list;
        for (std::size_t i = 0; i < conserved.size(); ++i)
          list += std::string(i ? (i + 1 == conserved.size() ? " and " : ", ") : "") + "(" + conserved[i] + ")";
        para({W("In " + list + " no impulse acts along the coordinate, so the generalized momentum along it is "
                "conserved through the impact.")});
      }
    }
    if (!ib.restitution.empty()) {
      para({W("At each contact the relative normal velocity reverses, scaled by e: "),
            N("(v_{B}' - v_{A}')\\cdot n = -e\\,(v_{B} - v_{A})\\cdot n", "(vB' - vA')·n = -e (vB - vA)·n"),
            W(" (and no relative tangential velocity after, where the contact is rough):")});
      std::vector<Row> r;
      for (auto& q : ib.restitution) {
        auto [lhs, rhs] = sides(q);
        Row row = tags.row({Math::of(lhs), Math::of(rhs)});
        remember(q, row.tag);
        r.push_back(row);
      }
      rows(r);
    }
  }

  // --- the system -----------------------------------------------------------------------------

  bool is_unknown(const ex& x) const {
    for (auto& p : m_.params)
      if (p.sym.is_equal(x)) return p.unknown;
    return !given_.count(x);
  }

  void system() {
    section("The system of equations");
    Tags ctags{"C", false};
    std::vector<Row> r;
    std::vector<ex> unknowns;
    bool impact_positions = false;
    std::size_t count = 0;
    for (std::size_t qi = 0; qi < s_.equations.size(); ++qi) {
      const auto& q = s_.equations[qi];
      if (q.principle == "impact") {
        impact_positions = true;
        continue;
      }
      auto [lhs, rhs] = sides(q);
      if (model::trig_simplify(lhs - rhs).is_zero()) continue;  // holds for the given values
      ++count;
      Row row;
      if (!tag_of_[qi].empty()) {
        row = Row{{Math::of(lhs), Math::of(rhs)}, {}, tag_of_[qi], ""};
      } else {
        row = ctags.row({Math::of(lhs), Math::of(rhs)});
        tag_of_[qi] = row.tag;
        constraints_shown_ = true;
      }
      r.push_back(row);
      std::vector<ex> syms;
      symbols_in(lhs - rhs, syms);
      std::sort(syms.begin(), syms.end(), [](const ex& a, const ex& b) { return plain(a) < plain(b); });
      for (auto& x : syms)
        if (is_unknown(x) && std::find_if(unknowns.begin(), unknowns.end(), [&](const ex& u) { return u.is_equal(x); }) == unknowns.end())
          unknowns.push_back(x);
    }
    Spans sp{W("With the values given at the states, " + std::to_string(count) +
               (count == 1 ? " equation remains" : " equations remain"))};
    if (!unknowns.empty()) {
      sp.push_back(W(unknowns.size() == 1 ? " in the unknown " : " in the unknowns "));
      for (std::size_t i = 0; i < unknowns.size(); ++i) {
        if (i) sp.push_back(W(i + 1 == unknowns.size() ? " and " : ", "));
        sp.push_back(M(unknowns[i]));
      }
    }
    if (constraints_shown_) sp.push_back(W(" (C: the constraints and conditions at the states)"));
    if (impact_positions) sp.push_back(W("; the positions and time after an impact are those before"));
    sp.push_back(W(":"));
    para(sp);
    rows(r);
  }

  bool constraints_shown_ = false;
  exmap hidden_;  ///< positions and times after impacts (those before), found without a step

  // --- the solution ---------------------------------------------------------------------------

  /// The solver's steps replayed: each unknown from its equation, with the unknowns found
  /// before put in (a linear step may leave later unknowns in its value: those are put in at
  /// the end, by back substitution).
  void solution() {
    section("Solution");
    Tags tags{"S", false};
    const auto& b = s_.branch;
    exmap now;                     // unknown → value as found so far (the solver's own order)
    std::vector<ex> order;         // unknowns in the order found (shown)
    exmap displayed;               // unknown → the value shown at its step
    std::vector<bool> used(s_.equations.size(), false);
    bool any_before = false;
    for (auto& step : b.steps) {
      // "NAME from LABEL (METHOD)"
      auto from = step.find(" from ");
      if (from == std::string::npos) continue;
      std::string name = step.substr(0, from), rest = step.substr(from + 6), method;
      if (auto p = rest.rfind(" ("); p != std::string::npos && rest.back() == ')') {
        method = rest.substr(p + 2, rest.size() - p - 3);
        rest = rest.substr(0, p);
      }
      ex u;
      bool found = false;
      for (auto& [k, v] : b.sol)
        if (model::text(k) == name) {
          u = k;
          found = true;
        }
      if (!found) continue;
      // the equation: the first unused one with that label that holds u
      int qi = -1;
      for (std::size_t i = 0; i < s_.equations.size() && qi < 0; ++i)
        if (!used[i] && s_.equations[i].label == rest && s_.equations[i].residual().subs(given_).subs(now).has(u))
          qi = static_cast<int>(i);
      if (qi >= 0) used[static_cast<std::size_t>(qi)] = true;
      ex value;
      if (method == "linear" && qi >= 0) {
        try {
          ex r = s_.equations[static_cast<std::size_t>(qi)].residual().subs(given_).subs(now);
          ex a = r.diff(ex_to<symbol>(u));
          value = final_form(-r.subs(u == 0) / a);
        } catch (const std::exception&) {
          value = b.sol.at(u);
        }
      } else {
        value = final_form(b.sol.at(u));  // a root of an equation in u alone: final already
      }
      for (auto& [k, v] : now) v = v.subs(u == value);
      now[u] = value;
      bool hidden = rest.rfind("positions kept", 0) == 0 || rest.rfind("time of the impact", 0) == 0;
      if (hidden) {
        hidden_[u] = b.sol.at(u);  // a position after an impact: that before
        continue;
      }
      order.push_back(u);
      if (method == "product") {
        // the solver took F·t as one unknown (F appears only multiplied by t)
        ex t = u;
        for (auto& [sym, d] : m_.dimensions())
          if (model::text(sym) == rest) t = sym;
        para({W("The unknown "), M(u), W(" appears in the equations only multiplied by "), M(t),
              W(": with that product as one unknown they are linear, and "), M(u), W(" is the product divided by "), M(t),
              W(", with the unknowns found after it put in:")});
        rows({tags.row({Math::of(u), Math::of(final_form(b.sol.at(u)))})});
        displayed[u] = b.sol.at(u);
        any_before = true;
        continue;
      }
      Spans sp{W("From ")};
      std::string tag = qi >= 0 ? tag_of_[static_cast<std::size_t>(qi)] : "";
      sp.push_back(W(!tag.empty() ? "(" + tag + ")" : "the " + rest));
      if (method == "linear") {
        sp.push_back(W(", linear in "));
        sp.push_back(M(u));
      } else if (method == "quadratic" || method == "trigonometric") {
        sp.push_back(W(", " + std::string(method == "quadratic" ? "a quadratic" : "a trigonometric equation") + " in "));
        sp.push_back(M(u));
        for (auto& x : root_reason()) sp.push_back(x);
      } else if (!method.empty()) {
        sp.push_back(W(" (" + method + ")"));
      }
      sp.push_back(W(any_before ? ", with the unknowns found before put in:" : ":"));
      any_before = true;
      para(sp);
      if (b.numeric_only.count(u)) {
        auto v = numerics::evaluate(b.sol.at(u), m_.numeric_environment(), 30);
        rows({tags.row({Math::of(u), Math::notation(v ? tex_number(numerics::format(*v, o_.digits)) : "?",
                                                    v ? numerics::format(*v, o_.digits) : "?")})});
      } else {
        rows({tags.row({Math::of(u), Math::of(value)})});
      }
      displayed[u] = value;
    }
    if (order.empty()) {
      para({W("Every unknown follows directly from the values given.")});
      return;
    }
    // back substitution: values that still held unknowns solved later
    std::vector<Row> back;
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
      const ex& u = *it;
      if (b.numeric_only.count(u)) continue;
      bool later = false;
      for (auto& x : order)
        if (!x.is_equal(u) && displayed.count(u) && displayed.at(u).has(x)) later = true;
      if (!later) continue;
      back.push_back(tags.row({Math::of(u), Math::of(final_form(b.sol.at(u)))}));
    }
    if (!back.empty()) {
      para({W("Back substitution, the last found first:")});
      rows(back);
    }
  }

  /// Why one root of two was kept: the results' root choices, or the direction of motion.
  Spans root_reason() const {
    Spans sp;
    for (auto& f : m_.finds) {
      if (f.root.kind == model::RootSpec::Kind::None) continue;
      std::string r = f.root.kind == model::RootSpec::Kind::Positive ? " positive"
                      : f.root.kind == model::RootSpec::Kind::Negative ? " negative"
                                                                         : " in its range";
      sp.push_back(W(sp.empty() ? "; of its roots the one kept makes " : ", "));
      sp.push_back(N(tex_name(f.name), f.name));
      sp.push_back(W(r));
    }
    if (sp.empty()) sp.push_back(W("; of its roots the one kept agrees with the direction of the motion"));
    return sp;
  }

  // --- results --------------------------------------------------------------------------------

  void results() {
    section("Results");
    Tags tags{"R", false};
    exmap env = m_.numeric_environment();
    std::vector<Row> r;
    for (std::size_t i = 0; i < s_.results.size(); ++i) {
      const Result& res = s_.results[i];
      const model::Find* f = nullptr;
      for (auto& x : m_.finds)
        if (x.name == res.name) f = &x;
      std::vector<Math> chain{Math::notation(tex_name(res.name), res.name)};
      if (f) {
        // what the result is, with the values given at the states put in
        ex what = f->value;
        try {
          what = tidy(f->value.subs(given_).subs(hidden_).subs(given_));
        } catch (const std::exception&) {
        }
        if (plain(what) != res.name && plain(what) != plain(res.closed) && res.extreme_note.empty()) chain.push_back(Math::of(what));
      }
      std::string unit_tex = res.unit == "deg" ? "{}^{\\circ}" : tex_unit(res.unit);
      std::optional<numeric> v;
      if (res.si) v = res.value(env, o_.digits);
      std::string number = v ? verify::figures(*v, o_.digits) : "";
      if (res.closed_form) {
        chain.push_back(Math::of(res.closed));
        bool all_values = true;
        std::vector<ex> syms;
        symbols_in(res.closed, syms);
        for (auto& x : syms)
          if (!d_.values_text.count(x)) all_values = false;
        if (v && all_values && !syms.empty()) chain.push_back(Math::of(res.closed, true));
      }
      if (v) {
        std::string tex = res.unit == "deg" ? tex_number(number) + "^{\\circ}"
                                            : tex_number(number) + (unit_tex.empty() ? "" : "\\," + unit_tex);
        chain.push_back(Math::notation(tex, number + (res.unit.empty() ? "" : " " + res.unit)));
      }
      r.push_back(tags.row(chain));
    }
    Spans sp{W("Each result in closed form, then with the given values (as written, with their units) and as a "
               "number to " + std::to_string(o_.digits) + " significant figures")};
    bool numeric_root = false;
    for (auto& res : s_.results) numeric_root = numeric_root || !res.closed_form;
    if (numeric_root) sp.push_back(W("; a result without closed form comes from a numeric root "
                                     "or an extreme"));
    sp.push_back(W(":"));
    para(sp);
    rows(r);
    // an extreme: the expression made greatest or least, its stationary points and the ends
    for (auto& res : s_.results) {
      if (res.extreme_note.empty()) continue;
      para({W("For " + res.name + ", " + res.extreme_what + ": "), M(res.extreme_of), W(" — " + res.extreme_note + ".")});
    }
  }

  // --- checks ---------------------------------------------------------------------------------

  void checks() {
    if (m_.expects.empty()) return;
    std::vector<verify::Check> cs;
    try {
      cs = verify::verify(s_);
    } catch (const std::exception&) {
      return;
    }
    section("Checks of the claimed results");
    para({W("The scene claims these results (its expect); each claimed form is compared with the derived "
            "closed form, each claimed value with the derived value to the figures it is written with.")});
    Tags tags{"A", false};
    std::size_t ci = 0;
    for (auto& x : m_.expects) {
      std::vector<Math> chain{Math::notation(tex_name(x.name), x.name)};
      if (x.form) chain.push_back(Math::of(*x.form));
      if (x.value) {
        std::string number = verify::figures(x.value->number, x.value->sig_figs);
        std::string u = x.value->unit.text;
        chain.push_back(Math::notation(
            u == "deg" ? tex_number(number) + "^{\\circ}" : tex_number(number) + (u.empty() ? "" : "\\," + tex_unit(u)),
            number + (u.empty() ? "" : " " + u)));
      }
      Row row = tags.row(chain);
      rows({row});
      Spans sp{W("(" + row.tag + ") ")};
      bool first = true;
      while (ci < cs.size() && cs[ci].name == x.name) {
        sp.push_back(W(std::string(first ? "" : "; ") + (cs[ci].what == "form" ? "form: " : "value: ") + cs[ci].detail));
        first = false;
        ++ci;
      }
      sp.push_back(W("."));
      para(sp);
    }
  }
};

}  // namespace

Derivation derive(const Solution& s, const DeriveOptions& o) {
  return Builder(s, s.scene, o).run();
}

}  // namespace kinergy::emit
