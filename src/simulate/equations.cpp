// Equations of motion from the kinematics: M(q) q̈ + c = Σ Q, constraint rows A q̈ = γ.
#include "kinergy/simulate/equations.hpp"

#include <sstream>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"

namespace kinergy::simulate {

using namespace GiNaC;
using model::collect_simplify;
using model::trig_simplify;

namespace {

lst rates(const model::Model& m) {
  lst l;
  for (auto& c : m.coords) l.append(c.qd);
  return l;
}

// v = Σ J_i q̇_i + b is linear in the rates: J_i = ∂v/∂q̇_i, and dv/dt at q̈ = 0 is the model's
// rate of v (it differentiates q and t only, so the q̈ terms J_i q̈_i are exactly the ones left out).
LinearRate linear_rate(const model::Model& m, const ex& v) {
  LinearRate r;
  lst l = rates(m);
  r.v = collect_simplify(v, l);
  for (auto& c : m.coords) r.J.push_back(trig_simplify(v.diff(c.qd)));
  r.a0 = collect_simplify(m.rate(v), l);
  return r;
}

}  // namespace

Equations equations_of_motion(const model::Model& m) {
  Equations eq;
  const std::size_t n = m.coords.size();
  for (auto& c : m.coords) {
    eq.q.push_back(c.q);
    eq.qd.push_back(c.qd);
  }
  eq.t = m.t;
  lst l = rates(m);

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

  // the power of a generalized force, P = Σ Q_i q̇_i
  auto power = [&](const std::vector<ex>& Q) {
    ex P = 0;
    for (std::size_t i = 0; i < n; ++i) P += Q[i] * m.coords[i].qd;
    return collect_simplify(P, l);
  };

  for (std::size_t k = 0; k < m.effects.size(); ++k) {
    const model::Effect& e = m.effects[k];
    const int idx = static_cast<int>(k);
    if (e.kind == "pin") continue;  // the coordinates already keep the pinned points together
    if (e.kind == "gravity" || e.kind == "spring" || e.kind == "torsion_spring") {
      // Q_i = −∂V/∂q_i
      ForceTerm f{idx, {}, true, 0};
      for (std::size_t i = 0; i < n; ++i) f.Q.push_back(collect_simplify(m.generalized_force(e, i), l));
      eq.forces.push_back(f);
    } else if (e.kind == "couple" || e.kind == "force") {
      // couple: Q_i = M ∂φ/∂q_i;  force: Q_i = F · ∂r_P/∂q_i
      ForceTerm f{idx, {}, false, 0};
      for (std::size_t i = 0; i < n; ++i) f.Q.push_back(collect_simplify(m.generalized_force(e, i), l));
      f.power = power(f.Q);
      eq.forces.push_back(f);
    } else if (e.kind == "power") {
      // a drive of power P on a body: the couple P/ω, Q_i = (P/ω) ∂φ/∂q_i
      ForceTerm f{idx, {}, false, e.P};
      ex w = m.omega(e.body);
      for (std::size_t i = 0; i < n; ++i) f.Q.push_back(e.P * m.bodies[e.body].angle.diff(m.coords[i].q) / w);
      eq.forces.push_back(f);
    } else if (e.kind == "damper" || e.kind == "torsion_damper") {
      ForceTerm f{idx, {}, false, 0};
      if (e.kind == "torsion_damper") {
        // torsional: couple −c (ω₁ − ω₂) on the body (and its reaction on the second),
        // Q_i = −c (ω₁ − ω₂) ∂(φ₁ − φ₂)/∂q_i
        ex rel = m.bodies[e.body].angle - (e.body2 >= 0 ? m.bodies[e.body2].angle : ex(0));
        ex w = m.rate(rel);
        for (std::size_t i = 0; i < n; ++i) f.Q.push_back(collect_simplify(-e.k * w * rel.diff(m.coords[i].q), l));
      } else {
        // along the line of its ends: d = r_B − r_A, the force on B is −c (d·ḋ/|d|²) d, so
        // Q_i = −c (d·ḋ)(d·∂d/∂q_i)/|d|²  (no root: the unit vector appears twice)
        auto [xa, ya] = m.position(e.a);
        auto [xb, yb] = m.position(e.b);
        ex dx = xb - xa, dy = yb - ya;
        ex dd = m.rate(dx) * dx + m.rate(dy) * dy;
        ex d2 = trig_simplify(dx * dx + dy * dy);
        for (std::size_t i = 0; i < n; ++i) {
          const symbol& qi = m.coords[i].q;
          f.Q.push_back(collect_simplify(-e.k * dd * (dx * dx.diff(qi) + dy * dy.diff(qi)) / d2, l));
        }
      }
      f.power = power(f.Q);
      eq.forces.push_back(f);
    } else if (e.kind == "friction") {
      // the slip velocity of the material point under the friction
      auto [vx, vy] = m.velocity(e.a);
      eq.friction.push_back({idx, false, linear_rate(m, vx), linear_rate(m, vy), e.mu * e.normal});
    } else if (e.kind == "friction_couple") {
      eq.friction.push_back({idx, true, linear_rate(m, m.omega(e.body)), {}, e.M});
    } else if (e.kind == "contact") {
      // gap along the normal from party a into party b: g = (r_b − r_a)·n̂ (the plane through a
      // perpendicular to n̂); its rate is the normal approach speed
      auto [xa, ya] = m.position(e.a);
      auto [xb, yb] = m.position(e.b);
      ContactTerm c{idx, trig_simplify((xb - xa) * e.nx + (yb - ya) * e.ny), {}, {}, e.e, e.stick};
      auto [vax, vay] = m.velocity(e.a);
      auto [vbx, vby] = m.velocity(e.b);
      c.normal = linear_rate(m, (vbx - vax) * e.nx + (vby - vay) * e.ny);
      c.tangent = linear_rate(m, -(vbx - vax) * e.ny + (vby - vay) * e.nx);
      eq.contacts.push_back(c);
    } else if (e.kind == "impulse") {
      // P_i = J · ∂r_P/∂q_i
      ImpulseTerm im{idx, {}};
      for (std::size_t i = 0; i < n; ++i) {
        auto [dx, dy] = m.position_derivative(e.a, m.coords[i].q);
        im.P.push_back(trig_simplify(e.Jx * dx + e.Jy * dy));
      }
      eq.impulses.push_back(im);
    } else {
      throw SceneError(e.pos, "effect '" + e.name + "' of kind '" + e.kind + "' cannot be simulated",
                       "remove it from the scene to simulate the rest");
    }
  }

  // holonomic constraints g(q, t) = 0:  A q̈ = γ,  γ = −d/dt(A q̇ + ∂g/∂t) at q̈ = 0
  const std::size_t nc = m.constraints.size();
  eq.A = matrix(nc, n);
  for (std::size_t r = 0; r < nc; ++r) {
    const ex& g = m.constraints[r].first;
    eq.g.push_back(g);
    for (std::size_t i = 0; i < n; ++i) eq.A(r, i) = trig_simplify(g.diff(m.coords[i].q));
    eq.gt.push_back(trig_simplify(g.diff(m.t)));
    eq.gamma.push_back(collect_simplify(-m.rate(m.rate(g)), l));
  }

  eq.T = m.kinetic_energy();
  eq.V = m.potential_energy();
  return eq;
}

std::string Equations::text(const model::Model& m) const {
  std::ostringstream os;
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
      if (!M(i, j).is_zero()) os << "  M[" << name(i) << "," << name(j) << "] = " << M(i, j) << "\n";
  bool any_c = false;
  for (auto& ci : c) any_c = any_c || !ci.is_zero();
  if (any_c) {
    os << "\nc(q, q', t) (velocity products):\n";
    for (std::size_t i = 0; i < n; ++i)
      if (!c[i].is_zero()) os << "  c[" << name(i) << "] = " << c[i] << "\n";
  }
  for (auto& f : forces) {
    const auto& e = m.effects[static_cast<std::size_t>(f.effect)];
    os << "\nQ from " << e.name << " (" << e.kind << "):\n";
    for (std::size_t i = 0; i < n; ++i)
      if (!f.Q[i].is_zero()) os << "  Q[" << name(i) << "] = " << f.Q[i] << "\n";
  }
  for (auto& f : friction) {
    const auto& e = m.effects[static_cast<std::size_t>(f.effect)];
    os << "\nQ from " << e.name << " (" << e.kind << "), sliding: ";
    if (f.rotary) os << "-(" << f.limit << ") sgn(w) dw/dq', w = " << f.x.v << "\n";
    else os << "-(" << f.limit << ") J^T v/|v|, v = (" << f.x.v << ", " << f.y.v << ")\n";
    os << "  sticking: v = 0 held by a force of at most " << f.limit << "\n";
  }
  for (auto& c : contacts) {
    const auto& e = m.effects[static_cast<std::size_t>(c.effect)];
    os << "\ncontact " << e.name << ": gap = " << c.gap << " >= 0, e = " << c.e
       << (c.stick ? ", rough (no slip after impact)" : "") << "\n";
  }
  for (auto& im : impulses) {
    const auto& e = m.effects[static_cast<std::size_t>(im.effect)];
    os << "\nimpulse " << e.name << " at the start:";
    for (std::size_t i = 0; i < n; ++i)
      if (!im.P[i].is_zero()) os << " P[" << name(i) << "] = " << im.P[i];
    os << "\n";
  }
  if (!g.empty()) {
    os << "\nconstraints g(q, t) = 0:\n";
    for (std::size_t r = 0; r < g.size(); ++r) os << "  " << g[r] << " = 0\n";
  }
  return os.str();
}

}  // namespace kinergy::simulate
