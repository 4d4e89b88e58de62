// A solved scene's states as numbers; each analysis run as a simulation and compared.
#include "kinergy/confirm/check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/tape.hpp"

namespace kinergy::simulate {

using namespace GiNaC;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// What is known of a scene's states: the given values, the solved ones, the parameters.
struct Known {
  exmap given, solved, params;
};

// a state symbol's value: given, or solved (closed forms may name other solved symbols)
double value(const Known& k, const ex& sym) {
  ex v = sym;
  for (int pass = 0; pass < 4; ++pass) {
    ex w = v.subs(k.given).subs(k.solved);
    if (w.is_equal(v)) break;
    v = w;
  }
  v = v.subs(k.params);
  try {
    ex e = v.evalf();
    if (is_a<numeric>(e) && ex_to<numeric>(e).is_real()) return ex_to<numeric>(e).to_double();
  } catch (const std::exception&) {
  }
  return kNaN;
}

/// The end of a run from leg.start toward state leg.to: its instant when both times are known,
/// else where S2's given values are reached (a rate given as zero — a turning point, crossed
/// transversally — else a given position, else a given rate; lacking all, the coordinate that
/// moves most). Sets leg.stop, leg.target and leg.expect.t; why_not when nothing places S2.
void aim(const model::Model& m, const Known& k, Leg& leg, double t1) {
  const model::State& S2 = m.states[static_cast<std::size_t>(leg.to)];
  const double t2 = value(k, S2.t);
  if (!std::isnan(t1) && !std::isnan(t2)) {
    leg.start.t = t1;
    leg.stop.until = t2;
    leg.expect.t = t2;
    leg.target = "t = " + numerics::g_text(t2, 8) + " s";
    if (!(t2 > t1)) leg.why_not = "state '" + S2.name + "' is not later than '" + m.states[static_cast<std::size_t>(leg.from)].name + "'";
  } else {
    // the end is where S2's given values are reached: a rate given as zero (a turning point,
    // crossed transversally), else a given position, else a given rate; lacking all, the
    // coordinate that moves most
    int pick = -1;
    bool rate = false;
    double best = -1;
    for (std::size_t i = 0; i < m.coords.size(); ++i)
      for (int r = 0; r < 2; ++r) {
        double v1 = r ? leg.start.qd[i] : leg.start.q[i], v2 = r ? leg.expect.qd[i] : leg.expect.q[i];
        auto& [qs, qds] = S2.sym.at(m.coords[i].name);
        bool given = S2.given.count(r ? qds : qs) > 0;
        // a turning point given as a zero rate ends the run even from rest (it is the next zero)
        // when the coordinate moves between the states to a place not given (a given place
        // with a zero rate is a stop the motion is held at)
        const bool moves = !std::isnan(leg.expect.q[i]) && leg.expect.q[i] != leg.start.q[i] && !S2.given.count(qs);
        if (std::isnan(v2) || (v1 == v2 && !(r && given && v2 == 0 && moves))) continue;
        double score = given ? (r && v2 == 0 ? 3e300 : (r ? 1e300 : 2e300)) : (r ? -1 : std::fabs(v2 - v1) / std::max({std::fabs(v1), std::fabs(v2), 1e-300}));
        if (score > best) {
          best = score;
          pick = static_cast<int>(i);
          rate = r == 1;
        }
      }
    if (pick < 0) {
      leg.why_not = "nothing given at state '" + S2.name + "' places it on the way (no time, and no coordinate or rate that changes)";
      return;
    }
    const auto i = static_cast<std::size_t>(pick);
    double q1 = leg.start.q[i], q2 = rate ? leg.expect.qd[i] : leg.expect.q[i];
    leg.stop.when = (rate ? m.coords[i].qd : m.coords[i].q) - numerics::exact(q2);
    // time enough: the distance at a tenth of the faster of the two rates (or 100 s)
    double v = std::max(std::fabs(leg.start.qd[i]), std::fabs(leg.expect.qd[i]));
    double dq = std::fabs(leg.expect.q[i] - q1);
    // (a rate reached at a known place too: a flywheel braked to rest over 2500 rad takes 145 s)
    leg.stop.until = leg.start.t + (v > 0 && !std::isnan(dq) && dq > 0 ? std::max(10 * dq / v, 1.0) : 100.0);
    leg.target = m.coords[i].name + (rate ? "_dot" : "") + " reaches " + numerics::g_text(q2, 8);
    leg.expect.t = kNaN;
  }
}

}  // namespace

exmap simulation_values(const Solution& s) { return parameter_values(s); }

namespace {

State state_values(const model::Model& m, const Known& k, int index) {
  const model::State& st = m.states[static_cast<std::size_t>(index)];
  State out;
  out.t = value(k, st.t);
  if (std::isnan(out.t)) out.t = 0;  // a state without time: its instant is the origin
  for (auto& c : m.coords) {
    auto& [q, qd] = st.sym.at(c.name);
    out.q.push_back(value(k, q));
    out.qd.push_back(value(k, qd));
  }
  return out;
}

Known known(const Solution& s) { return {s.model.given_values(), s.branch.sol, simulation_values(s)}; }

}  // namespace

State state_values(const model::Model& m, const exmap& solved, const exmap& params, int index) {
  return state_values(m, Known{m.given_values(), solved, params}, index);
}

State state_values(const Solution& s, int index) { return state_values(s.model, known(s), index); }

std::vector<Leg> legs(const Solution& s) {
  const model::Model& m = s.model;
  const Known k = known(s);
  const exmap& params = k.params;
  std::vector<Leg> out;
  for (std::size_t ai = 0; ai < m.analyses.size(); ++ai) {
    const model::Analysis& a = m.analyses[ai];
    Leg leg;
    leg.analysis = static_cast<int>(ai);
    leg.from = a.from;
    leg.to = a.to;
    leg.start = state_values(m, k, a.from);
    leg.expect = state_values(m, k, a.to);
    leg.stop.impulses = a.takes_blows();  // a blow at its first state, as its principle counts it
    // a state given by a parameter without a value (the variable of an extreme, the speed whose
    // least value is asked) is no one motion
    for (int st : {a.from, a.to})
      for (auto& [sym, val] : m.states[st].given)
        for (auto& p : m.params)
          if (leg.why_not.empty() && p.without_value() && val.has(p.sym))
            leg.why_not = "state '" + m.states[st].name + "' depends on '" + p.name + "', which has no value";
    for (std::size_t i = 0; i < m.coords.size(); ++i)
      if (leg.why_not.empty() && (std::isnan(leg.start.q[i]) || std::isnan(leg.start.qd[i])))
        leg.why_not = "state '" + m.states[a.from].name + "' does not fix " + m.coords[i].name +
                      (std::isnan(leg.start.q[i]) ? "" : "_dot");
    // a coordinate past 2^40 (an angle of 1e300 deg) has no step a double resolves, nor a sine
    for (std::size_t i = 0; i < m.coords.size(); ++i)
      for (double x : {leg.start.q[i], leg.expect.q[i]})
        if (leg.why_not.empty() && std::isfinite(x) && std::fabs(x) > 0x1p40)
          leg.why_not = m.coords[i].name + " = " + numerics::g_text(x, 8) + " is beyond what a simulation in doubles resolves";
    if (leg.why_not.empty() && a.type->at_state())
      leg.why_not = "taken at one state, no motion to run (its accelerations are checked against the equations of motion there)";
    if (!leg.why_not.empty()) {
      out.push_back(leg);
      continue;
    }
    const model::State& S1 = m.states[a.from];
    const model::State& S2 = m.states[a.to];
    const double t1 = value(k, S1.t);
    if (a.instant()) {
      // an impact: everything happens at the start
      leg.stop.until = leg.start.t;
      leg.target = "the impact at the start";
      leg.expect.t = leg.start.t;
    } else {
      aim(m, k, leg, t1);
    }
    // The solved values at S2 are the closed forms to check; S2's given values define the state
    // (or assume it: balls locked at their stops). Without a solved value (a parameter or the
    // time was solved for), the given ones are checked, all but the one that ends the run.
    bool solved = false;
    for (std::size_t i = 0; i < m.coords.size(); ++i) {
      auto& [qs, qds] = S2.sym.at(m.coords[i].name);
      solved = solved || (!S2.given.count(qs) && !std::isnan(leg.expect.q[i])) ||
               (!S2.given.count(qds) && !std::isnan(leg.expect.qd[i]));
    }
    for (std::size_t i = 0; i < m.coords.size(); ++i) {
      auto& [qs, qds] = S2.sym.at(m.coords[i].name);
      if (S2.given.count(qs) && (solved || (leg.stop.when && leg.stop.when->has(m.coords[i].q)))) leg.expect.q[i] = kNaN;
      if (S2.given.count(qds) && (solved || (leg.stop.when && leg.stop.when->has(m.coords[i].qd)))) leg.expect.qd[i] = kNaN;
    }
    // an effect switched inside the analysis: the closed form takes its work over its part;
    // one run of the equations cannot switch it
    for (auto& e : m.effects)
      if (leg.why_not.empty() && e.activity(a) == model::Effect::Activity::Part)
        leg.why_not = "effect '" + e.name + "' is switched inside it (at state '" +
                      m.states[e.on > std::min(a.from, a.to) && e.on < std::max(a.from, a.to) ? e.on : e.off].name +
                      "'): check the analyses on either side of that state";
    // an effect undefined at the start (a power drive from rest: its couple P/ω is infinite)
    if (leg.why_not.empty()) {
      exmap at = params;
      for (std::size_t i = 0; i < m.coords.size(); ++i) {
        at[m.coords[i].q] = numerics::exact(leg.start.q[i]);
        at[m.coords[i].qd] = numerics::exact(leg.start.qd[i]);
      }
      at[m.t] = numerics::exact(leg.start.t);
      // a load that may be undefined (it says why) and has no value at the start
      auto undefined = [&](const ex& v) {
        try {
          ex x = v.subs(at).evalf();
          return !GiNaC::is_a<GiNaC::numeric>(x) || !std::isfinite(GiNaC::ex_to<GiNaC::numeric>(x).to_double());
        } catch (const std::exception&) {
          return true;  // (a division by zero)
        }
      };
      for (auto& e : m.effects)
        for (const model::Load& l : e.loads(m))
          if (leg.why_not.empty() && !l.singular.empty() && (undefined(l.Fx) || undefined(l.Fy) || undefined(l.M)))
            leg.why_not = l.singular + ", and the run would start there";
    }
    out.push_back(leg);
  }
  return out;
}

namespace {

/// A state at rest that the closed form's motion reaches only asymptotically (the least speed for
/// a wheel to roll over a step: at exactly that speed it creeps toward the top for ever, and a
/// simulation's rounding sends it over or back). Checked as the least-value feature checks it:
/// started with every rate 10⁻⁶ larger, the motion passes the end state's position; 10⁻⁶
/// smaller, it turns back (comes to rest) before it. When both hold, the check passes and says so
/// in its note; else it stands as it was.
void limit_state(const Solution& s, const Leg& leg, Simulator& sim, const State& end, LegCheck& c) {
  const model::Model& m = s.model;
  // at rest at the end, and moving at the start, along the coordinate that moves most
  std::size_t pick = m.coords.size();
  double best = 0;
  for (std::size_t i = 0; i < m.coords.size(); ++i) {
    if (!(end.qd[i] == 0) || !std::isfinite(end.q[i])) return;
    const double d = std::fabs(end.q[i] - leg.start.q[i]);
    if (d > best) best = d, pick = i;
  }
  if (pick == m.coords.size() || leg.start.qd[pick] == 0 || (end.q[pick] - leg.start.q[pick]) * leg.start.qd[pick] <= 0) return;
  const double sign = end.q[pick] > leg.start.q[pick] ? 1 : -1;
  auto scaled = [&](double f) {
    State x = leg.start;
    for (auto& v : x.qd) v *= f;
    return x;
  };
  // above: it reaches the end's position, still moving on
  Stop reach;
  reach.when = m.coords[pick].q - numerics::exact(end.q[pick]);
  reach.until = leg.start.t + 100 * std::max(leg.stop.until - leg.start.t, 1.0);
  reach.impulses = leg.stop.impulses;
  const Run above = sim.run(scaled(1 + 1e-6), reach);
  if (!above.stopped || !(above.end.qd[pick] * sign > 0)) return;
  // below: it comes to rest first, short of the end's position
  Stop rest = reach;
  rest.when = ex(m.coords[pick].qd);
  const Run below = sim.run(scaled(1 - 1e-6), rest);
  if (!below.stopped || !((end.q[pick] - below.end.q[pick]) * sign > 0)) return;
  c.ok = true;
  c.note = (c.note.empty() ? "" : c.note + "; ") + "a limit state, reached only asymptotically: started 1e-6 faster the motion passes " +
           m.coords[pick].name + " = " + numerics::g_text(end.q[pick], 8) + ", 1e-6 slower it turns back at " + m.coords[pick].name + " = " +
           numerics::g_text(below.end.q[pick], 8);
  c.worst = 0;
  c.worst_what.clear();
  c.outcome = LegCheck::Outcome::Compared;
}

}  // namespace

LegCheck check_leg(const Solution& s, const Leg& leg, const Options& o, double tolerance) {
  LegCheck c;
  c.leg = leg;
  const model::Model& m = s.model;
  // only the effects that act over this analysis
  Options own = o;
  own.effects_on.clear();
  // an analysis keeps its bodies on their surfaces: the first release refutes it (ReleaseError)
  own.follow_releases = false;
  // (a blow only where it strikes: at the first state of the analysis that takes it)
  for (auto& e : m.effects)
    own.effects_on.push_back(e.blow() ? e.strikes_in(m, m.analyses[leg.analysis]) : e.activity(m.analyses[leg.analysis]) != model::Effect::Activity::None);
  // the motion's own size, so that the absolute tolerance is relative to it (never larger than
  // tol): the smallest of the coordinates' changes and rates that are not zero (a time scale of
  // 1 s), so that each keeps its relative accuracy — a rate of 6e-5 among positions of 1 — but not
  // below 1e-9 of the largest
  double lo = 0, hi = 0;
  const State end = state_values(s, leg.to);
  for (std::size_t i = 0; i < m.coords.size(); ++i)
    for (double x : {end.q[i] - leg.start.q[i], leg.start.qd[i], end.qd[i]})
      if (std::isfinite(x) && x != 0) {
        lo = lo == 0 ? std::fabs(x) : std::min(lo, std::fabs(x));
        hi = std::max(hi, std::fabs(x));
      }
  const double size = std::max(lo, 1e-9 * hi);
  if (size > 0 && size < 1) own.atol = o.tol * size;
  const GiNaC::exmap values = simulation_values(s);
  Simulator sim(m, values, own);
  c.run = sim.run(leg.start, leg.stop);
  // not reached: run longer; from rest on an equilibrium (nothing moved), nudged toward the end
  Stop longer = leg.stop;
  State start = leg.start;
  for (int tries = 0; leg.stop.when && !c.run.stopped && tries < 4; ++tries) {
    bool rest = true, moved = false;
    for (std::size_t i = 0; i < m.coords.size(); ++i) {
      rest = rest && start.qd[i] == 0;
      moved = moved || c.run.end.q[i] != start.q[i] || c.run.end.qd[i] != 0;
    }
    if (!rest && tries == 0 && !(own.max_dt > 0)) {
      // a stop condition crossed twice within one long step (a ball passing a height just below
      // its top and falling back through it) is not seen: once more in steps of a thousandth of
      // the run's estimated span
      Options short_steps = own;
      short_steps.max_dt = (leg.stop.until - leg.start.t) / 1000;
      Simulator fine(m, values, short_steps);
      Run again = fine.run(start, leg.stop);
      if (again.stopped) {
        c.run = std::move(again);
        c.note = "in steps of at most " + numerics::g_text(short_steps.max_dt, 8) + " s";
        break;
      }
    }
    if (rest && !moved && c.note.empty()) {
      // q̇ = ε Δq/|Δq| with ½ ε² (the scale of M) ≈ 10⁻²⁰ T at the end: ε = 10⁻¹⁰ × the end's rates
      // (the end's values as the solution has them, given ones included)
      double d2 = 0, v2 = 0;
      for (std::size_t i = 0; i < m.coords.size(); ++i) {
        const double d = end.q[i] - start.q[i];
        if (std::isfinite(d)) d2 += d * d;
        if (std::isfinite(end.qd[i])) v2 = std::max(v2, std::fabs(end.qd[i]));
      }
      if (!(d2 > 0) || !(v2 > 0)) break;
      const double eps = 1e-10 * v2 / std::sqrt(d2);
      std::string how;
      for (std::size_t i = 0; i < m.coords.size(); ++i) {
        const double d = end.q[i] - start.q[i];
        start.qd[i] = std::isfinite(d) ? eps * d : 0;
        if (start.qd[i] != 0) how += (how.empty() ? "" : ", ") + m.coords[i].name + "_dot = " + numerics::g_text(start.qd[i], 8);
      }
      c.note = "nudged: released at rest on an equilibrium, started with " + how + " toward state '" + m.states[static_cast<std::size_t>(leg.to)].name + "'";
      longer.until = leg.start.t + 10 * (leg.stop.until - leg.start.t);
    } else {
      longer.until = leg.start.t + 10 * (longer.until - leg.start.t);
      c.note = (c.note.empty() ? "" : c.note + "; ") + "run for " + numerics::g_text(longer.until - leg.start.t, 8) + " s";
    }
    c.run = sim.run(start, longer);
  }
  const Sample& e = c.run.end;
  c.ok = true;
  for (std::size_t i = 0; i < m.coords.size(); ++i) {
    // the scale of a coordinate: its size at the two states; of a rate: the largest seen
    double qs = std::max({std::fabs(leg.start.q[i]), std::fabs(leg.expect.q[i]), 1e-300});
    double vs = std::max({std::fabs(leg.start.qd[i]), std::fabs(leg.expect.qd[i]), 1e-300});
    for (auto& smp : c.run.samples) vs = std::max(vs, std::fabs(smp.qd[i]));
    for (auto& smp : c.run.samples) qs = std::max(qs, std::fabs(smp.q[i]));
    auto compare = [&](double sim_v, double want, double scale, const std::string& what) {
      if (std::isnan(want)) return;
      double err = std::fabs(sim_v - want) / scale;
      if (!(err <= c.worst) || std::isnan(err)) {
        c.worst = std::isnan(err) ? std::numeric_limits<double>::infinity() : err;
        c.worst_what = what + ": simulated " + numerics::g_text(sim_v, 8) + ", closed form " + numerics::g_text(want, 8);
      }
    };
    compare(e.q[i], leg.expect.q[i], qs, m.coords[i].name + "@" + m.states[leg.to].name);
    compare(e.qd[i], leg.expect.qd[i], vs, m.coords[i].name + "_dot@" + m.states[leg.to].name);
  }
  if (!std::isnan(leg.expect.t) && std::fabs(e.t - leg.expect.t) > 1e-12 * std::max(1.0, std::fabs(leg.expect.t))) {
    c.worst = std::numeric_limits<double>::infinity();
    c.outcome = LegCheck::Outcome::WrongTime;
    c.worst_what = "the run ended at t = " + numerics::g_text(e.t, 8) + " s, not at " + numerics::g_text(leg.expect.t, 8);
  }
  bool any = false;
  for (std::size_t i = 0; i < m.coords.size(); ++i) any = any || !std::isnan(leg.expect.q[i]) || !std::isnan(leg.expect.qd[i]);
  if (leg.stop.when && !c.run.stopped) {
    c.worst = std::numeric_limits<double>::infinity();
    c.outcome = LegCheck::Outcome::NotReached;
    c.worst_what = "the simulation does not reach state '" + m.states[static_cast<std::size_t>(leg.to)].name + "' (" + leg.target +
                   ") by t = " + numerics::g_text(c.run.end.t, 8) + " s";
  }
  c.ok = any && c.worst <= tolerance;
  if (!any) {
    c.outcome = LegCheck::Outcome::NothingToCompare;
    c.worst_what = "no solved value at state '" + m.states[leg.to].name + "' to compare";
  }
  if (!c.ok && any && leg.stop.when) limit_state(s, leg, sim, end, c);
  return c;
}

draw::Motion motion_of(const Run& r, const std::string& title) {
  draw::Motion mo;
  mo.title = title;
  for (auto& x : r.samples) mo.frames.push_back({x.t, x.q, x.qd});
  for (auto& im : r.impacts) {
    std::string at;
    for (auto& name : im.contacts) at += (at.empty() ? "" : ", ") + name;
    mo.moments.push_back({im.t, "impact at " + at});
  }
  return mo;
}

bool impulses_at(const model::Model& m, int start) {
  bool at = m.analyses.empty();
  for (auto& a : m.analyses) at = at || (a.takes_blows() && a.from == start);
  return at;
}

std::vector<draw::Motion> motions(const Solution& s, int samples) {
  std::vector<draw::Motion> out;
  const model::Model& m = s.model;
  for (Leg leg : legs(s)) {
    if (!leg.why_not.empty()) continue;
    const model::Analysis& a = m.analyses[static_cast<std::size_t>(leg.analysis)];
    if (a.instant()) {
      // an impact has no duration: its motion shown is what follows it, for as long as the
      // fastest body takes to cover the scene's size (L/v: its bodies' sizes and the distances
      // between their centres; their speeds just after, v̄ and ω times the size), at most 5 s
      exmap at = simulation_values(s);
      for (std::size_t i = 0; i < m.coords.size(); ++i) {
        at[m.coords[i].q] = leg.start.q[i];
        at[m.coords[i].qd] = std::isnan(leg.expect.qd[i]) ? leg.start.qd[i] : leg.expect.qd[i];
      }
      at[m.t] = leg.start.t;
      auto number = [&](const ex& e) {
        ex v = e.subs(at).evalf();
        return is_a<numeric>(v) && ex_to<numeric>(v).is_real() ? ex_to<numeric>(v).to_double() : 0.0;
      };
      double L = 0, v = 0;
      for (std::size_t b = 0; b < m.bodies.size(); ++b) {
        double size = 0;
        for (auto& z : m.bodies[b].lengths()) size = std::max(size, std::fabs(number(z)));
        L = std::max(L, size);
        v = std::max({v, std::hypot(number(m.rate(m.bodies[b].x)), number(m.rate(m.bodies[b].y))), std::fabs(number(m.omega(static_cast<int>(b)))) * size});
        for (std::size_t c = 0; c < b; ++c)
          L = std::max(L, std::hypot(number(m.bodies[b].x) - number(m.bodies[c].x), number(m.bodies[b].y) - number(m.bodies[c].y)));
      }
      if (!(L > 0) || !(v > 0) || !std::isfinite(L / v)) continue;
      leg.stop = Stop{};
      leg.stop.until = leg.start.t + std::min(L / v, 5.0);
      leg.stop.impulses = true;
      leg.target = "t = " + numerics::g_text(leg.stop.until, 8) + " s, after the impact";
    }
    // a leg that ends at a time is sampled over it at once; one that ends where a value is
    // reached is run a first time to find where, then sampled at regular times
    Options o;
    o.native = false;  // the tape: no compiler run for a page
    o.record = false;
    const double span = leg.stop.when ? check_leg(s, leg, o, 1).run.end.t - leg.start.t : leg.stop.until - leg.start.t;
    if (!(span > 0) || !std::isfinite(span)) continue;
    o.record = true;
    o.sample_dt = span / std::max(samples, 1);
    const LegCheck c = check_leg(s, leg, o, 1);
    draw::Motion mo = motion_of(c.run, "Analysis " + std::to_string(leg.analysis + 1) + " (" + a.kind + "), from state " +
                                           m.states[static_cast<std::size_t>(leg.from)].name +
                                           (a.instant() ? " through the impact until " + leg.target
                                                      : " until state " + m.states[static_cast<std::size_t>(leg.to)].name + " (" + leg.target + ")") +
                                           ", simulated");
    if (!mo.frames.empty()) out.push_back(std::move(mo));
  }
  return out;
}

namespace {

// an effect acts after state `st` when it is switched on at or before it and not off by then
bool acts_after(const model::Effect& e, int st) { return (e.on < 0 || e.on <= st) && (e.off < 0 || e.off > st); }

// The state a run ended in, for the next run's simulator: the same coordinates (the scene's, and
// the gaps of the surfaces its bodies may leave), or the scene's alone where every gap the next
// one does not have is closed. @throws SimulationError where a body is off a surface the next run
// cannot free it from.
State carried(const Run& all, const Simulator& next, const model::Model& scene) {
  State x{all.end.t, all.end.q, all.end.qd};
  const model::Model& was = all.model ? *all.model : scene;
  const model::Model& will = next.model();
  if (was.coords.size() == will.coords.size()) return x;
  for (std::size_t i = scene.coords.size(); i < was.coords.size(); ++i)
    if (std::fabs(x.q[i]) > 1e-12 * std::max(1.0, std::fabs(x.q[i])) || x.qd[i] != 0)
      throw SimulationError("at t = " + numerics::g_text(x.t, 6) + " s a body is off a surface (" + was.coords[i].name + " = " + numerics::g_text(x.q[i], 6) +
                                " m), and the effects that act from here on hold it there",
                            "end the run before the switch (--until)");
  x.q.resize(scene.coords.size());
  x.qd.resize(scene.coords.size());
  if (will.coords.size() > x.q.size()) {
    x.q.resize(will.coords.size(), 0.0);
    x.qd.resize(will.coords.size(), 0.0);
  }
  return x;
}

// r appended to all: one run in time (works summed by effect, the drift weighted by each scale)
void append(Run& all, Run r, bool first) {
  if (first) {
    all = std::move(r);
    return;
  }
  if (!all.samples.empty() && !r.samples.empty() && r.samples.front().t == all.samples.back().t) r.samples.erase(r.samples.begin());
  all.samples.insert(all.samples.end(), r.samples.begin(), r.samples.end());
  all.impacts.insert(all.impacts.end(), r.impacts.begin(), r.impacts.end());
  all.log.insert(all.log.end(), r.log.begin(), r.log.end());
  for (auto& w : r.work) {
    auto it = std::find_if(all.work.begin(), all.work.end(), [&](auto& x) { return x.first == w.first; });
    if (it == all.work.end()) all.work.push_back(w);
    else it->second += w.second;
  }
  const double scale = std::max(all.energy_scale, r.energy_scale);
  all.drift = scale > 0 ? (all.drift * all.energy_scale + r.drift * r.energy_scale) / scale : 0;
  all.energy_scale = scale;
  all.end = r.end;
  all.stopped = r.stopped;
  all.switches.insert(all.switches.end(), r.switches.begin(), r.switches.end());
  if (r.model) all.model = r.model;
  all.E1 = r.E1;
  all.impact_loss += r.impact_loss;
  all.conservative = all.conservative && r.conservative;
  all.steps += r.steps;
  all.rejected += r.rejected;
  all.rhs_calls += r.rhs_calls;
}

}  // namespace

Run run_following(const model::Model& m, const exmap& solved, const exmap& params, int start, const State& s0, double until,
                  const Options& o, bool impulses) {
  const Known k{m.given_values(), solved, params};
  Run all;
  State x = s0;
  int cur = start;
  for (bool first = true;; first = false) {
    Options own = o;
    own.effects_on.clear();
    // (a blow at the state where it strikes, or at the start of a scene without analyses)
    for (auto& e : m.effects)
      own.effects_on.push_back(acts_after(e, cur) && (!e.blow() || m.analyses.empty() || e.strike_state(m) == cur));
    // the next state where an effect is switched
    int next = -1;
    const model::Effect* by = nullptr;
    for (auto& e : m.effects)
      for (int st : {e.on, e.off})
        if (st > cur && (next < 0 || st < next)) {
          next = st;
          by = &e;
        }
    Stop stop;
    stop.until = until;
    stop.impulses = first && impulses;
    if (next >= 0) {
      // it is reached as a check's leg reaches its end: its time, or a value given there
      Leg leg;
      leg.from = cur;
      leg.to = next;
      leg.start = x;
      leg.expect = state_values(m, k, next);
      aim(m, k, leg, x.t);
      const model::State& S = m.states[static_cast<std::size_t>(next)];
      if (!leg.why_not.empty())
        throw SceneError(S.pos, "effect '" + by->name + "' is switched at state '" + S.name + "', which a run cannot find: " + leg.why_not,
                         "give the time or a coordinate at state '" + S.name + "'");
      if (leg.stop.when) stop.when = leg.stop.when;
      else stop.until = std::min(until, leg.stop.until);
    }
    if (!(stop.until > x.t) && !first) break;
    Simulator sim(m, params, own);
    if (!first) x = carried(all, sim, m);
    Run r = sim.run(x, stop);
    const bool reached = next >= 0 && (r.stopped || (!stop.when && r.end.t == stop.until && stop.until < until));
    append(all, std::move(r), first);
    if (!reached) break;
    // the switch: the effects that start or stop acting at state `next`
    std::ostringstream note;
    note.precision(8);
    note << "t = " << all.end.t << " s: state '" << m.states[static_cast<std::size_t>(next)].name << "' reached:";
    for (auto& e : m.effects)
      if (acts_after(e, cur) != acts_after(e, next)) note << " effect '" << e.name << "' switched " << (acts_after(e, next) ? "on" : "off") << ";";
    std::string line = note.str();
    line.pop_back();
    all.log.push_back(line);
    all.stopped = false;
    x.t = all.end.t;
    x.q = all.end.q;
    x.qd = all.end.qd;
    cur = next;
  }
  return all;
}

}  // namespace kinergy::simulate
