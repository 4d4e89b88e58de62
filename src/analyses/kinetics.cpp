// Kinetics at an instant: Newton's second law at one state, ΣF = m a_G and ΣM_G = Ī α for each
// body with the supports' reactions as unknowns, and Lagrange's equation along each coordinate;
// the rates at the state come from the other analyses (or as given).
#include "common.hpp"
#include "kinergy/principles/kinetics.hpp"

namespace kinergy::analyses {

namespace {

using GiNaC::ex;
using BalanceRow = principles::KineticsBalance::Row;

/// Its section: the unknowns, the equations read off each body's free-body diagram and along each
/// coordinate, those solved and those checked to follow.
void section(emit::Sections& w, int k, const model::Analysis& a, const principles::KineticsBalance& kb) {
  using namespace emit;
  const model::Model& m = w.solution().model;
  const std::string S = w.state_name(a.from);
  w.section("Kinetics at state " + S);
  w.legend("N", "Newton's second law at a state");
  Tags tags{"N" + std::to_string(k)};
  Spans intro{W("Newton's second law at state " + S + ", with the positions and rates there: ")};
  if (!a.bodies.empty())
    intro.insert(intro.end(), {W("for each body of " + w.bodies(a) + " "),
                               N("\\sum F = m\\,\\bar{a},\\ \\sum M_{G} = \\bar{I}\\,\\alpha", "ΣF = m a_G, ΣM_G = I α"),
                               W(", the supports' reactions unknown; ")});
  intro.insert(intro.end(), {W("along each coordinate q, Lagrange's equation "),
              N("\\sum_{b}\\left(m\\,\\bar{a}\\cdot\\frac{\\partial\\bar{r}}{\\partial q} + \\bar{I}\\,\\alpha\\,\\frac{\\partial\\phi}{\\partial q}\\right) = Q",
                "Σ (m a_G·∂r_G/∂q + I α ∂φ/∂q) = Q"),
              W(" (the supports the coordinates hold do no virtual work). The unknowns: ")});
  for (std::size_t i = 0; i < kb.unknowns.size(); ++i) {
    if (i) intro.push_back(W(i + 1 == kb.unknowns.size() ? " and " : ", "));
    intro.push_back(M(kb.unknowns[i]));
  }
  intro.push_back(W("."));
  w.para(intro);
  auto group = [&](BalanceRow::Kind kind, int body) {
    std::vector<BalanceRow> rows;
    for (auto& r : kb.rows)
      if (r.used && r.kind == kind && r.body == body) rows.push_back(r);
    return rows;
  };
  std::vector<emit::Row> shown;
  for (auto kind : {BalanceRow::Kind::Motion, BalanceRow::Kind::Constraint})
    for (auto& r : group(kind, -1)) shown.push_back(w.equation(tags, r.equation));
  if (!shown.empty()) {
    bool constraints = false;
    for (auto& r : kb.rows) constraints = constraints || (r.used && r.kind == BalanceRow::Kind::Constraint);
    w.para({W(constraints ? "Along each coordinate, and each constraint's second rate c\u0308 = 0:" : "Along each coordinate:")});
    w.rows(shown);
  }
  for (const principles::BodyAcceleration& acc : kb.accelerations) {
    const int b = acc.body;
    shown.clear();
    for (auto kind : {BalanceRow::Kind::ForceX, BalanceRow::Kind::ForceY, BalanceRow::Kind::Moment})
      for (auto& r : group(kind, b)) shown.push_back(w.equation(tags, r.equation));
    const std::string name = m.bodies[static_cast<std::size_t>(b)].name;
    w.kinetic_figure(a, acc, kb.loads, "Free-body diagram of " + name + " at state " + S + " (the forces on it) and its kinetic diagram (m a\u0304 and I\u0304 \u03b1): equivalent.");
    // (a body whose Newton–Euler equations all follow from the ones above: drawn, and said below)
    if (shown.empty()) continue;
    w.para({W("The free body " + m.bodies[static_cast<std::size_t>(b)].name + ": "),
            N("\\sum F_x = m\\,\\bar{a}_x,\\ \\sum F_y = m\\,\\bar{a}_y,\\ \\sum M_G = \\bar{I}\\,\\alpha", "ΣF_x = m a_x, ΣF_y = m a_y, ΣM_G = I α"),
            W(" (those not already implied):")});
    w.rows(shown);
  }
  std::vector<std::string> checked;
  for (auto& r : kb.rows)
    if (!r.used) checked.push_back(r.equation.label);
  if (!checked.empty()) w.para({W("The others follow from these (checked): " + listed(checked) + ".")});
}

class Kinetics : public Balanced<principles::KineticsBalance, principles::kinetics, section> {
public:
  Kinetics() : Balanced("kinetics") {}

  bool at_state() const override { return true; }
  bool impulsive() const override { return true; }  // not an energy balance: it says nothing of where a motion goes

  std::vector<std::string> keys() const override { return {"bodies"}; }

  void read(model::EffectReader& r, const scene::AnalysisDef&, model::Analysis& a) const override {
    a.unknowns = principles::kinetics_unknowns(r.model(), a);
  }
};

}  // namespace

const model::AnalysisKind& kinetics() { return instance<Kinetics>(); }

}  // namespace kinergy::analyses
