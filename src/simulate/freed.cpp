// The scene with its surfaces that only push able to let go (see freed.hpp).
//
// A one-sided track holds its point on the surface through the coordinates themselves: the ball
// on a dome has one coordinate, its angle. To follow the ball after it leaves, the simulator
// integrates the scene with one more coordinate per surface, the gap s: every point of the body
// is carried off by s n̂,
//   r' = r(q) + s n̂(q),   angle' = angle(q),
// n̂ the unit direction the surface pushes, at the place the coordinates keep the point (a line's
// normal; a circle's radius). On a line through r₀ the gap is n̂·(r' − r₀) − offset = s; on a
// circle |r' − c| − (R + offset) = s (outward; inward −s): s is the gap, and ṡ its rate. The
// surface is then a contact: closed (s = 0 held by a row whose multiplier is the normal force N),
// it opens where N falls to zero; open, the body flies, and strikes it again with the track's e.

#include "freed.hpp"

#include <algorithm>
#include <map>

#include <Eigen/Dense>

#include "kinergy/units/units.hpp"

namespace kinergy::simulate {

using namespace GiNaC;

namespace {

bool moves_with(const model::Body& b, const ex& q) { return b.x.has(q) || b.y.has(q) || b.angle.has(q); }

/// A relation with mu_s rolling body b on one of `tracks` (its `normal`), against a fixed party:
/// the track it rolls on, or −1.
int rolls_on(const model::Model& m, const model::Reaction& r, int b, const std::vector<int>& tracks) {
  if (r.kind != model::Reaction::Kind::Relation || r.mu_s.is_zero()) return -1;
  const bool fixed_other = (r.a.body == b && r.b.body < 0) || (r.b.body == b && r.a.body < 0);
  if (!fixed_other) return -1;
  for (int t : tracks)
    if (m.effects[static_cast<std::size_t>(t)].name == r.normal) return t;
  return -1;
}

/// Why body `b` cannot be freed from `tracks` ("" when it can): something else holds it, which
/// the shift would break. A relation rolling it on one of them is not in the way (it goes with
/// the surface).
std::string held_otherwise(const model::Model& m, int b, const std::vector<int>& tracks, const std::vector<bool>& on) {
  const model::Body& body = m.bodies[static_cast<std::size_t>(b)];
  for (std::size_t c = 0; c < m.bodies.size(); ++c) {
    if (static_cast<int>(c) == b) continue;
    for (auto& co : m.coords)
      if (moves_with(body, co.q) && moves_with(m.bodies[c], co.q))
        return "'" + body.name + "' and '" + m.bodies[c].name + "' move with the same coordinate " + co.name;
  }
  for (std::size_t k = 0; k < m.constraints.size(); ++k) {
    const model::Effect* carrier = m.carrier(k);
    if (carrier) {
      auto r = carrier->reaction(m);
      const std::size_t ci = static_cast<std::size_t>(m.effect_index(carrier->name));
      if ((!on.empty() && !on[ci]) || (r && rolls_on(m, *r, b, tracks) >= 0)) continue;
    }
    for (auto& co : m.coords)
      if (m.constraints[k].first.has(co.q) && moves_with(body, co.q)) return "a relation between the coordinates holds '" + body.name + "'";
  }
  for (std::size_t i = 0; i < m.effects.size(); ++i) {
    if (std::find(tracks.begin(), tracks.end(), static_cast<int>(i)) != tracks.end()) continue;
    if (!on.empty() && !on[i]) continue;
    auto r = m.effects[i].reaction(m);
    if (!r || r->kind == model::Reaction::Kind::Contact) continue;  // (a contact is geometric: it follows the body)
    if (rolls_on(m, *r, b, tracks) >= 0) continue;                  // (it rolls the body on its surface)
    auto bs = r->bodies();
    if (std::find(bs.begin(), bs.end(), b) != bs.end()) return "'" + m.effects[i].name + "' holds '" + body.name + "' too";
  }
  return "";
}

/// Do the coordinates move body b every way a free body moves — x, y and (unless a particle) its
/// angle — each coordinate it moves with a way of its own? The Jacobian of (x, y, angle) at
/// sample coordinates: its rank, and as many coordinates moving the body (two surfaces pushing it
/// the same way would give two gaps along one line: a mass matrix without an inverse).
bool moves_freely(const model::Model& m, int b, const exmap& values) {
  const model::Body& body = m.bodies[static_cast<std::size_t>(b)];
  const bool turns = !body.inertia.is_zero();
  std::vector<ex> place{body.x, body.y};
  if (turns) place.push_back(body.angle);
  exmap at = values;
  for (std::size_t i = 0; i < m.coords.size(); ++i) at[m.coords[i].q] = numeric(37 + 11 * static_cast<int>(i), 100);
  at[m.t] = numeric(1, 3);
  Eigen::MatrixXd J(static_cast<Eigen::Index>(place.size()), static_cast<Eigen::Index>(m.coords.size()));
  for (std::size_t r = 0; r < place.size(); ++r)
    for (std::size_t i = 0; i < m.coords.size(); ++i) {
      ex v = place[r].diff(m.coords[i].q).subs(at).evalf();
      if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) return false;
      J(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(i)) = ex_to<numeric>(v).to_double();
    }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
  lu.setThreshold(1e-9);
  std::size_t moving = 0;
  for (Eigen::Index i = 0; i < J.cols(); ++i) moving += J.col(i).norm() > 0;
  return static_cast<std::size_t>(lu.rank()) == place.size() && moving == place.size();
}

std::string unused_name(const model::Model& m, std::string name) {
  auto taken = [&](const std::string& s) {
    for (auto& c : m.coords)
      if (c.name == s) return true;
    for (auto& p : m.params)
      if (p.name == s) return true;
    return false;
  };
  while (taken(name)) name += "_";
  return name;
}

}  // namespace

Freed free_surfaces(const model::Model& m, const std::vector<bool>& on, const exmap& values) {
  Freed f{m, {}, {}};
  // the one-sided tracks that act, by the body each holds
  std::map<int, std::vector<int>> by_body;
  for (std::size_t i = 0; i < m.effects.size(); ++i) {
    if (!on.empty() && !on[i]) continue;
    auto r = m.effects[i].reaction(m);
    if (!r || r->kind != model::Reaction::Kind::Track || !r->one_sided) continue;
    if (r->a.body < 0 || r->a.world_place) {
      f.kept.emplace_back(static_cast<int>(i), "its point is not a point of the body");
      continue;
    }
    by_body[r->a.body].push_back(static_cast<int>(i));
  }
  for (auto& [b, tracks] : by_body) {
    const std::string why = held_otherwise(m, b, tracks, on);
    model::Model trial = f.m;
    model::Body& body = trial.bodies[static_cast<std::size_t>(b)];
    std::vector<Freed::Surface> mine;
    for (int i : tracks) {
      // n̂ where the scene keeps the point: the way the surface pushes
      const model::Reaction r = *m.effects[static_cast<std::size_t>(i)].reaction(m);
      const std::string name = unused_name(trial, m.effects[static_cast<std::size_t>(i)].name + "_gap");
      model::Coordinate c{name, m.effects[static_cast<std::size_t>(i)].pos, realsymbol(name), realsymbol(name + "_dot"),
                          units::Dimension::length(), realsymbol(name + "_ddot")};
      // r' = r(q) + s n̂(q)
      body.x += c.q * r.dir_x;
      body.y += c.q * r.dir_y;
      trial.coords.push_back(c);
      mine.push_back({i, c.q, tracks.size() == 1, -1});
    }
    // the relations that roll the body on its surfaces go with them
    for (std::size_t k = 0; k < m.effects.size(); ++k) {
      if (!on.empty() && !on[k]) continue;
      auto r = m.effects[k].reaction(m);
      const int t = r ? rolls_on(m, *r, b, tracks) : -1;
      for (auto& sf : mine)
        if (sf.effect == t) sf.rolling = static_cast<int>(k);
    }
    std::string not_free = why;
    if (not_free.empty() && !moves_freely(trial, b, values))
      not_free = "its coordinates do not move it every way a free body moves, each in a way of its own (they tie its turning to its place, as "
                 "in rolling, or keep its angle; or two surfaces push it the same way)";
    if (!not_free.empty()) {
      for (int i : tracks) f.kept.emplace_back(i, not_free);
      continue;
    }
    f.m = std::move(trial);
    f.surfaces.insert(f.surfaces.end(), mine.begin(), mine.end());
  }
  std::sort(f.surfaces.begin(), f.surfaces.end(), [](auto& a, auto& b) { return a.effect < b.effect; });
  return f;
}

ContactTerm surface_contact(const Freed& f, const Freed::Surface& s) {
  const model::Model& freed = f.m;
  const model::Reaction r = *freed.effects[static_cast<std::size_t>(s.effect)].reaction(freed);
  ContactTerm c;
  c.effect = s.effect;
  c.surface = true;
  // the body's one surface: its gap is its own coordinate (exactly); more: each one's distance
  c.gap = s.alone ? ex(s.s) : r.gap;
  c.normal = linear_rate(freed, freed.rate(c.gap));
  // the slip across n̂ (t̂ = (−n_y, n_x)) of the point: not held (a smooth surface)
  auto [vx, vy] = freed.velocity(r.a);
  c.tangent = linear_rate(freed, -r.dir_y * vx + r.dir_x * vy);
  c.e = r.e;
  if (s.rolling >= 0) {
    // the rolling: its relation c(q, t) = 0 held at the velocity level, ċ = 0, while it sticks
    const model::Reaction rr = *freed.effects[static_cast<std::size_t>(s.rolling)].reaction(freed);
    c.rolling = s.rolling;
    c.stick = true;
    c.tangent = linear_rate(freed, freed.rate(freed.constraints[rr.constraint].first));
    c.mu_s = rr.mu_s;
    c.mu_k = rr.mu_k;
    c.force_per = sqrt(rr.fx * rr.fx + rr.fy * rr.fy);
  }
  return c;
}

}  // namespace kinergy::simulate
