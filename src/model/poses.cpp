// Poses that cannot be (issue 47): two bodies in one place. Each body's outline as convex
// pieces (a disk as a 32-gon, a block, a rod as a segment), tested pair by pair with the
// separating axis theorem: two convex sets overlap by the least, over the axes normal to
// their edges, of the overlap of their projections.
#include <algorithm>
#include <cmath>
#include <limits>

#include "kinergy/model/poses.hpp"

#include "kinergy/model/inertia.hpp"
#include "kinergy/model/model.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::model {

using GiNaC::ex;

namespace {

using Piece = std::vector<std::pair<double, double>>;  // a convex outline (2 points: a segment)

/// A body's outline at `at` as convex pieces (its parts' for a composite body), and its size;
/// none for a particle or a wheel known by its radius of gyration alone (drawn at no size of
/// its own).
std::pair<std::vector<Piece>, double> pieces(const Body& B, const std::function<double(const ex&)>& at) {
  std::vector<Piece> out;
  double size = 0;
  const double gx = at(B.x), gy = at(B.y), phi = at(B.angle);
  auto add = [&](const std::string& shape, const std::vector<ex>& sizes, double cx, double cy, double turn) {
    if (shape.empty() || sizes.empty()) return;
    const InertiaShape& s = inertia_shape(shape);
    const double a = at(sizes[0]), b = sizes.size() > 1 ? at(sizes[1]) : a, c = std::cos(turn), d = std::sin(turn);
    if (!std::isfinite(a) || !std::isfinite(b)) return;
    Piece p;
    auto put = [&](double lx, double ly) { p.push_back({cx + c * lx - d * ly, cy + d * lx + c * ly}); };
    switch (s.outline) {
      case Outline::Bar: put(-a / 2, 0), put(a / 2, 0), size = std::max(size, a); break;
      case Outline::EdgeOn: put(s.span == 1 ? -a / 2 : -a, 0), put(s.span == 1 ? a / 2 : a, 0), size = std::max(size, s.span * a); break;
      case Outline::Rect: put(-a / 2, -b / 2), put(a / 2, -b / 2), put(a / 2, b / 2), put(-a / 2, b / 2), size = std::max({size, a, b}); break;
      case Outline::Round:
        for (int k = 0; k < 32; ++k) put(a * std::cos(k * M_PI / 16), a * std::sin(k * M_PI / 16));
        size = std::max(size, 2 * a);
        break;
      default: return;
    }
    out.push_back(std::move(p));
  };
  const bool drawn = B.parts.empty() && !B.drawn_shape.empty();
  if (B.parts.empty()) add(drawn ? B.drawn_shape : B.shape, drawn ? B.drawn_sizes : B.sizes, gx, gy, phi);
  for (auto& part : B.parts) {
    const double lx = at(part.lx), ly = at(part.ly);
    add(part.shape, part.sizes, gx + std::cos(phi) * lx - std::sin(phi) * ly, gy + std::sin(phi) * lx + std::cos(phi) * ly, phi + at(part.angle));
  }
  return {out, size};
}

/// How deep two convex pieces overlap: min over the axes n̂ normal to their edges of
///   min(max_A − min_B, max_B − min_A)   (projections on n̂)
/// (≤ 0: apart or touching).
double overlap(const Piece& A, const Piece& B) {
  double least = std::numeric_limits<double>::infinity();
  for (const Piece* P : {&A, &B}) {
    const std::size_t k = P->size();
    for (std::size_t i = 0; i < (k == 2 ? 1 : k); ++i) {
      const auto& p = (*P)[i];
      const auto& q = (*P)[(i + 1) % k];
      double nx = -(q.second - p.second), ny = q.first - p.first;
      const double len = std::hypot(nx, ny);
      if (!(len > 0)) continue;
      nx /= len, ny /= len;
      auto span = [&](const Piece& S) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (auto& [x, y] : S) lo = std::min(lo, x * nx + y * ny), hi = std::max(hi, x * nx + y * ny);
        return std::pair<double, double>{lo, hi};
      };
      const auto [a0, a1] = span(A);
      const auto [b0, b1] = span(B);
      least = std::min(least, std::min(a1 - b0, b1 - a0));
    }
  }
  // (two segments: also along each one, where they lie on one line)
  return least;
}

/// Does the scene join bodies i and j, so that one may stand over the other in the plane drawn:
/// a support or connector between them (a pin, a relation, a contact, a track: a rod pinned on a
/// disk, a collar on its rod), or an effect between the two (a spring, a torsion spring, friction
/// of one against the other: a ring on a turntable seen from above)?
bool joined(const Model& m, int i, int j) {
  auto pair = [&](int a, int b) { return (a == i && b == j) || (a == j && b == i); };
  for (auto& e : m.effects) {
    const auto r = e.reaction(m);
    if (r && pair(r->a.body, r->b.body)) return true;
    for (auto& l : e.loads(m))
      if (l.partner && pair(l.at.body, l.partner->body)) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> overlapping(const Model& m, const std::function<double(const ex&)>& at) {
  std::vector<std::string> out;
  std::vector<std::pair<std::vector<Piece>, double>> all;
  for (auto& b : m.bodies) all.push_back(pieces(b, at));
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      if (all[i].first.empty() || all[j].first.empty() || joined(m, static_cast<int>(i), static_cast<int>(j))) continue;
      // one centre on the other (two disks on one shaft, a ring laid on a turntable): bodies in
      // planes one behind the other, as a plane figure draws them
      const double gap = std::hypot(at(m.bodies[i].x) - at(m.bodies[j].x), at(m.bodies[i].y) - at(m.bodies[j].y));
      if (gap <= 1e-9 * std::max(all[i].second, all[j].second)) continue;
      // deeper than a hundredth of the smaller body (touching is not overlapping)
      const double tol = 0.01 * std::min(all[i].second, all[j].second);
      double deepest = 0;
      for (auto& a : all[i].first)
        for (auto& b : all[j].first) deepest = std::max(deepest, overlap(a, b));
      if (deepest > tol && std::isfinite(deepest))
        out.push_back(m.bodies[i].name + " and " + m.bodies[j].name + " overlap by " + numerics::g_text(deepest, 3) + " m");
    }
  return out;
}

std::vector<std::string> overlapping_at(const Model& m, int state, const GiNaC::exmap& values) {
  // q → q@S (its number), t → t@S, then the values
  const State& S = m.states.at(static_cast<std::size_t>(state));
  GiNaC::exmap at = values;
  for (auto& c : m.coords) {
    const auto it = values.find(S.sym.at(c.name).first);
    if (it == values.end()) return {};
    at[c.q] = it->second;
  }
  at[m.t] = values.count(S.t) ? values.at(S.t) : ex(0);
  auto num = [&](const ex& e) {
    try {
      const ex v = e.subs(at).subs(at).evalf();
      return GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real() ? GiNaC::ex_to<GiNaC::numeric>(v).to_double() : std::nan("");
    } catch (const std::exception&) {
      return std::nan("");
    }
  };
  return overlapping(m, num);
}

}  // namespace kinergy::model
