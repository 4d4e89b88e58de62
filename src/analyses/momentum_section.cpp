// The derivation's section of a linear or an angular momentum analysis (both kinds write it):
// the momentum at each state and each impulse, component by component, with the set's
// impulse–momentum diagram.
#include "common.hpp"

namespace kinergy::analyses {

using GiNaC::ex;

namespace {

/// The TeX of the moment point: a body point by its name, a mass centre G.
std::string about_tex(const model::Model& m, const std::string& about) {
  std::string p = about;
  if (auto dot = p.find('.'); dot != std::string::npos) return emit::tex_name(p.substr(dot + 1));
  if (m.body_index(p) >= 0) return "G";
  return emit::tex_name(p);
}

/// t at a state in TeX: t_{1}, t_{\mathrm{top}}.
std::string t_tex(const std::string& S) { return emit::digits_only(S) ? "t_{" + S + "}" : "t_{\\mathrm{" + S + "}}"; }

/// The second integral of a component (its positions at the end): Φ₂ = Φ₁ + L₁ (t₂ − t₁) + Σ ∫∫F.
void displacement_rows(emit::Sections& w, emit::Tags& tags, const principles::MomentumBalance::Component& c, bool angular,
                       const std::string& base_tex, const std::string& base_text, const std::string& S1, const std::string& S2,
                       const std::string& dt_tex) {
  using namespace emit;
  const principles::MomentumBalance::Displacement& d = *c.displacement;
  const std::string phi_tex = "\\Phi", phi_text = "\u03a6";
  const std::string t1 = t_tex(S1), t2 = t_tex(S2);
  const std::string span_text = " (" + text_at("t", S2) + " − " + text_at("t", S1) + ")";
  const std::string inner = "\\int_{" + t1 + "}^{t}";
  w.para({W("Every push " + std::string(angular ? "has a moment that is" : "is") + " a known function of time, so the momentum integrates once more: "),
          N(base_tex + " = \\frac{d" + phi_tex + "}{dt}", base_text + " = d" + phi_text + "/dt"),
          W(" with "),
          angular ? N(phi_tex + " = \\sum_i h_i\\,q_i", phi_text + " = Σ h_i q_i")
          : c.name == "x" || c.name == "y" ? N(phi_tex + " = \\sum m\\,\\bar{" + c.name + "}", phi_text + " = Σ m " + c.name + "_G")
                                           : N(phi_tex + " = \\sum m\\,\\bar{r}\\cdot n", phi_text + " = Σ m r_G·n"),
          W(" (" + std::string(angular ? "H = Σ h_i q̇_i with every h_i constant" : "the set's first moment of mass") + "), and "),
          N(tex_at(phi_tex, S2) + " = " + tex_at(phi_tex, S1) + " + " + tex_at(base_tex, S1) + "\\,(" + t2 + " - " + t1 + ") + \\sum " + dt_tex + inner +
                (angular ? " M" : " F") + "\\,dt'\\,dt",
            text_at(phi_text, S2) + " = " + text_at(phi_text, S1) + " + " + text_at(base_text, S1) + span_text + " + Σ ∫∫" + (angular ? "M" : "F") + " dt' dt"),
          W(":")});
  std::vector<Row> r;
  r.push_back(tags.row({Math::notation(tex_at(phi_tex, S1), text_at(phi_text, S1)), Math::of(w.sub(d.before))}));
  r.push_back(tags.row({Math::notation(tex_at(base_tex, S1) + "\\,(" + t2 + " - " + t1 + ")", text_at(base_text, S1) + span_text),
                        Math::of(w.sub(d.drift))}));
  for (auto& term : d.terms)
    r.push_back(tags.row({Math::notation(dt_tex + inner + (angular ? " M" : " F") + "^{" + tex_word(term.effect) + "}\\,dt'\\,dt",
                                         "∫∫" + std::string(angular ? "M" : "F") + " dt' dt (" + term.effect + ")"),
                          Math::of(w.sub(term.value))}));
  r.push_back(tags.row({Math::notation(tex_at(phi_tex, S2), text_at(phi_text, S2)), Math::of(w.sub(d.after))}));
  w.rows(r);
  w.para({W("So:")});
  w.rows({w.equation(tags, d.equation)});
}

}  // namespace

/// The section of a linear or an angular momentum analysis: the momentum at each state, each
/// impulse, component by component, with the impulse–momentum diagram of the set.
void momentum_section(emit::Sections& w, int k, const model::Analysis& a, const principles::MomentumBalance& mb) {
  using namespace emit;
  const Solution& s = w.solution();
  const model::Model& m = s.model;
  const std::string S1 = w.state_name(a.from), S2 = w.state_name(a.to);
  bool angular = mb.angular;
  const std::string bodies = w.bodies(a);
  std::string what = angular ? (mb.conserved ? "Conservation of angular momentum" : "Angular impulse and momentum")
                             : (mb.conserved ? "Conservation of linear momentum" : "Linear impulse and momentum");
  std::string about = !angular ? "" : m.body_index(a.about()->text) >= 0 ? "the mass centre of " + a.about()->text : a.about()->text;
  std::string where = angular ? " about " + about : (a.along() ? " along " + a.along()->name : "");
  w.section(what + where + ", states " + text_interval(S1, S2));
  Tags tags{"M" + std::to_string(k)};
  std::string dt_tex = "\\int_{" + t_tex(S1) + "}^{" + t_tex(S2) + "}";
  if (angular) {
    std::string P = about_tex(m, a.about()->text);
    std::string H = "H_{" + P + "}";
    // a place that follows the motion: dH_P/dt = ΣM_P − v_P × m v̄, and v_P ∥ v̄ (checked on reading)
    const auto [px, py] = m.position(*a.about());
    if (a.about()->body < 0 && !principles::motion_free(m, px + py))
      w.para({W(about + " is the place x = "), M(px), W(", y = "), M(py),
              W(", which moves parallel to the mass centre of " + bodies + ": the angular momentum about a moving point changes as "),
              N("\\dot{H}_{" + P + "} = \\sum M_{" + P + "} - v_{" + P + "}\\times m\\bar{v}", "dH/dt = ΣM - v_" + about + " × m*v"),
              W(", and the last term is zero.")});
    w.para({W("Bodies: " + bodies + ". The angular momentum about " + about + " is "),
          N(H + " = \\sum \\left(\\bar{I}\\omega + (\\bar{r} - r_{" + P + "})\\times m\\bar{v}\\right)",
            "H = Σ (I*omega + (r_G - r_" + a.about()->text + ") × m*v)"),
          W(", and "),
          mb.conserved ? N(tex_at(H, S1) + " = " + tex_at(H, S2), text_at("H", S1) + " = " + text_at("H", S2))
                       : N(tex_at(H, S1) + " + \\sum " + dt_tex + " M_{" + P + "}\\,dt = " + tex_at(H, S2),
                           text_at("H", S1) + " + Σ ∫M dt = " + text_at("H", S2)),
          W(mb.conserved ? " when no effect has a moment about " + about + "." : ".")});
  } else {
    w.para({W("Bodies: " + bodies + ". The linear momentum is "), N("L = \\sum m\\bar{v}", "L = Σ m*v"), W(", and "),
          mb.conserved ? N(tex_at("L", S1) + " = " + tex_at("L", S2), text_at("L", S1) + " = " + text_at("L", S2))
                       : N(tex_at("L", S1) + " + \\sum " + dt_tex + " F\\,dt = " + tex_at("L", S2),
                           text_at("L", S1) + " + Σ ∫F dt = " + text_at("L", S2)),
          W(mb.conserved ? " along a direction in which no effect has an impulse" : ""),
          W(mb.components.size() > 1 ? ". Component by component:" : ".")});
  }
  // a guided body's implied support: only the loads' components along its line count, at G
  for (int b : mb.supported) {
    const std::string B = m.bodies[static_cast<std::size_t>(b)].name, P = about_tex(m, a.about()->text);
    w.para({W(B + " keeps to a fixed straight line without turning, on a support the scene implies (a table, a guide), drawn as N_" + B +
              ". That support balances the loads on " + B + " across its line and about its mass centre ("),
            N("m\\bar{a}\\cdot\\hat{n} = 0,\\ \\bar{I}\\alpha = 0", "m a·n = 0, I α = 0"),
            W("), so of each load F on " + B + " only its component along the line counts, as if at the mass centre: "),
            N("(\\bar{r} - r_{" + P + "})\\times\\hat{u}\\,(F\\cdot\\hat{u})", "(r_G - r_" + a.about()->text + ") × u (F·u)"),
            W(", with u along the line. A cord or a coupling between " + B + " and the other bodies is taken to pull along its line, through its mass centre.")});
  }
  // (the effects whose impulses the equations hold: the diagram must draw each)
  std::vector<std::string> held;
  for (auto& c : mb.components)
    for (auto& t : c.impulses)
      if (!t.value.is_zero() && std::find(held.begin(), held.end(), t.effect) == held.end()) held.push_back(t.effect);
  w.momentum_figure(a, a.bodies, mb.shown, held, "Impulse-momentum diagram of " + bodies + ": the momenta at " + S1 + ", plus the impulses from " + S1 +
                                  " to " + S2 + ", equal the momenta at " + S2 + ".");
  for (auto& c : mb.components) {
    std::string base_tex, base_text, comp;
    if (angular) {
      base_tex = "H_{" + about_tex(m, a.about()->text) + "}";
      base_text = "H";
      comp = "about " + about;
    } else {
      std::string n = c.name == "x" || c.name == "y" ? c.name : "n";
      base_tex = "L_{" + n + "}";
      base_text = "L_" + n;
      comp = "along " + (c.name == "x" || c.name == "y" ? c.name : c.name + " (n)");
    }
    if (mb.components.size() > 1) w.subsection("Component " + comp);
    std::vector<Row> r;
    r.push_back(tags.row({Math::notation(tex_at(base_tex, S1), text_at(base_text, S1)), Math::of(w.sub(c.before))}));
    Spans unknowns;
    for (auto& imp : c.impulses) {
      ex v = w.sub(imp.value);
      bool reaction = imp.kind == principles::ImpulseTerm::Kind::Reaction;
      std::string F = angular ? "M" : "F";
      std::string sub_ = angular ? "_{" + about_tex(m, a.about()->text) + "}" : "_{" + std::string(c.name == "x" || c.name == "y" ? c.name : "n") + "}";
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
    r.push_back(tags.row({Math::notation(tex_at(base_tex, S2), text_at(base_text, S2)), Math::of(w.sub(c.after))}));
    w.rows(r);
    if (!unknowns.empty()) {
      unknowns.insert(unknowns.begin(), W("Unknown impulses: "));
      unknowns.push_back(W("."));
      w.para(unknowns);
    }
    if (mb.conserved)
      w.para({W("No effect acting on " + bodies + " has an impulse " + comp + " between states " + S1 + " and " + S2 +
              " (each effect was checked), so the " + std::string(angular ? "angular" : "linear") + " momentum " + comp +
              " is conserved:")});
    else if (c.impulses.empty())
      w.para({W("No impulse acts " + comp + ", so the " + std::string(angular ? "angular" : "linear") + " momentum " + comp +
              " does not change:")});
    else
      w.para({W("So:")});
    w.rows({w.equation(tags, c.equation)});
    if (c.displacement && s.drew_on(c.displacement->equation)) displacement_rows(w, tags, c, angular, base_tex, base_text, S1, S2, dt_tex);
  }
}

}  // namespace kinergy::analyses
