#include "kinergy/print/plain.hpp"
#include "kinergy/principles/momentum.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <functional>
#include <random>
#include <sstream>
#include <tuple>

#include <Eigen/Dense>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/trace.hpp"

namespace kinergy::principles {

using namespace GiNaC;
using model::Analysis;
using model::Effect;
using model::Model;
using model::PointRef;

bool in_set(const std::vector<int>& s, int b) { return std::find(s.begin(), s.end(), b) != s.end(); }

bool vanishes(const Model& m, const ex& e) {
  ex x = model::trig_simplify(e);
  if (x.is_zero()) return true;
  exmap env = m.numeric_environment();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int i = 0; i < 4; ++i) {
    exmap at = env;
    for (auto& c : m.coords) {
      at[c.q] = numeric(u(rng));
      at[c.qd] = numeric(u(rng));
    }
    at[m.t] = numeric(u(rng) + 2);
    // (a sweep's trace takes the probe's coordinates as the numbers they are here)
    exmap probe;
    if (numerics::tracing()) {
      for (auto& c : m.coords) probe[c.q] = at[c.q], probe[c.qd] = at[c.qd];
      probe[m.t] = at[m.t];
    }
    const numerics::TraceForms traced(probe);
    // zero against the size of its own terms, never against an absolute 1e-12
    if (!numerics::negligible(x, at).value_or(false)) return false;
  }
  return true;
}

bool motion_free(const Model& m, const ex& e) {
  for (auto& c : m.coords)
    if (e.has(c.q) || e.has(c.qd)) return false;
  return true;
}

int motion_direction(const Model& m, const Effect& e, std::optional<int> declared, const ex& generic, const Analysis& a,
                     const Knowledge& k, const std::string& what, std::vector<Condition>* holds) {
  const std::string S1 = m.states[a.from].name, S2 = m.states[a.to].name;
  const auto word = [](int s) { return std::string(s > 0 ? "positive" : "negative"); };
  for (int s : {a.from, a.to}) {
    auto v = k.value(m.bind(generic, s));
    if (!v || v->is_zero()) continue;
    const int told = v->is_positive() ? 1 : -1;
    if (declared && *declared != told)
      throw SceneError(e.pos, "effect '" + e.name + "' declares 'direction: " + word(*declared) + "', but the " + what + " at state '" +
                                  m.states[s].name + "' is " + word(told) + " (" + model::text(m.bind(generic, s)) + " = " +
                                  numerics::format(*v, 6) + ")",
                       "remove 'direction:' from '" + e.name + "' (the states tell it), or check the states");
    // told by one state: at the other it must not go the other way (a block that stops inside
    // the interval and would be pushed back by a friction that no longer acts so)
    const int other = s == a.from ? a.to : a.from;
    if (holds)
      holds->push_back({told * m.bind(generic, other),
                        "the " + what + " under '" + e.name + "' is " + word(told) + " at state '" + m.states[s].name + "' but the other way at state '" +
                            m.states[other].name + "' (by {} in SI units): it stops between them, and kinetic friction does not keep pushing the same way after",
                        "end the analysis where the " + what + " stops (a state with 'where: [\"... = 0\"]'), and take what follows from there",
                        e.pos, "the " + what + " under '" + e.name + "' keeps its sense (" + word(told) + ") at state '" + m.states[other].name + "'"});
    return told;
  }
  if (declared) {
    // taken as declared: the solution must slide (turn) that way at both states
    if (holds)
      for (int s : {a.from, a.to})
        holds->push_back({*declared * m.bind(generic, s),
                          "effect '" + e.name + "' declares 'direction: " + word(*declared) + "', but the solution has the " + what +
                              " at state '" + m.states[s].name + "' the other way (by {} in SI units): friction cannot drive the motion",
                          "give 'direction: " + word(-*declared) + "' on '" + e.name + "', or leave it out and give a velocity at state '" +
                              S1 + "' or '" + S2 + "'",
                          e.pos, "the " + what + " under '" + e.name + "' goes the declared way (" + word(*declared) + ") at state '" +
                                     m.states[s].name + "'"});
    return *declared;
  }
  throw SceneError(e.pos, "the direction of " + what + " under '" + e.name + "' between states " + S1 + " and " + S2 +
                              " is not known (no velocity there tells it)",
                   "give a nonzero velocity at state '" + S1 + "' or '" + S2 + "', or 'direction: positive|negative' on '" +
                       e.name + "' (the sign of the " + what + ")");
}

namespace {

/// A virtual motion of the body set: for each body in it, the displacement of its mass centre
/// and its rotation (δx̄, δȳ, δφ) per unit of the motion, generic in q.
using VirtualMotion = std::function<std::array<ex, 3>(int body)>;

/// A motion a declared support releases (a pin: its body's translations; a track: its body's
/// translation along the normal), or a guided body's support (across its line, and turning):
/// body b moving by (δx̄, δȳ, δφ).
struct Released {
  int body;
  std::array<ex, 3> motion;
};

/// Can the coordinates, with the motions `released` added, move the set by `field` while every
/// other body stays put?
///   find δq, δλ with  ∂(x̄_b, ȳ_b, φ_b)/∂q · δq + Σ δλ_j r_j(b) = field(b) for b in the set, = 0
///   for the rest.
/// When they can, the supports the parametrization implies (a track, a floor, an axle) that are not
/// declared do no work on that motion, so they have no part in its balance; when they cannot, one
/// of them has.
/// Tested numerically at random positions (parameters at their values): a least-squares δq whose
/// residual is negligible against the sizes involved. Unknown parameters or undefined positions:
/// taken as free (nothing can be told).
bool moves_freely(const Model& m, const Analysis& a, const VirtualMotion& field, const std::vector<Released>& released = {},
                  const std::vector<ex>& relations = {}) {
  const std::size_t B = m.bodies.size(), n = m.coords.size() + released.size(), R = relations.size();
  exmap env = m.numeric_environment();
  int j = 0;
  for (auto& p : m.params)  // an unknown parameter (solved for) at a sample value too
    if (p.unknown) env[p.sym] = numeric(1) + numeric(13 * (++j) % 29, 29);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-2, 2);
  // where the states put each coordinate (a position defined only near them: a groove of 2 mm)
  std::vector<std::optional<double>> near(m.coords.size());
  for (std::size_t i = 0; i < m.coords.size() && !m.states.empty(); ++i)
    for (auto& st : m.states) {
      auto g = st.given.find(st.sym.at(m.coords[i].name).first);
      if (g == st.given.end()) continue;
      ex v = g->second.subs(env).evalf();
      if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) near[i] = ex_to<numeric>(v).to_double();
      break;
    }
  // three positions where everything has a value (a square root of a negative at a random place
  // is no position: another is drawn): 12 draws in (−2, 2), 12 in (−0.2, 0.2), 12 in (−0.02, 0.02),
  // 12 in (−0.002, 0.002), then 12 close to where the states put the coordinates; none at all:
  // nothing can be told, and the set is not taken to turn freely
  int tested = 0;
  for (int trial = 0; trial < 60 && tested < 3; ++trial) {
    exmap at = env;
    const int block = trial / 12;
    for (std::size_t i = 0; i < m.coords.size(); ++i) {
      const double d = u(rng);
      const double x = block < 4 ? d * std::pow(10.0, -block) : near[i].value_or(0.0) * (1 + 0.005 * d) + 0.0005 * d;
      at[m.coords[i].q] = numeric(x);
    }
    at[m.t] = numeric(u(rng) + 2);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(3 * B + R), static_cast<Eigen::Index>(n));
    Eigen::VectorXd e = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(3 * B + R));
    try {
      auto value = [&](const ex& x) {
        ex v = x.subs(at).evalf();
        if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) throw std::domain_error("not a number");
        return ex_to<numeric>(v).to_double();
      };
      for (std::size_t b = 0; b < B; ++b) {
        const model::Body& body = m.bodies[b];
        const ex comp[3] = {body.x, body.y, body.angle};
        std::array<ex, 3> want = {0, 0, 0};
        if (in_set(a.bodies, static_cast<int>(b))) want = field(static_cast<int>(b));
        for (int r = 0; r < 3; ++r) {
          // a particle's angle carries no momentum: its turning does not matter
          bool matters = r < 2 || !body.inertia.is_zero();
          for (std::size_t i = 0; i < m.coords.size(); ++i) J(3 * b + r, i) = matters ? value(comp[r].diff(m.coords[i].q)) : 0.0;
          for (std::size_t j = 0; j < released.size(); ++j)
            J(3 * b + r, m.coords.size() + j) = matters && released[j].body == static_cast<int>(b) ? value(released[j].motion[r]) : 0.0;
          e(3 * b + r) = matters ? value(want[r]) : 0.0;
        }
      }
      // each relation kept: ∇c·δq = 0 (a row of unit length, whatever c's unit)
      for (std::size_t k = 0; k < R; ++k) {
        Eigen::VectorXd row = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.coords.size()));
        for (std::size_t i = 0; i < m.coords.size(); ++i) row(static_cast<Eigen::Index>(i)) = value(relations[k].diff(m.coords[i].q));
        if (row.norm() > 0) row /= row.norm();
        for (std::size_t i = 0; i < m.coords.size(); ++i) J(static_cast<Eigen::Index>(3 * B + k), static_cast<Eigen::Index>(i)) = row(static_cast<Eigen::Index>(i));
      }
    } catch (const std::exception&) {
      continue;
    }
    if (!J.allFinite() || !e.allFinite()) continue;
    ++tested;
    Eigen::VectorXd dq = J.completeOrthogonalDecomposition().solve(e);
    double scale = e.norm() + J.norm() * dq.norm();
    if ((J * dq - e).norm() > 1e-9 * scale) return false;
  }
  return tested > 0;
}

/// The unknown reactions of the supports the coordinates imply (pins, tracks) that join the set to
/// the rest. (A constraint's reaction is a force the coordinates do not imply: the set still has to
/// move freely along n for every other support to do no work.)
std::vector<Push> implied_reactions(const Model& m, const Analysis& a, const Knowledge& k) {
  std::vector<Push> out, all;
  for (auto& e : m.effects) effect_pushes(m, e, a, k, all);
  for (auto& p : all)
    if (p.implied) out.push_back(p);
  return out;
}

/// What the declared supports across the set release: a pin's unknown force frees its body's
/// translations, a track's its translation along the normal.
std::vector<Released> released_by(const Model& m, const Analysis& a) {
  std::vector<Released> out;
  for (auto& e : m.effects) {
    auto r = e.reaction(m);
    if (!r || !r->across(a.bodies) || !a.reactions.count(e.name) || e.activity(a) == Effect::Activity::None) continue;
    const model::PointRef& in = inside(a, r->a) ? r->a : r->b;
    if (r->kind == model::Reaction::Kind::Pin) {
      out.push_back({in.body, {1, 0, 0}});
      out.push_back({in.body, {0, 1, 0}});
    } else if (r->kind == model::Reaction::Kind::Track) {
      out.push_back({in.body, {r->dir_x, r->dir_y, 0}});
    }
  }
  return out;
}

/// ∫_{t₁}^{t₂} f(t) dt for f free of the motion. @throws SceneError when it has no closed form.
ex time_integral(const Model& m, const Effect& e, const ex& f, const Analysis& a) {
  auto I = over_duration(m, f, a);
  if (!I)
    throw SceneError(e.pos, "the impulse of '" + e.name + "' has no closed form in t",
                     "write it with an elementary antiderivative (polynomials, sin, cos, exp of a t)");
  return *I;
}

std::string state_pair(const Model& m, const Analysis& a) {
  return "states " + m.states[a.from].name + " -> " + m.states[a.to].name;
}

/// The pushes of effect e on the bodies of analysis a (none when e is internal, does not act on
/// them, or is switched off over the analysis). @throws SceneError when it is switched inside it.
std::vector<Push> pushes(const Model& m, const Effect& e, const Analysis& a, const Knowledge& k) {
  std::vector<Push> out;
  switch (e.activity(a)) {
    case Effect::Activity::None:
      return out;
    case Effect::Activity::Part: {
      int at = e.on > std::min(a.from, a.to) && e.on < std::max(a.from, a.to) ? e.on : e.off;
      throw SceneError(a.pos, "effect '" + e.name + "' is switched " + (at == e.on ? "on" : "off") + " at state '" + m.states[at].name +
                                  "', inside this " + a.kind + " analysis: its impulse covers only part of the interval",
                       "split the analysis at state '" + m.states[at].name + "' (one from '" + m.states[a.from].name + "' to '" +
                           m.states[at].name + "', one from there to '" + m.states[a.to].name + "')");
    }
    case Effect::Activity::Whole:
      break;
  }
  effect_pushes(m, e, a, k, out);
  return out;
}

ex dot(const ex& ax, const ex& ay, const ex& bx, const ex& by) { return ax * bx + ay * by; }

/// What an impulse term is, from the push it comes from: ∫F dt, an unknown reaction, a given impulse.
ImpulseTerm::Kind kind_of(const Push& p) {
  return !p.unknown ? ImpulseTerm::Kind::Integral : p.reaction ? ImpulseTerm::Kind::Reaction : ImpulseTerm::Kind::Given;
}

/// Which bodies are in the set, for messages.
std::string set_name(const Model& m, const Analysis& a) {
  if (a.bodies.size() == m.bodies.size()) return "all bodies";
  std::string s;
  for (int b : a.bodies) s += (s.empty() ? "" : ", ") + m.bodies[b].name;
  return s;
}

/// A constraint's force is internal to the set when every body it couples is in the set and
/// it couples two or more (a cord, a gear mesh, rolling on another body). A constraint on one
/// body alone is with the ground (rolling), and one that reaches outside the set pulls from
/// outside: both forces are unknown, so over a duration the analysis cannot hold them.
void check_constraints(const Model& m, const Analysis& a) {
  m.constraints_over(a);  // none switched inside the analysis
  for (std::size_t ci = 0; ci < m.constraints.size(); ++ci) {
    const auto& [c, pos] = m.constraints[ci];
    if (m.constraint_activity(ci, a) == model::Effect::Activity::None) continue;  // switched off over it
    // held by a named effect: its reaction is that effect's unknown
    if (m.carrier(ci)) continue;
    std::vector<int> coupled;
    for (std::size_t b = 0; b < m.bodies.size(); ++b)
      for (auto& co : m.coords)
        if (c.has(co.q) && (m.bodies[b].x.has(co.q) || m.bodies[b].y.has(co.q) || m.bodies[b].angle.has(co.q))) {
          coupled.push_back(static_cast<int>(b));
          break;
        }
    bool touches = false, all_in = true;
    for (int b : coupled) {
      if (in_set(a.bodies, b)) touches = true;
      else all_in = false;
    }
    if (!touches || (all_in && coupled.size() >= 2)) continue;
    std::string names;
    for (int b : coupled) names += (names.empty() ? "" : ", ") + m.bodies[b].name;
    // the effect to declare, spelled out: its parties, and where it acts — for moments about a
    // place, that place (a cable that leaves a drum there has no moment about it)
    const model::PointRef* P = a.about();
    const std::string at = P && (P->body < 0 || P->world_place) ? "[" + model::text(P->wx) + ", " + model::text(P->wy) + "]" : "[x, y]";
    const std::string between = coupled.size() == 1 ? "[" + names + ", ground]" : "[" + names + "]";
    throw SceneError(a.pos, "the constraint '" + emit::plain(c) + " = 0' (line " + std::to_string(pos.line) + ") pushes on " + names +
                                " with a force this " + a.kind + " analysis cannot include (" +
                                (coupled.size() == 1 ? "a contact with the ground, such as rolling, or a cable the body climbs" : "a cord, a gear or a link to a body outside it") + ")",
                     "declare it as an effect so that its force is an unknown, and remove it from 'constraints:': 'cable: {constraint: \"" + emit::plain(c) +
                         " = 0\", between: " + between + ", at: " + at + "}' (at: where it acts on " + names +
                         (P && (P->body < 0 || P->world_place) ? ", here the point moments are taken about, where its moment is zero" : "") + ")" +
                         (coupled.size() == 1 ? std::string(", or use an energy analysis")
                                              : ", list every body it couples in 'bodies' (" + names + "), or use an energy analysis"));
  }
}

/// The second integral of component c, whose momentum is dΦ/dt, into c.displacement when a result
/// asks for a position Φ holds; its pushes `forces` (effect, force or moment along it, free of the
/// motion) when every push is known in time, else `blocked` says why it has none:
///   Φ₂ = Φ₁ + L₁ (t₂ − t₁) + Σ ∫_{t₁}^{t₂}∫_{t₁}^{t} F dt' dt.
void integrate_positions(const Model& m, const Analysis& a, MomentumBalance::Component& c, const ex& phi,
                         const std::vector<std::pair<std::string, ex>>& forces, std::string blocked) {
  MomentumBalance::Displacement d;
  d.before = m.bind(phi, a.from);
  d.after = m.bind(phi, a.to);
  for (auto& x : a.positions_asked)
    if (d.before.has(x) || d.after.has(x)) c.positions.push_back(x);
  if (c.positions.empty()) return;  // no result asks for what it gives
  d.drift = c.before * (m.states[a.to].t - m.states[a.from].t);
  ex rhs = d.before + d.drift;
  for (auto& [effect, f] : forces) {
    if (!blocked.empty()) break;
    auto D = twice_over_duration(m, f, a);
    if (!D) blocked = "the push of '" + effect + "' (" + model::text(f) + ") has no elementary double integral in t";
    else {
      d.terms.push_back({effect, *D, "double integral", ImpulseTerm::Kind::Integral});
      rhs += *D;
    }
  }
  if (!blocked.empty()) {
    c.no_positions = blocked;
    return;
  }
  d.equation = {rhs, d.after, c.equation.principle, "positions from the " + c.equation.label, a.pos};
  c.displacement = d;
}

/// The line a body's mass centre keeps to while the body turns freely (a disk rolling on an
/// incline with its angle a coordinate of its own, a particle on a straight guide): every
/// ∂r̄/∂q_i along one constant u, no coordinate that moves the centre turns the body, and one
/// turns it alone (or the body is a particle). Its support is then a single force normal to u
/// through the mass centre, the only load the coordinates leave unknown; nothing otherwise.
std::optional<std::pair<ex, ex>> free_centre_line(const Model& m, int b) {
  auto c = centre_line(m, b);
  // (a coordinate that moves the centre and turns the body: rolling written into the coordinates, whose friction is implied too)
  if (!c || c->turns_with_centre || !(c->turns_alone || m.bodies[static_cast<std::size_t>(b)].inertia.is_zero())) return std::nullopt;
  return std::pair<ex, ex>{c->ux, c->uy};
}

/// Does body b interact with another body of a's set: a coordinate that moves both, or a load
/// between them? Then a support's force on b is not found from the loads on b alone (the
/// others' pull through the interaction is not among the set's impulses).
bool coupled_in_set(const Model& m, const Analysis& a, int b) {
  auto moves = [&](int x, const ex& q) {
    const model::Body& B = m.bodies[static_cast<std::size_t>(x)];
    return B.x.has(q) || B.y.has(q) || B.angle.has(q);
  };
  for (int o : a.bodies) {
    if (o == b) continue;
    for (auto& co : m.coords)
      if (moves(b, co.q) && moves(o, co.q)) return true;
  }
  for (auto& e : m.effects)
    for (const model::Load& l : e.loads(m))
      if (l.partner && ((l.at.body == b && l.partner->body != b && in_set(a.bodies, l.partner->body)) ||
                        (l.partner->body == b && l.at.body != b && in_set(a.bodies, l.at.body))))
        return true;
  return false;
}

/// The implied support of each body of the set whose centre keeps to a line while it turns
/// freely (free_centre_line), for its impulse–momentum diagram: the equations along the line (or
/// about a point on the normal through its centre) drop it, but the diagram shows every impulse
/// on the set. The centre does not accelerate across its line, so N = −(ΣF·n) n at the mass centre,
/// n normal to the line, from the known loads on the body; not shown where a load on it across
/// the line is unknown (a declared support's reaction), or where a support of it is already shown.
/// Where the body interacts with another body of the set (coupled_in_set: a collar on its guide
/// with a rod hanging from it), the guide answers the others' pull too, which the set's equations
/// do not give: it is shown by its direction only (Push::assumed), against the given loads on the
/// whole set across the line, −(Σ_set F·n) n.
void show_line_supports(const Model& m, const Analysis& a, MomentumBalance& out) {
  for (int b : a.bodies) {
    const bool coupled = coupled_in_set(m, a, b);
    const std::string name = "N_" + m.bodies[static_cast<std::size_t>(b)].name;
    if (std::any_of(out.shown.begin(), out.shown.end(), [&](const Shown& sh) { return sh.effect == name; })) continue;
    const auto u = free_centre_line(m, b);
    if (!u) continue;
    const ex nx = -u->second, ny = u->first;
    ex Fn = 0;
    bool unknown = false;
    for (auto& sh : out.shown) {
      if (coupled ? !in_set(a.bodies, sh.push.body) : sh.push.body != b) continue;
      if (sh.push.unknown) unknown = unknown || !vanishes(m, dot(sh.push.Rx, sh.push.Ry, nx, ny));
      else Fn += dot(sh.push.Fx, sh.push.Fy, nx, ny);
    }
    if (unknown || vanishes(m, Fn)) continue;
    Push n;
    n.body = b;
    n.assumed = coupled;
    n.Fx = model::trig_simplify(-Fn * nx);
    n.Fy = model::trig_simplify(-Fn * ny);
    n.arm_x = m.bodies[static_cast<std::size_t>(b)].x;
    n.arm_y = m.bodies[static_cast<std::size_t>(b)].y;
    out.shown.push_back({name, n});
  }
}

}  // namespace

/// A claim `conserved: true`, judged on the total over the set: Σ M_P = 0 about P (Σ F·n = 0 along
/// n) holds — equal and opposite couples (or forces) written as two effects cancel; else refused,
/// naming each effect with its moment (force): `single` says one ("has a moment about O ("), `noun`
/// several ("moments about O").
static void conserved_total(const Model& m, const Analysis& a, const std::vector<std::pair<std::string, ex>>& claimed, const ex& total,
                            const std::string& head, const std::string& single, const std::string& noun, const std::string& unknown = "") {
  const std::string fix = "remove 'conserved: true' so their impulse is included, or choose another direction or point";
  if (claimed.empty() || vanishes(m, model::trig_simplify(total))) {
    // (an unknown impulse breaks the claim whatever the rest: said after the known ones)
    if (!unknown.empty()) throw SceneError(a.pos, head + " is not conserved between " + state_pair(m, a) + ": " + unknown, fix);
    return;
  }
  // (a long expression of the coordinates — a spring's moment — is named by what it does)
  auto said = [&](const ex& v) {
    const std::string t = emit::plain(model::trig_simplify(v));
    return t.size() > 80 && !motion_free(m, v) ? std::string("one that changes with the motion") : t;
  };
  std::string which;
  for (auto& [name, v] : claimed) which += (which.empty() ? "" : ", ") + ("'" + name + "' (" + said(v) + ")");
  const std::string why = claimed.size() == 1 ? "effect '" + claimed[0].first + "' " + single + said(claimed[0].second) + ")"
                                              : "the " + noun + " of " + which + " do not add up to zero";
  throw SceneError(a.pos, head + " is not conserved between " + state_pair(m, a) + ": " + why, fix);
}

/// Adds an effect's known moment (force) to a conservation claim's list (one effect on several
/// bodies, gravity, summed) and to the total.
static void claim(std::vector<std::pair<std::string, ex>>& claimed, ex& total, const std::string& name, const ex& v) {
  auto it = std::find_if(claimed.begin(), claimed.end(), [&](const auto& x) { return x.first == name; });
  if (it == claimed.end()) claimed.push_back({name, v});
  else it->second += v;
  total += v;
}

MomentumBalance linear_momentum(const Model& m, const Analysis& a, const Knowledge& k) {
  MomentumBalance out;
  out.conserved = a.conserved;
  std::vector<std::pair<std::string, std::pair<ex, ex>>> dirs;
  if (const model::Along* al = a.along()) dirs.push_back({al->name, {al->nx, al->ny}});
  else dirs = {{"x", {1, 0}}, {"y", {0, 1}}};
  const std::vector<Push> implied = implied_reactions(m, a, k);
  for (auto& [name, n] : dirs) {
    auto [nx, ny] = n;
    const ex along_x = nx, along_y = ny;  // (a lambda may not capture a structured binding in C++20 with clang 14)
    MomentumBalance::Component c;
    c.name = name;
    // L·n = Σ m v̄·n
    ex L = 0;
    for (int b : a.bodies) L += m.bodies[b].mass * dot(m.rate(m.bodies[b].x), m.rate(m.bodies[b].y), nx, ny);
    L = model::collect_simplify(L, [&] { lst l; for (auto& co : m.coords) l.append(co.qd); return l; }());
    // a declared support across the set (a pin) takes up, with its unknown reaction, what the
    // set's own motion does not; any other support along n is one the scene does not declare
    const bool declared = std::any_of(implied.begin(), implied.end(),
                                      [&](const Push& p) { return !vanishes(m, p.Rx * along_x + p.Ry * along_y); });
    if (!declared && vanishes(m, L)) {
      // the coordinates never move these bodies along n: their supports (a floor, a guide, a
      // cord held fixed) take every impulse along n, so the balance says nothing there — and
      // an effect pushing along n would be met by a support force the analysis cannot know
      for (auto& e : m.effects)
        for (auto& p : pushes(m, e, a, k)) {
          if (a.conserved && !p.unknown && !vanishes(m, dot(p.Fx, p.Fy, nx, ny)))
            throw SceneError(a.pos, "linear momentum of " + set_name(m, a) + " along " + name + " is not conserved between " +
                                        state_pair(m, a) + ": effect '" + e.name + "' has an impulse along it",
                             "remove 'conserved: true', or choose another direction");
          if (p.reaction && a.conserved)
            throw SceneError(a.pos, "linear momentum of " + set_name(m, a) + " along " + name + " is not conserved between " +
                                        state_pair(m, a) + ": effect '" + e.name + "' has an impulse along it (its reaction is unknown)",
                             "remove 'conserved: true', or choose bodies the pin does not hold");
          if (!p.unknown && !vanishes(m, dot(p.Fx, p.Fy, nx, ny)))
            throw SceneError(a.pos, "the bodies of this momentum analysis (" + set_name(m, a) + ") cannot move along " + name +
                                        ", so a support holds them against '" + e.name + "' with a force the analysis does not know",
                             "take the momentum along a direction they can move (e.g. 'along: x'), or give them a coordinate along " + name);
        }
      continue;
    }
    if (!moves_freely(m, a, [&](int) { return std::array<ex, 3>{along_x, along_y, 0}; }, released_by(m, a)))
      throw SceneError(a.pos, "the bodies of this momentum analysis (" + set_name(m, a) + ") cannot move freely along " + name +
                                  ": a support the scene does not declare (a track, a surface, an axle) pushes on them along " + name +
                                  " with a force the analysis does not know",
                       "take the momentum along a direction in which they move freely (along their track), or declare the support "
                       "(a pin, a track) so that its reaction is an unknown");
    check_constraints(m, a);
    c.before = m.bind(L, a.from);
    c.after = m.bind(L, a.to);
    ex I = 0;
    std::vector<std::pair<std::string, ex>> forces;  // the known forces along n, for the positions
    std::vector<std::pair<std::string, ex>> claimed;  // with `conserved: true`: each known force along n, and their sum
    ex claimed_total = 0;
    std::string unknown_along;  // with `conserved: true`: the first unknown impulse along n
    std::string blocked;                               // why not every push along n is a known function of t
    for (auto& e : m.effects) {
      for (auto& p : pushes(m, e, a, k)) {
        ex In;
        std::string how;
        if (p.unknown) {
          In = model::trig_simplify(dot(p.Rx, p.Ry, nx, ny));
          if (blocked.empty() && !In.is_zero())
            blocked = "the impulse of '" + e.name + "' along " + name + " is an unknown total, not a force known in time";
          if (!motion_free(m, In))
            throw SceneError(e.pos, "the reaction of '" + e.name + "' turns with the motion, so its impulse along " + name +
                                        " is unknown in a way no equation fixes",
                             "take the momentum along a direction its component keeps, or use its angular impulse");
          how = !p.what.empty() ? p.what : p.reaction ? "reaction impulse (unknown)" : "given impulse";
        } else {
          const ex Fn = model::trig_simplify(dot(p.Fx, p.Fy, nx, ny));
          if (vanishes(m, Fn)) continue;
          // (a conservation claim is judged on the total over the set, below)
          if (a.conserved) {
            claim(claimed, claimed_total, e.name, Fn);
            continue;
          }
          if (!p.changing.empty()) throw SceneError(e.pos, p.changing, p.changing_fix);
          if (!motion_free(m, Fn))
            throw SceneError(e.pos, "the force of '" + e.name + "' along " + name + " changes with the motion; its impulse has no closed form",
                             "use an energy analysis, or a force that is constant or a function of t");
          In = time_integral(m, e, Fn, a);
          forces.push_back({e.name, Fn});
          how = "integral of F dt";
        }
        if (In.is_zero()) continue;
        if (a.conserved) {
          if (unknown_along.empty()) unknown_along = "effect '" + e.name + "' has an impulse " + emit::plain(In);
          continue;
        }
        c.impulses.push_back({e.name, In, how, kind_of(p)});
        I += In;
      }
    }
    if (a.conserved)
      conserved_total(m, a, claimed, claimed_total, "linear momentum of " + set_name(m, a) + " along " + name,
                      "has an impulse along it (its force along " + name + " is ", "forces along " + name, unknown_along);
    c.equation = {c.before + I, c.after, a.conserved ? "conservation of linear momentum" : "linear impulse-momentum",
                  std::string(a.conserved ? "conservation of linear momentum" : "linear impulse-momentum") + " along " + name + ", " +
                      state_pair(m, a),
                  a.pos};
    // L·n = dΦ/dt with Φ = Σ m r̄·n
    if (!a.positions_asked.empty()) {
      ex phi = 0;
      for (int b : a.bodies) phi += m.bodies[b].mass * dot(m.bodies[b].x, m.bodies[b].y, nx, ny);
      integrate_positions(m, a, c, phi, forces, blocked);
    }
    out.components.push_back(c);
  }
  for (auto& e : m.effects)
    for (auto& p : pushes(m, e, a, k)) {
      out.holds.insert(out.holds.end(), p.holds.begin(), p.holds.end());
      out.shown.push_back({e.name, p});
    }
  show_line_supports(m, a, out);
  return out;
}

namespace {

/// The guided bodies of an angular momentum analysis about (px, py), after checking that the set
/// turns freely about it but for its declared supports and the guided bodies' own.
/// @throws SceneError when a support the scene does not declare has a moment about P.
std::vector<Guided> turns_freely(const Model& m, const Analysis& a, const ex& px, const ex& py) {
  // a body held to a fixed line without turning (a block on a table): its support balances the
  // loads on it across the line and about its mass centre, so it turns with the set about P only
  // along its line
  std::vector<Guided> guided = guided_bodies(m, a);
  std::vector<Released> released = released_by(m, a);
  for (const Guided& g : guided) {
    released.push_back({g.body, {-g.uy, g.ux, 0}});
    released.push_back({g.body, {0, 0, 1}});
  }
  // a support the scene does not declare must have no moment about P: the set turns freely
  // about P (δr̄ = k × (r̄ − r_P), δφ = 1) while the rest stays put
  check_guided_interactions(m, a, guided, px, py);
  check_internal_pairs(m, a);
  // a guided body turns with the set only along its line; a cord between it and the others (a
  // relation under 'constraints:') must then keep its length, or its pull has a part across the
  // line, or off the mass centre, that the support answers unknown:
  //   δℓ = −(c·n) (r̄ − r_P) × n − (r_Q − r̄) × c per unit pull T c — the support's share
  // (so must any relation between bodies of the set: a reversing gear train's does not, and its
  // housing takes a moment)
  std::vector<ex> relations;
  for (std::size_t ci = 0; ci < m.constraints.size(); ++ci)
    if (!m.carrier(ci) && m.constraint_activity(ci, a) != Effect::Activity::None) relations.push_back(m.constraints[ci].first);
  if (!moves_freely(m, a, [&, Px = px, Py = py](int b) { return std::array<ex, 3>{-(m.bodies[b].y - Py), m.bodies[b].x - Px, 1}; },
                    released, relations))
    throw SceneError(a.pos, "the bodies of this angular momentum analysis (" + set_name(m, a) + ") cannot turn freely about " +
                                a.about()->text + ": a support the scene does not declare (a track, a surface, an axle) has a moment about " +
                                a.about()->text + " the analysis does not know" +
                                (relations.empty() ? std::string()
                                                   : ", or a relation between them (a cord, a gear train) does not hold as they turn together, "
                                                     "so its forces do not cancel about " + a.about()->text),
                     "take moments about a point they turn about freely (a pivot, a contact point on the ground, their mass centre), "
                     "or declare the support (a pin, a track) so that its reaction is an unknown" +
                         std::string(relations.empty() ? "" : "; a mesh or a cord between bodies on declared axles: name it as a constraint "
                                                              "effect ('NAME: {constraint: \"...\", between: [A, B], at: [...]}'), whose places are checked"));
  return guided;
}

/// The implied support of each guided body in `supported`, for its diagram: −(ΣF·n) n at its mass
/// centre, against the known loads across its line.
void show_supports(const Model& m, const std::vector<Guided>& guided, const std::vector<int>& supported, MomentumBalance& out) {
  for (int b : supported) {
    const Guided& g = *find_guided(guided, b);
    ex Fn = 0;
    for (auto& sh : out.shown)
      if (sh.push.body == b && !sh.push.unknown) Fn += dot(sh.push.Fx, sh.push.Fy, -g.uy, g.ux);
    Push n;
    n.body = b;
    n.Fx = model::trig_simplify(Fn * g.uy);
    n.Fy = model::trig_simplify(-Fn * g.ux);
    n.arm_x = m.bodies[static_cast<std::size_t>(b)].x;
    n.arm_y = m.bodies[static_cast<std::size_t>(b)].y;
    if (!vanishes(m, Fn)) out.shown.push_back({"N_" + m.bodies[static_cast<std::size_t>(b)].name, n});
  }
}

}  // namespace


MomentumBalance angular_momentum(const Model& m, const Analysis& a, const Knowledge& k) {
  check_constraints(m, a);
  MomentumBalance out;
  out.angular = true;
  out.conserved = a.conserved;
  MomentumBalance::Component c;
  c.name = "moment about " + a.about()->text;
  ex H = m.angular_momentum(*a.about(), a.bodies);
  c.before = m.bind(H, a.from);
  c.after = m.bind(H, a.to);
  ex px, py;  // (not a structured binding: the lambda below captures them, which clang 14 refuses)
  std::tie(px, py) = m.position(*a.about());
  const std::vector<Guided> guided = turns_freely(m, a, px, py);
  std::vector<int> supported;  // guided bodies whose support answers a load across the line (for the derivation)
  // F at Q on a guided body: (r̄ − r_P) × u (F·u), the support's answer included
  auto moment_on_guided = [&](const Guided& g, const ex& qx, const ex& qy, const ex& Fx, const ex& Fy, const ex& M) {
    const ex Mg = guided_moment(m, g, px, py, Fx, Fy);
    if (!vanishes(m, Mg - M - cross(qx - px, qy - py, Fx, Fy)) && !in_set(supported, g.body)) supported.push_back(g.body);
    return Mg;
  };
  ex I = 0;
  std::vector<std::pair<std::string, ex>> moments;  // the known moments about P, for the positions
  std::vector<std::pair<std::string, ex>> claimed;  // with `conserved: true`: each known moment about P, and their sum
  ex claimed_total = 0;
  std::string blocked;                                // why not every push's moment is a known function of t
  for (auto& e : m.effects) {
    for (auto& p : pushes(m, e, a, k)) {
      // moment about P: (r_Q − r_P) × F, plus couples
      ex Mp, In;
      std::string how;
      const Guided* on_guided = find_guided(guided, p.body);
      if (p.unknown) {
        // (r_Q − r_P) × R; a reaction's arm must stay fixed over the interval, a given impulse
        // acts at the first state
        // (a force sliding along its own line keeps its moment: a rolling contact's friction)
        ex ax = model::trig_simplify(p.arm_x - px), ay = model::trig_simplify(p.arm_y - py);
        if (vanishes(m, ax) && vanishes(m, ay) && !on_guided) continue;
        ex Mr = on_guided ? moment_on_guided(*on_guided, p.arm_x, p.arm_y, p.Rx, p.Ry, 0)
                                          : model::trig_simplify(cross(ax, ay, p.Rx, p.Ry));
        if (vanishes(m, Mr)) continue;
        if (p.reaction && (!motion_free(m, Mr) || Mr.has(m.t)) && !a.instant())
          throw SceneError(e.pos, "the reaction of '" + e.name + "' has a moment about " + a.about()->text +
                                      " that changes with the motion (or in time), so its angular impulse is unknown in a way no equation fixes",
                           "take moments about the pin itself, or about a fixed point");
        In = m.bind(Mr, a.from);
        if (blocked.empty()) blocked = "the angular impulse of '" + e.name + "' is an unknown total, not a moment known in time";
        how = !p.what.empty() ? "moment of the " + p.what : p.reaction ? "moment of the reaction impulse (unknown)" : "moment of the given impulse";
      } else {
        Mp = on_guided ? moment_on_guided(*on_guided, p.arm_x, p.arm_y, p.Fx, p.Fy, p.M)
                                       : model::trig_simplify(p.M + cross(p.arm_x - px, p.arm_y - py, p.Fx, p.Fy));
        if (vanishes(m, Mp)) continue;
        // a conservation claim is judged on the total over the set (two equal and opposite
        // couples written as two effects cancel), below
        if (a.conserved) {
          claim(claimed, claimed_total, e.name, Mp);
          continue;
        }
        if (!p.changing.empty()) throw SceneError(e.pos, p.changing, p.changing_fix);
        if (!motion_free(m, Mp))
          throw SceneError(e.pos, "the moment of '" + e.name + "' about " + a.about()->text + " changes with the motion (" + model::text(Mp) +
                                      "); its angular impulse has no closed form",
                           "take moments about a point where it is constant (a pivot, the mass centre), or use an energy analysis");
        In = time_integral(m, e, Mp, a);
        moments.push_back({e.name, Mp});
        how = "integral of M dt";
      }
      if (In.is_zero()) continue;
      if (a.conserved && p.unknown)
        throw SceneError(a.pos, "angular momentum of " + set_name(m, a) + " about " + a.about()->text + " is not conserved between " +
                                    state_pair(m, a) + ": effect '" + e.name + "' has a moment about " + a.about()->text,
                         "remove 'conserved: true' so its angular impulse is included, or take moments about another point");
      c.impulses.push_back({e.name, In, how, kind_of(p)});
      I += In;
    }
  }
  if (a.conserved)
    conserved_total(m, a, claimed, claimed_total, "angular momentum of " + set_name(m, a) + " about " + a.about()->text,
                    "has a moment about " + a.about()->text + " (", "moments about " + a.about()->text);
  out.supported = supported;
  // H_P ≡ 0 with no moment about P (a body moving along a line through P): 0 = 0 says nothing
  if (vanishes(m, H) && I.is_zero())
    throw SceneError(a.pos, "the angular momentum of " + set_name(m, a) + " about " + a.about()->text +
                                " is zero at every position and rate, and no load has a moment about it: the balance says nothing (" +
                                a.about()->text + " lies on the line the bodies move along)",
                     "take moments about a point off their line of motion, or balance the linear momentum along it");
  const char* what = a.conserved ? "conservation of angular momentum" : "angular impulse-momentum";
  c.equation = {c.before + I, c.after, what, std::string(what) + " about " + a.about()->text + ", " + state_pair(m, a), a.pos};
  // H = Σ h_i q̇_i with every h_i constant is dΦ/dt with Φ = Σ h_i q_i (a body turning about its
  // mass centre or a fixed axle: H = I ω, Φ = I φ)
  if (!a.positions_asked.empty()) {
    ex phi = 0, rest = H;
    bool constant = true;
    for (auto& co : m.coords) {
      const ex h = model::trig_simplify(H.diff(co.qd));
      constant = constant && motion_free(m, h) && !h.has(m.t);
      phi += h * co.q;
      rest -= h * co.qd;
    }
    if ((!constant || !vanishes(m, rest)) && blocked.empty())
      blocked = "the angular momentum about " + a.about()->text + " changes with the position (it is not a constant times the rates), so it does not integrate to angles";
    integrate_positions(m, a, c, phi, moments, blocked);
  }
  for (auto& e : m.effects)
    for (auto& p : pushes(m, e, a, k)) {
      out.holds.insert(out.holds.end(), p.holds.begin(), p.holds.end());
      out.shown.push_back({e.name, p});
    }
  show_supports(m, guided, supported, out);
  show_line_supports(m, a, out);
  out.components.push_back(c);
  return out;
}

/// The impact's generalized impulse–momentum equations, one per coordinate that moves.
static void impact_momentum(const Model& m, const Analysis& a, ImpactBalance& out) {
  const int B = a.from, A = a.to;  // before, after
  const std::string SB = m.states[B].name, SA = m.states[A].name;
  auto after = [&](const ex& e) { return m.bind_mixed(e, B, A); };
  auto before = [&](const ex& e) { return m.bind(e, B); };
  // generalized impulse–momentum along each coordinate q_i:
  //   Σ_b [m_b Δv̄_b·∂r_G/∂q_i + Ī_b Δω_b ∂φ_b/∂q_i] = Σ_c P_c·(∂r_B/∂q_i − ∂r_A/∂q_i) + Σ_g J_g·∂r_g/∂q_i + Σ_k λ_k ∂c_k/∂q_i
  for (std::size_t i = 0; i < m.coords.size(); ++i) {
    const symbol& q = m.coords[i].q;
    ex lhs = 0;
    for (std::size_t bi = 0; bi < m.bodies.size(); ++bi) {
      const auto& b = m.bodies[bi];
      ex vx = m.rate(b.x), vy = m.rate(b.y), w = m.omega(static_cast<int>(bi));
      ex Jx = b.x.diff(q), Jy = b.y.diff(q), Jw = b.angle.diff(q);
      lhs += b.mass * ((after(vx) - before(vx)) * before(Jx) + (after(vy) - before(vy)) * before(Jy)) +
             b.inertia * (after(w) - before(w)) * before(Jw);
    }
    ex rhs = 0;
    for (int ci : a.struck()->contacts) {
      const Model::Contact e = m.contact(ci);
      const auto& [J, Jt] = a.struck()->impulses.at(e.name);
      auto dr = [&](const PointRef& p) -> std::pair<ex, ex> {
        if (p.ground || p.body < 0) return {0, 0};
        return m.position_derivative(p, q);
      };
      auto [dbx, dby] = dr(e.b);
      auto [dax, day] = dr(e.a);
      ex wn = dot(dbx - dax, dby - day, e.nx, e.ny);
      rhs += J * before(wn);
      if (e.stick) rhs += Jt * before(dot(dbx - dax, dby - day, -e.ny, e.nx));
    }
    for (auto& e : m.effects) {
      const model::Blow* g = e.blow();
      if (!g || !e.strikes_in(m, a)) continue;  // switched off, or struck before: it does not strike here
      auto [dx, dy] = m.position_derivative(g->at, q);
      rhs += before(dot(g->Jx, g->Jy, dx, dy));
    }
    for (std::size_t kk = 0; kk < m.constraints.size(); ++kk)
      rhs += a.struck()->lambdas[kk] * before(m.constraints[kk].first.diff(q));
    ex res = model::trig_simplify(lhs - rhs);
    if (res.is_zero()) continue;
    out.momentum.push_back({lhs, rhs, "impulse-momentum",
                            "impulse-momentum along " + m.coords[i].name + " in the impact " + SB + " -> " + SA, a.pos});
    out.along.push_back(static_cast<int>(i));
  }
}

/// What each body's impulse–momentum diagram of the impact shows.
static void impact_diagrams(const Model& m, const Analysis& a, ImpactBalance& out) {
  // what each body's diagram shows: P = J n (+ Jt t) on the second party at the contact, −P on
  // the first; the given blows; a pin's impulse (its body's momentum change less the others)
  for (int ci : a.struck()->contacts) {
    const Model::Contact e = m.contact(ci);
    const auto& [J, Jt] = a.struck()->impulses.at(e.name);
    for (const PointRef* p : {&e.b, &e.a}) {
      if (p->ground || p->body < 0) continue;
      const int sign = p == &e.b ? 1 : -1;
      Push push;
      push.unknown = true;
      push.body = p->body;
      std::tie(push.arm_x, push.arm_y) = m.position(*p);
      push.Rx = sign * (J * e.nx - (e.stick ? Jt * e.ny : ex(0)));
      push.Ry = sign * (J * e.ny + (e.stick ? Jt * e.nx : ex(0)));
      out.shown.push_back({e.name, push});
    }
  }
  for (std::size_t ei = 0; ei < m.effects.size(); ++ei) {
    const Effect& e = m.effects[ei];
    if (const model::Blow* g = e.blow(); g && g->at.body >= 0 && e.strikes_in(m, a)) {
      Push push;
      push.unknown = true;
      push.body = g->at.body;
      std::tie(push.arm_x, push.arm_y) = m.position(g->at);
      push.Rx = g->Jx;
      push.Ry = g->Jy;
      out.shown.push_back({e.name, push});
    }
    // (a pin to the ground: its impulse on its one body; one between two bodies is internal to neither's
    // diagram alone, and not drawn)
    const std::vector<int> acted = e.bodies_acted(m);
    const int ai = static_cast<int>(&a - m.analyses.data());
    if (ai < 0 || ai >= static_cast<int>(m.analyses.size())) continue;
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      if (!holds(m, e, static_cast<int>(b)) || acted.size() != 1) continue;
      Push push;
      push.unknown = push.reaction = true;
      push.body = static_cast<int>(b);
      try {
        std::tie(push.Rx, push.Ry) = e.impulse(m, static_cast<int>(ei), ai);
      } catch (const std::exception&) {
        continue;  // not told apart from the others (two pins on a body): not drawn
      }
      out.shown.push_back({e.name, push});
    }
  }
}

ImpactBalance impact(const Model& m, const Analysis& a, const Knowledge& k) {
  ImpactBalance out;
  const int B = a.from, A = a.to;  // before, after
  const std::string SB = m.states[B].name, SA = m.states[A].name;
  // positions do not change during an impact
  for (auto& c : m.coords) {
    ex qb = m.states[B].sym.at(c.name).first, qa = m.states[A].sym.at(c.name).first;
    out.positions.push_back({qa, qb, "impact", "positions kept in the impact " + SB + " -> " + SA, a.pos});
  }
  out.positions.push_back({m.states[A].t, m.states[B].t, "impact", "time of the impact " + SB + " -> " + SA, a.pos});

  // velocities after, at the positions before
  auto after = [&](const ex& e) { return m.bind_mixed(e, B, A); };
  auto before = [&](const ex& e) { return m.bind(e, B); };

  struct Party {
    std::pair<ex, ex> v, r;  // generic velocity and position
  };
  auto party = [&](const PointRef& p) {
    Party x;
    if (p.ground) {
      x.v = {0, 0};
      x.r = {0, 0};
    } else {
      x.v = m.velocity(p);
      x.r = m.position(p);
    }
    return x;
  };

  impact_momentum(m, a, out);

  for (int ci : a.struck()->contacts) {
    const Model::Contact e = m.contact(ci);
    Party pa = party(e.a), pb = party(e.b);
    // the parties must touch at the impact
    if (!e.a.ground && !e.b.ground) {
      auto dx = k.value(before(pb.r.first - pa.r.first)), dy = k.value(before(pb.r.second - pa.r.second));
      if (dx && dy) {
        // apart, against the size of the positions (no absolute floor: a scene may be tiny), in
        // CLN's numbers: in doubles a scene 1e400 m from the origin is ∞ apart from ∞ and passes
        // (the size: the points' places, and each body's centre and the point's offset from it —
        // two points that meet at the origin have no size of their own)
        numeric d2 = *dx * *dx + *dy * *dy, scale = 0;
        std::vector<ex> sizes{pa.r.first, pa.r.second, pb.r.first, pb.r.second};
        for (const PointRef* p : {&e.a, &e.b})
          if (p->body >= 0)
            for (const ex& c : {m.bodies[static_cast<std::size_t>(p->body)].x, m.bodies[static_cast<std::size_t>(p->body)].y, p->lx, p->ly}) sizes.push_back(c);
        for (const ex& c : sizes)
          if (auto s = k.value(before(c))) scale = std::max(scale, abs(*s));
        if (d2 > pow(numeric(1, 1000000000) * scale, 2))
          throw SceneError(e.pos, "contact '" + e.name + "': " + e.a.text + " and " + e.b.text + " are " +
                                      numerics::format(numeric(sqrt(d2)), 6) + " m apart at state '" + SB +
                                      "', so they cannot strike each other there",
                           "give positions at '" + SB + "' that bring the two points together");
      }
    } else {
      // the ground is the plane through the origin across n̂ (where the simulator measures the
      // gap from): the other party must be on it, g = (r_b − r_a)·n̂ = 0
      const ex n = sqrt(e.nx * e.nx + e.ny * e.ny);
      auto gap = k.value(before(dot(pb.r.first - pa.r.first, pb.r.second - pa.r.second, e.nx, e.ny) / n));
      numeric scale = 0;
      for (const ex& c : {pa.r.first, pa.r.second, pb.r.first, pb.r.second})
        if (auto s = k.value(before(c))) scale = std::max(scale, abs(*s));
      if (gap && abs(*gap) > numeric(1, 1000000000) * scale)
        throw SceneError(e.pos, "contact '" + e.name + "': " + (e.a.ground ? e.b.text : e.a.text) + " is " + numerics::format(abs(*gap), 6) +
                                    " m " + ((gap->is_positive() == e.a.ground) ? "above" : "below") +
                                    " the ground at state '" + SB + "' (the ground is the line through the origin across the normal), so it cannot strike it there",
                         "give positions at '" + SB + "' that put it on the ground (at 0 along the normal)");
    }
    // restitution: (v_B′ − v_A′)·n = −e (v_B − v_A)·n
    ex vn_after = dot(pb.v.first - pa.v.first, pb.v.second - pa.v.second, e.nx, e.ny);
    ex vn_before = before(vn_after);
    if (auto v = k.value(vn_before); v && !v->is_negative())
      throw SceneError(e.pos, "contact '" + e.name + "': the parties are not approaching along the normal at state '" + SB +
                                  "' (relative normal velocity " + numerics::format(*v, 6) + " m/s), so no impact happens",
                       "check the normal: it points from the first party (" + e.a.text + ") into the second (" + e.b.text + ")");
    out.restitution.push_back({after(vn_after), -e.e * vn_before, "restitution",
                               "restitution at contact " + e.name + " in the impact " + SB + " -> " + SA, e.pos});
    if (e.stick) {
      ex vt = dot(pb.v.first - pa.v.first, pb.v.second - pa.v.second, -e.ny, e.nx);
      out.restitution.push_back({after(vt), 0, "no sliding",
                                 "no sliding at contact " + e.name + " after the impact " + SB + " -> " + SA, e.pos});
    }
  }
  impact_diagrams(m, a, out);
  return out;
}

}  // namespace kinergy::principles
