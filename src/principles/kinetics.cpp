// Newton's second law at a state: the accelerations and the supports' forces at an instant, from
// the loads the effects declare and the reactions the supports declare (src/model/loads.cpp).
#include "kinergy/principles/kinetics.hpp"

#include <cmath>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"

namespace kinergy::principles {

using namespace GiNaC;
using model::Model;
using model::Reaction;

namespace {

/// Does effect e act at state s? @throws SceneError when it switches there (its force jumps).
bool acts_at(const Model& m, const model::Effect& e, const model::Analysis& a) {
  const int s = a.from;
  const auto at = e.at_state(s);
  if (at == model::Effect::AtState::Switches)
    throw SceneError(a.pos, "effect '" + e.name + "' switches " + (e.on == s ? "on" : "off") + " at state '" + m.states[s].name +
                                "', so its force jumps there and the accelerations at that instant are not one value",
                     "take the kinetics at a state just before or after it");
  return at == model::Effect::AtState::Acts;
}

/// Does the reaction act on a body of the set?
bool touches(const Reaction& r, const std::vector<int>& set) {
  for (int b : r.bodies())
    if (std::find(set.begin(), set.end(), b) != set.end()) return true;
  return false;
}

bool is_body(const model::PointRef& p) { return p.body >= 0 && !p.ground; }

/// The generic unknowns: q̈, the reactions of the supports on the set (a constraint effect's
/// always: its force enters Lagrange's equations), the multipliers of the constraints no effect holds.
std::vector<ex> generic_unknowns(const Model& m, const model::Analysis& a) {
  std::vector<ex> u;
  for (auto& c : m.coords) u.push_back(c.qdd);
  for (auto& e : m.effects) {
    auto r = e.reaction(m);
    if (!r || !acts_at(m, e, a)) continue;
    if (r->kind == Reaction::Kind::Relation || touches(*r, a.bodies))
      if (auto it = m.instant_reactions.find(e.name); it != m.instant_reactions.end()) u.insert(u.end(), it->second.begin(), it->second.end());
  }
  for (std::size_t k = 0; k < m.constraints.size(); ++k)
    if (!m.carrier(k) && m.constraint_at(k, a.from, true)) u.push_back(m.instant_lambdas[k]);
  return u;
}

/// Every force and couple on the bodies (generic): the effects' loads (a load's partner takes
/// −F, −M: Newton's third law) and the supports' reactions.
std::vector<BodyLoad> body_loads(const Model& m, const model::Analysis& a) {
  std::vector<BodyLoad> out;
  auto put = [&](const std::string& name, const model::PointRef& p, const ex& Fx, const ex& Fy, const ex& M, bool unknown) {
    if (!is_body(p)) return;
    auto [x, y] = m.position(p);
    out.push_back({name, p.body, x, y, Fx, Fy, M, unknown});
  };
  for (auto& e : m.effects) {
    if (!acts_at(m, e, a)) continue;
    for (const model::Load& l : e.loads(m)) {
      const model::Wrench f = model::force_of(m, l);
      put(e.name, l.at, f.Fx, f.Fy, f.M, false);
      if (l.partner) put(e.name, *l.partner, -f.Fx, -f.Fy, -f.M, false);
    }
    auto r = e.reaction(m);
    auto it = m.instant_reactions.find(e.name);
    if (!r || it == m.instant_reactions.end()) continue;
    const auto& u = it->second;
    switch (r->kind) {
      case Reaction::Kind::Pin: {
        // R = (Rx, Ry) on its first party that is a body (what a textbook asks: the pin's force on
        // the bar), −R on the other
        const bool a_first = is_body(r->a);
        put(e.name, a_first ? r->a : r->b, u[0], u[1], 0, true);
        put(e.name, a_first ? r->b : r->a, -u[0], -u[1], 0, true);
        break;
      }
      case Reaction::Kind::Track:  // N n̂ on party a
        put(e.name, r->a, u[0] * r->dir_x, u[0] * r->dir_y, 0, true);
        break;
      case Reaction::Kind::Relation:  // F û on party a, −F û on party b
        put(e.name, r->a, u[0] * r->dir_x, u[0] * r->dir_y, 0, true);
        put(e.name, r->b, -u[0] * r->dir_x, -u[0] * r->dir_y, 0, true);
        break;
      case Reaction::Kind::Contact: break;  // impacts only
    }
  }
  return out;
}

/// The rows, generic: Lagrange's equation along each coordinate, c̈ = 0 for each constraint, and
/// Newton–Euler for each body of the set.
/// Every body's accelerations (generic): ā = d/dt of its mass centre's velocity, α = dω/dt.
std::vector<BodyAcceleration> accelerations(const Model& m) {
  std::vector<BodyAcceleration> out;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const model::Body& B = m.bodies[b];
    out.push_back({static_cast<int>(b), m.d_dt(m.rate(B.x)), m.d_dt(m.rate(B.y)), m.d_dt(m.rate(B.angle))});
  }
  return out;
}

std::vector<KineticsBalance::Row> generic_rows(const Model& m, const model::Analysis& a, const std::vector<BodyLoad>& loads,
                                                const std::vector<BodyAcceleration>& acc) {
  using Kind = KineticsBalance::Row::Kind;
  std::vector<KineticsBalance::Row> rows;
  const std::string S = m.states[a.from].name;
  auto row = [&](Kind kind, int body, int coord, const ex& lhs, const ex& rhs, const std::string& label) {
    rows.push_back({kind, body, coord, {model::trig_simplify(lhs), model::trig_simplify(rhs), "kinetics", label + " at state " + S, a.pos}, false});
  };
  // along each coordinate q_i (the supports that the coordinates hold do no virtual work):
  //   Σ_b m_b a_G·∂r_G/∂q_i + Ī_b α_b ∂φ_b/∂q_i = Σ loads Q_i + Σ relations F û·(∂r_a − ∂r_b)/∂q_i + Σ λ_k ∂c_k/∂q_i
  for (std::size_t i = 0; i < m.coords.size(); ++i) {
    const symbol& q = m.coords[i].q;
    ex lhs = 0, rhs = 0;
    for (auto& g : acc) {
      const model::Body& b = m.bodies[static_cast<std::size_t>(g.body)];
      lhs += b.mass * (g.ax * b.x.diff(q) + g.ay * b.y.diff(q)) + b.inertia * g.alpha * b.angle.diff(q);
    }
    for (auto& e : m.effects) {
      if (!acts_at(m, e, a)) continue;
      for (const model::Load& l : e.loads(m)) rhs += model::generalized_force(m, l, i);
      auto r = e.reaction(m);
      if (!r || r->kind != Reaction::Kind::Relation) continue;
      auto [dax, day] = m.position_derivative(r->a, q);
      auto [dbx, dby] = m.position_derivative(r->b, q);
      rhs += m.instant_reactions.at(e.name)[0] * (r->dir_x * (dax - dbx) + r->dir_y * (day - dby));
    }
    for (std::size_t k = 0; k < m.constraints.size(); ++k)
      if (!m.carrier(k) && m.constraint_at(k, a.from, true)) rhs += m.instant_lambdas[k] * m.constraints[k].first.diff(q);
    row(Kind::Motion, -1, static_cast<int>(i), lhs, rhs, "equation of motion along " + m.coords[i].name);
  }
  // each constraint held at the state keeps holding: c̈ = 0
  for (std::size_t k = 0; k < m.constraints.size(); ++k)
    if (m.constraint_at(k, a.from, true))
      row(Kind::Constraint, -1, static_cast<int>(k), m.d_dt(m.rate(m.constraints[k].first)), 0,
          "second rate of constraint " + std::to_string(k + 1));
  // each body of the set: ΣF = m a_G, ΣM_G = Ī α
  for (int bi : a.bodies) {
    const model::Body& b = m.bodies[static_cast<std::size_t>(bi)];
    ex Fx = 0, Fy = 0, MG = 0;
    for (auto& l : loads) {
      if (l.body != bi) continue;
      Fx += l.Fx;
      Fy += l.Fy;
      // M_G = (r − r_G) × F + M
      MG += (l.x - b.x) * l.Fy - (l.y - b.y) * l.Fx + l.M;
    }
    const BodyAcceleration& g = acc[static_cast<std::size_t>(bi)];
    row(Kind::ForceX, bi, -1, b.mass * g.ax, Fx, "Newton's second law for " + b.name + " along x");
    row(Kind::ForceY, bi, -1, b.mass * g.ay, Fy, "Newton's second law for " + b.name + " along y");
    // (a particle's forces all act at its centre: 0 = 0, not written; a light body's moments
    // balance, 0 = ΣM_G)
    const ex lhs = b.inertia * g.alpha;
    if (!lhs.is_zero() || !model::trig_simplify(MG).is_zero()) row(Kind::Moment, bi, -1, lhs, MG, "moments about the mass centre of " + b.name);
  }
  return rows;
}

/// A number at the sample point: the state's values, then the parameters' (GiNaC's substitution
/// is one pass: a state value written in parameters needs the second). NaN where it has none.
double number(const ex& e, const exmap& state, const exmap& env) {
  ex v = e.subs(state).subs(env).evalf();
  if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) return std::nan("");
  return ex_to<numeric>(v).to_double();
}

/// Solve the n×n system A u = b in place by Gaussian elimination with partial pivoting.
std::vector<double> solve_dense(std::vector<std::vector<double>> A, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::fabs(A[r][c]) > std::fabs(A[p][c])) p = r;
    std::swap(A[c], A[p]);
    std::swap(b[c], b[p]);
    for (std::size_t r = c + 1; r < n; ++r) {
      double f = A[r][c] / A[c][c];
      for (std::size_t k = c; k < n; ++k) A[r][k] -= f * A[c][k];
      b[r] -= f * b[c];
    }
  }
  std::vector<double> u(n);
  for (std::size_t c = n; c-- > 0;) {
    double s = b[c];
    for (std::size_t k = c + 1; k < n; ++k) s -= A[c][k] * u[k];
    u[c] = s / A[c][c];
  }
  return u;
}

std::string names_of(const std::vector<ex>& xs) {
  std::string s;
  for (std::size_t i = 0; i < xs.size(); ++i) s += (i ? ", " : "") + model::text(xs[i]);
  return s;
}

}  // namespace

std::vector<ex> kinetics_unknowns(const Model& m, const model::Analysis& a) {
  std::vector<ex> out;
  for (auto& g : generic_unknowns(m, a)) out.push_back(m.bind(g, a.from));
  return out;
}

KineticsBalance kinetics(const Model& m, const model::Analysis& a, const Knowledge&) {
  KineticsBalance out;
  const int S = a.from;
  out.state = S;
  out.unknowns = kinetics_unknowns(m, a);
  std::vector<BodyLoad> loads = body_loads(m, a);
  const std::vector<BodyAcceleration> acc = accelerations(m);
  out.rows = generic_rows(m, a, loads, acc);
  for (int b : a.bodies) {
    const BodyAcceleration& g = acc[static_cast<std::size_t>(b)];
    out.accelerations.push_back({b, m.bind(g.ax, S), m.bind(g.ay, S), m.bind(g.alpha, S)});
  }
  for (auto& r : out.rows) r.equation = {m.bind(r.equation.lhs, S), m.bind(r.equation.rhs, S), r.equation.principle, r.equation.label, r.equation.pos};
  for (auto& l : loads)
    if (std::find(a.bodies.begin(), a.bodies.end(), l.body) != a.bodies.end())
      out.loads.push_back({l.effect, l.body, m.bind(l.x, S), m.bind(l.y, S), m.bind(l.Fx, S), m.bind(l.Fy, S), m.bind(l.M, S), l.unknown});

  // a sample point: the parameters' values, the values given at S, and for every other symbol of
  // the state a fixed sample (the rows are linear in the unknowns: which of them are independent,
  // and whether the others follow, does not depend on where)
  const exmap env = m.numeric_environment();
  exmap at;
  for (auto& [k, v] : m.states[static_cast<std::size_t>(S)].given) at[k] = v;
  int j = 0;
  const model::State& st = m.states[static_cast<std::size_t>(S)];
  for (auto& c : m.coords)
    for (const ex& x : {ex(st.sym.at(c.name).first), ex(st.sym.at(c.name).second)})
      if (!at.count(x)) at[x] = numeric(30 + 17 * (j++), 100);
  if (!at.count(st.t)) at[st.t] = numeric(1, 3);
  exmap env_all = env;
  for (auto& p : m.params)
    if (p.unknown) env_all[p.sym] = numeric(1) + numeric(13 * (++j) % 29, 29);
  exmap zero;
  for (auto& u : out.unknowns) zero[u] = 0;

  // each row r(u) = A u − b: its coefficients at the sample point
  const std::size_t n = out.unknowns.size();
  std::vector<std::vector<double>> A;
  std::vector<double> b;
  for (auto& r : out.rows) {
    ex res = r.equation.lhs - r.equation.rhs;
    std::vector<double> row;
    try {
      for (auto& u : out.unknowns) row.push_back(number(res.diff(ex_to<symbol>(u)), at, env_all));
      b.push_back(-number(res.subs(zero), at, env_all));
    } catch (const std::exception& err) {
      throw SceneError(a.pos, "the kinetics at state '" + m.states[static_cast<std::size_t>(S)].name + "' cannot be taken: the " + r.equation.label +
                                  " is undefined there (" + model::math_fault(err) + ")",
                       "a kinetic friction where nothing slides, or a drive at rest, has no force there: take the kinetics at another state");
    }
    for (double x : row)
      if (!std::isfinite(x))
        throw SceneError(a.pos, "the kinetics at state '" + m.states[static_cast<std::size_t>(S)].name + "' cannot be taken: the " +
                                    r.equation.label + " has no value at the state's values",
                         "give the positions and rates at that state, or take the kinetics at another state");
    A.push_back(row);
  }
  // independent rows, in order (Lagrange's equations and the constraints first): Gram–Schmidt
  std::vector<std::vector<double>> basis;
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < out.rows.size(); ++i) {
    std::vector<double> v = A[i];
    double norm0 = 0;
    for (double x : v) norm0 += x * x;
    if (!(norm0 > 0) || !std::isfinite(norm0)) continue;
    for (auto& e : basis) {
      double d = 0;
      for (std::size_t k = 0; k < n; ++k) d += v[k] * e[k];
      for (std::size_t k = 0; k < n; ++k) v[k] -= d * e[k];
    }
    double norm = 0;
    for (double x : v) norm += x * x;
    if (norm <= 1e-18 * norm0) continue;
    for (double& x : v) x /= std::sqrt(norm);
    basis.push_back(v);
    chosen.push_back(i);
  }
  if (chosen.size() < n) {
    // the unknowns outside the rows' span are what Newton's law leaves open
    std::vector<ex> open;
    for (std::size_t k = 0; k < n; ++k) {
      double in = 0;
      for (auto& e : basis) in += e[k] * e[k];
      if (in < 1 - 1e-9) open.push_back(out.unknowns[k]);
    }
    throw SceneError(a.pos, "Newton's second law at state '" + m.states[S].name + "' does not determine " + names_of(open) +
                                ": the supports on the bodies of this kinetics analysis are more than their motion needs (statically indeterminate)",
                     "remove a support the coordinates make redundant, or leave out of 'bodies' the body it holds");
  }
  std::vector<std::vector<double>> As;
  std::vector<double> bs;
  for (std::size_t i : chosen) {
    As.push_back(A[i]);
    bs.push_back(b[i]);
    out.rows[i].used = true;
  }
  const std::vector<double> u = solve_dense(As, bs);
  // every other row follows from the chosen ones, or a force is missing from it
  for (std::size_t i = 0; i < out.rows.size(); ++i) {
    if (out.rows[i].used) continue;
    double lhs = 0, scale = std::fabs(b[i]);
    for (std::size_t k = 0; k < n; ++k) {
      lhs += A[i][k] * u[k];
      scale = std::max(scale, std::fabs(A[i][k] * u[k]));
    }
    if (!std::isfinite(lhs) || std::fabs(lhs - b[i]) <= 1e-8 * std::max(scale, 1e-300)) continue;
    const auto& r = out.rows[i];
    const std::string who = r.body >= 0 ? m.bodies[static_cast<std::size_t>(r.body)].name : "";
    throw SceneError(a.pos, r.equation.label + " does not hold with the supports the scene declares: a force the scene does not "
                                "declare acts on " + (who.empty() ? std::string("the bodies") : who) +
                                " (its coordinates hold it to a path, or a constraint without an effect acts on it)",
                     "declare that support (a pin, a track, a constraint effect), or leave " + (who.empty() ? std::string("that body") : who) +
                         " out of the kinetics analysis' 'bodies'");
  }
  return out;
}

}  // namespace kinergy::principles
