// An effect is its loads (issue 26): every principle derives what it needs from the loads an
// effect declares, so they must agree with one another and with the motion itself. Over every
// effect kind, in every derivation it appears in (and tests/data/loads/every_load.yaml, which
// holds the kinds no derivation has: dampers, a torsion damper between two bodies, a one-sided
// spring, friction between two bodies):
//   - at random states (q, q̇, t): the power P = Σ Q_i q̇_i; a potential's force −∂V/∂q_i is its
//     loads' generalized force; the equations of motion carry, for the effect, exactly Q;
//   - along each analysis simulated as a leg (from its first state until its second is
//     reached): the work between the two states, as the energy principle takes it (−ΔV, or the
//     effect's work between the simulated states), equals ∫P dt along the run; the simulator's
//     own work of a non-conservative effect (from its equation-of-motion term) equals it too;
//     and the impulse over the duration (∫F dt, as a momentum analysis takes it) equals ∫F dt
//     on the run.
// ∫ along the run: the trapezoid rule over 40000 regular samples.
#include <catch2/catch.hpp>

#include <cmath>
#include <iomanip>
#include <map>
#include <random>
#include <set>

#include "../support/helpers.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/tape.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/simulate/equations.hpp"

namespace fs = std::filesystem;
namespace sim = kinergy::simulate;
using GiNaC::ex;
using kinergy::model::Effect;
using kinergy::model::Model;

namespace {

std::vector<std::string> scenes() {
  auto all = kt::scene_files("derivations");
  all.push_back(std::string(KINERGY_SOURCE_DIR) + "/tests/data/loads/every_load.yaml");
  return all;
}

/// The value of e at a point (nothing where it is undefined or not a real number).
std::optional<double> value_at(const ex& e, const GiNaC::exmap& at) {
  try {
    ex v = e.subs(at).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nullopt;
    double d = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
    if (!std::isfinite(d)) return std::nullopt;
    return d;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// a agrees with b, relative to `scale` (the size of the terms they are made of).
bool agree(double a, double b, double scale, double rel) { return std::fabs(a - b) <= rel * (scale + 1e-300) + 1e-300; }

/// The size of the terms e is made of at a point (a sum: the sum of its terms' sizes), against
/// which a difference is judged: a component that rounds to 3e-18 where its terms are 1 is zero.
double magnitude(const ex& e, const GiNaC::exmap& at) {
  if (GiNaC::is_a<GiNaC::add>(e)) {
    double s = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) s += magnitude(e.op(i), at);
    return s;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    double s = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) s *= magnitude(e.op(i), at);
    return s;
  }
  if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)))
    return std::pow(magnitude(e.op(0), at), GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_double());
  if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1 && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs")
    return magnitude(e.op(0), at);
  auto v = value_at(e, at);
  return v ? std::fabs(*v) : 0;
}

/// An effect that does something to the bodies (a support or an impact party has no loads).
bool has_loads(const Model& m, const Effect& e) { return !e.loads(m).empty(); }

}  // namespace

TEST_CASE("every effect's power is Σ Q q̇, its potential's force is its loads', its equation-of-motion term is Q (random states)",
          "[effects][loads]") {
  std::set<std::string> kinds;
  int points = 0;
  for (const auto& f : scenes()) {
    kinergy::Solution s = kinergy::solve_file(f);
    const Model& m = s.model;
    const sim::Equations eq = sim::equations_of_motion(m);
    std::mt19937 rng(2026);
    std::uniform_real_distribution<double> u(-1, 1);
    const GiNaC::exmap env = m.numeric_environment();
    for (std::size_t k = 0; k < m.effects.size(); ++k) {
      const Effect& e = m.effects[k];
      if (!has_loads(m, e)) continue;
      INFO(fs::path(f).filename().string() << ": effect " << e.name << " (" << e.kind << ")");
      const std::size_t n = m.coords.size();
      std::vector<ex> Q, loadQ(n, 0);
      for (std::size_t i = 0; i < n; ++i) Q.push_back(e.generalized_force(m, i));
      for (auto& l : e.loads(m))
        for (std::size_t i = 0; i < n; ++i) loadQ[i] += kinergy::model::generalized_force(m, l, i);
      const ex P = e.power(m);
      // the equation-of-motion term of this effect, as generalized forces
      std::vector<ex> eomQ(n, 0);
      for (auto& t : eq.forces)
        if (t.effect == static_cast<int>(k))
          for (std::size_t i = 0; i < n; ++i) eomQ[i] += t.Q[i];
      for (auto& t : eq.friction) {
        if (t.effect != static_cast<int>(k)) continue;
        // sliding: Q_i = −limit (v·∂v/∂q̇_i)/|v|; turning: −limit sgn(ω) ∂ω/∂q̇_i
        if (t.rotary)
          for (std::size_t i = 0; i < n; ++i) eomQ[i] += -t.limit * t.x.v / abs(t.x.v) * t.x.J[i];
        else
          for (std::size_t i = 0; i < n; ++i)
            eomQ[i] += -t.limit * (t.x.v * t.x.J[i] + t.y.v * t.y.J[i]) / sqrt(t.x.v * t.x.v + t.y.v * t.y.v);
      }
      int here = 0;
      for (int trial = 0; trial < 40 && here < 8; ++trial) {
        GiNaC::exmap at = env;
        for (auto& c : m.coords) {
          at[c.q] = u(rng) * 1.5;
          at[c.qd] = u(rng) * 2;
        }
        at[m.t] = (u(rng) + 1) * 2;
        auto p = value_at(P, at);
        if (!p) continue;
        double sum = 0, scale = magnitude(P, at);
        bool ok = true;
        std::vector<double> q(n), lq(n), mq(n);
        for (std::size_t i = 0; i < n && ok; ++i) {
          auto qi = value_at(Q[i], at), li = value_at(loadQ[i], at), ei = value_at(eomQ[i], at);
          auto qdi = value_at(m.coords[i].qd, at);
          ok = qi && li && ei && qdi;
          if (!ok) break;
          q[i] = *qi, lq[i] = *li, mq[i] = *ei;
          sum += *qi * *qdi;
          scale += magnitude(Q[i] * m.coords[i].qd, at);
        }
        if (!ok) continue;
        ++here;
        // P = Σ Q_i q̇_i
        CHECK(agree(*p, sum, scale, 1e-9));
        for (std::size_t i = 0; i < n; ++i) {
          const double s_i = magnitude(Q[i], at) + magnitude(loadQ[i], at) + magnitude(eomQ[i], at);
          INFO("along " << m.coords[i].name << ": Q = " << q[i] << ", from the loads " << lq[i] << ", in the equations of motion " << mq[i]);
          CHECK(agree(q[i], lq[i], s_i, 1e-9));  // −∂V/∂q_i where there is a potential
          CHECK(agree(q[i], mq[i], s_i, 1e-9));
        }
      }
      if (here > 0) kinds.insert(e.kind);
      points += here;
    }
  }
  // every kind that puts loads on bodies
  for (const char* k : {"gravity", "spring", "torsion_spring", "damper", "torsion_damper", "couple", "force", "friction",
                        "friction_couple", "power", "cord_pull"}) {
    INFO(k);
    CHECK(kinds.count(k) == 1);
  }
  CHECK(points > 500);
}

namespace {

/// What a compiled integrand takes: q, q̇, t.
std::vector<ex> inputs_of(const Model& m) {
  std::vector<ex> inputs;
  for (auto& c : m.coords) inputs.push_back(c.q);
  for (auto& c : m.coords) inputs.push_back(c.qd);
  inputs.push_back(m.t);
  return inputs;
}

/// ∫ f dt over a run's samples (the trapezoid rule), f compiled over (q, q̇, t).
double along(const sim::Run& r, const kinergy::numerics::Tape& f, std::size_t n) {
  double total = 0, last = 0, t0 = 0;
  std::vector<double> x(2 * n + 1);
  bool first = true;
  for (const auto& smp : r.samples) {
    for (std::size_t i = 0; i < n; ++i) x[i] = smp.q[i], x[n + i] = smp.qd[i];
    x[2 * n] = smp.t;
    const double v = f(x.data());
    if (!first) total += (smp.t - t0) * (v + last) / 2;
    first = false;
    last = v, t0 = smp.t;
  }
  return total;
}

}  // namespace

TEST_CASE("the work between two states is ∫P dt along a simulated leg, the impulse over it ∫F dt", "[effects][loads]") {
  std::set<std::string> worked, pushed;
  int works = 0, impulses = 0;
  for (const auto& f : scenes()) {
    kinergy::Solution s = kinergy::solve_file(f);
    const Model& m = s.model;
    const GiNaC::exmap values = sim::simulation_values(s);
    const std::size_t n = m.coords.size();
    const std::vector<ex> inputs = inputs_of(m);
    for (auto& leg : sim::legs(s)) {
      const auto& an = m.analyses[static_cast<std::size_t>(leg.analysis)];
      if (!leg.why_not.empty() || an.instant()) continue;
      INFO(fs::path(f).filename().string() << ": " << an.kind << " " << m.states[leg.from].name << " -> " << m.states[leg.to].name);
      sim::Options o;
      o.tol = 1e-11;
      o.native = false;
      o.effects_on.assign(m.effects.size(), true);
      for (std::size_t k = 0; k < m.effects.size(); ++k) o.effects_on[k] = m.effects[k].activity(an) != Effect::Activity::None;
      // the span of the leg, then the same run sampled at 4000 regular times
      sim::Simulator probe(m, values, o);
      sim::Run first = probe.run(leg.start, leg.stop);
      if (!first.impacts.empty() || first.end.t <= leg.start.t) continue;
      o.sample_dt = (first.end.t - leg.start.t) / 40000;
      sim::Simulator simulator(m, values, o);
      sim::Stop stop = leg.stop;
      stop.until = first.end.t + (first.end.t - leg.start.t) * 1e-6;  // its own end ends it first
      sim::Run r = simulator.run(leg.start, stop);
      if (!r.impacts.empty() || r.samples.size() < 100) continue;
      // the state symbols of the two states at the run's start and end
      GiNaC::exmap at = values;
      kinergy::principles::Knowledge know(m);
      auto bind = [&](int state, const std::vector<double>& q, const std::vector<double>& qd, double t) {
        for (std::size_t i = 0; i < n; ++i) {
          auto [qs, qds] = m.states[state].sym.at(m.coords[i].name);
          at[qs] = kinergy::numerics::exact(q[i]);
          at[qds] = kinergy::numerics::exact(qd[i]);
          know.set(qs, GiNaC::ex_to<GiNaC::numeric>(at[qs]));
          know.set(qds, GiNaC::ex_to<GiNaC::numeric>(at[qds]));
        }
        at[m.states[state].t] = kinergy::numerics::exact(t);
        know.set(m.states[state].t, GiNaC::ex_to<GiNaC::numeric>(at[m.states[state].t]));
      };
      bind(leg.from, r.samples.front().q, r.samples.front().qd, r.samples.front().t);
      bind(leg.to, r.end.q, r.end.qd, r.end.t);
      for (std::size_t k = 0; k < m.effects.size(); ++k) {
        const Effect& e = m.effects[k];
        if (!has_loads(m, e) || e.activity(an) != Effect::Activity::Whole) continue;
        INFO("effect " << e.name << " (" << e.kind << ")");
        // ∫P dt along the run, and ∫|P| dt for its scale
        const ex P = e.power(m).subs(values);
        auto tape = kinergy::numerics::Tape::compile(P, inputs);
        auto abs_tape = kinergy::numerics::Tape::compile(abs(P), inputs);
        const double U_run = along(r, tape, n), scale = along(r, abs_tape, n);
        if (!(scale > 0) || !std::isfinite(U_run)) continue;
        // as the energy principle takes it: −ΔV, or the effect's work between the two states
        std::optional<double> U;
        if (e.conservative()) {
          U = value_at(-(m.bind(e.potential(m), leg.to) - m.bind(e.potential(m), leg.from)), at);
        } else {
          // its own work in the simulation (from its equation-of-motion term's power)
          for (auto& [name, w] : r.work)
            if (name == e.name) {
              INFO("the simulator's " << w << ", along the run " << U_run << " (scale " << scale << ")");
              CHECK(agree(w, U_run, scale, 1e-6));
            }
          try {
            U = value_at(kinergy::principles::work(m, e, leg.from, leg.to, know).U, at);
          } catch (const kinergy::SceneError&) {
            // it depends on the path (several degrees of freedom) or the speeds (a damper)
          }
        }
        if (U) {
          INFO(std::setprecision(12) << "principle: " << *U << ", along the run: " << U_run << " (scale " << scale << ")");
          CHECK(agree(*U, U_run, scale, 1e-6));
          worked.insert(e.kind);
          ++works;
        }
        // the impulse over the duration, where the analysis' set has a body it acts on
        std::pair<ex, ex> J;
        try {
          J = kinergy::principles::load_impulse(m, e, leg.analysis);
        } catch (const std::exception&) {
          continue;  // its force changes with the motion: no impulse of its own
        }
        ex Fx = 0, Fy = 0;
        for (auto& l : e.loads(m)) {
          const bool on = l.at.body >= 0 && kinergy::principles::in_set(an.bodies, l.at.body);
          const bool pon = l.partner && l.partner->body >= 0 && kinergy::principles::in_set(an.bodies, l.partner->body);
          if (on == pon || l.kind != kinergy::model::Load::Kind::Given) continue;
          Fx += (on ? 1 : -1) * l.Fx;
          Fy += (on ? 1 : -1) * l.Fy;
        }
        auto jx = value_at(J.first, at), jy = value_at(J.second, at);
        if (!jx || !jy || (Fx.is_zero() && Fy.is_zero())) continue;
        auto fx = kinergy::numerics::Tape::compile(Fx.subs(values), inputs), fy = kinergy::numerics::Tape::compile(Fy.subs(values), inputs);
        const double Ix = along(r, fx, n), Iy = along(r, fy, n), Js = std::fabs(Ix) + std::fabs(Iy);
        INFO("impulse: (" << *jx << ", " << *jy << "), along the run: (" << Ix << ", " << Iy << ")");
        CHECK(agree(*jx, Ix, Js, 1e-6));
        CHECK(agree(*jy, Iy, Js, 1e-6));
        pushed.insert(e.kind);
        ++impulses;
      }
    }
  }
  // every kind along one run of tests/data/loads/every_load.yaml (no analyses: 1 s from state 1)
  {
    kinergy::Solution s = kinergy::solve_file(std::string(KINERGY_SOURCE_DIR) + "/tests/data/loads/every_load.yaml");
    const Model& m = s.model;
    const GiNaC::exmap values = sim::simulation_values(s);
    const std::size_t n = m.coords.size();
    const std::vector<ex> inputs = inputs_of(m);
    sim::Options o;
    o.tol = 1e-11;
    o.native = false;
    o.sample_dt = 1.0 / 40000;
    sim::Simulator simulator(m, values, o);
    sim::Stop stop;
    stop.until = 1;
    sim::Run r = simulator.run(sim::state_values(s, 0), stop);
    REQUIRE(r.impacts.empty());
    for (std::size_t k = 0; k < m.effects.size(); ++k) {
      const Effect& e = m.effects[k];
      INFO("every_load.yaml: effect " << e.name << " (" << e.kind << ")");
      const ex P = e.power(m).subs(values);
      const double U_run = along(r, kinergy::numerics::Tape::compile(P, inputs), n);
      const double scale = along(r, kinergy::numerics::Tape::compile(abs(P), inputs), n);
      REQUIRE(scale > 0);
      if (e.conservative()) {
        // −ΔV from the run's ends
        GiNaC::exmap a = values, b = values;
        for (std::size_t i = 0; i < n; ++i) {
          a[m.coords[i].q] = kinergy::numerics::exact(r.samples.front().q[i]);
          b[m.coords[i].q] = kinergy::numerics::exact(r.end.q[i]);
        }
        a[m.t] = 0;
        b[m.t] = kinergy::numerics::exact(r.end.t);
        auto Va = value_at(e.potential(m), a), Vb = value_at(e.potential(m), b);
        REQUIRE((Va && Vb));
        CHECK(agree(*Va - *Vb, U_run, scale, 1e-6));
      } else {
        bool found = false;
        for (auto& [name, w] : r.work)
          if (name == e.name) {
            INFO("the simulator's " << w << ", along the run " << U_run);
            CHECK(agree(w, U_run, scale, 1e-6));
            found = true;
          }
        CHECK(found);
      }
    }
  }
  INFO("work checked for " << worked.size() << " kinds, impulses for " << pushed.size());
  for (const char* k : {"gravity", "spring", "torsion_spring", "couple", "force", "friction", "friction_couple", "cord_pull"}) {
    INFO(k);
    CHECK(worked.count(k) == 1);
  }
  for (const char* k : {"gravity", "force"}) {
    INFO(k);
    CHECK(pushed.count(k) == 1);
  }
  CHECK(works >= 90);
  CHECK(impulses > 20);
}
