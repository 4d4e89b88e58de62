// Work–energy between two states: T₁ + V₁ + Σ U₁→₂ = T₂ + V₂ (conservation when no work is done).
#include <algorithm>

#include "common.hpp"
#include "kinergy/principles/momentum.hpp"
#include "../emit/figures.hpp"

namespace kinergy::analyses {

namespace {

/// Its section: the positions with the effects that do work, T and V at each state, each work,
/// the equation.
void section(emit::Sections& w, int k, const model::Analysis& a, const principles::EnergyBalance& b) {
  using namespace emit;
  const Solution& s = w.solution();
  const model::Model& m = s.model;
  const std::string S1 = w.state_name(a.from), S2 = w.state_name(a.to);
  w.section(std::string(b.conservative ? "Conservation of energy" : "Work and energy") + ", states " + text_interval(S1, S2));
  Tags tags{"E" + std::to_string(k)};
  auto T = [&](const std::string& S) { return Math::notation(tex_at("T", S), text_at("T", S)); };
  auto V = [&](const std::string& S) { return Math::notation(tex_at("V", S), text_at("V", S)); };
  std::string U_tex = "U_{" + tex_interval_sub(S1, S2) + "}", U_text = "U" + text_interval_sub(S1, S2);

  // the positions at the two states with the effects that do work between them, and the supports
  // that hold the bodies, which do none (a pin, a track, a relation with a party outside the set)
  try {
    const std::string names = listed(b.working);
    std::vector<std::string> drawn = b.working, supports;
    for (const std::string& e : emit::outside_supports(m, a.bodies))
      if (std::find(drawn.begin(), drawn.end(), e) == drawn.end()) {
        drawn.push_back(e);
        supports.push_back(e);
      }
    w.figure(draw::positions_with(m, s.branch.sol, emit::figure_values(s), a.from, a.to, a.bodies, drawn),
             "Positions at " + S1 + " and " + S2 + (names.empty() ? ", with no effect doing work" : ", with the effects that do work: " + names) +
                 (supports.empty() ? "" : "; and the supports, which do none: " + listed(supports)) + ".");
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
  if (a.bodies.size() != m.bodies.size()) {
    intro.insert(intro.begin(), W("Bodies: " + w.bodies(a) + ", isolated from the rest: T is their kinetic energy, and the rest acts on them "
                                  "through the effects that cross the boundary. "));
  }
  if (!potentials.empty()) {
    intro.push_back(W(" The potential energy V is that of " + listed(potentials) + "."));
  }
  w.para(intro);
  w.para({W("At state " + S1 + ", with the values given there:")});
  std::vector<Row> r;
  r.push_back(tags.row({T(S1), Math::of(w.sub(b.at_from.T))}));
  r.push_back(tags.row({V(S1), Math::of(w.sub(b.at_from.V))}));
  w.rows(r);
  if (!b.works.empty()) {
    w.para({W(b.works.size() == 1 ? "The work of the non-conservative effect:" : "The work of each non-conservative effect:")});
    r.clear();
    for (auto& work : b.works)
      r.push_back(tags.row({Math::notation(U_tex + "^{" + tex_word(work.effect) + "}", U_text + "(" + work.effect + ")"),
                            Math::of(w.sub(work.U))}));
    w.rows(r);
    Spans how;
    for (auto& work : b.works)
      if (!work.how.empty()) how.push_back(W(std::string(how.empty() ? "" : "; ") + work.effect + ": " + work.how));
    if (!how.empty()) {
      how.insert(how.begin(), W("How each work is taken: "));
      how.push_back(W("."));
      w.para(how);
    }
  }
  w.para({W("At state " + S2 + ":")});
  r.clear();
  r.push_back(tags.row({T(S2), Math::of(w.sub(b.at_to.T))}));
  r.push_back(tags.row({V(S2), Math::of(w.sub(b.at_to.V))}));
  w.rows(r);
  w.para({W(b.conservative ? "So the energy equation reads:" : "So the work\u2013energy equation reads:")});
  w.rows({w.equation(tags, b.equation)});
}

class Energy : public Balanced<principles::EnergyBalance, principles::energy, section> {
public:
  Energy() : Balanced("energy") {}

  bool impulsive() const override { return false; }  // energy alone keeps a motion going one way

  std::vector<std::string> keys() const override { return {"bodies"}; }

  /// Isolating a body set: each interaction across its boundary that does work on it (a tooth
  /// force, a cord's tension on a moving body) brings its average force F̄ as an unknown:
  /// U = F̄ × the distance its point moves along it.
  void read(model::EffectReader& r, const scene::AnalysisDef&, model::Analysis& a) const override {
    const model::Model& m = r.model();
    const std::string S1 = m.states[a.from].name, S2 = m.states[a.to].name;
    for (auto& e : m.effects) {
      auto rea = e.reaction(m);
      if (!rea || !principles::works_across(m, *rea, a.bodies)) continue;
      GiNaC::ex F = r.unknown("F_" + e.name + "[" + S1 + "," + S2 + "]", units::Dimension::mass() * units::Dimension::length() /
                                                                     (units::Dimension::time() * units::Dimension::time()));
      a.reactions[e.name] = {F};
      a.unknowns.push_back(F);
    }
  }
};

}  // namespace

const model::AnalysisKind& energy() { return instance<Energy>(); }

}  // namespace kinergy::analyses
