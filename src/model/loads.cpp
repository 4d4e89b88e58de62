// The kinematics of a load: what its force and couple do work along, once for every effect kind.
#include <algorithm>
#include <cmath>

#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"

namespace kinergy::model {

namespace {

/// The angle of a party's body, 0 for a fixed party.
ex angle_of(const Model& m, const PointRef& p) { return p.body >= 0 && !p.ground ? m.bodies[p.body].angle : ex(0); }

std::pair<ex, ex> velocity_of(const Model& m, const PointRef& p) {
  if (p.body < 0 || p.ground) return {0, 0};
  return m.velocity(p);
}

}  // namespace

std::pair<ex, ex> relative_velocity(const Model& m, const Load& l) {
  // v_rel = v_at − v_partner
  auto [vx, vy] = velocity_of(m, l.at);
  if (!l.partner) return {vx, vy};
  auto [ux, uy] = velocity_of(m, *l.partner);
  return {vx - ux, vy - uy};
}

ex relative_angle(const Model& m, const Load& l) { return angle_of(m, l.at) - (l.partner ? angle_of(m, *l.partner) : ex(0)); }

ex relative_omega(const Model& m, const Load& l) { return m.rate(relative_angle(m, l)); }  // ω_rel = dφ_rel/dt

Wrench force_of(const Model& m, const Load& l) {
  switch (l.kind) {
    case Load::Kind::Given:
      return {l.Fx, l.Fy, l.M};
    case Load::Kind::Slide: {
      // kinetic friction: F = −size v̂_rel, against the slip of its point over the partner
      auto [vx, vy] = relative_velocity(m, l);
      const ex v = sqrt(trig_simplify(vx * vx + vy * vy));
      return {-l.size * vx / v, -l.size * vy / v, 0};
    }
    case Load::Kind::Turn: {
      // a friction couple: M = −size sgn ω_rel
      const ex w = relative_omega(m, l);
      return {0, 0, -l.size * w / abs(w)};
    }
  }
  return {};
}

ex generalized_force(const Model& m, const Load& l, std::size_t i) {
  const GiNaC::symbol& q = m.coords[i].q;
  if (l.kind == Load::Kind::Given) {
    // Q_i = F·∂(r_at − r_partner)/∂q_i + M ∂(φ_at − φ_partner)/∂q_i
    auto [dx, dy] = m.position_derivative(l.at, q);
    if (l.partner) {
      auto [px, py] = m.position_derivative(*l.partner, q);
      dx -= px;
      dy -= py;
    }
    return l.Fx * dx + l.Fy * dy + l.M * relative_angle(m, l).diff(q);
  }
  // a force of the motion: Q_i = F·∂v_rel/∂q̇_i + M ∂ω_rel/∂q̇_i (∂v/∂q̇ = ∂r/∂q)
  const GiNaC::symbol& qd = m.coords[i].qd;
  const Wrench f = force_of(m, l);
  auto [vx, vy] = relative_velocity(m, l);
  return f.Fx * vx.diff(qd) + f.Fy * vy.diff(qd) + f.M * relative_omega(m, l).diff(qd);
}

ex power(const Model& m, const Load& l) {
  switch (l.kind) {
    case Load::Kind::Given: {
      // P = F·v_rel + M ω_rel
      auto [vx, vy] = relative_velocity(m, l);
      ex P = l.Fx * vx + l.Fy * vy;
      if (!l.M.is_zero()) P += l.M * relative_omega(m, l);
      return P;
    }
    case Load::Kind::Slide: {
      // P = −size |v_rel|: F·v_at on the one plus (−F)·v_partner on the other
      auto [vx, vy] = relative_velocity(m, l);
      return -l.size * sqrt(trig_simplify(vx * vx + vy * vy));
    }
    case Load::Kind::Turn:
      return -l.size * abs(relative_omega(m, l));  // P = −size |ω_rel|
  }
  return 0;
}

bool changes_with_motion(const Model& m, const Load& l) {
  for (auto& c : m.coords)
    for (const ex& e : {l.Fx, l.Fy, l.M, l.size})
      if (e.has(c.q) || e.has(c.qd)) return true;
  return false;
}

}  // namespace kinergy::model

namespace kinergy::model {

std::vector<std::string> Reaction::parts() const {
  switch (kind) {
    case Kind::Pin:
      return {"Rx", "Ry"};
    case Kind::Track:
      return {"N"};
    case Kind::Relation:
      return {"J"};
    case Kind::Contact:
      break;
  }
  return {};
}

bool Reaction::across(const std::vector<int>& set) const {
  auto in = [&](const PointRef& p) { return p.body >= 0 && !p.ground && std::find(set.begin(), set.end(), p.body) != set.end(); };
  switch (kind) {
    case Kind::Track:
      return in(a);  // the track is fixed: outside every set
    case Kind::Pin:
    case Kind::Relation:
      return in(a) != in(b);
    case Kind::Contact:
      break;
  }
  return false;
}

Reaction Reaction::pin(PointRef a, PointRef b) {
  Reaction r;
  r.kind = Kind::Pin;
  r.a = std::move(a);
  r.b = std::move(b);
  return r;
}

Reaction Reaction::track(PointRef a, ex nx, ex ny) {
  Reaction r;
  r.kind = Kind::Track;
  r.a = std::move(a);
  r.dir_x = std::move(nx);
  r.dir_y = std::move(ny);
  return r;
}

Reaction Reaction::relation(PointRef a, PointRef b, ex ux, ex uy, ex fx, ex fy, std::size_t constraint) {
  Reaction r = pin(std::move(a), std::move(b));
  r.kind = Kind::Relation;
  r.dir_x = std::move(ux);
  r.dir_y = std::move(uy);
  r.fx = std::move(fx);
  r.fy = std::move(fy);
  r.constraint = constraint;
  return r;
}

OneWay one_way(bool pulls, const std::string& body, const std::string& effect) {
  if (pulls)
    return {"cord '" + effect + "' goes slack", "tension", "a cord can only pull", "cord '" + effect + "' pulls on " + body,
            "cord '" + effect + "' would have to push on " + body, "keeps cord '" + effect + "' taut", "the cord", "goes slack",
            "where: [\"T(" + effect + ") = 0\"]"};
  return {body + " leaves '" + effect + "'", "normal force", "a surface can only push", "the surface of '" + effect + "' pushes on " + body,
          "the surface of '" + effect + "' would have to pull on " + body, "keeps " + body + " on '" + effect + "'", "the surface", "leaves",
          "where: [\"N(" + effect + ") = 0\"]"};
}

Reaction Reaction::contact(PointRef a, PointRef b, ex nx, ex ny, ex e, bool stick) {
  Reaction r = pin(std::move(a), std::move(b));
  r.kind = Kind::Contact;
  r.dir_x = std::move(nx);
  r.dir_y = std::move(ny);
  r.e = std::move(e);
  r.stick = stick;
  return r;
}

std::vector<int> Reaction::bodies() const {
  std::vector<int> out;
  for (const PointRef* p : {&a, &b})
    if (p->body >= 0 && !p->ground && std::find(out.begin(), out.end(), p->body) == out.end() && (kind != Kind::Track || p == &a))
      out.push_back(p->body);
  return out;
}

}  // namespace kinergy::model
