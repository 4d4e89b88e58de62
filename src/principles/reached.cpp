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

void check_reached(const Model& m, const model::Analysis& a, const EnergyBalance& bal, const exmap& values) {
  // the constraints that hold from S1 to S2 fix every coordinate but one
  const auto cs = m.constraints_between(a.from, a.to);
  const std::size_t n = m.coords.size();
  if (n == 0 || cs.size() + 1 != n) return;
  const auto &S1 = m.states[a.from], &S2 = m.states[a.to];
  if (numerics::tracing()) note_way(m, a, bal, cs.empty());
  auto at = [&](const ex& e) -> std::optional<double> {
    try {
      ex v = e.subs(values).subs(values).evalf();
      if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) return ex_to<numeric>(v).to_double();
    } catch (const std::exception&) {
    }
    return std::nullopt;
  };
  std::vector<double> q1(n), q2(n);
  for (std::size_t i = 0; i < n; ++i) {
    auto x1 = at(S1.sym.at(m.coords[i].name).first), x2 = at(S2.sym.at(m.coords[i].name).first);
    if (!x1 || !x2 || !std::isfinite(*x1) || !std::isfinite(*x2)) return;
    q1[i] = *x1;
    q2[i] = *x2;
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
    return;
  }
  if (!only_coordinates(m, K) || !only_coordinates(m, scale)) return;
  // the path coordinate: the one that changes most between the states, relative to its size
  std::size_t p = 0;
  double best = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = std::fabs(q2[i] - q1[i]) / std::max({std::fabs(q1[i]), std::fabs(q2[i]), 1e-300});
    if (d > best) best = d, p = i;
  }
  if (!(q2[p] != q1[p])) return;
  // doubles must resolve the path's points: past 2^40 a step of the samples is lost to rounding
  // (an angle of 1e300 deg has no meaningful sine in doubles): not decided here
  if (std::max(std::fabs(q1[p]), std::fabs(q2[p])) > 0x1p40) return;
  // one tape: K, its scale, the constraints and their Jacobian in the other coordinates
  std::vector<ex> outs = {K, scale}, inputs;
  for (auto& c : m.coords) inputs.push_back(c.q);
  for (auto& [c, pos] : cs) outs.push_back(c.subs(values).subs(values));
  for (auto& [c, pos] : cs)
    for (std::size_t j = 0; j < n; ++j)
      if (j != p) outs.push_back(c.diff(m.coords[j].q).subs(values).subs(values));
  std::optional<numerics::Tape> tape;
  try {
    tape = numerics::Tape::compile(outs, inputs);
  } catch (const std::exception&) {
    return;  // a form the tape does not take (a held integral): not checked
  }
  const std::size_t nc = cs.size();
  std::vector<double> out(outs.size()), q = q1;
  // sample the path: s from q1[p] to q2[p]; the other coordinates by Newton's method on the
  // constraints from the previous point (continuation)
  const int N = kSamples;
  double prev = q1[p];
  for (int i = 1; i < N; ++i) {
    const double s = q1[p] + (q2[p] - q1[p]) * i / N;
    q[p] = s;
    bool converged = nc == 0;
    for (int it = 0; it < 30 && !converged; ++it) {
      tape->eval(q.data(), out.data());
      Eigen::VectorXd r(static_cast<long>(nc));
      Eigen::MatrixXd J(static_cast<long>(nc), static_cast<long>(n - 1));
      for (std::size_t k = 0; k < nc; ++k) {
        r(static_cast<long>(k)) = out[2 + k];
        for (std::size_t j = 0; j + 1 < n; ++j) J(static_cast<long>(k), static_cast<long>(j)) = out[2 + nc + k * (n - 1) + j];
      }
      if (!r.allFinite() || !J.allFinite()) return;  // the path leaves where the constraints are defined: not checked
      Eigen::VectorXd dq = J.fullPivLu().solve(-r);
      if (!dq.allFinite()) return;
      double size = 0, step = 0;
      for (std::size_t j = 0, k = 0; j < n; ++j) {
        if (j == p) continue;
        q[j] += dq(static_cast<long>(k++));
        size = std::max(size, std::fabs(q[j]));
        step = std::max(step, std::fabs(dq(static_cast<long>(k - 1))));
      }
      converged = step <= 1e-13 * std::max(size, 1.0);
    }
    if (!converged) return;  // the mechanism locks, or a branch point: not decided here
    tape->eval(q.data(), out.data());
    const double k = out[0], sc = out[1];
    if (!std::isfinite(k) || !std::isfinite(sc)) return;
    // negative against the size of the energies involved (no absolute floor)
    if (k < -1e-9 * sc) {
      const std::string name = m.coords[p].name, unit = units::si_name(m.coords[p].dim).empty() ? "rad" : units::si_name(m.coords[p].dim);
      throw SceneError(a.pos, "state '" + S2.name + "' is not reached from state '" + S1.name + "': on the way, at " + name + " = " + shown(s) + " " +
                                  unit + ", the kinetic energy would be " + shown(k) + " (SI units), negative, so the motion turns back " +
                                  (i == 1 ? "at once (from " + name + "@" + S1.name + " = " + shown(q1[p]) + " " + unit + " it goes the other way)"
                                          : "between " + name + " = " + shown(prev) + " and " + shown(s) + " " + unit),
                       "check the states: the motion from state '" + S1.name + "' cannot get to state '" + S2.name +
                           "' (a root on the side the motion goes, more energy at the start, or the state it does reach)");
    }
    prev = s;
  }
}

}  // namespace kinergy::principles
