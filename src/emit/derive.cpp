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

class Builder : public Sections {
public:
  Builder(const Solution& s, const scene::SceneDef& def, const DeriveOptions& o)
      : s_(s), m_(s.model), def_(def), o_(o), given_(s.model.given_values()), tag_of_(s.equations.size()) {
    // the figures of a scene whose parameters have no values are drawn at sample values: each
    // caption says which
    figure_values(s, &samples_);
    if (!samples_.empty()) samples_ = " Drawn with sample values for the parameters that have none: " + samples_ + ".";
  }

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
    d_.legend = "Equations are tagged by where they come from: K kinematics, E energy, M momentum, I impact, " + legend_ +
                "C constraints and conditions, S solution, R results, A claimed answers.";
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
  std::vector<std::vector<std::string>> prints_;  ///< each figure's panels as panel_print writes them
  std::string samples_;  ///< " Drawn with sample values …: L = 1 m." when some parameter has no value
  std::string legend_;  ///< the tags the analysis kinds add ("N Newton's second law at a state, ")

  // --- what an analysis kind writes its section with (Sections: called through it) ------------

  const Solution& solution() const override { return s_; }
  void section(const std::string& t) override { d_.blocks.push_back({Block::Kind::Section, t, {}, {}, {}, {}, nullptr}); }
  void subsection(const std::string& t) override { d_.blocks.push_back({Block::Kind::Subsection, t, {}, {}, {}, {}, nullptr}); }
  void para(Spans sp) override { d_.blocks.push_back({Block::Kind::Paragraph, "", std::move(sp), {}, {}, {}, nullptr}); }
  void figure(draw::Sheet sheet, const std::string& caption) override {
    // a figure whose every panel an earlier figure has already drawn (the positions of an energy
    // analysis where every effect does work, as the scene at its states) is not drawn again: said
    std::vector<std::string> prints;
    for (std::size_t i = 0; i < sheet.size(); ++i) prints.push_back(panel_print(sheet.panel(i)));
    for (std::size_t k = 0; k < prints_.size(); ++k)
      if (std::all_of(prints.begin(), prints.end(), [&](const std::string& p) {
            return std::find(prints_[k].begin(), prints_[k].end(), p) != prints_[k].end();
          })) {
        const std::string said = caption.empty() || caption.back() != '.' ? caption : caption.substr(0, caption.size() - 1);
        para({W(said + ": as drawn in Figure " + std::to_string(k + 1) + ".")});
        return;
      }
    prints_.push_back(std::move(prints));
    // numbered in order, as `kinergy draw --figure N` finds them
    ++figures_;
    // (what the drawing says of itself — its scale, the arrows not drawn to it — after the caption)
    const std::string note = sheet.note.empty() ? "" : " " + sheet.note;
    Block b{Block::Kind::Figure, "Figure " + std::to_string(figures_) + ": " + caption + note + samples_, {}, {}, {}, {}, nullptr};
    b.sheet = std::make_shared<const draw::Sheet>(std::move(sheet));
    d_.blocks.push_back(std::move(b));
  }
  void momentum_figure(const model::Analysis& a, const std::vector<int>& bodies, const std::vector<principles::Shown>& shown,
                       const std::vector<std::string>& held, const std::string& caption) override {
    if (auto sheet = momentum_diagram(s_, a, bodies, shown, held, &d_.names)) figure(std::move(*sheet), caption);
  }
  void legend(const std::string& letter, const std::string& meaning) override {
    const std::string entry = letter + " " + meaning + ", ";
    if (legend_.find(entry) == std::string::npos) legend_ += entry;
  }
  void kinetic_figure(const model::Analysis& a, const principles::BodyAcceleration& acc, const std::vector<principles::BodyLoad>& loads,
                      const std::string& caption) override {
    if (auto sheet = kinetic_diagram(s_, a, acc, loads, &d_.names)) figure(std::move(*sheet), caption);
  }
  void rows(std::vector<Row> r) override {
    if (!r.empty()) d_.blocks.push_back({Block::Kind::Equations, "", {}, std::move(r), {}, {}, nullptr});
  }

  /// An expression with the given state values put in, tidied (as it was, if that fails).
  /// An expression with the given state values put in, tidied but not factored (the terms of
  /// an energy or a momentum as a person adds them up).
  ex sub(const ex& e) const override {
    try {
      return tidy(e.subs(given_));
    } catch (const std::exception&) {
      return e;
    }
  }

  /// Trigonometric and rational simplification, squares out of roots; not factored (factor()
  /// picks its form by GiNaC's term order, and a sum of energies reads better expanded).
  ex tidy(const ex& e) const override {
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

  /// The equation of the system that a principle's equation is (same sides and label).
  int index_of(const principles::Equation& q) const {
    for (std::size_t i = 0; i < s_.equations.size(); ++i) {
      const auto& e = s_.equations[i];
      if (e.label == q.label && e.lhs.is_equal(q.lhs) && e.rhs.is_equal(q.rhs)) return static_cast<int>(i);
    }
    return -1;
  }

  void remember(const principles::Equation& q, const std::string& tag) override {
    int i = index_of(q);
    if (i >= 0 && tag_of_[static_cast<std::size_t>(i)].empty()) tag_of_[static_cast<std::size_t>(i)] = tag;
  }

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

  /// A composite body's words: its parts, and its mass centre and Ī by composition,
  ///   c = Σ m_i a_i / m,  Ī = Σ (Ī_i + m_i |a_i − c|²)  (the parallel-axis theorem).
  void composite_body(const model::Body& b, Spans& sp) const {
    sp.push_back(W(", welded of "));
    for (std::size_t i = 0; i < b.parts.size(); ++i) {
      const auto& p = b.parts[i];
      if (i) sp.push_back(W(i + 1 == b.parts.size() ? " and " : ", "));
      const std::string words = model::inertia_shape(p.shape).words;
      sp.push_back(W(p.name + " (" + (words.empty() ? "" : words + ", ") + "mass "));
      sp.push_back(M(p.mass));
      if (!p.inertia.is_zero()) {
        sp.push_back(W(", "));
        sp.push_back(Span::m(Math::named("\\bar{I}_{\\mathrm{" + p.name + "}}", "I_" + p.name, tidy(p.inertia))));
      }
      // a_i: its centre from the reference point, in body axes
      sp.push_back(W(", centred at ("));
      sp.push_back(M(tidy(normal(p.lx - b.ref_x))));
      sp.push_back(W(", "));
      sp.push_back(M(tidy(normal(p.ly - b.ref_y))));
      sp.push_back(W("))"));
    }
    sp.push_back(W(" in body axes from its reference point; its mass centre is at c = Σ m_i a_i / m = ("));
    sp.push_back(M(tidy(-b.ref_x)));
    sp.push_back(W(", "));
    sp.push_back(M(tidy(-b.ref_y)));
    sp.push_back(W(") from that point, and by the parallel-axis theorem "));
    sp.push_back(N("\\bar{I} = \\sum \\left(\\bar{I}_i + m_i\\,|a_i - c|^{2}\\right)", "I = Σ (I_i + m_i |a_i − c|^2)"));
    sp.push_back(W(", "));
    sp.push_back(Span::m(Math::named("\\bar{I}", "I", tidy(b.inertia))));
    sp.push_back(W("."));
  }

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
      if (!b.parts.empty()) {
        composite_body(b, sp);
      } else if (particle) {
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
    // a contact that closes in its impact (plastic and rough) holds its parties from then on: its
    // relations are said apart from those that hold throughout
    auto closing = [&](std::size_t k) -> const model::Effect* {
      const model::Effect* e = m_.carrier(k);
      return e && !e->reaction(m_)->holds.empty() ? e : nullptr;
    };
    auto relation_rows = [&](const std::vector<std::size_t>& ks) {
      std::vector<Row> r;
      for (std::size_t k : ks) {
        const ex& c = m_.constraints[k].first;
        Row row = tags.row({Math::of(tidy(c)), Math::of(0)});
        ex rate = model::trig_simplify(m_.rate(c));
        if (!rate.is_zero()) row.also.push_back({Math::of(tidy(rate)), Math::of(0)});
        r.push_back(row);
      }
      rows(r);
    };
    std::vector<std::size_t> always;
    for (std::size_t k = 0; k < m_.constraints.size(); ++k)
      if (!closing(k)) always.push_back(k);
    if (!always.empty()) {
      para({W(always.size() == 1 ? "The constraint holds at every instant, and so does its rate:"
                                 : "The constraints hold at every instant, and so do their rates:")});
      relation_rows(always);
    }
    for (const model::Effect& e : m_.effects) {
      const auto r = e.reaction(m_);
      if (!r || r->holds.empty()) continue;
      const int S = m_.closed_from(e);
      if (S < 0) continue;
      const std::string turns = r->turns >= 0 ? "it turns with " + m_.bodies[static_cast<std::size_t>(r->turns)].name + ", whose surface it is" : "it stays as written";
      if (r->lodged)
        para({W("From state " + m_.states[static_cast<std::size_t>(S)].name + " on, " + r->b.text + " is embedded in " + r->a.text + " (contact " + e.name +
                " lodges): it moves with it, held both ways, its point keeping its place, with its rate:")});
      else
        para({W("From state " + m_.states[static_cast<std::size_t>(S)].name + " on, the contact " + e.name +
                " (plastic and rough) holds " + r->b.text + " at " + r->a.text + ", as a pin that can only push along its normal (" + turns +
                "): while its push N >= 0, its point keeps its place, with its rate:")});
      relation_rows(r->holds);
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
    // what the solution took for granted that holds a parameter without a value
    for (auto& c : s_.valid_where)
      para({W("Valid only where "), M(c.e), W(" \u2265 0: " + c.assumed + " (it holds parameters without values, so it is not checked here).")});
    friction_checked();
    // an extreme: the expression made greatest or least, its stationary points and the ends
    for (auto& res : s_.results) {
      if (res.extreme_note.empty()) continue;
      para({W("For " + res.name + ", " + res.extreme_what + ": "), M(res.extreme_of), W(" — " + res.extreme_note + ".")});
    }
  }

  /// The static friction each rolling contact states, as checked on the solution: the share of
  /// the normal force it takes at each state, and where that share changes along an analysis,
  /// whether the simulation that confirms it checked the way between.
  void friction_checked() {
    std::vector<std::string> done;
    for (auto& first : s_.friction_limits) {
      if (std::find(done.begin(), done.end(), first.effect) != done.end()) continue;
      done.push_back(first.effect);
      std::string at;
      for (auto& l : s_.friction_limits) {
        if (l.effect != first.effect) continue;
        if (std::any_of(s_.valid_where.begin(), s_.valid_where.end(), [&](const principles::Condition& w) { return w.assumed == l.holds.assumed; }))
          continue;  // stated with the closed form instead
        std::optional<GiNaC::numeric> v;
        try {
          v = numerics::evaluate(l.holds.shown.subs(m_.given_values()).subs(s_.branch.sol), m_.numeric_environment(), 30);
        } catch (const std::exception&) {
          // (no normal force and no friction needed: 0/0, nothing to show)
        }
        if (v) at += std::string(at.empty() ? "" : ", ") + numerics::format(*v, o_.digits) + " at state " + m_.states[static_cast<std::size_t>(l.state)].name;
      }
      if (at.empty()) continue;
      std::string text = "Static friction, checked on the solution: '" + first.effect + "' holds without slipping where |F| <= mu_s |N(" + first.normal +
                         ")|, mu_s = " + first.mu + "; it takes |F|/|N| = " + at + ".";
      for (int ai : s_.friction_along) {
        const model::Analysis& a = m_.analyses[static_cast<std::size_t>(ai)];
        const bool simulated = std::any_of(s_.confirmed.begin(), s_.confirmed.end(), [&](const Confirmed& c) {
          return c.analysis == ai && c.by == Confirmed::By::Simulation;
        });
        text += " Between states " + m_.states[static_cast<std::size_t>(a.from)].name + " and " + m_.states[static_cast<std::size_t>(a.to)].name +
                " that share changes with the motion: " +
                (simulated ? "the simulation that confirms the " + a.kind + " analysis checks it along the way, and it holds."
                           : "it is not checked between them (the solution was not confirmed by simulation).");
      }
      para({W(text)});
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
