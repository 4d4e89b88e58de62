// Every answer confirmed a second way before it is printed (see confirm.hpp).
#include "kinergy/confirm/confirm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "kinergy/common/error.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/principles/kinetics.hpp"
#include "kinergy/print/plain.hpp"
#include "kinergy/units/units.hpp"

namespace kinergy {

using namespace GiNaC;

namespace {

/// The largest relative residual of the scene's equations at the chosen solution, at 50 digits:
/// |lhs − rhs| / (|lhs| + |rhs|); its equation's label in `which`. Equations whose value cannot be
/// had there (a parameter without a value) are left out; nothing when none is left.
std::optional<double> residuals(const Solution& s, std::string& which) {
  const exmap given = s.model.given_values(), env = s.model.numeric_environment();
  std::optional<double> worst;
  for (auto& e : s.equations) {
    std::optional<numeric> r, scale;
    try {
      const ex lhs = e.lhs.subs(given).subs(s.branch.sol).subs(given), rhs = e.rhs.subs(given).subs(s.branch.sol).subs(given);
      r = numerics::evaluate(lhs - rhs, env, 50);
      // against the size of the terms (a sum of terms that cancel exactly is 0 of its terms' size)
      auto terms = [](const ex& x) {
        if (!is_a<add>(x)) return ex(abs(x));
        ex sum = 0;
        for (std::size_t i = 0; i < x.nops(); ++i) sum += abs(x.op(i));
        return sum;
      };
      scale = numerics::evaluate(terms(lhs) + terms(rhs), env, 50);
    } catch (const std::exception&) {
      continue;
    }
    if (!r || !scale || !r->is_real()) continue;
    const double rel = scale->is_zero() ? abs(*r).to_double() : (abs(*r) / *scale).to_double();
    if (!worst || rel > *worst) {
      worst = rel;
      which = e.label;
    }
  }
  return worst;
}

}  // namespace

bool no_second_opinion(const model::Analysis& a, const simulate::LegCheck& c) {
  return !c.ok && c.outcome == simulate::LegCheck::Outcome::NotReached && a.type->impulsive();
}

std::string Confirmed::name(By b) {
  switch (b) {
    case By::Simulation: return "simulation";
    case By::Residuals: return "residuals";
    case By::EquationsOfMotion: return "equations of motion";
    case By::Shared: return "shared solution";
    case By::None: break;
  }
  return "";
}

KineticsCheck check_kinetics(const Solution& s, int ai) {
  const model::Model& m = s.model;
  const model::Analysis& a = m.analyses[static_cast<std::size_t>(ai)];
  const auto* kb = s.balance<principles::KineticsBalance>(static_cast<std::size_t>(ai));
  if (!kb) throw std::logic_error("check_kinetics: analysis " + std::to_string(ai) + " is not kinetics at a state");
  const exmap given = m.given_values(), env = m.numeric_environment();
  const std::string at = "the kinetics at state '" + m.states[static_cast<std::size_t>(a.from)].name + "'";
  auto number = [&](const ex& e, int digits) { return numerics::evaluate(e.subs(given).subs(s.branch.sol).subs(given), env, digits); };
  // the state: its positions and rates as solved
  const std::size_t n = m.coords.size();
  simulate::Options o;
  o.native = false;  // the tape: no compiler run for a check
  o.rolling_limits = false;  // the accelerations at the state (its static friction is checked on the solution)
  simulate::Simulator sim(m, parameter_values(s), o);
  std::vector<double> y(sim.size(), 0.0), dy(sim.size(), 0.0);
  const model::State& S = m.states[static_cast<std::size_t>(a.from)];
  auto t = number(S.t, 30);
  for (std::size_t i = 0; i < n; ++i) {
    auto q = number(S.sym.at(m.coords[i].name).first, 30), qd = number(S.sym.at(m.coords[i].name).second, 30);
    if (!q || !qd) throw SceneError(a.pos, at + ": state '" + S.name + "' does not fix " + m.coords[i].name, "give its position and rate there");
    y[i] = q->to_double();
    y[n + i] = qd->to_double();
  }
  sim.modes_at(y.data(), t ? t->to_double() : 0.0);  // (contacts resting and friction slipping as at the state)
  sim.rhs(y.data(), t ? t->to_double() : 0.0, dy.data());
  // q̈ by Newton–Euler against the equations of motion, relative to the accelerations' size (or
  // q̇² where they vanish: a pendulum at its lowest point)
  KineticsCheck c;
  double scale = 0;
  std::vector<double> ne(n);
  for (std::size_t i = 0; i < n; ++i) {
    auto v = number(m.bind(m.coords[i].qdd, a.from), 30);
    if (!v || !v->is_real()) throw SceneError(a.pos, at + ": " + m.coords[i].name + "_ddot has no value at the solution", "report the scene");
    ne[i] = v->to_double();
    scale = std::max({scale, std::fabs(ne[i]), std::fabs(dy[n + i]), y[n + i] * y[n + i]});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double d = scale > 0 ? std::fabs(ne[i] - dy[n + i]) / scale : 0;
    if (d > c.worst || !std::isfinite(d)) {
      c.worst = d;
      std::ostringstream os;
      os.precision(10);
      os << m.coords[i].name << "_ddot@" << S.name << ": Newton-Euler " << ne[i] << ", the equations of motion " << dy[n + i];
      c.what = os.str();
    }
  }
  c.ok = c.worst <= kConfirmSimulation;
  // the equations it did not solve hold at the solution: against their own size, or, where both
  // sides vanish there (a reaction of zero, a body at rest), against the size of the system's
  // terms — 50 digits leave noise of 1e-50 of it, which is not a residual
  double system = 0;
  for (auto& r : kb->rows)
    if (auto size = number(abs(r.equation.lhs) + abs(r.equation.rhs), 50)) system = std::max(system, size->to_double());
  for (auto& r : kb->rows) {
    if (r.used || !c.ok) continue;
    auto v = number(r.equation.lhs - r.equation.rhs, 50), size = number(abs(r.equation.lhs) + abs(r.equation.rhs), 50);
    if (!v || !size) continue;
    if (abs(*v).to_double() <= 1e-30 * system) continue;
    const double rel = size->is_zero() ? abs(*v).to_double() : (abs(*v) / *size).to_double();
    if (rel > kConfirmResidual) {
      c.ok = false;
      c.worst = rel;
      c.what = "the " + r.equation.label + " does not hold at the solution (off by " + numerics::g_text(rel, 3) + " of its size)";
    }
  }
  return c;
}

namespace {

/// Where the static friction a rolling contact needs changes along analysis c.analysis, its states
/// alone do not settle it: the simulated motion must have confirmed it. @throws SceneError when not.
void friction_along(const Solution& s, const Confirmed& c, const std::string& between) {
  if (c.by == Confirmed::By::Simulation || std::find(s.friction_along.begin(), s.friction_along.end(), c.analysis) == s.friction_along.end()) return;
  throw SceneError(s.model.analyses[static_cast<std::size_t>(c.analysis)].pos,
                   between + " takes a contact with mu_s as rolling, and the friction it needs changes along the motion; its states "
                             "are checked, but the way between them only by simulating it, which did not confirm it here (" + c.note + ")",
                   "give every parameter a value so that the motion can be simulated, or leave 'mu_s' out and check the friction at "
                   "states with kinetics analyses");
}

/// Leg `leg` simulated and compared (simulate::check_leg): once more at 1e-13 where the first
/// run differs — a difference may be the integration's (a motion of 1e-11 rad/s among rates of
/// 1), and where doubles cannot tell more (a rate of 6e-6 rad/s from positions of 1.57 rad, near
/// a turning point) it stays put at that level: accepted up to kConfirmFloor, and said so.
/// Nothing where the simulator cannot run the scene (a drive from rest, a singular mass matrix, a
/// stiff spring beyond the steps allowed: no second opinion, not a disagreement; c.note says
/// why). @throws SceneError where the simulated motion breaks what the analysis takes for
/// granted: a body leaves a surface that only pushes, a rolling contact slips.
std::optional<simulate::LegCheck> simulated(const Solution& s, const simulate::Leg& leg, const simulate::Options& o, const simulate::Options& fine,
                                            const std::string& between, Confirmed& c) {
  const model::Model& m = s.model;
  const model::Analysis& a = m.analyses[static_cast<std::size_t>(leg.analysis)];
  const std::string S2 = m.states[static_cast<std::size_t>(a.to)].name;
  std::optional<simulate::LegCheck> run;
  try {
    run = simulate::check_leg(s, leg, o, kConfirmSimulation);
    if (!run->ok && std::isfinite(run->worst)) {
      try {
        auto again = simulate::check_leg(s, leg, fine, kConfirmSimulation);
        if (again.ok || again.worst < run->worst) run = again;
      } catch (const std::exception&) {
        // more steps than allowed at 1e-13: the first run stands
      }
      if (!run->ok && run->worst <= kConfirmFloor && run->outcome != simulate::LegCheck::Outcome::NotReached) {
        run->ok = true;
        run->note = (run->note.empty() ? "" : run->note + "; ") + "integrated at 1e-13, the difference stays at the double's limit for this motion";
      }
    }
  } catch (const simulate::ReleaseError& err) {  // a body leaves a surface the analysis keeps it on
    throw SceneError(err.pos(), between + " " + err.keeps() + ", but in the simulated motion it " + err.verb() + " before state '" + S2 + "': " + err.what(),
                     "ask for the state where it " + err.verb() + ", " + err.ask() + ", or take state '" + S2 + "' before it");
  } catch (const simulate::SlipError& err) {  // a contact the analysis takes as rolling slips on the way
    throw SceneError(err.pos(), between + " takes the contact as rolling, but the simulated motion slips: " + err.what(), err.fix());
  } catch (const std::exception& err) {
    c.note = std::string("not simulated: ") + err.what();
  }
  return run;
}

/// Every analysis of a scene whose parameters all have numbers (or, without, by residuals).
void confirm_numeric(Solution& s) {
  s.confirmed.clear();
  const model::Model& m = s.model;
  simulate::Options o;
  o.tol = 1e-10;
  o.native = false;  // the tape: no compiler run for a confirmation
  o.record = true;  // the rates' scale is the largest seen on the way (a rest at both ends)
  o.max_steps = 50'000;  // a stiff scene is confirmed by its residuals, not by minutes of simulation
  simulate::Options fine = o;  // a difference at 1e-10 is looked at again at 1e-13
  fine.tol = 1e-13;
  fine.max_steps = 200'000;
  std::optional<std::optional<double>> residual;  // taken once, when some analysis needs it
  std::string residual_of;
  for (const simulate::Leg& leg : simulate::legs(s)) {
    const model::Analysis& a = m.analyses[static_cast<std::size_t>(leg.analysis)];
    const std::string between = "the " + a.kind + " analysis from state '" + m.states[static_cast<std::size_t>(a.from)].name + "' to '" +
                                m.states[static_cast<std::size_t>(a.to)].name + "'";
    Confirmed c;
    c.analysis = leg.analysis;
    bool placed = true;  // the state's positions and rates are known (a kinetics analysis needs no leg)
    for (std::size_t i = 0; i < leg.start.q.size(); ++i) placed = placed && std::isfinite(leg.start.q[i]) && std::isfinite(leg.start.qd[i]);
    if (s.balance<principles::KineticsBalance>(static_cast<std::size_t>(leg.analysis)) && placed) {
      // kinetics at a state: its accelerations against the equations of motion there
      std::optional<KineticsCheck> k;
      try {
        k = check_kinetics(s, leg.analysis);
      } catch (const SceneError&) {
        throw;
      } catch (const std::exception& err) {
        c.note = std::string("not checked against the equations of motion: ") + err.what();
      }
      if (k && !k->ok)
        throw SceneError(a.pos, "the kinetics at state '" + m.states[static_cast<std::size_t>(a.from)].name +
                                    "' is not confirmed by the equations of motion there: " + k->what + " (relative difference " + numerics::g_text(k->worst, 3) +
                                    ", more than " + numerics::g_text(kConfirmSimulation, 3) + ")",
                         "check the supports the scene declares against the coordinates; '--no-confirm' prints the closed form without this check");
      if (k) {
        c.by = Confirmed::By::EquationsOfMotion;
        c.difference = std::max(k->worst, 1e-16);
        c.tolerance = kConfirmSimulation;
        c.note = "the simulator's accelerations at the state, and the equations not solved checked at 50 digits";
      }
    } else if (!leg.why_not.empty()) {
      c.note = "not simulated: " + leg.why_not;
    } else {
      std::optional<simulate::LegCheck> run = simulated(s, leg, o, fine, between, c);
      if (run && run->ok) {
        c.by = Confirmed::By::Simulation;
        c.difference = run->worst;
        c.tolerance = kConfirmSimulation;
        c.note = run->note;
      } else if (run && run->outcome == simulate::LegCheck::Outcome::NothingToCompare) {
        c.note = "not simulated: " + run->worst_what;
      } else if (run && no_second_opinion(a, *run)) {
        c.unreached = true;
        // over a duration the scene's effects alone may not take the motion there (balls drawn in
        // by a mechanism the scene leaves out, under a conservation claim): no value to compare,
        // not a disagreement. (An energy analysis has every effect that works in it: a state its
        // motion does not reach is a disagreement, below.)
        c.note = "not confirmed by simulation: " + run->worst_what + ", with the effects the scene lists";
      } else if (run) {
        // a disagreement is an error that shows both numbers, never an answer; where the run met
        // an impact the analysis does not have, say so (an energy analysis across a bounce)
        std::string struck;
        if (!a.instant())
          for (auto& im : run->run.impacts)
            for (auto& name : im.contacts)
              if (struck.find("'" + name + "'") == std::string::npos) struck += (struck.empty() ? "" : ", ") + ("'" + name + "'");
        throw SceneError(a.pos, between + " is not confirmed by a simulation of the same scene: " + run->worst_what +
                                    " (relative difference " + numerics::g_text(run->worst, 3) + ", more than " + numerics::g_text(kConfirmSimulation, 3) + ")" +
                                    (run->note.empty() ? "" : "; " + run->note) +
                                    (struck.empty() ? "" : "; on the way the simulation strikes at " + struck +
                                                               ", an impact this analysis does not have (split it there with an impact analysis)"),
                         "check the scene's states and effects against the problem (the simulation runs exactly what the scene says); "
                         "'--no-confirm' prints the closed form without this check");
      }
    }
    friction_along(s, c, between);
    if (c.by == Confirmed::By::None) {
      if (!residual) residual = residuals(s, residual_of);
      if (*residual && **residual > kConfirmResidual)
        throw SceneError(a.pos, between + ": the equations do not hold at the solution found: the " + residual_of + " is off by " +
                                    numerics::g_text(**residual, 3) + " of its size at 50 digits",
                         "report the scene: the solution is not confirmed ('--no-confirm' prints it anyway)");
      if (*residual) {
        c.by = Confirmed::By::Residuals;
        // below 1e-30 a residual at 50 digits is the rounding of its terms, whose order (and so
        // the last digits) GiNaC may pick differently from run to run: said as 1e-30
        c.difference = std::max(**residual, 1e-30);
        c.tolerance = kConfirmResidual;
      }
    }
    s.confirmed.push_back(c);
  }
}


/// The parameters without a value (not solved for): the sampled ones (the simulation needs each
/// that the scene uses, a mass that cancels from the results too).
std::vector<std::size_t> free_parameters(const model::Model& m) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < m.params.size(); ++i)
    if (m.params[i].without_value() && !m.params[i].ranged) out.push_back(i);
  return out;
}

/// Does a result or a condition of s hold parameter p? (One that none holds — a length that only
/// places the drawing, a mass that cancels — is sampled for the simulation, but the closed forms
/// are not said to be confirmed at values of it.)
bool in_closed_forms(const Solution& s, const model::Parameter& p) {
  return std::any_of(s.results.begin(), s.results.end(), [&](const Result& r) { return r.closed.has(p.sym); }) ||
         std::any_of(s.valid_where.begin(), s.valid_where.end(), [&](const principles::Condition& c) { return c.e.has(p.sym); });
}

/// The closed forms of `at` (its parameters given a sample) against the scene solved with those
/// numbers: each result to 1e-12 relative. @throws SceneError at the result that differs, with
/// both numbers.
void same_values(const Solution& at, const Solution& n, const std::string& shown) {
  const exmap env = at.model.numeric_environment(), nenv = n.model.numeric_environment();
  for (std::size_t i = 0; i < at.results.size() && i < n.results.size(); ++i) {
    const Result& r = at.results[i];
    std::optional<numeric> a, b;
    try {
      a = r.value(env, 15);
      b = n.results[i].value(nenv, 15);
    } catch (const std::exception&) {
    }
    if (!a || !b) continue;
    const numeric x = *a, y = *b;  // (both in the display unit the scene asks)
    const numeric scale = std::max(abs(x), abs(y));
    if (scale.is_zero() || abs(x - y) <= numeric(1, 1000000000000LL) * scale) continue;
    throw SceneError(r.pos, "'" + r.name + "' = " + emit::plain(r.closed) + " is " + numerics::format(x, 10) + " at the sampled values " + shown +
                                ", but the scene solved with those numbers gives " + numerics::format(y, 10) +
                                ": the closed form does not hold for every value of its parameters",
                     "report the scene; give the parameters values, or state the root with 'root:'");
  }
}

}  // namespace

void confirm(Solution& s) {
  const std::vector<std::size_t> free = free_parameters(s.model);
  if (free.empty()) return confirm_numeric(s);
  // Closed forms in parameters without values: at sampled values of those parameters (kSamples
  // of them, from a fixed sequence of candidates), the scene is solved as written with those
  // numbers, its values compared with the closed forms there, and confirmed as a numeric scene
  // is. A candidate where the solution's conditions fail, or where the scene with those numbers
  // has no solution (a user's root the motion does not take, a body that does not get there), is
  // passed over: outside the domain the closed forms hold in. Where no candidate is left, the
  // closed forms are refused (confirmed nowhere).
  std::vector<Solution> done;
  std::vector<std::string> values;  // each sample's values, as text
  std::string skipped;  // why the first candidate passed over was
  int passed_over = 0;
  // a sample at which every analysis is confirmed by simulation (or the equations of motion) is
  // taken before one where some analysis has only its residuals (a run beyond the steps allowed
  // at those values): weak ones fill up only after kSampleCandidates / 16 candidates
  std::vector<Solution> weak;
  std::vector<std::string> weak_values;
  auto full = [](const Solution& n) {
    return std::all_of(n.confirmed.begin(), n.confirmed.end(),
                       [](const Confirmed& c) { return c.by == Confirmed::By::Simulation || c.by == Confirmed::By::EquationsOfMotion; });
  };
  int solves = 0;
  for (int k = 0; k < kSampleCandidates && solves < kSampleSolves && static_cast<int>(done.size()) < kSamples &&
                  !(static_cast<int>(done.size() + weak.size()) >= kSamples && k >= kSampleCandidates / 16);
       ++k) {
    Solution at = s;  // the closed forms, their parameters given the sample
    scene::SceneDef def = s.scene;  // the scene as written, with those numbers
    std::string shown;
    for (std::size_t i : free) {
      model::Parameter& p = at.model.params[i];
      const numeric v = model::Model::sample_value(p, 1, k);  // (stream 1: not the solve's choices')
      p.value = v;
      const std::string unit = p.angle ? "rad" : units::si_name(p.dim), text = numerics::format(v, model::Model::sample_digits(v)) + (unit.empty() ? "" : " " + unit);
      shown += (shown.empty() ? "" : ", ") + p.name + " = " + text;
      for (auto& d : def.parameters)
        if (d.name == p.name) d.value.s = text;
    }
    std::string why;
    std::optional<Solution> n;
    if (admissible(at, why)) {
      ++solves;
      try {
        n = solve_scene(def);
      } catch (const SceneError& err) {
        why = err.problem();
      }
    }
    if (!n) {
      if (skipped.empty()) skipped = why + " (at " + shown + ")";
      ++passed_over;
      continue;
    }
    same_values(at, *n, shown);
    try {
      confirm_numeric(*n);
    } catch (const SceneError& err) {
      throw SceneError(err.pos(), err.problem() + " (at the sampled values " + shown + ")", err.fix());
    }
    // a momentum analysis whose end the scene's effects do not take the motion to at these
    // values (cords that would pull the balls in, sampled with the end further out): outside
    // the domain too
    if (auto c = std::find_if(n->confirmed.begin(), n->confirmed.end(), [](const Confirmed& x) { return x.unreached; }); c != n->confirmed.end()) {
      if (skipped.empty()) skipped = c->note.substr(std::string("not confirmed by simulation: ").size()) + " (at " + shown + ")";
      ++passed_over;
      continue;
    }
    if (full(*n)) {
      done.push_back(std::move(*n));
      values.push_back(shown);
    } else {
      weak.push_back(std::move(*n));
      weak_values.push_back(shown);
    }
  }
  for (std::size_t i = 0; i < weak.size() && static_cast<int>(done.size()) < kSamples; ++i) {
    done.push_back(std::move(weak[i]));
    values.push_back(weak_values[i]);
  }
  // no sample inside the domain the closed forms hold in: they are confirmed nowhere (the
  // model's own sample, where the solve made its choices, lies outside it too), so not printed
  if (done.empty()) {
    std::string names;
    for (std::size_t i : free) names += (names.empty() ? "" : ", ") + s.model.params[i].name;
    throw SceneError(s.model.analyses.front().pos,
                     "the closed forms are confirmed nowhere: at none of the " + std::to_string(passed_over) + " sampled values of " + names +
                         " does the scene have a solution that meets their conditions (first: " + skipped + ")",
                     "give the parameters the range the problem means, e.g. 'theta0: {value: deg, in: [100 deg, 170 deg]}' "
                     "(an angle is otherwise sampled in [0.2, 1.4] rad), or give them values");
  }
  // each analysis: the weakest way any sample confirmed it (simulation, the equations of motion,
  // residuals), its largest difference
  std::string names;
  for (std::size_t i : free)
    if (in_closed_forms(s, s.model.params[i])) names += (names.empty() ? "" : ", ") + s.model.params[i].name;
  s.confirmed.clear();
  for (std::size_t j = 0; j < done.front().confirmed.size(); ++j) {
    Confirmed c = done.front().confirmed[j];
    for (auto& at : done) {
      const Confirmed& o = at.confirmed[j];
      auto rank = [](Confirmed::By b) { return b == Confirmed::By::None ? 0 : b == Confirmed::By::Residuals ? 1 : 2; };
      if (rank(o.by) < rank(c.by)) c = o;
      else if (o.by == c.by) c.difference = std::max(c.difference, o.difference);
    }
    c.sampled = names;
    if (!names.empty()) c.samples = values;  // (none that the closed forms hold: as a numeric scene's)
    // the static friction a rolling contact needs along the way: at those values only
    if (std::find(s.friction_along.begin(), s.friction_along.end(), c.analysis) != s.friction_along.end())
      c.note = (c.note.empty() ? "" : c.note + "; ") + "the static friction of the rolling along the way holds at these values; at others it is not checked";
    // the candidates passed over tell where the closed forms do not hold
    if (passed_over > 0)
      c.note = (c.note.empty() ? "" : c.note + "; ") + "passed over " + std::to_string(passed_over) + " sampled value" + (passed_over > 1 ? "s" : "") +
               " where the scene has no solution, first: " + skipped;
    s.confirmed.push_back(c);
  }
}

}  // namespace kinergy
