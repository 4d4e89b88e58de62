// An impact: positions and time kept, velocities jump; generalized impulse–momentum along each
// coordinate with the contact impulses (J along n, Jt along the tangent when rough), given blows and
// one impulsive reaction per constraint; restitution at each contact.
#include "kinergy/numeric/evaluate.hpp"
#include "common.hpp"

namespace kinergy::analyses {

namespace {

using GiNaC::ex;
using units::Dimension;

/// Its section: the parties, each struck body's impulse–momentum diagram, the generalized
/// impulse–momentum along each coordinate, restitution at each contact.
void section(emit::Sections& w, int k, const model::Analysis& a, const principles::ImpactBalance& ib) {
  using namespace emit;
  const Solution& s = w.solution();
  const model::Model& m = s.model;
  const std::string SB = w.state_name(a.from), SA = w.state_name(a.to);
  w.section("Impact, " + text_interval(SB, SA));
  Tags tags{"I" + std::to_string(k)};
  Spans intro{W("During the impact the positions and the time do not change (the state " + SA +
                " has the positions of " + SB + "), and only impulsive forces act: ")};
  bool any = false;
  for (int ci : a.struck()->contacts) {
    const auto e = m.contact(ci);
    if (any) intro.push_back(W("; "));
    any = true;
    intro.push_back(W("the contact " + e.name + " between " + e.a.text + " and " + e.b.text + ", normal "));
    intro.push_back(N("n = \\left(" + latex(w.tidy(e.nx)) + ", " + latex(w.tidy(e.ny)) + "\\right)",
                      "n = (" + plain(w.tidy(e.nx)) + ", " + plain(w.tidy(e.ny)) + ")"));
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
        intro.push_back(W(e.lodged ? " along the tangent (" + e.b.text + " embeds in " + e.a.text + ": they move together after)"
                                   : std::string(" along the tangent (rough: no sliding after)")));
      }
    }
  }
  for (auto& e : m.effects)
    if (const model::Blow* g = e.blow(); g && e.strikes_in(m, a)) {
      if (any) intro.push_back(W("; "));
      any = true;
      intro.push_back(W("the given impulse " + e.name + " at " + g->at.text + ", "));
      intro.push_back(N("\\left(" + latex(w.tidy(g->Jx)) + ", " + latex(w.tidy(g->Jy)) + "\\right)",
                        "(" + plain(w.tidy(g->Jx)) + ", " + plain(w.tidy(g->Jy)) + ")"));
    }
  if (!any) intro.push_back(W("none"));
  intro.push_back(W(". Pins and constraints carry workless impulsive reactions; gravity, springs, couples and "
                    "forces are not impulsive."));
  w.para(intro);
  // each body the impact moves: momenta before + impulses on it = momenta after
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    bool struck = false;
    for (auto& sh : ib.shown) struck = struck || sh.push.body == static_cast<int>(b);
    if (!struck) continue;
    // (the impulses on it: the diagram must draw each)
    std::vector<std::string> held;
    for (auto& sh : ib.shown)
      if (sh.push.body == static_cast<int>(b) && std::find(held.begin(), held.end(), sh.effect) == held.end()) held.push_back(sh.effect);
    w.momentum_figure(a, {static_cast<int>(b)}, ib.shown, held, "Impulse-momentum diagram of " + m.bodies[b].name + " in the impact: its momenta before (" + SB +
                                    "), plus the impulses on it, equal its momenta after (" + SA + ").");
  }
  if (!ib.momentum.empty()) {
    w.para({W("Impulse and momentum along each coordinate q (its generalized momentum changes by the generalized "
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
      Row row = w.equation(tags, q);
      if (i) order.push_back(W(i + 1 == ib.momentum.size() ? " and " : ", "));
      order.push_back(M(m.coords[static_cast<std::size_t>(ib.along[i])].q));
      if (w.sub(q.rhs).is_zero()) conserved.push_back("(" + row.tag + ")");
      r.push_back(row);
    }
    order.push_back(W(":"));
    w.para(order);
    w.rows(r);
    if (!conserved.empty()) {
      w.para({W("In " + listed(conserved) + " no impulse acts along the coordinate, so the generalized momentum along it is "
              "conserved through the impact.")});
    }
  }
  if (!ib.restitution.empty()) {
    w.para({W("At each contact the relative normal velocity reverses, scaled by e: "),
          N("(v_{B}' - v_{A}')\\cdot n = -e\\,(v_{B} - v_{A})\\cdot n", "(vB' - vA')·n = -e (vB - vA)·n"),
          W(" (and no relative tangential velocity after, where the contact is rough):")});
    std::vector<Row> r;
    for (auto& q : ib.restitution) {
      r.push_back(w.equation(tags, q));
    }
    w.rows(r);
  }
}

class Impact : public Balanced<principles::ImpactBalance, principles::impact, section> {
public:
  Impact() : Balanced("impact") {}

  std::vector<std::string> keys() const override { return {"contact", "contacts"}; }

  bool instant() const override { return true; }  // no time passes: positions and t are kept

  void read(model::EffectReader& r, const scene::AnalysisDef& ad, model::Analysis& a) const override {
    const model::Model& m = r.model();
    const Dimension M = Dimension::mass(), L = Dimension::length(), T = Dimension::time();
    const Dimension P = M * L / T;  // impulse
    const std::string S1 = m.states[a.from].name, S2 = m.states[a.to].name;
    std::vector<const scene::Node*> names;
    const scene::Node* c1 = ad.options.get("contact");
    const scene::Node* cs = ad.options.get("contacts");
    if (c1) names.push_back(c1);
    if (cs) {
      if (!cs->is_list()) throw SceneError(cs->pos, "'contacts' must be a list", "write 'contacts: [hit1, hit2]'");
      for (auto& it : cs->items) names.push_back(&it);
    }
    // a given impulse switched off (or not yet on) at this impact does not strike in it (read
    // before the later analyses: which one a blow strikes in is settled once all are read)
    bool blows = std::any_of(m.effects.begin(), m.effects.end(),
                             [&](const model::Effect& e) { return e.blow() != nullptr && e.activity(a) != model::Effect::Activity::None; });
    model::Struck st;
    if (names.empty() && !blows)
      throw SceneError(ad.pos, "an impact needs a contact or a given impulse",
                       "write 'impact: {from: before, to: after, contact: hit}', or add an effect '{impulse: body.P, J: [Jx, Jy]}'");
    for (auto* n : names) {
      int ei = n->is_scalar() ? m.effect_index(n->scalar) : -1;
      if (ei < 0 || !m.is_contact(m.effects[ei])) {
        std::vector<std::string> contacts;
        for (auto& e : m.effects)
          if (m.is_contact(e)) contacts.push_back(e.name);
        std::string near = n->is_scalar() ? scene::closest(n->scalar, contacts) : "";
        throw SceneError(n->pos, "'" + (n->is_scalar() ? n->scalar : std::string("?")) + "' is not a contact effect",
                         near.empty() ? "define it under effects: 'hit: {contact: [A, B], normal: [nx, ny], e: e}'"
                                      : "did you mean '" + near + "'?");
      }
      if (m.effects[ei].activity(a) == model::Effect::Activity::None)
        throw SceneError(n->pos, "contact '" + n->scalar + "' is switched " + (m.effects[ei].off >= 0 && m.effects[ei].off <= a.from ? "off" : "on") +
                                     " at state '" + m.states[m.effects[ei].off >= 0 && m.effects[ei].off <= a.from ? m.effects[ei].off : m.effects[ei].on].name +
                                     "', so it does not act in the impact " + S1 + " -> " + S2,
                         "name a contact that acts there, or move its 'on:'/'off:'");
      if (std::find(st.contacts.begin(), st.contacts.end(), ei) != st.contacts.end())
        throw SceneError(n->pos, "contact '" + n->scalar + "' is named twice in this impact", "name each contact once");
      st.contacts.push_back(ei);
      const model::Effect& e = m.effects[ei];
      const bool stick = m.contact(ei).stick;
      // unknown impulses: J along n (and Jt along the tangent when rough)
      ex J = r.unknown("J_" + e.name + "[" + S1 + "," + S2 + "]", P);
      ex Jt = stick ? r.unknown("Jt_" + e.name + "[" + S1 + "," + S2 + "]", P) : ex(0);
      st.impulses[e.name] = {J, Jt};
      a.unknowns.push_back(J);
      if (stick) a.unknowns.push_back(Jt);
    }
    // one impulsive reaction per constraint: its generalized impulse λ ∂c/∂q has the
    // dimension of (kg·m²/s) / [q], so λ has (kg·m²/s) / [c]
    for (std::size_t kk = 0; kk < m.constraints.size(); ++kk) {
      // a constraint effect switched off at `before` (a cord gone slack) carries no impulse
      if (m.constraint_activity(kk, a) == model::Effect::Activity::None) {
        st.lambdas.push_back(0);
        continue;
      }
      Dimension dc = m.dimension(m.constraints[kk].first);
      ex lam = r.unknown("lambda" + std::to_string(kk + 1) + "[" + S1 + "," + S2 + "]", M * L * L / T / dc);
      st.lambdas.push_back(lam);
      a.unknowns.push_back(lam);
    }
    a.options = std::move(st);
  }

  void check(const model::Model& m, const model::Analysis& a, const GiNaC::exmap& given, const solve::Branch& b,
             const GiNaC::exmap& env) const override {
    // a contact can only push: J ≥ 0 along its normal
    for (int ci : a.struck()->contacts) {
      const model::Model::Contact e = m.contact(ci), &c = e;
      ex J = a.struck()->impulses.at(e.name).first.subs(given).subs(b.sol);
      auto v = numerics::evaluate(J, env, 30);
      if (v && v->is_negative())
        throw SceneError(e.pos, "contact '" + e.name + "' would have to pull (impulse " + numerics::format(*v, 6) +
                                    " N*s along its normal) in the impact " + m.states[a.from].name + " -> " + m.states[a.to].name,
                         "check the normal: it points from the first party (" + c.a.text + ") into the second (" + c.b.text + ")");
    }
  }
};

}  // namespace

const model::AnalysisKind& impact() { return instance<Impact>(); }

}  // namespace kinergy::analyses
