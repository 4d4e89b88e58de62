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

int Model::analysis_between(int from, int to, const std::string& effect) const {
  // first one that carries that effect's reaction (a body set it holds to the rest), else the first
  for (bool carries : {true, false})
    for (std::size_t i = 0; i < analyses.size(); ++i)
      if (analyses[i].from == from && analyses[i].to == to && analyses[i].type->impulsive() &&
          (!carries || analyses[i].reactions.count(effect)))
        return static_cast<int>(i);
  return -1;
}

std::pair<ex, ex> Model::impulse(int ei, int ai) const { return effects[ei].impulse(*this, ei, ai); }

ex Model::impact_loss(int ci, int ai) const { return effects[ci].impact_loss(*this, ai); }

}  // namespace kinergy::model
