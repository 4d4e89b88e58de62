// Newton's second law at a state: the accelerations and the supports' forces at an instant, from
// the loads the effects declare and the reactions the supports declare (src/model/loads.cpp).
#include "kinergy/principles/kinetics.hpp"

#include <cmath>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"

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

/// The instant the equations are written for: which effects act and which constraints hold
/// there, the bodies whose Newton–Euler equations are written, and how it is named.
struct Instant {
  std::vector<bool> effect, constraint;
  std::vector<int> bodies;
  std::string where;  ///< " at state 2" (labels of the rows)
  SourcePos pos;
};

/// The instant of kinetics analysis a: its state. @throws SceneError where an effect switches there.
Instant instant_of(const Model& m, const model::Analysis& a) {
  Instant in{{}, {}, a.bodies, " at state " + m.states[static_cast<std::size_t>(a.from)].name, a.pos};
  for (auto& e : m.effects) in.effect.push_back(acts_at(m, e, a));
  for (std::size_t k = 0; k < m.constraints.size(); ++k) in.constraint.push_back(m.constraint_at(k, a.from, true));
  return in;
}

/// Does the reaction act on a body of the set?
bool touches(const Reaction& r, const std::vector<int>& set) {
  for (int b : r.bodies())
    if (std::find(set.begin(), set.end(), b) != set.end()) return true;
  return false;
}

bool is_body(const model::PointRef& p) { return p.body >= 0 && !p.ground; }

/// A contact that has closed after its impact and holds its parties together at this instant.
bool closed(const Reaction& r, const Instant& in) { return !r.holds.empty() && in.constraint[r.holds[0]]; }

/// The generic unknowns: q̈, the reactions of the supports on the set (a constraint effect's
/// always: its force enters Lagrange's equations), the multipliers of the constraints no effect holds.
std::vector<ex> generic_unknowns(const Model& m, const Instant& in) {
  std::vector<ex> u;
  for (auto& c : m.coords) u.push_back(c.qdd);
  for (std::size_t i = 0; i < m.effects.size(); ++i) {
    const model::Effect& e = m.effects[i];
    auto r = e.reaction(m);
    if (!r || !in.effect[i] || (r->kind == Reaction::Kind::Contact && !closed(*r, in))) continue;
    if (r->kind == Reaction::Kind::Relation || touches(*r, in.bodies))
      if (auto it = m.instant_reactions.find(e.name); it != m.instant_reactions.end()) u.insert(u.end(), it->second.begin(), it->second.end());
  }
  for (std::size_t k = 0; k < m.constraints.size(); ++k)
    if (!m.carrier(k) && in.constraint[k]) u.push_back(m.instant_lambdas[k]);
  return u;
}

/// Every force and couple on the bodies (generic): the effects' loads (a load's partner takes
/// −F, −M: Newton's third law) and the supports' reactions.
std::vector<BodyLoad> body_loads(const Model& m, const Instant& in) {
  std::vector<BodyLoad> out;
  auto put = [&](const std::string& name, const model::PointRef& p, const ex& Fx, const ex& Fy, const ex& M, bool unknown,
                 const std::string& symbol = "") {
    if (!is_body(p)) return;
    auto [x, y] = m.position(p);
    out.push_back({name, p.body, x, y, Fx, Fy, M, unknown, symbol});
  };
  for (std::size_t i = 0; i < m.effects.size(); ++i) {
    const model::Effect& e = m.effects[i];
    if (!in.effect[i]) continue;
    for (const model::Load& l : e.loads(m)) {
      const model::Wrench f = model::force_of(m, l);
      put(e.name, l.at, f.Fx, f.Fy, f.M, false, l.symbol);
      if (l.partner) put(e.name, *l.partner, -f.Fx, -f.Fy, -f.M, false, l.symbol);
    }
    auto r = e.reaction(m);
    auto it = m.instant_reactions.find(e.name);
    if (!r || it == m.instant_reactions.end()) continue;
    const auto& u = it->second;
    switch (r->kind) {
      case Reaction::Kind::Pin: {
        // R = (Rx, Ry) on its first party that is a body (what a textbook asks: the pin's force on
        // the bar), −R on the other
        put(e.name, r->first(), u[0], u[1], 0, true);
        put(e.name, r->second(), -u[0], -u[1], 0, true);
        break;
      }
      case Reaction::Kind::Track:  // N n̂ on party a
        put(e.name, r->a, u[0] * r->dir_x, u[0] * r->dir_y, 0, true);
        break;
      case Reaction::Kind::Relation:  // F û on party a, −F û on party b
        put(e.name, r->a, u[0] * r->dir_x, u[0] * r->dir_y, 0, true);
        put(e.name, r->b, -u[0] * r->dir_x, -u[0] * r->dir_y, 0, true);
        break;
      case Reaction::Kind::Contact:  // in impacts; once closed, R = (Rx, Ry) on party b, −R on a
        if (!closed(*r, in)) break;
        put(e.name, r->b, u[0], u[1], 0, true);
        put(e.name, r->a, -u[0], -u[1], 0, true);
        break;
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

std::vector<KineticsBalance::Row> generic_rows(const Model& m, const Instant& in, const std::vector<BodyLoad>& loads,
                                                const std::vector<BodyAcceleration>& acc) {
  using Kind = KineticsBalance::Row::Kind;
  std::vector<KineticsBalance::Row> rows;
  auto row = [&](Kind kind, int body, int coord, const ex& lhs, const ex& rhs, const std::string& label) {
    rows.push_back({kind, body, coord, {model::trig_simplify(lhs), model::trig_simplify(rhs), "kinetics", label + in.where, in.pos}, false});
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
    for (std::size_t j = 0; j < m.effects.size(); ++j) {
      const model::Effect& e = m.effects[j];
      if (!in.effect[j]) continue;
      for (const model::Load& l : e.loads(m)) rhs += model::generalized_force(m, l, i);
      auto r = e.reaction(m);
      // a closed contact: R·δ(r_b − r_a) = Rx δc_x + Ry δc_y
      if (r && r->kind == Reaction::Kind::Contact && closed(*r, in))
        for (std::size_t j = 0; j < 2; ++j) rhs += m.instant_reactions.at(e.name)[j] * m.constraints[r->holds[j]].first.diff(q);
      if (!r || r->kind != Reaction::Kind::Relation) continue;
      auto [dax, day] = m.position_derivative(r->a, q);
      auto [dbx, dby] = m.position_derivative(r->b, q);
      rhs += m.instant_reactions.at(e.name)[0] * (r->dir_x * (dax - dbx) + r->dir_y * (day - dby));
    }
    for (std::size_t k = 0; k < m.constraints.size(); ++k)
      if (!m.carrier(k) && in.constraint[k]) rhs += m.instant_lambdas[k] * m.constraints[k].first.diff(q);
    row(Kind::Motion, -1, static_cast<int>(i), lhs, rhs, "equation of motion along " + m.coords[i].name);
  }
  // each constraint held at the state keeps holding: c̈ = 0
  for (std::size_t k = 0; k < m.constraints.size(); ++k)
    if (in.constraint[k])
      row(Kind::Constraint, -1, static_cast<int>(k), m.d_dt(m.rate(m.constraints[k].first)), 0,
          "second rate of constraint " + std::to_string(k + 1));
  // each body of the set: ΣF = m a_G, ΣM_G = Ī α
  for (int bi : in.bodies) {
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

/// The independent rows, in order (Lagrange's equations and the constraints first), from their
/// coefficients at the sample point `at` (the rows are linear in the unknowns: which of them are
/// independent, and whether the others follow, does not depend on where). `what` names the
/// instant for messages. @throws SceneError where a row is undefined there, where the rows leave
/// an unknown open (statically indeterminate), or where a row does not follow from the chosen ones
/// (a force the scene does not declare).
struct Independent {
  std::vector<std::size_t> chosen;
  std::vector<double> u;  ///< the unknowns at the sample point
};
Independent independent_rows(const Model& m, const std::vector<KineticsBalance::Row>& rows, const std::vector<ex>& unknowns, const exmap& at,
                             const exmap& env_all, const std::string& what, const SourcePos& pos) {
  exmap zero;
  for (auto& u : unknowns) zero[u] = 0;
  // each row r(u) = A u − b: its coefficients at the sample point
  const std::size_t n = unknowns.size();
  std::vector<std::vector<double>> A;
  std::vector<double> b;
  for (auto& r : rows) {
    ex res = r.equation.lhs - r.equation.rhs;
    std::vector<double> row;
    try {
      for (auto& u : unknowns) row.push_back(number(res.diff(ex_to<symbol>(u)), at, env_all));
      b.push_back(-number(res.subs(zero), at, env_all));
    } catch (const std::exception& err) {
      throw SceneError(pos, what + " cannot be taken: the " + r.equation.label + " is undefined there (" + model::math_fault(err) + ")",
                       "a kinetic friction where nothing slides, or a drive at rest, has no force there: take the kinetics at another state");
    }
    for (double x : row)
      if (!std::isfinite(x))
        throw SceneError(pos, what + " cannot be taken: the " + r.equation.label + " has no value at the state's values",
                         "give the positions and rates at that state, or take the kinetics at another state");
    A.push_back(row);
  }
  // independent rows, in order: Gram–Schmidt
  std::vector<std::vector<double>> basis;
  Independent out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
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
    out.chosen.push_back(i);
  }
  if (out.chosen.size() < n) {
    // the unknowns outside the rows' span are what Newton's law leaves open
    std::vector<ex> open;
    for (std::size_t k = 0; k < n; ++k) {
      double in = 0;
      for (auto& e : basis) in += e[k] * e[k];
      if (in < 1 - 1e-9) open.push_back(unknowns[k]);
    }
    throw SceneError(pos, "Newton's second law in " + what + " does not determine " + names_of(open) +
                              ": the supports on the bodies are more than their motion needs (statically indeterminate)",
                     "remove a support the coordinates make redundant, or leave out of 'bodies' the body it holds");
  }
  std::vector<std::vector<double>> As;
  std::vector<double> bs;
  for (std::size_t i : out.chosen) {
    As.push_back(A[i]);
    bs.push_back(b[i]);
  }
  const std::vector<double> u = solve_dense(As, bs);
  out.u = u;
  // every other row follows from the chosen ones, or a force is missing from it
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (std::find(out.chosen.begin(), out.chosen.end(), i) != out.chosen.end()) continue;
    double lhs = 0, scale = std::fabs(b[i]);
    for (std::size_t k = 0; k < n; ++k) {
      lhs += A[i][k] * u[k];
      scale = std::max(scale, std::fabs(A[i][k] * u[k]));
    }
    if (!std::isfinite(lhs) || std::fabs(lhs - b[i]) <= 1e-8 * std::max(scale, 1e-300)) continue;
    const auto& r = rows[i];
    const std::string who = r.body >= 0 ? m.bodies[static_cast<std::size_t>(r.body)].name : "";
    throw SceneError(pos, r.equation.label + " does not hold with the supports the scene declares: a force the scene does not "
                              "declare acts on " + (who.empty() ? std::string("the bodies") : who) +
                              " (its coordinates hold it to a path, or a constraint without an effect acts on it)",
                     "declare that support (a pin, a track, a constraint effect), or leave " + (who.empty() ? std::string("that body") : who) +
                         " out of the kinetics analysis' 'bodies'");
  }
  return out;
}

}  // namespace

std::vector<ex> kinetics_unknowns(const Model& m, const model::Analysis& a) {
  std::vector<ex> out;
  for (auto& g : generic_unknowns(m, instant_of(m, a))) out.push_back(m.bind(g, a.from));
  return out;
}

KineticsBalance kinetics(const Model& m, const model::Analysis& a, const Knowledge&) {
  KineticsBalance out;
  const int S = a.from;
  out.state = S;
  out.unknowns = kinetics_unknowns(m, a);
  const Instant in = instant_of(m, a);
  const std::vector<BodyLoad> loads = body_loads(m, in);
  const std::vector<BodyAcceleration> acc = accelerations(m);
  const std::vector<KineticsBalance::Row> rows = generic_rows(m, in, loads, acc);
  for (int b : a.bodies) {
    const BodyAcceleration& g = acc[static_cast<std::size_t>(b)];
    out.accelerations.push_back({b, m.bind(g.ax, S), m.bind(g.ay, S), m.bind(g.alpha, S)});
  }

  // a sample point: the parameters' values, the values given at S, and for every other symbol of
  // the state a fixed sample (the rows are linear in the unknowns: which of them are independent,
  // and whether the others follow, does not depend on where)
  const exmap env = m.numeric_environment();
  exmap at;
  const model::State& st = m.states[static_cast<std::size_t>(S)];
  for (auto& [k, v] : st.given) at[k] = v;
  int j = 0;
  for (auto& c : m.coords)
    for (const ex& x : {ex(st.sym.at(c.name).first), ex(st.sym.at(c.name).second)})
      if (!at.count(x)) at[x] = numeric(30 + 17 * (j++), 100);
  if (!at.count(st.t)) at[st.t] = numeric(1, 3);
  exmap env_all = env;
  for (auto& p : m.params)
    if (p.unknown) env_all[p.sym] = numeric(1) + numeric(13 * (++j) % 29, 29);
  const std::string what = "the kinetics at state '" + st.name + "'";

  // The rows bound to S, each friction couple at rest there taken with sense σ: its couple
  // −M ω/|ω| is −σ M (|ω| = σ ω).
  auto bound = [&](const exmap& sense) {
    KineticsBalance b = out;
    b.rows = rows;
    for (auto& r : b.rows)
      r.equation = {m.bind(r.equation.lhs.subs(sense), S), m.bind(r.equation.rhs.subs(sense), S), r.equation.principle, r.equation.label, r.equation.pos};
    for (auto& l : loads)
      if (std::find(a.bodies.begin(), a.bodies.end(), l.body) != a.bodies.end())
        b.loads.push_back({l.effect, l.body, m.bind(l.x, S), m.bind(l.y, S), m.bind(l.Fx.subs(sense), S), m.bind(l.Fy.subs(sense), S),
                           m.bind(l.M.subs(sense), S), l.unknown, l.symbol});
    const Independent ind = independent_rows(m, b.rows, b.unknowns, at, env_all, what, a.pos);
    for (std::size_t i : ind.chosen) b.rows[i].used = true;
    return std::make_pair(b, ind.u);
  };
  // A friction couple at rest at S (a body just released against its bearing's couple): its
  // sense is that of the motion that follows. Each sense (the declared one, else both) is tried,
  // and the one whose relative angular acceleration turns that way kept: σ α_rel ≥ 0, checked on
  // the solution (stated where it holds parameters without values).
  struct AtRest {
    ex w;  // ω_rel, generic
    std::optional<int> declared;
    std::string effect;
  };
  std::vector<AtRest> rest;
  for (std::size_t i = 0; i < m.effects.size(); ++i)
    if (in.effect[i])
      for (const model::Load& l : m.effects[i].loads(m))
        if (l.kind == model::Load::Kind::Turn) {
          const ex w = model::relative_omega(m, l);
          if (m.bind(w, S).subs(st.given).subs(st.given).is_zero()) rest.push_back({w, l.direction, m.effects[i].name});
        }
  if (rest.empty() || rest.size() > 3) return bound({}).first;  // (more than three at once: undefined, as at any state of rest)
  std::vector<KineticsBalance> consistent;
  std::vector<std::string> tried;
  for (unsigned mask = 0; mask < (1u << rest.size()); ++mask) {
    exmap sense;
    std::vector<int> sigma;
    bool allowed = true;
    for (std::size_t i = 0; i < rest.size(); ++i) {
      sigma.push_back(mask & (1u << i) ? -1 : 1);
      allowed = allowed && (!rest[i].declared || *rest[i].declared == sigma[i]);
      sense[abs(rest[i].w)] = sigma[i] * rest[i].w;
    }
    if (!allowed) continue;
    auto [b, u] = bound(sense);
    exmap solved;
    for (std::size_t k = 0; k < b.unknowns.size() && k < u.size(); ++k) solved[b.unknowns[k]] = numeric(u[k]);
    bool turns = true;
    std::string these;
    for (std::size_t i = 0; i < rest.size(); ++i) {
      // α_rel = dω_rel/dt at S
      const ex alpha = m.bind(m.d_dt(rest[i].w), S);
      const double v = number(alpha.subs(solved), at, env_all);
      turns = turns && std::isfinite(v) && sigma[i] * v > 0;
      these += (these.empty() ? "" : ", ") + rest[i].effect + (sigma[i] > 0 ? " against a positive turning" : " against a negative turning") +
               " (the relative angular acceleration " + numerics::format_double(v, 6) + " rad/s^2)";
      b.holds.push_back({sigma[i] * alpha, "the friction couple of '" + rest[i].effect + "' was taken against the turning that follows the state of rest at '" + st.name +
                                               "', but the solution turns the other way ({} rad/s^2)",
                         "the body stays at rest there (its couple balances the others): take the kinetics at another state", a.pos,
                         "the motion that follows state '" + st.name + "' turns against the friction couple of '" + rest[i].effect + "'"});
    }
    tried.push_back(these);
    if (turns) consistent.push_back(b);
  }
  if (consistent.size() == 1) return consistent.front();
  std::string all;
  for (auto& t : tried) all += (all.empty() ? "" : "; ") + t;
  const bool declared = std::any_of(rest.begin(), rest.end(), [](const AtRest& r) { return r.declared.has_value(); });
  if (consistent.empty() && declared)
    throw SceneError(a.pos, what + ": at rest there, a friction couple's sense is that of the motion that follows, but taken as its 'direction:' says, the body turns against it (" +
                                all + ")",
                     "leave 'direction:' out (the sense is found from the motion that follows), or check it");
  if (consistent.empty())
    throw SceneError(a.pos, what + ": at rest there, a friction couple's sense is that of the motion that follows, but taken either way the body turns against it (" +
                                all + "): the couples hold it at rest",
                     "the body stays at rest at that state: there is no motion to take the kinetics of");
  throw SceneError(a.pos, what + ": at rest there, the motion that follows may turn either way against the friction couples (" + all + ")",
                   "give the couple's 'direction:' (the sense of the turning that follows)");
}

std::vector<ex> support_forces(const Model& m, const std::vector<bool>& on, const std::vector<bool>& held, const std::vector<int>& bodies,
                               const std::vector<ex>& wanted, const std::string& what, const SourcePos& pos) {
  const Instant in{on, held, bodies, " during " + what, pos};
  const std::vector<ex> unknowns = generic_unknowns(m, in);
  for (const ex& w : wanted)
    if (std::find_if(unknowns.begin(), unknowns.end(), [&](const ex& u) { return u.is_equal(w); }) == unknowns.end())
      throw SceneError(pos, "the force " + model::text(w) + " does not act during " + what, "report the scene");
  const std::vector<BodyLoad> loads = body_loads(m, in);
  const std::vector<KineticsBalance::Row> rows = generic_rows(m, in, loads, accelerations(m));
  // a sample point of the motion: t, q, q̇ and the parameters without values
  exmap at, env_all = m.numeric_environment();
  int j = 0;
  for (auto& c : m.coords) {
    at[c.q] = numeric(30 + 17 * (j++), 100);
    at[c.qd] = numeric(30 + 17 * (j++), 100);
  }
  at[m.t] = numeric(1, 3);
  for (auto& p : m.params)
    if (p.unknown || !p.value) env_all[p.sym] = numeric(1) + numeric(13 * (++j) % 29, 29);
  const Independent ind = independent_rows(m, rows, unknowns, at, env_all, what, pos);
  // A u = b over the chosen rows, solved in closed form
  lst eqs, xs;
  for (std::size_t i : ind.chosen) eqs.append(rows[i].equation.lhs == rows[i].equation.rhs);
  for (const ex& u : unknowns) xs.append(u);
  ex sol;
  try {
    sol = lsolve(eqs, xs);
  } catch (const std::exception& err) {
    throw SceneError(pos, "Newton's second law during " + what + " has no closed form for the supports' forces (" + std::string(err.what()) + ")",
                     "check the forces at states with kinetics analyses instead");
  }
  std::vector<ex> out;
  for (const ex& w : wanted)
    for (const ex& r : sol)
      if (r.lhs().is_equal(w)) out.push_back(model::trig_simplify(normal(r.rhs())));
  if (out.size() != wanted.size())
    throw SceneError(pos, "Newton's second law during " + what + " does not give every force asked for", "report the scene");
  return out;
}

std::vector<int> friction_bodies(const Model& m, const Reaction& r) {
  std::vector<int> out = r.bodies();
  for (int b : m.effects[static_cast<std::size_t>(m.effect_index(r.normal))].reaction(m)->bodies())
    if (std::find(out.begin(), out.end(), b) == out.end()) out.push_back(b);
  return out;
}

namespace {
/// "disk and plank", for messages.
std::string body_names(const Model& m, const std::vector<int>& bodies) {
  std::string out;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    out += (i ? (i + 1 == bodies.size() ? " and " : ", ") : "") + m.bodies[static_cast<std::size_t>(bodies[i])].name;
  return out;
}

/// The effects that act (by index) and the constraints that hold over analysis a — throughout
/// it, or at its state (`at_state`: a kinetics analysis) — and how messages name it.
struct Acting {
  std::vector<bool> on, held;
  std::string what;
};
Acting acting_in(const Model& m, const model::Analysis& a, bool at_state) {
  Acting out;
  for (auto& x : m.effects) out.on.push_back(at_state ? x.at_state(a.from) == model::Effect::AtState::Acts : x.activity(a) == model::Effect::Activity::Whole);
  for (std::size_t k = 0; k < m.constraints.size(); ++k)
    out.held.push_back(at_state ? m.constraint_at(k, a.from, true) : m.constraint_activity(k, a) == model::Effect::Activity::Whole);
  out.what = "the " + a.kind + " analysis" + (at_state ? " at state '" + m.states[a.from].name + "'"
                                                        : " from state '" + m.states[a.from].name + "' to '" + m.states[a.to].name + "'");
  return out;
}

/// Does e hold a parameter without a value?
bool mu_unvalued(const Model& m, const ex& e) {
  for (auto& p : m.params)
    if (!p.value && e.has(p.sym)) return true;
  return false;
}
}  // namespace

FrictionLimits static_friction_limits(const Model& m) {
  FrictionLimits out;
  for (std::size_t ei = 0; ei < m.effects.size(); ++ei) {
    const model::Effect& e = m.effects[ei];
    const auto r = e.reaction(m);
    if (!r || r->kind != Reaction::Kind::Relation || r->mu_s.is_zero()) continue;
    const ex F = m.instant_reactions.at(e.name)[0], N = m.instant_reactions.at(r->normal)[0];
    const model::Effect& track = m.effects[static_cast<std::size_t>(m.effect_index(r->normal))];
    // |F| ≤ μ_s |N| at state S: μ_s |N| − |F| ≥ 0, showing the ratio |F|/|N| it needs
    std::string mu = model::text(r->mu_s);
    if (!is_a<numeric>(r->mu_s))
      if (auto v = numerics::evaluate(r->mu_s, m.numeric_environment(), 30); v && !mu_unvalued(m, r->mu_s)) mu += " = " + numerics::format(*v, 6);
    // the track's normal force as the surface presses the body: N for a surface that only pushes
    // (a floor, a dome, a bowl: N along the way it pushes), |N| for a guide that holds both ways
    const bool one_sided = track.reaction(m)->one_sided;
    auto limit = [&](const ex& Fs, const ex& Ns, int S) {
      const std::string st = m.states[static_cast<std::size_t>(S)].name;
      const ex pressed = one_sided ? Ns : abs(Ns);
      // |F| ≤ μ_s N (N as the surface presses)
      Condition c{r->mu_s * pressed - abs(Fs),
                  "'" + e.name + "' slips at state '" + st + "': holding it takes |F|/|N| = {v} of the normal force of '" + r->normal +
                      "', more than mu_s = " + mu + " allows (short by {} N)",
                  "give a larger mu_s, or let it slide: kinetic friction (a friction effect) in place of the constraint; the least mu_s is "
                  "abs(F(" + e.name + ")@" + st + "/N(" + r->normal + ")@" + st + "), which a result can ask for",
                  r->limit_pos, "'" + e.name + "' holds without slipping at state '" + st + "', |F| <= mu_s |N(" + r->normal + ")| with mu_s = " + mu};
      c.shown = abs(Fs) / pressed;
      // one per state (a kinetics analysis and an energy analysis ending there say the same)
      if (std::none_of(out.at_states.begin(), out.at_states.end(), [&](const FrictionLimit& x) { return x.effect == e.name && x.state == S; }))
        out.at_states.push_back({e.name, r->normal, mu, S, c});
    };
    for (std::size_t ai = 0; ai < m.analyses.size(); ++ai) {
      const model::Analysis& a = m.analyses[ai];
      const bool at_state = a.type && a.type->at_state();
      if (at_state ? e.at_state(a.from) != model::Effect::AtState::Acts || track.at_state(a.from) != model::Effect::AtState::Acts
                   : e.activity(a) != model::Effect::Activity::Whole || track.activity(a) != model::Effect::Activity::Whole)
        continue;
      if (a.instant())
        throw SceneError(r->limit_pos, "constraint '" + e.name + "' states mu_s, and acts in the impact from state '" + m.states[a.from].name + "' to '" +
                                           m.states[a.to].name + "', where kinergy does not check static friction (the impulse it takes against mu_s times the normal impulse)",
                         "switch the constraint off over the impact ('off:'), or leave 'mu_s' out");
      const auto has = [&](const ex& x) { return std::any_of(a.unknowns.begin(), a.unknowns.end(), [&](const ex& u) { return u.is_equal(x); }); };
      if (at_state && has(m.bind(F, a.from)) && has(m.bind(N, a.from))) {
        limit(m.bind(F, a.from), m.bind(N, a.from), a.from);  // the forces the kinetics solves for
        continue;
      }
      // over the motion of the analysis (or at a state the kinetics' bodies do not cover), F and
      // N in closed form from Newton–Euler for every body
      const auto [on, held, what] = acting_in(m, a, at_state);
      std::vector<ex> FN;
      try {
        FN = support_forces(m, on, held, friction_bodies(m, *r), {F, N}, what, a.pos);
      } catch (const SceneError& err) {
        throw SceneError(r->limit_pos, "constraint '" + e.name + "' states mu_s, which is checked against the forces Newton's second law gives during " +
                                           what + ", but: " + err.problem(),
                         "declare every support of " + body_names(m, friction_bodies(m, *r)) +
                             " (a pin, a track, a constraint effect): the check writes Newton's second law for each; or leave 'mu_s' out");
      }
      limit(m.bind(FN[0], a.from), m.bind(FN[1], a.from), a.from);
      if (at_state) continue;
      limit(m.bind(FN[0], a.to), m.bind(FN[1], a.to), a.to);
      // the ratio |F|/|N| along the motion: where it changes, the states do not settle it
      const ex ratio = model::trig_simplify(FN[0] / FN[1]);
      if ((!motion_free(m, ratio) || ratio.has(m.t)) && std::find(out.along.begin(), out.along.end(), static_cast<int>(ai)) == out.along.end())
        out.along.push_back(static_cast<int>(ai));
    }
  }
  return out;
}

OneSidedLimits one_sided_limits(const Model& m) {
  OneSidedLimits out;
  for (std::size_t ei = 0; ei < m.effects.size(); ++ei) {
    const model::Effect& e = m.effects[ei];
    const auto r = e.reaction(m);
    const bool contact = r && r->kind == Reaction::Kind::Contact && !r->holds.empty() && !r->lodged;  // (a lodged body holds both ways)
    if (!r || !(contact || (r->kind == Reaction::Kind::Track && r->one_sided))) continue;
    const model::PointRef& pushed = contact && r->b.body >= 0 ? r->b : r->a;
    const std::string body = pushed.body >= 0 ? m.bodies[static_cast<std::size_t>(pushed.body)].name : pushed.text;
    const model::OneWay w = model::one_way(r->pulls, body, e.name);
    // its unknowns, and N from them: a track's N; a closed contact's push along its normal,
    //   N = R·n̂,  n̂ = Rot(φ − φ@S) n̂₀ turning with the body whose surface it is (S: where it closed)
    const std::vector<ex> parts(m.instant_reactions.at(e.name).begin(), m.instant_reactions.at(e.name).end());
    ex N = parts[0];
    if (contact) {
      const auto [nx, ny] = m.closed_normal(e);
      N = parts[0] * nx + parts[1] * ny;
    }
    // does it act (a closed contact: hold its parties) over analysis a, or at its state?
    const auto acts = [&](const model::Analysis& a, bool instant) {
      if (contact) return instant ? m.constraint_at(r->holds[0], a.from, true) : m.constraint_activity(r->holds[0], a) == model::Effect::Activity::Whole;
      return instant ? e.at_state(a.from) == model::Effect::AtState::Acts : e.activity(a) == model::Effect::Activity::Whole;
    };
    // N ≥ 0 at state S: the surface pushes there (it cannot pull a body resting on it)
    auto at_state = [&](const ex& Ns, int S) {
      const std::string st = m.states[static_cast<std::size_t>(S)].name;
      if (std::any_of(out.at_states.begin(), out.at_states.end(), [&](const OneSidedLimit& x) { return x.effect == e.name && x.state == S; })) return;
      // a state the motion starts from (no analysis ends there): it lets go at once, not "before" it
      const auto over = [](const model::Analysis& x) { return !x.instant() && !(x.type && x.type->at_state()); };  // a motion, not an instant
      const bool start = std::none_of(m.analyses.begin(), m.analyses.end(), [&](const model::Analysis& x) { return x.to == S && over(x); }) &&
                         std::any_of(m.analyses.begin(), m.analyses.end(), [&](const model::Analysis& x) { return x.from == S && over(x); });
      if (start)
        out.at_states.push_back({e.name, S,
                                 Condition{Ns,
                                           "at state '" + st + "', where the motion starts, " + w.would + " ({} N): " + (r->pulls ? "it is slack" : body + " leaves it") +
                                               " at once, and " + w.only + ", so no motion " + (r->pulls ? "with the cord taut" : "on it") + " starts there",
                                           "start with the rates at which " + w.is + (r->pulls ? " pulls" : " pushes") + ", or let the body go free of it",
                                           e.pos, w.acts + " at state '" + st + "' (N >= 0)"}});
      else
        out.at_states.push_back({e.name, S,
                                 Condition{Ns,
                                           "at state '" + st + "' " + w.would + " ({} N): " + (r->pulls ? "it goes slack" : body + " leaves it") +
                                               " before that state, and " + w.only,
                                           "ask for the state where it " + w.verb + ", " + w.ask + ", or take state '" + st + "' before it",
                                           e.pos, w.acts + " at state '" + st + "' (N >= 0)"}});
    };
    // the analyses at a state first: where one solves the force there, N ≥ 0 at that state is said
    // in the solved force, not in the longer form Newton–Euler gives along a motion that ends there
    std::vector<std::size_t> order;
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t ai = 0; ai < m.analyses.size(); ++ai)
        if ((m.analyses[ai].type && m.analyses[ai].type->at_state()) == (pass == 0)) order.push_back(ai);
    for (const std::size_t ai : order) {
      const model::Analysis& a = m.analyses[ai];
      if (a.instant()) continue;  // an impact's reaction is an impulse (its sign: the impact's own check)
      const bool instant = a.type && a.type->at_state();
      if (!acts(a, instant)) continue;
      const auto has = [&](const ex& x) { return std::any_of(a.unknowns.begin(), a.unknowns.end(), [&](const ex& u) { return u.is_equal(x); }); };
      if (instant && std::all_of(parts.begin(), parts.end(), [&](const ex& x) { return has(m.bind(x, a.from)); })) {
        at_state(m.bind(N, a.from), a.from);  // the force the kinetics solves for
        continue;
      }
      // over a duration across the set: its impulse pushes too, ∫N dt ≥ 0
      if (auto it = a.reactions.find(e.name); !instant && it != a.reactions.end() && !it->second.empty()) {
        const std::string S1 = m.states[static_cast<std::size_t>(a.from)].name, S2 = m.states[static_cast<std::size_t>(a.to)].name;
        out.at_states.push_back({e.name, -1,
                                 Condition{it->second[0],
                                           "the impulse of '" + e.name + "' on " + body + " from state '" + S1 + "' to '" + S2 + "' would " +
                                               (r->pulls ? "push" : "pull") + " ({} N*s): " + w.lets_go + " on the way, and " + w.only,
                                           "check the loads and states: the motion " + w.keeps + " only while " + w.is + (r->pulls ? " pulls" : " pushes"),
                                           e.pos, w.acts + " from state '" + S1 + "' to '" + S2 + "'"}});
      }
      // N in closed form from Newton–Euler over the motion (or at the state), for the states'
      // values and the way between them
      const auto [on, held, what] = acting_in(m, a, instant);
      ex Ng = N;
      try {
        const std::vector<ex> got = support_forces(m, on, held, r->bodies(), parts, what, e.pos);
        exmap by;
        for (std::size_t i = 0; i < parts.size(); ++i) by[parts[i]] = got[i];
        Ng = model::trig_simplify(N.subs(by));
      } catch (const SceneError& err) {
        const std::string why = "'" + e.name + "' during " + what + ": " + err.problem();
        if (std::find(out.unchecked.begin(), out.unchecked.end(), why) == out.unchecked.end()) out.unchecked.push_back(why);
        continue;
      }
      at_state(m.bind(Ng, a.from), a.from);
      if (instant) continue;
      at_state(m.bind(Ng, a.to), a.to);
      out.along[static_cast<int>(ai)].push_back({e.name, body, Ng, e.pos, r->pulls});
    }
  }
  return out;
}

}  // namespace kinergy::principles
