// Equations of motion from the kinematics: M(q) q̈ + c = Σ Q, constraint rows A q̈ = γ.
#include "kinergy/simulate/equations.hpp"

#include <sstream>

#include "kinergy/common/error.hpp"
#include "kinergy/print/plain.hpp"
#include "kinergy/model/simplify.hpp"

namespace kinergy::simulate {

using namespace GiNaC;
using model::collect_simplify;
using model::trig_simplify;

// v = Σ J_i q̇_i + b is linear in the rates: J_i = ∂v/∂q̇_i, and dv/dt at q̈ = 0 is the model's
// rate of v (it differentiates q and t only, so the q̈ terms J_i q̈_i are exactly the ones left out).
LinearRate linear_rate(const model::Model& m, const ex& v) {
  LinearRate r;
  lst l = m.rates();
  r.v = collect_simplify(v, l);
  for (auto& c : m.coords) r.J.push_back(trig_simplify(v.diff(c.qd)));
  r.a0 = collect_simplify(m.rate(v), l);
  return r;
}

ForceTerm force_term(const model::Model& m, int self, std::vector<ex> Q, bool conservative) {
  ForceTerm f{self, std::move(Q), conservative, 0, ""};
  if (!conservative) {
    // the power of a generalized force, P = Σ Q_i q̇_i
    ex P = 0;
    for (std::size_t i = 0; i < m.coords.size(); ++i) P += f.Q[i] * m.coords[i].qd;
    f.power = collect_simplify(P, m.rates());
  }
  return f;
}

ForceTerm force_term(const model::Model& m, const model::Effect& e, int self) {
  std::vector<ex> Q;
  for (std::size_t i = 0; i < m.coords.size(); ++i) Q.push_back(collect_simplify(e.generalized_force(m, i), m.rates()));
  return force_term(m, self, std::move(Q), e.conservative());
}

void load_terms(const model::Model& m, const model::Effect& e, int self, Equations& eq) {
  if (auto r = e.reaction(m); r && r->kind == model::Reaction::Kind::Contact) {
    // gap along the normal from party a into party b: g = (r_b − r_a)·n̂ (the plane through a
    // perpendicular to n̂); its rate is the normal approach speed
    auto [xa, ya] = m.position(r->a);
    auto [xb, yb] = m.position(r->b);
    ContactTerm c{self, model::trig_simplify((xb - xa) * r->dir_x + (yb - ya) * r->dir_y), {}, {}, r->e, r->stick};
    auto [vax, vay] = m.velocity(r->a);
    auto [vbx, vby] = m.velocity(r->b);
    c.normal = linear_rate(m, (vbx - vax) * r->dir_x + (vby - vay) * r->dir_y);
    c.tangent = linear_rate(m, -(vbx - vax) * r->dir_y + (vby - vay) * r->dir_x);
    if (r->stick && r->turns >= 0) c.turn = m.bodies[static_cast<std::size_t>(r->turns)].angle;
    c.lodged = r->lodged;
    eq.contacts.push_back(c);
  }
  if (const model::Blow* j = e.blow()) {
    // a given impulse: P_i = J · ∂r_P/∂q_i
    ImpulseTerm im{self, {}};
    for (auto& co : m.coords) {
      auto [dx, dy] = m.position_derivative(j->at, co.q);
      im.P.push_back(trig_simplify(j->Jx * dx + j->Jy * dy));
    }
    eq.impulses.push_back(im);
  }
  // (a support the coordinates or the constraint rows imply gives no term of its own)
  if (e.conservative()) {
    // a potential's generalized force Q_i = −∂V/∂q_i (a support without one, V = 0, gives none)
    if (!e.potential(m).is_zero()) eq.forces.push_back(force_term(m, e, self));
    return;
  }
  std::vector<ex> Q(m.coords.size(), 0);
  bool given = false;
  std::string singular;
  for (const model::Load& l : e.loads(m)) {
    switch (l.kind) {
      case model::Load::Kind::Given:
        // Q_i = F·∂(r − r_partner)/∂q_i + M ∂(φ − φ_partner)/∂q_i
        given = true;
        for (std::size_t i = 0; i < Q.size(); ++i) Q[i] += model::generalized_force(m, l, i);
        if (!l.singular.empty()) singular = l.singular;
        break;
      case model::Load::Kind::Slide: {
        // the slip of its point over the partner's: the force −μN û there and +μN û on the
        // partner give Q = −μN (∂v_rel/∂q̇)ᵀ û
        auto [vx, vy] = model::relative_velocity(m, l);
        eq.friction.push_back({self, false, linear_rate(m, vx), linear_rate(m, vy), l.size});
        break;
      }
      case model::Load::Kind::Turn:
        eq.friction.push_back({self, true, linear_rate(m, model::relative_omega(m, l)), {}, l.size});
        break;
    }
  }
  if (!given) return;
  for (auto& q : Q) q = collect_simplify(q, m.rates());
  ForceTerm f = force_term(m, self, std::move(Q), false);
  f.singular = singular;
  eq.forces.push_back(f);
}

Equations equations_of_motion(const model::Model& m, const std::vector<bool>& on) {
  Equations eq;
  const std::size_t n = m.coords.size();
  for (auto& c : m.coords) {
    eq.q.push_back(c.q);
    eq.qd.push_back(c.qd);
  }
  eq.t = m.t;
  lst l = m.rates();

  // M(q) = Σ_bodies m Jᵀ J + Ī Jωᵀ Jω  (J = ∂r_G/∂q, Jω = ∂φ/∂q)
  eq.M = m.mass_matrix();

  // Newton–Euler projected on the coordinates (Kane's form): for each body
  //   m Jᵀ (J q̈ + a0) + Ī Jωᵀ (Jω q̈ + α0) = Jᵀ F + Jωᵀ M_G,
  // a0 = d(v̄)/dt and α0 = dω/dt at q̈ = 0 (velocity products, explicit time dependence).
  eq.c.assign(n, 0);
  for (auto& b : m.bodies) {
    ex ax = m.rate(m.rate(b.x)), ay = m.rate(m.rate(b.y)), al = m.rate(m.rate(b.angle));
    for (std::size_t i = 0; i < n; ++i) {
      const symbol& qi = m.coords[i].q;
      eq.c[i] += b.mass * (b.x.diff(qi) * ax + b.y.diff(qi) * ay) + b.inertia * b.angle.diff(qi) * al;
    }
  }
  for (auto& ci : eq.c) ci = collect_simplify(ci, l);

  // each effect adds its own terms (a force's Q, a friction's slip, a contact's gap, a blow)
  for (std::size_t k = 0; k < m.effects.size(); ++k)
    if (on.empty() || on[k]) load_terms(m, m.effects[k], static_cast<int>(k), eq);

  // holonomic constraints g(q, t) = 0:  A q̈ = γ,  γ = −d/dt(A q̇ + ∂g/∂t) at q̈ = 0
  // (a constraint effect that does not act, a cord gone slack, gives no row)
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < m.constraints.size(); ++r) {
    // (a contact that stays closed after its impact holds its parties as a resting contact does:
    // the run's own contact rows, which let go where it stops pushing)
    const model::Effect* carrier = m.carrier(r);
    if (carrier && !carrier->reaction(m)->holds.empty()) continue;
    bool acts = true;
    for (std::size_t k = 0; k < m.effects.size(); ++k)
      if (carrier == &m.effects[k] && !on.empty() && !on[k]) acts = false;
    if (acts) rows.push_back(r);
  }
  const std::size_t nc = rows.size();
  eq.A = matrix(nc, n);
  for (std::size_t r = 0; r < nc; ++r) {
    const ex& g = m.constraints[rows[r]].first;
    eq.g.push_back(g);
    for (std::size_t i = 0; i < n; ++i) eq.A(r, i) = trig_simplify(g.diff(m.coords[i].q));
    eq.gt.push_back(trig_simplify(g.diff(m.t)));
    eq.gamma.push_back(collect_simplify(-m.rate(m.rate(g)), l));
  }

  eq.T = m.kinetic_energy();
  eq.V = 0;  // of the effects that act
  for (std::size_t k = 0; k < m.effects.size(); ++k)
    if (on.empty() || on[k]) eq.V += m.effects[k].potential(m);
  return eq;
}

std::string Equations::text(const model::Model& m) const {
  std::ostringstream os;
  // the plain printer: its term order does not depend on addresses (GiNaC's own does)
  auto P = [](const GiNaC::ex& e) { return emit::plain(e); };
  const std::size_t n = q.size();
  auto name = [&](std::size_t i) { return m.coords[i].name; };
  os << "Equations of motion  M(q) q'' + c(q, q', t) = Q";
  if (!g.empty()) os << " + A^T lambda,  A q'' = gamma";
  os << "\n";
  os << "coordinates:";
  for (std::size_t i = 0; i < n; ++i) os << " " << name(i);
  os << "\n\nM(q):\n";
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j <= i; ++j)
      if (!M(i, j).is_zero()) os << "  M[" << name(i) << "," << name(j) << "] = " << P(M(i, j)) << "\n";
  bool any_c = false;
  for (auto& ci : c) any_c = any_c || !ci.is_zero();
  if (any_c) {
    os << "\nc(q, q', t) (velocity products):\n";
    for (std::size_t i = 0; i < n; ++i)
      if (!c[i].is_zero()) os << "  c[" << name(i) << "] = " << P(c[i]) << "\n";
  }
  for (auto& f : forces) {
    const auto& e = m.effects[static_cast<std::size_t>(f.effect)];
    os << "\nQ from " << e.name << " (" << e.kind << "):\n";
    for (std::size_t i = 0; i < n; ++i)
      if (!f.Q[i].is_zero()) os << "  Q[" << name(i) << "] = " << P(f.Q[i]) << "\n";
  }
  for (auto& f : friction) {
    const auto& e = m.effects[static_cast<std::size_t>(f.effect)];
    os << "\nQ from " << e.name << " (" << e.kind << "), sliding: ";
    if (f.rotary) os << "-(" << P(f.limit) << ") sgn(w) dw/dq', w = " << P(f.x.v) << "\n";
    else os << "-(" << P(f.limit) << ") J^T v/|v|, v = (" << P(f.x.v) << ", " << P(f.y.v) << ")\n";
    os << "  sticking: v = 0 held by a force of at most " << P(f.limit) << "\n";
  }
  for (auto& c : contacts) {
    const auto& e = m.effects[static_cast<std::size_t>(c.effect)];
    os << "\ncontact " << e.name << ": gap = " << P(c.gap) << " >= 0, e = " << P(c.e)
       << (c.stick ? ", rough (no slip after impact)" : "") << "\n";
  }
  for (auto& im : impulses) {
    const auto& e = m.effects[static_cast<std::size_t>(im.effect)];
    os << "\nimpulse " << e.name << " at the start:";
    for (std::size_t i = 0; i < n; ++i)
      if (!im.P[i].is_zero()) os << " P[" << name(i) << "] = " << P(im.P[i]);
    os << "\n";
  }
  if (!g.empty()) {
    os << "\nconstraints g(q, t) = 0:\n";
    for (std::size_t r = 0; r < g.size(); ++r) os << "  " << P(g[r]) << " = 0\n";
  }
  return os.str();
}

}  // namespace kinergy::simulate
