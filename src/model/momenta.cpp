// Momenta and impulses of the model: the bookkeeping behind impulse–momentum and impact.
#include <sstream>

#include "kinergy/common/error.hpp"
#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"

namespace kinergy::model {

using namespace GiNaC;

static lst rates_of(const std::vector<Coordinate>& coords) {
  lst l;
  for (auto& c : coords) l.append(c.qd);
  return l;
}

std::pair<ex, ex> Model::position_derivative(const PointRef& p, const symbol& q) const {
  if (p.body < 0 || p.ground) return {0, 0};
  if (p.world_place) {
    // ∂r/∂q of the material point at w: ∂r_G/∂q + ∂φ/∂q k × (w − r_G)
    const Body& b = bodies[p.body];
    ex dphi = b.angle.diff(q);
    return {b.x.diff(q) - dphi * (p.wy - b.y), b.y.diff(q) + dphi * (p.wx - b.x)};
  }
  auto [x, y] = position(p);
  return {x.diff(q), y.diff(q)};
}

ex Model::angular_momentum(const PointRef& p, const std::vector<int>& set) const {
  // H_P = Σ Ī ω + (r_G − r_P) × m v̄
  auto [px, py] = position(p);
  ex H = 0;
  for (int i : set) {
    const Body& b = bodies[i];
    ex vx = rate(b.x), vy = rate(b.y);
    H += b.inertia * omega(i) + b.mass * ((b.x - px) * vy - (b.y - py) * vx);
  }
  return collect_simplify(H, rates_of(coords));
}

std::pair<ex, ex> Model::linear_momentum(const std::vector<int>& set) const {
  // L = Σ m v̄
  ex Lx = 0, Ly = 0;
  for (int i : set) {
    Lx += bodies[i].mass * rate(bodies[i].x);
    Ly += bodies[i].mass * rate(bodies[i].y);
  }
  return {collect_simplify(Lx, rates_of(coords)), collect_simplify(Ly, rates_of(coords))};
}

ex Model::bind_mixed(const ex& e, int ps, int rs) const {
  exmap m;
  for (auto& c : coords) {
    m[c.q] = states[ps].sym.at(c.name).first;
    m[c.qd] = states[rs].sym.at(c.name).second;
  }
  m[t] = states[ps].t;
  return e.subs(m);
}

int Model::analysis_between(int from, int to) const {
  for (std::size_t i = 0; i < analyses.size(); ++i)
    if (analyses[i].from == from && analyses[i].to == to && analyses[i].kind != "energy") return static_cast<int>(i);
  return -1;
}

std::pair<ex, ex> Model::impulse(int ei, int ai) const {
  const Effect& e = effects[ei];
  const Analysis& a = analyses[ai];
  const std::string between = " between states " + states[a.from].name + " and " + states[a.to].name;
  if (e.kind == "contact") {
    auto it = a.contact_impulses.find(e.name);
    if (it == a.contact_impulses.end())
      throw InputError("contact '" + e.name + "' takes no part in an impact" + between,
                       "name it in the impact's 'contact' or 'contacts'");
    // P = J n + Jt t,  t = (−n_y, n_x)
    auto [J, Jt] = it->second;
    return {J * e.nx - Jt * e.ny, J * e.ny + Jt * e.nx};
  }
  if (e.kind == "impulse") return {e.Jx, e.Jy};
  if (e.kind == "pin") {
    if (!a.instant) {
      auto it = a.reactions.find(e.name);
      if (it == a.reactions.end())
        throw InputError("pin '" + e.name + "' is not external to the bodies of the analysis" + between,
                         "list in 'bodies' the body the pin holds, and not the body on its other side");
      return it->second;
    }
    // impact: the impulse on the pinned body = its momentum change minus the other impulses on it
    int b = e.b.body >= 0 ? e.b.body : e.a.body;
    if (b < 0) throw InputError("pin '" + e.name + "' joins no body", "pin a body point to a point");
    for (auto& c : constraints)
      for (auto& co : coords)
        if (c.first.has(co.q) && (bodies[b].x.has(co.q) || bodies[b].y.has(co.q) || bodies[b].angle.has(co.q)))
          throw InputError("the impulse of pin '" + e.name + "' cannot be told apart from the constraint impulses on '" +
                               bodies[b].name + "'",
                           "describe the body's motion with coordinates that need no constraint");
    for (std::size_t j = 0; j < effects.size(); ++j) {
      const Effect& o = effects[j];
      if (static_cast<int>(j) != ei && o.kind == "pin" && (o.a.body == b || o.b.body == b))
        throw InputError("body '" + bodies[b].name + "' has two pins, '" + e.name + "' and '" + o.name +
                             "'; their impulses cannot be told apart",
                         "ask for the impulse of a pin that holds a body alone");
    }
    const Body& B = bodies[b];
    ex vx = rate(B.x), vy = rate(B.y);
    ex Rx = B.mass * (bind_mixed(vx, a.from, a.to) - bind(vx, a.from));
    ex Ry = B.mass * (bind_mixed(vy, a.from, a.to) - bind(vy, a.from));
    for (int ci : a.contacts) {
      const Effect& c = effects[ci];
      auto [Px, Py] = impulse(ci, ai);
      if (c.b.body == b) { Rx -= Px; Ry -= Py; }
      if (c.a.body == b) { Rx += Px; Ry += Py; }
    }
    for (auto& o : effects)
      if (o.kind == "impulse" && o.a.body == b) {
        Rx -= o.Jx;
        Ry -= o.Jy;
      }
    return {Rx, Ry};
  }
  if ((e.kind == "force" || e.kind == "gravity") && !a.instant) {
    // ∫F dt over the interval for a force free of the motion
    ex Fx = 0, Fy = 0;
    if (e.kind == "force") {
      Fx = e.Fx;
      Fy = e.Fy;
    } else {
      for (int b : a.bodies) {
        Fx += bodies[b].mass * e.g * e.dir_x;
        Fy += bodies[b].mass * e.g * e.dir_y;
      }
    }
    for (auto& c : coords)
      if (Fx.has(c.q) || Fy.has(c.q) || Fx.has(c.qd) || Fy.has(c.qd))
        throw InputError("the force of '" + e.name + "' changes with the motion; its impulse has no closed form",
                         "ask for impulses of forces that are constant or functions of t");
    ex t1 = states[a.from].t, t2 = states[a.to].t;
    auto integral = [&](const ex& f) -> ex {
      if (!f.has(t)) return f * (t2 - t1);
      auto F = antiderivative(f, t);
      if (!F) throw InputError("the impulse of '" + e.name + "' has no closed form in t", "use an elementary function of t");
      return F->subs(t == t2) - F->subs(t == t1);
    };
    return {integral(Fx), integral(Fy)};
  }
  throw InputError("effect '" + e.name + "' (" + e.kind + ") has no impulse to report" + between,
                   "ask for the impulse of a contact, a pin, a given impulse, or a force over a momentum analysis");
}

ex Model::impact_loss(int ci, int ai) const {
  const Effect& c = effects[ci];
  const Analysis& a = analyses[ai];
  if (c.kind != "contact" || !a.instant)
    throw InputError("'loss' takes a contact and the two states of its impact", "write loss(hit, before, after)");
  auto it = a.contact_impulses.find(c.name);
  if (it == a.contact_impulses.end())
    throw InputError("contact '" + c.name + "' takes no part in that impact", "name it in the impact's contacts");
  auto [J, Jt] = it->second;
  auto vel = [&](const PointRef& p) -> std::pair<ex, ex> {
    if (p.ground) return {0, 0};
    return velocity(p);
  };
  auto [vbx, vby] = vel(c.b);
  auto [vax, vay] = vel(c.a);
  ex vn = bind((vbx - vax) * c.nx + (vby - vay) * c.ny, a.from);
  ex vt = bind(-(vbx - vax) * c.ny + (vby - vay) * c.nx, a.from);
  // T⁺ − T⁻ = Σ P·(v⁻ + v⁺)/2 with v_n⁺ = −e v_n⁻ and (stick) v_t⁺ = 0:
  //   lost = −½ [(1 − e) J v_n⁻ + Jt v_t⁻]
  return -((1 - c.e) * J * vn + (c.stick ? ex(Jt * vt) : ex(0))) / 2;
}

}  // namespace kinergy::model
