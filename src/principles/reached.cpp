// Does the motion get from an energy analysis' first state to its second? The energy equation
// between the two states alone cannot tell: released at 45° a linkage that must pass 90° (where
// its kinetic energy would be negative) falls the other way, yet T₂ from T₁ + V₁ + U = T₂ + V₂
// is positive at 153°.
#include <Eigen/Dense>
#include <cmath>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/tape.hpp"
#include "kinergy/numeric/trace.hpp"
#include "kinergy/principles/principles.hpp"

namespace kinergy::principles {

using namespace GiNaC;
using model::Model;

namespace {

std::string shown(double v) { return numerics::format(numerics::exact(v), 6); }

bool only_coordinates(const Model& m, const ex& e) {
  exmap zero;
  for (auto& c : m.coords) zero[c.q] = 0;
  // every symbol left must be a coordinate: what stays after they are set to 0 is a number
  ex z;
  try {
    z = e.subs(zero).evalf();
  } catch (const std::exception&) {
    return true;  // undefined at 0: decided by the tape at the path's points
  }
  return is_a<numeric>(z);
}

/// Points the path is sampled at, ends excluded: q₁ + (q₂ − q₁) i/N, 0 < i < N.
constexpr int kSamples = 256;

/// For a sweep (numeric/trace.hpp): with one coordinate and no constraint, the check below passes
/// wherever K(q) = T₁ + V₁ + U₁→q − V(q) ≥ 0 for q over its samples (the forms of the states put in).
void note_way(const Model& m, const model::Analysis& a, const EnergyBalance& bal, bool unconstrained) {
  if (m.coords.size() != 1 || !unconstrained) {
    numerics::note_untraced("the kinetic energy along a way that constraints bend");
    return;
  }
  const auto &S1 = m.states[a.from], &S2 = m.states[a.to];
  const ex q = m.coords[0].q, s1 = S1.sym.at(m.coords[0].name).first, s2 = S2.sym.at(m.coords[0].name).first;
  try {
    // (the samples run from the first step past q₁ to the last before q₂)
    numerics::note_path((bal.equation.lhs - bal.at_to.V).subs(s2 == q), q, s1 + (s2 - s1) / kSamples, s1 + (s2 - s1) * (kSamples - 1) / kSamples);
  } catch (const std::exception&) {
    numerics::note_untraced("the kinetic energy along the way");
  }
}

}  // namespace

namespace {

/// The way of an energy analysis with one degree of freedom between its states: the path
/// coordinate s (the one that changes most, relative to its size) from s₁ to s₂, the others
/// following by Newton's method on the constraints (continuation from the previous point), and
/// the kinetic energy K along it, all from one tape in doubles.
class Way {
public:
  /// Nothing where the way cannot be followed in doubles (no one degree of freedom, a form the
  /// tape does not take, a coordinate beyond 2^40, the states' places not numbers).
  static std::optional<Way> of(const Model& m, const model::Analysis& a, const EnergyBalance& bal, const exmap& values) {
    Way w(m, values);
    // the constraints that hold from S1 to S2 fix every coordinate but one
    const auto cs = m.constraints_between(a.from, a.to);
    w.n = m.coords.size();
    w.nc = cs.size();
    if (w.n == 0 || w.nc + 1 != w.n) return std::nullopt;
    // an effect switched on or off at a state inside the analysis does its work over part of the
    // way only (Q (x − x@2) from the state it is switched on at): the equation with state 2's
    // positions moved to q does not say the energy there — not decided here (the simulation that
    // confirms the analysis follows the switch)
    for (auto& e : m.effects)
      if (e.activity(a) == model::Effect::Activity::Part) return std::nullopt;
    const auto &S1 = m.states[a.from], &S2 = m.states[a.to];
    if (numerics::tracing()) note_way(m, a, bal, cs.empty());
    w.q1.resize(w.n);
    w.q2.resize(w.n);
    for (std::size_t i = 0; i < w.n; ++i) {
      auto x1 = w.at(S1.sym.at(m.coords[i].name).first), x2 = w.at(S2.sym.at(m.coords[i].name).first);
      if (!x1 || !x2 || !std::isfinite(*x1) || !std::isfinite(*x2)) return std::nullopt;
      w.q1[i] = *x1;
      w.q2[i] = *x2;
    }
    // K(q) = T₁ + V₁ + U₁→q − V(q): the energy equation with S2's positions at q (its own rates
    // and time do not enter the left side; a work that needs them, or a held integral, is skipped)
    exmap to_generic;
    for (auto& c : m.coords) to_generic[S2.sym.at(c.name).first] = c.q;
    ex K, scale;
    try {
      K = (bal.equation.lhs - bal.at_to.V).subs(to_generic).subs(values).subs(values);
      scale = (abs(bal.equation.lhs) + abs(bal.at_to.V)).subs(to_generic).subs(values).subs(values);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (!only_coordinates(m, K) || !only_coordinates(m, scale)) return std::nullopt;
    double best = -1;
    for (std::size_t i = 0; i < w.n; ++i) {
      const double d = std::fabs(w.q2[i] - w.q1[i]) / std::max({std::fabs(w.q1[i]), std::fabs(w.q2[i]), 1e-300});
      if (d > best) best = d, w.p = i;
    }
    if (!(w.q2[w.p] != w.q1[w.p])) return std::nullopt;
    // doubles must resolve the path's points: past 2^40 a step of the samples is lost to rounding
    // (an angle of 1e300 deg has no meaningful sine in doubles): not decided here
    if (std::max(std::fabs(w.q1[w.p]), std::fabs(w.q2[w.p])) > 0x1p40) return std::nullopt;
    // one tape: K, its scale, the constraints and their Jacobian in the other coordinates, then
    // their derivative along the path coordinate
    std::vector<ex> outs = {K, scale};
    for (auto& c : m.coords) w.inputs.push_back(c.q);
    for (auto& [c, pos] : cs) outs.push_back(c.subs(values).subs(values));
    for (auto& [c, pos] : cs)
      for (std::size_t j = 0; j < w.n; ++j)
        if (j != w.p) outs.push_back(c.diff(m.coords[j].q).subs(values).subs(values));
    for (auto& [c, pos] : cs) outs.push_back(c.diff(m.coords[w.p].q).subs(values).subs(values));
    try {
      w.tape = numerics::Tape::compile(outs, w.inputs);
    } catch (const std::exception&) {
      return std::nullopt;  // a form the tape does not take (a held integral): not checked
    }
    w.out.resize(outs.size());
    return w;
  }

  /// The other coordinates at s (qs holds a nearby point, and is moved there); out() then holds
  /// K, its scale, the constraints and their derivatives there. False where Newton's method does
  /// not converge (the mechanism locks, a branch point) or the constraints are undefined.
  bool place(double s, std::vector<double>& qs) {
    qs[p] = s;
    bool converged = nc == 0;
    for (int it = 0; it < 30 && !converged; ++it) {
      tape->eval(qs.data(), out.data());
      Eigen::VectorXd r(static_cast<long>(nc));
      Eigen::MatrixXd J = jacobian();
      for (std::size_t k = 0; k < nc; ++k) r(static_cast<long>(k)) = out[2 + k];
      if (!r.allFinite() || !J.allFinite()) return false;
      Eigen::VectorXd dq = J.fullPivLu().solve(-r);
      if (!dq.allFinite()) return false;
      double size = 0, step = 0;
      for (std::size_t j = 0, k = 0; j < n; ++j) {
        if (j == p) continue;
        qs[j] += dq(static_cast<long>(k++));
        size = std::max(size, std::fabs(qs[j]));
        step = std::max(step, std::fabs(dq(static_cast<long>(k - 1))));
      }
      converged = step <= 1e-13 * std::max(size, 1.0);
    }
    if (converged) tape->eval(qs.data(), out.data());
    return converged;
  }

  /// The tangent t of the way at the last place (t_p = 1; the constraints' rates A t = 0 give
  /// the others: A_rest t_rest = −A_p). Nothing where A_rest is singular.
  std::optional<Eigen::VectorXd> tangent() const {
    Eigen::VectorXd t = Eigen::VectorXd::Zero(static_cast<long>(n));
    t(static_cast<long>(p)) = 1;
    if (nc == 0) return t;
    Eigen::VectorXd Ap(static_cast<long>(nc));
    for (std::size_t r = 0; r < nc; ++r) Ap(static_cast<long>(r)) = out[2 + nc + nc * (n - 1) + r];
    Eigen::VectorXd rest = jacobian().fullPivLu().solve(-Ap);
    if (!rest.allFinite()) return std::nullopt;
    for (std::size_t j = 0, r = 0; j < n; ++j)
      if (j != p) t(static_cast<long>(j)) = rest(static_cast<long>(r++));
    return t;
  }

  double K() const { return out[0]; }
  double scale() const { return out[1]; }

  const Model& m;
  const exmap& values;
  std::size_t n = 0, nc = 0, p = 0;
  std::vector<double> q1, q2;
  std::vector<ex> inputs;  ///< the coordinates, in order

private:
  Way(const Model& mm, const exmap& v) : m(mm), values(v) {}
  std::optional<double> at(const ex& e) const {
    try {
      ex v = e.subs(values).subs(values).evalf();
      if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) return ex_to<numeric>(v).to_double();
    } catch (const std::exception&) {
    }
    return std::nullopt;
  }
  Eigen::MatrixXd jacobian() const {
    Eigen::MatrixXd J(static_cast<long>(nc), static_cast<long>(n - 1));
    for (std::size_t k = 0; k < nc; ++k)
      for (std::size_t j = 0; j + 1 < n; ++j) J(static_cast<long>(k), static_cast<long>(j)) = out[2 + nc + k * (n - 1) + j];
    return J;
  }
  std::optional<numerics::Tape> tape;
  std::vector<double> out;
};

/// One sample of the way: s and every coordinate there.
using Samples = std::vector<std::pair<double, std::vector<double>>>;

/// Surfaces that only push (PushAlong): N ≥ 0 along the way's samples. At each the rates follow
/// from K: q̇ = t ṗ along the tangent, T = ½ ṗ² tᵀ M t = K, so ṗ = σ √(2K / tᵀ M t), σ the way
/// the motion goes (toward state 2); N(q, q̇) in closed form (Newton–Euler, support_forces).
/// Where N turns negative, the place the body leaves is bisected. @throws SceneError naming it.
void check_pushes(Way& w, const model::Analysis& a, const std::vector<PushAlong>& pushes, const Samples& way) {
  const Model& m = w.m;
  const std::size_t n = w.n;
  std::vector<ex> outs, inputs = w.inputs;
  for (auto& c : m.coords) inputs.push_back(c.qd);
  for (auto& push : pushes) {
    const ex N = push.N.subs(w.values).subs(w.values);
    if (N.has(m.t)) return;  // a push that depends on time: the simulation follows it
    outs.push_back(N);
  }
  const GiNaC::matrix M = m.mass_matrix();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) outs.push_back(M(i, j).subs(w.values).subs(w.values));
  std::optional<numerics::Tape> forces;
  try {
    forces = numerics::Tape::compile(outs, inputs);
  } catch (const std::exception&) {
    return;  // a form the tape does not take: the simulation follows it
  }
  const double sigma = w.q2[w.p] > w.q1[w.p] ? 1 : -1;
  std::vector<double> fout(outs.size()), x(2 * n);
  // each push's N at s (the others placed from qs); nothing where it cannot be had
  auto pushes_at = [&](double s, std::vector<double>& qs) -> std::optional<std::vector<double>> {
    if (!w.place(s, qs)) return std::nullopt;
    auto t = w.tangent();
    if (!t) return std::nullopt;
    for (std::size_t i = 0; i < n; ++i) x[i] = qs[i], x[n + i] = 0;
    forces->eval(x.data(), fout.data());
    double tMt = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) tMt += (*t)(static_cast<long>(i)) * fout[pushes.size() + i * n + j] * (*t)(static_cast<long>(j));
    if (!(tMt > 0)) return std::nullopt;
    const double pd = sigma * std::sqrt(2 * std::max(w.K(), 0.0) / tMt);
    for (std::size_t i = 0; i < n; ++i) x[n + i] = (*t)(static_cast<long>(i)) * pd;
    forces->eval(x.data(), fout.data());
    std::vector<double> Ns(fout.begin(), fout.begin() + static_cast<long>(pushes.size()));
    for (double v : Ns)
      if (!std::isfinite(v)) return std::nullopt;
    return Ns;
  };
  std::vector<std::vector<double>> Ns;
  double size = 0;
  for (auto& [s, qw] : way) {
    std::vector<double> qs = qw;
    auto v = pushes_at(s, qs);
    if (!v) return;  // not followed here: the simulation follows it
    for (double x0 : *v) size = std::max(size, std::fabs(x0));
    Ns.push_back(*v);
  }
  // (one that pulls already at the start lets go at once: the check at that state says so)
  std::vector<double> q0 = w.q1;
  const auto at_start = pushes_at(w.q1[w.p], q0);
  for (std::size_t i = 0; i < way.size(); ++i)
    for (std::size_t k = 0; k < pushes.size(); ++k) {
      if (!(Ns[i][k] < -1e-9 * size) || (at_start && (*at_start)[k] < -1e-9 * size)) continue;
      // the release lies between the sample before (or the start) and this one: bisected
      double lo = i ? way[i - 1].first : w.q1[w.p], hi = way[i].first;
      std::vector<double> ql = i ? way[i - 1].second : w.q1;
      for (int it = 0; it < 200 && std::fabs(hi - lo) > 1e-13 * std::max(std::fabs(lo), 1.0); ++it) {
        const double mid = 0.5 * (lo + hi);
        std::vector<double> qm = ql;
        auto v = pushes_at(mid, qm);
        if (!v) break;
        if ((*v)[k] < 0) hi = mid;
        else lo = mid, ql = qm;
      }
      const PushAlong& push = pushes[k];
      const auto &S1 = m.states[a.from], &S2 = m.states[a.to];
      const std::string name = m.coords[w.p].name, unit = units::si_name(m.coords[w.p].dim).empty() ? "rad" : units::si_name(m.coords[w.p].dim);
      const double where = 0.5 * (lo + hi);
      const std::string deg = unit == "rad" ? " (" + numerics::g_text(where * 180 / M_PI, 6) + " deg)" : "";
      const model::OneWay ow = model::one_way(push.pulls, push.body, push.effect);
      throw SceneError(push.pos, ow.lets_go + " at " + name + " = " + numerics::g_text(where, 6) + " " + unit + deg + ", before state '" + S2.name +
                                     "': there its " + ow.force + " falls to zero, and " + ow.only + ", so the motion the " + a.kind + " analysis from state '" +
                                     S1.name + "' takes (" + (push.pulls ? "the cord taut" : "on the surface") + " up to state '" + S2.name + "') does not happen",
                       "ask for the state where it " + ow.verb + ", " + ow.ask + ", or take state '" + S2.name + "' before it");
    }
}

}  // namespace

void check_reached(const Model& m, const model::Analysis& a, const EnergyBalance& bal, const exmap& values, const std::vector<PushAlong>& pushes) {
  auto way = Way::of(m, a, bal, values);
  if (!way) return;
  Way& w = *way;
  const auto &S1 = m.states[a.from], &S2 = m.states[a.to];
  const std::size_t p = w.p;
  // sample the path: s from q1 to q2, each point's K against the size of the energies involved
  // (no absolute floor)
  const int N = kSamples;
  double prev = w.q1[p];
  std::vector<double> q = w.q1;
  Samples samples;
  for (int i = 1; i < N; ++i) {
    const double s = w.q1[p] + (w.q2[p] - w.q1[p]) * i / N;
    if (!w.place(s, q)) return;  // the mechanism locks, or a branch point: not decided here
    const double k = w.K(), sc = w.scale();
    if (!std::isfinite(k) || !std::isfinite(sc)) return;
    if (k < -1e-9 * sc) {
      const std::string name = m.coords[p].name, unit = units::si_name(m.coords[p].dim).empty() ? "rad" : units::si_name(m.coords[p].dim);
      throw SceneError(a.pos, "state '" + S2.name + "' is not reached from state '" + S1.name + "': on the way, at " + name + " = " + shown(s) + " " +
                                  unit + ", the kinetic energy would be " + shown(k) + " (SI units), negative, so the motion turns back " +
                                  (i == 1 ? "at once (from " + name + "@" + S1.name + " = " + shown(w.q1[p]) + " " + unit + " it goes the other way)"
                                          : "between " + name + " = " + shown(prev) + " and " + shown(s) + " " + unit),
                       "check the states: the motion from state '" + S1.name + "' cannot get to state '" + S2.name +
                           "' (a root on the side the motion goes, more energy at the start, or the state it does reach)");
    }
    samples.emplace_back(s, q);
    prev = s;
  }
  if (!pushes.empty()) check_pushes(w, a, pushes, samples);
}

}  // namespace kinergy::principles
