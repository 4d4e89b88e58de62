// What the coordinates and constraints imply about how the bodies are held and joined (see
// connectors.hpp). Read at a state from the motions the scene allows there: the rates q̇ with
// J q̇ = 0 for every constraint, J_kj = ∂c_k/∂q_j, and each body's v̄ and ω along them.
#include "connectors.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/principles/momentum.hpp"

namespace kinergy::draw::detail {

using GiNaC::ex;

namespace {

/// A basis of the rates the constraints allow at `at`: the kernel of J (its columns); none
/// where J has no value there.
Eigen::MatrixXd allowed_rates(const model::Model& m, const At& at) {
  const auto nq = static_cast<Eigen::Index>(m.coords.size());
  if (m.constraints.empty()) return Eigen::MatrixXd::Identity(nq, nq);
  Eigen::MatrixXd J(static_cast<Eigen::Index>(m.constraints.size()), nq);
  for (std::size_t k = 0; k < m.constraints.size(); ++k)
    for (std::size_t j = 0; j < m.coords.size(); ++j)
      J(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = at(m.constraints[k].first.diff(m.coords[j].q));
  if (!J.allFinite()) return Eigen::MatrixXd(nq, 0);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
  lu.setThreshold(1e-10);
  if (lu.dimensionOfKernel() == 0) return Eigen::MatrixXd(nq, 0);
  return lu.kernel();
}

/// A body's motion along each allowed rate k: v̄_k = Σ_j ∂r̄/∂q_j N_jk, ω_k = Σ_j ∂φ/∂q_j N_jk.
struct Moves {
  std::vector<double> vx, vy, w;
  bool known = true;
};

Moves moves_of(const model::Model& m, const At& at, const model::Body& B, const Eigen::MatrixXd& N) {
  Moves mv;
  std::vector<double> dx, dy, dw;
  for (auto& c : m.coords) {
    dx.push_back(at(B.x.diff(c.q)));
    dy.push_back(at(B.y.diff(c.q)));
    dw.push_back(at(B.angle.diff(c.q)));
  }
  for (Eigen::Index k = 0; k < N.cols(); ++k) {
    double vx = 0, vy = 0, w = 0;
    for (std::size_t j = 0; j < dx.size(); ++j) {
      const double n = N(static_cast<Eigen::Index>(j), k);
      vx += dx[j] * n;
      vy += dy[j] * n;
      w += dw[j] * n;
    }
    mv.known = mv.known && std::isfinite(vx) && std::isfinite(vy) && std::isfinite(w);
    mv.vx.push_back(vx);
    mv.vy.push_back(vy);
    mv.w.push_back(w);
  }
  return mv;
}

/// a = c·b for every allowed motion, with some b nonzero: the constant c (nothing otherwise).
std::optional<double> ratio(const std::vector<double>& a, const std::vector<double>& b) {
  std::size_t best = 0;
  for (std::size_t k = 0; k < b.size(); ++k)
    if (std::fabs(b[k]) > std::fabs(b[best])) best = k;
  if (b.empty() || !(std::fabs(b[best]) > 1e-12)) return std::nullopt;
  const double c = a[best] / b[best];
  for (std::size_t k = 0; k < b.size(); ++k)
    if (std::fabs(a[k] - c * b[k]) > 1e-7 * (std::fabs(a[k]) + std::fabs(c * b[k])) + 1e-12) return std::nullopt;
  return c;
}

bool depends(const model::Model& m, const ex& e, const GiNaC::symbol& q) {
  return e.has(q) && !principles::vanishes(m, model::trig_simplify(e.diff(q)));
}

/// Turns about a fixed centre: no coordinate moves its centre, one turns it.
bool pivoted(const model::Model& m, const model::Body& B) {
  if (B.x.has(m.t) || B.y.has(m.t)) return false;
  bool turns = false;
  for (auto& c : m.coords) {
    if (depends(m, B.x, c.q) || depends(m, B.y, c.q)) return false;
    turns = turns || depends(m, B.angle, c.q);
  }
  return turns;
}

/// Held by a support the scene names (a track on it, a pin to a fixed point): that draws itself.
bool held(const model::Model& m, int b, bool tracks_only = false) {
  for (auto& e : m.effects) {
    const auto r = e.reaction(m);
    if (!r || (r->kind != model::Reaction::Kind::Pin && r->kind != model::Reaction::Kind::Track)) continue;
    if (tracks_only && r->kind != model::Reaction::Kind::Track) continue;
    if (r->kind == model::Reaction::Kind::Pin && r->a.body >= 0 && r->b.body >= 0) continue;  // a joint between bodies
    if (r->a.body == b || r->b.body == b) return true;
  }
  return false;
}

/// The centre of the circle body B's mass centre keeps to about a fixed point, where one
/// coordinate q moves it: the centre of curvature r̄ + |r̄'|² k × r̄' / (r̄' × r̄''), when it does
/// not move with q.
std::optional<std::pair<ex, ex>> circle_centre(const model::Model& m, const model::Body& B) {
  if (B.x.has(m.t) || B.y.has(m.t)) return std::nullopt;
  const GiNaC::symbol* q = nullptr;
  for (auto& c : m.coords) {
    if (!depends(m, B.x, c.q) && !depends(m, B.y, c.q)) continue;
    if (q) return std::nullopt;
    q = &c.q;
  }
  if (!q) return std::nullopt;
  const ex x1 = B.x.diff(*q), y1 = B.y.diff(*q), x2 = x1.diff(*q), y2 = y1.diff(*q);
  const ex den = model::trig_simplify(x1 * y2 - y1 * x2), s = model::trig_simplify(x1 * x1 + y1 * y1);
  if (principles::vanishes(m, den)) return std::nullopt;
  const ex cx = model::trig_simplify(B.x - y1 * s / den), cy = model::trig_simplify(B.y + x1 * s / den);
  if (!principles::vanishes(m, model::trig_simplify(cx.diff(*q))) || !principles::vanishes(m, model::trig_simplify(cy.diff(*q))))
    return std::nullopt;
  return std::pair<ex, ex>{cx, cy};
}

}  // namespace

/// The sum of the given loads on body b across (nx, ny) at `at` (its weight, a push), and the
/// sum of their sizes (to judge the first against); with `weight`, of its weight alone.
std::pair<double, double> pressing(const model::Model& m, const At& at, int b, double nx, double ny, bool weight) {
  double across = 0, size = 0;
  for (auto& e : m.effects)
    for (const model::Load& l : e.loads(m)) {
      // F on its point's body, −F on its partner's (a spring's other end)
      if (l.kind != model::Load::Kind::Given || (weight && l.symbol != "W")) continue;
      const double sign = l.at.body == b ? 1 : (l.partner && l.partner->body == b) ? -1 : 0;
      if (sign == 0 || (l.partner && l.partner->body == l.at.body)) continue;
      const double fx = sign * at(l.Fx), fy = sign * at(l.Fy);
      if (!std::isfinite(fx) || !std::isfinite(fy)) continue;
      across += fx * nx + fy * ny;
      size += std::hypot(fx, fy);
    }
  return {across, size};
}

namespace {

struct Reader {
  const model::Model& m;
  const At& at;
  std::vector<Moves> mv;
  std::vector<bool> pivot;
  std::vector<std::optional<principles::CentreLine>> line;
  Implied out;

  double gx(int b) const { return at(m.bodies[static_cast<std::size_t>(b)].x); }
  // the state's values with each coordinate moved by 0.3 s (|q| + 0.1): other values of the
  // coordinates, for a property that must hold at all of them (s = 0: the state itself)
  static constexpr double kSamples[] = {0.0, 1.0, -1.3, 0.7};
  At perturbed(double s) const {
    At other = at;
    for (auto& co : m.coords) other.values[co.q] = at(co.q) + 0.3 * s * (std::fabs(at(co.q)) + 0.1);
    return other;
  }
  double gy(int b) const { return at(m.bodies[static_cast<std::size_t>(b)].y); }

  // a cord off drum a to body b: b moves along its line u through Ḡ_b, tangent to the circle of
  // radius d about a's centre C at T = Ḡ_b + ((C − Ḡ_b)·u) u, and at the speed of a's rim there:
  //   u·v̄_b = (ω_a k × (T − C))·u   for every allowed motion
  bool cord(int a, int b) {
    const double ux = at(line[b]->ux), uy = at(line[b]->uy), cx = gx(a), cy = gy(a);
    const double s = (cx - gx(b)) * ux + (cy - gy(b)) * uy, tx = gx(b) + s * ux, ty = gy(b) + s * uy;
    const double d = std::hypot(tx - cx, ty - cy);
    if (!(d > 1e-9 * (std::hypot(cx, cy) + std::hypot(tx, ty) + 1e-9))) return false;
    const double rim = -(ty - cy) * ux + (tx - cx) * uy;  // (k × (T − C))·u
    std::vector<double> along, drum;
    for (std::size_t k = 0; k < mv[b].vx.size(); ++k) {
      along.push_back(ux * mv[b].vx[k] + uy * mv[b].vy[k]);
      drum.push_back(rim * mv[a].w[k]);
    }
    auto c = ratio(along, drum);
    if (!c || std::fabs(*c - 1) > 1e-7) return false;
    out.cords.push_back({a, b, cx, cy, d, tx, ty});
    return true;
  }

  // two wheels about fixed centres A and B, D apart, with ω_b = κ ω_a, κ < 0: in mesh, their
  // pitch radii ρ_a ω_a = −ρ_b ω_b and ρ_a + ρ_b = D, so ρ_a = D|κ|/(1 + |κ|), ρ_b = D/(1 + |κ|)
  void mesh(int a, int b) {
    const double D = std::hypot(gx(a) - gx(b), gy(a) - gy(b));
    auto k = ratio(mv[b].w, mv[a].w);
    if (!k || !(*k < 0) || !(D > 0)) return;
    const double K = -*k;
    out.meshes.push_back({a, b, D * K / (1 + K), D / (1 + K)});
  }

  bool turns(int b) const {
    for (auto& c : m.coords)
      if (depends(m, m.bodies[static_cast<std::size_t>(b)].angle, c.q)) return true;
    return false;
  }

  // moved with other bodies: a coordinate moves both, or a relation ties coordinates of each
  bool coupled(int b) const {
    auto moved_by = [&](int x, const ex& e) {
      const model::Body& B = m.bodies[static_cast<std::size_t>(x)];
      for (auto& c : m.coords)
        if (e.has(c.q) && (B.x.has(c.q) || B.y.has(c.q) || B.angle.has(c.q))) return true;
      return false;
    };
    std::vector<ex> ties;
    for (auto& c : m.coords) ties.push_back(c.q);
    for (auto& [c, pos] : m.constraints) ties.push_back(c);
    for (const ex& t : ties)
      for (int o = 0; o < static_cast<int>(m.bodies.size()); ++o)
        if (o != b && moved_by(b, t) && moved_by(o, t)) return true;
    return false;
  }

  // a body on a line that no cord holds: rolling on a surface (ω = c u·v̄ for every allowed
  // motion, so its contact point P = Ḡ + (1/c) k × u is at rest: offset −1/c); else on a surface
  // its loads press it onto, or a guide where other bodies move it (line_support)
  void on_line(int b, bool on_cord) {
    const double ux = at(line[b]->ux), uy = at(line[b]->uy);
    if (turns(b) && !on_cord) {
      std::vector<double> along;
      for (std::size_t k = 0; k < mv[b].vx.size(); ++k) along.push_back(ux * mv[b].vx[k] + uy * mv[b].vy[k]);
      auto c = ratio(mv[b].w, along);
      if (c && std::fabs(*c) > 1e-12) {
        if (!held(m, b, true)) out.lines.push_back({b, ux, uy, -1 / *c});
        return;
      }
    }
    if (held(m, b)) return;
    auto [across, size] = pressing(m, at, b, -uy, ux, false);
    if (std::fabs(across) > 1e-9 * size || (!on_cord && coupled(b))) out.lines.push_back({b, ux, uy, 0});
  }

  // a centre the constraints keep to a fixed line though its coordinates alone do not (the
  // collar of a linkage, x = r cos θ + l cos β held at 0): n̂·r̄ = const + κ c_k for a relation
  // c_k = 0, so n̂·∂r̄/∂q_j − κ ∂c_k/∂q_j = 0 for every coordinate, here and at other values of the
  // coordinates: (n_x, n_y, κ) the one direction those rows leave free (a dead point included)
  std::optional<principles::CentreLine> line_by_relation(int b) const {
    const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
    for (auto& [c, pos] : m.constraints) {
      std::vector<Eigen::RowVector3d> rows;
      for (double s : kSamples) {
        const At other = perturbed(s);
        for (auto& co : m.coords) {
          const Eigen::RowVector3d row(other(B.x.diff(co.q)), other(B.y.diff(co.q)), -other(c.diff(co.q)));
          if (row.allFinite()) rows.push_back(row / std::max(row.norm(), 1e-300));
        }
      }
      if (rows.size() < 3) continue;
      Eigen::MatrixXd A(static_cast<Eigen::Index>(rows.size()), 3);
      for (std::size_t i = 0; i < rows.size(); ++i) A.row(static_cast<Eigen::Index>(i)) = rows[i];
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
      const auto& sv = svd.singularValues();
      if (!(sv(2) <= 1e-9 * sv(0)) || !(sv(1) > 1e-6 * sv(0))) continue;  // exactly one free direction
      const Eigen::Vector3d v = svd.matrixV().col(2);
      const double nn = std::hypot(v(0), v(1));
      if (!(nn > 1e-9)) continue;
      return principles::CentreLine{v(1) / nn, -v(0) / nn, false, false};
    }
    return std::nullopt;
  }

  // a named point P of body b whose place r_P = r̄ + R(φ) p keeps to a fixed line: every ∂r_P/∂q_j
  // along one u, here and at other values of the coordinates (a straight path)
  void points_on_lines(int b) {
    const model::Body& B = m.bodies[static_cast<std::size_t>(b)];
    for (auto& [name, lp] : B.points) {
      const ex px = B.x + cos(B.angle) * lp.first - sin(B.angle) * lp.second, py = B.y + sin(B.angle) * lp.first + cos(B.angle) * lp.second;
      double ux = 0, uy = 0;
      bool line = true, moves = false;
      for (double s : kSamples) {
        const At other = perturbed(s);
        for (auto& co : m.coords) {
          const double dx = other(px.diff(co.q)), dy = other(py.diff(co.q)), d = std::hypot(dx, dy);
          if (!std::isfinite(d) || d < 1e-12) continue;
          if (!moves) ux = dx / d, uy = dy / d, moves = true;
          line = line && std::fabs(dx * uy - dy * ux) <= 1e-9 * d;
        }
      }
      if (!moves || !line || px.has(m.t) || py.has(m.t)) continue;
      if (held_at(b, lp)) continue;
      const double x = at(px), y = at(py), nx = -uy, ny = ux, side = (gx(b) - x) * nx + (gy(b) - y) * ny;
      const double s = std::fabs(side) > 1e-9 * (std::fabs(x) + std::fabs(y) + 1) ? (side > 0 ? -1 : 1) : 0;
      out.points.push_back({b, name, x, y, ux, uy, s * nx, s * ny});
    }
  }

  // a support the scene names at that point (body axes lp) of the body: a track on it, a pin there
  bool held_at(int b, const std::pair<ex, ex>& lp) const {
    for (auto& e : m.effects) {
      const auto r = e.reaction(m);
      if (!r) continue;
      for (const model::PointRef* p : {&r->a, &r->b})
        if (p->body == b && !p->world_place && (p->lx - lp.first).expand().is_zero() && (p->ly - lp.second).expand().is_zero()) return true;
    }
    return false;
  }

  void read() {
    const Eigen::MatrixXd N = allowed_rates(m, at);
    const int nb = static_cast<int>(m.bodies.size());
    for (auto& B : m.bodies) {
      mv.push_back(moves_of(m, at, B, N));
      pivot.push_back(mv.back().known && pivoted(m, B));
    }
    for (int b = 0; b < nb; ++b) {
      line.push_back(mv[b].known ? principles::centre_line(m, b) : std::nullopt);
      if (!line.back() && mv[b].known && !pivot[b]) line.back() = line_by_relation(b);
    }
    std::set<int> on_cord;
    for (int b = 0; b < nb; ++b) {
      if (!line[b] || turns(b)) continue;
      for (int a = 0; a < nb; ++a)
        if (pivot[a] && cord(a, b)) on_cord.insert(b);
    }
    for (int a = 0; a < nb; ++a)
      for (int b = a + 1; b < nb; ++b)
        if (pivot[a] && pivot[b]) mesh(a, b);
    for (int b = 0; b < nb; ++b) {
      if (!mv[b].known || pivot[b]) continue;
      if (line[b]) {
        on_line(b, on_cord.count(b) > 0);
        continue;
      }
      // a bob (a particle) whose centre keeps its distance from a fixed point, held by nothing named
      // and moved with no other body (a ball at a rod's end is held by the rod)
      if (held(m, b) || !m.bodies[static_cast<std::size_t>(b)].inertia.is_zero() || coupled(b)) continue;
      if (auto c = circle_centre(m, m.bodies[static_cast<std::size_t>(b)])) {
        const double cx = at(c->first), cy = at(c->second);
        if (std::isfinite(cx) && std::isfinite(cy)) out.hangs.push_back({b, cx, cy});
      }
    }
    for (int b = 0; b < nb; ++b)
      if (mv[b].known && !pivot[b]) points_on_lines(b);
    for (auto& c : out.cords)
      if (m.bodies[static_cast<std::size_t>(c.drum)].shape == "gyration") out.rim[c.drum] = std::max(out.rim[c.drum], c.r);
    // where its loads and supports act on it: a tooth force at the pitch radius, a brake's shoe
    auto reach_to = [&](const model::PointRef& p) {
      if (p.body < 0 || m.bodies[static_cast<std::size_t>(p.body)].shape != "gyration") return;
      auto [px, py] = at.point(m.position(p));
      const double d = std::hypot(px - gx(p.body), py - gy(p.body));
      if (std::isfinite(d) && d > 0) out.rim[p.body] = std::max(out.rim[p.body], d);
    };
    for (auto& e : m.effects) {
      for (const model::Load& l : e.loads(m)) reach_to(l.at);
      if (const auto r = e.reaction(m)) {
        reach_to(r->a);
        reach_to(r->b);
      }
    }
    for (auto& g : out.meshes)
      for (auto [b, r] : {std::pair{g.a, g.ra}, std::pair{g.b, g.rb}})
        if (m.bodies[static_cast<std::size_t>(b)].shape == "gyration") out.rim[b] = std::max(out.rim[b], r);
  }

  // a `constraints:` relation is accounted for when a connector among the bodies it moves holds
  // them (the cord of yA = r φ − a, the rolling of x + r φ = 0, a track's ball rolling in a bowl)
  void explain() {
    std::vector<std::vector<int>> held_sets;
    for (auto& c : out.cords) held_sets.push_back({c.drum, c.body});
    for (auto& g : out.meshes) held_sets.push_back({g.a, g.b});
    for (auto& l : out.lines) held_sets.push_back({l.body});
    for (auto& h : out.hangs) held_sets.push_back({h.body});
    for (int b = 0; b < static_cast<int>(m.bodies.size()); ++b)
      if (held(m, b, true)) held_sets.push_back({b});
    for (std::size_t k = 0; k < m.constraints.size(); ++k) {
      if (m.carrier(k)) continue;
      std::set<int> moved;
      for (auto& c : m.coords) {
        if (!m.constraints[k].first.has(c.q)) continue;
        for (std::size_t b = 0; b < m.bodies.size(); ++b) {
          const model::Body& B = m.bodies[b];
          if (B.x.has(c.q) || B.y.has(c.q) || B.angle.has(c.q)) moved.insert(static_cast<int>(b));
        }
      }
      const bool ok = std::any_of(held_sets.begin(), held_sets.end(), [&](const std::vector<int>& s) {
        return std::all_of(s.begin(), s.end(), [&](int b) { return moved.count(b) > 0; });
      });
      if (!ok) out.unexplained.push_back({k, std::vector<int>(moved.begin(), moved.end())});
    }
  }
};

}  // namespace

Implied implied(const model::Model& m, const At& at) {
  Reader r{m, at, {}, {}, {}, {}};
  r.read();
  r.explain();
  return std::move(r.out);
}

namespace {

bool shown(const std::vector<int>* bodies, std::initializer_list<int> bs) {
  if (!bodies) return true;
  return std::all_of(bs.begin(), bs.end(), [&](int b) { return std::find(bodies->begin(), bodies->end(), b) != bodies->end(); });
}

}  // namespace

void draw_implied(const model::Model& m, const At& at, const Implied& imp, Figure& f, const std::vector<int>* bodies) {
  const double g = f.glyph();
  auto owner = [&](int b) { return "body " + m.bodies[static_cast<std::size_t>(b)].name; };
  // the edge of body b's drawing toward (x, y): where a cord to it ends
  auto edge = [&](int b, double x, double y) {
    const double bx = at(m.bodies[static_cast<std::size_t>(b)].x), by = at(m.bodies[static_cast<std::size_t>(b)].y), d = std::hypot(x - bx, y - by);
    if (!(d > 0)) return std::pair{bx, by};
    const double o = std::min(d, f.reach(owner(b), bx, by, (x - bx) / d, (y - by) / d));
    return std::pair{bx + o * (x - bx) / d, by + o * (y - by) / d};
  };
  for (auto& c : imp.cords) {
    if (!shown(bodies, {c.drum, c.body})) continue;
    f.owned_by("cord");
    // the drum the cord winds on, where the drum's own outline is not that circle
    if (!f.has_circle(c.cx, c.cy, c.r)) f.circle(c.cx, c.cy, c.r, Ink::Body);
    // to the body's edge facing the drum
    const auto [ex_, ey] = edge(c.body, c.tx, c.ty);
    f.line(c.tx, c.ty, ex_, ey, Ink::Cord);
  }
  for (auto& w : imp.meshes) {
    if (!shown(bodies, {w.a, w.b})) continue;
    f.owned_by("mesh");
    for (auto [b, r] : {std::pair{w.a, w.ra}, std::pair{w.b, w.rb}}) {
      const double cx = at(m.bodies[static_cast<std::size_t>(b)].x), cy = at(m.bodies[static_cast<std::size_t>(b)].y);
      if (!f.has_circle(cx, cy, r)) f.circle(cx, cy, r, Ink::Body);
    }
  }
  for (auto& l : imp.lines) {
    if (!shown(bodies, {l.body})) continue;
    const model::Body& B = m.bodies[static_cast<std::size_t>(l.body)];
    f.owned_by("support");
    line_support(m, at, f, l.body, at(B.x), at(B.y), l.ux, l.uy, l.offset);
  }
  for (auto& p : imp.points) {
    if (!shown(bodies, {p.body})) continue;
    // a surface through the point along its line, hatched away from the body; a slot where the
    // body's centre is on the line itself
    const double L = 4 * g;
    f.owned_by("support");
    if (p.nx == 0 && p.ny == 0) f.line(p.px - L * p.ux, p.py - L * p.uy, p.px + L * p.ux, p.py + L * p.uy, Ink::Support);
    else f.surface(p.px - L * p.ux, p.py - L * p.uy, p.px + L * p.ux, p.py + L * p.uy, p.nx, p.ny);
  }
  for (auto& h : imp.hangs) {
    if (!shown(bodies, {h.body})) continue;
    f.owned_by("hang");
    // to the bob's edge facing the point
    const auto [ex_, ey] = edge(h.body, h.cx, h.cy);
    f.line(h.cx, h.cy, ex_, ey, Ink::Cord);
    f.circle(h.cx, h.cy, g * 0.45, Ink::Support);
    f.ground(h.cx, h.cy, 0, 1);
  }
  // a relation no connector accounts for: a dashed link between the first two bodies it moves,
  // named by the relation (at the body, where it moves one)
  for (auto& l : imp.unexplained) {
    if (l.bodies.empty()) continue;
    f.owned_by("constraint " + std::to_string(l.k + 1));
    const model::Body& A = m.bodies[static_cast<std::size_t>(l.bodies[0])];
    const model::Body& B = m.bodies[static_cast<std::size_t>(l.bodies.size() > 1 ? l.bodies[1] : l.bodies[0])];
    const double x1 = at(A.x), y1 = at(A.y), x2 = at(B.x), y2 = at(B.y);
    if (l.bodies.size() > 1) f.line(x1, y1, x2, y2, Ink::Hidden);
    else f.circle(x1, y1, 0.8 * g, Ink::Hidden);
    f.label((x1 + x2) / 2, (y1 + y2) / 2, model::text(m.constraints[l.k].first) + " = 0");
  }
  f.owned_by("");
}

}  // namespace kinergy::draw::detail

namespace kinergy::draw {

std::map<int, double> wheel_rims(const model::Model& m, const At& at) { return detail::implied(m, at).rim; }

void line_support(const model::Model& m, const At& at, Figure& f, int b, double px, double py, double ux, double uy, double offset, int pushes) {
  const double g = f.glyph(), nx = -uy, ny = ux;
  const std::string owner = b >= 0 ? "body " + m.bodies[static_cast<std::size_t>(b)].name : "";
  const double L = std::max(4 * g, 1.6 * f.reach(owner, px, py, ux, uy));
  // a surface through (fx, fy) along u, its ground on the side s n̂
  auto surface = [&](double fx, double fy, double s) { f.surface(fx - L * ux, fy - L * uy, fx + L * ux, fy + L * uy, s * nx, s * ny); };
  // a round body at `offset` on the normal's side of its surface: the foot P − offset n̂, the
  // ground beyond it
  if (offset != 0) return surface(px - offset * nx, py - offset * ny, offset > 0 ? -1 : 1);
  // a surface that pushes along σ n̂: at the body's edge the other way (a rod's end: the point
  // itself), its ground behind it
  if (pushes != 0) {
    const double s = -pushes, o = b >= 0 ? f.reach(owner, px, py, s * nx, s * ny) : 0;
    return surface(px + o * s * nx, py + o * s * ny, s);
  }
  // its weight presses the body across the line, and all its given loads to the same side
  // (Σ F·n̂ of the same sign as W·n̂): it rests on a surface at its edge on that side; else a
  // guide holds it (a collar's rod: a spring or a cord pulling it across)
  if (b >= 0) {
    auto [across, size] = detail::pressing(m, at, b, nx, ny, false);
    auto [weight, w] = detail::pressing(m, at, b, nx, ny, true);
    if (std::fabs(weight) > 1e-9 * w && std::fabs(across) > 1e-9 * size && (across > 0) == (weight > 0)) {
      const double s = across > 0 ? 1 : -1, o = f.reach(owner, px, py, s * nx, s * ny);
      return surface(px + o * s * nx, py + o * s * ny, s);
    }
  }
  f.line(px - L * ux, py - L * uy, px + L * ux, py + L * uy, Ink::Support);
}

}  // namespace kinergy::draw
