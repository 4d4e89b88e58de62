#include "kinergy/model/model.hpp"

#include <cmath>
#include <cstdint>

#include <algorithm>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/trace.hpp"

#include "context.hpp"

namespace kinergy::model {

using namespace GiNaC;
using scene::Node;
using scene::Text;

// ---------------------------------------------------------------- dimensions

Dimension Model::dimension(const ex& e) const {
  if (is_a<numeric>(e) || is_a<constant>(e)) return {};
  if (is_a<symbol>(e)) {
    auto it = dims_.find(e);
    if (it == dims_.end()) throw DimensionError("'" + text(e) + "' has no known dimension");
    return it->second;
  }
  if (is_a<add>(e)) {
    // a float term is a value taken numerically in SI units (a work integral with no closed
    // form): it has the dimension of the terms it is added to
    auto is_float = [](const ex& x) { return is_a<numeric>(x) && !ex_to<numeric>(x).is_rational(); };
    std::size_t first = 0;
    while (first < e.nops() && is_float(e.op(first))) ++first;
    if (first == e.nops()) return {};
    Dimension d0 = dimension(e.op(first));
    for (std::size_t i = first + 1; i < e.nops(); ++i) {
      if (is_float(e.op(i))) continue;
      Dimension di = dimension(e.op(i));
      if (di != d0)
        throw DimensionError("'" + text(e.op(first)) + "' has dimension " + d0.str() + " but '" +
                             text(e.op(i)) + "' has " + di.str());
    }
    return d0;
  }
  if (is_a<mul>(e)) {
    Dimension d;
    for (std::size_t i = 0; i < e.nops(); ++i) d = d * dimension(e.op(i));
    return d;
  }
  if (is_a<GiNaC::power>(e)) {
    Dimension b = dimension(e.op(0));
    Dimension x = dimension(e.op(1));
    if (!x.dimensionless())
      throw DimensionError("the exponent '" + text(e.op(1)) + "' has dimension " + x.str() +
                           "; an exponent must be a pure number");
    if (b.dimensionless()) return {};
    if (!is_a<numeric>(e.op(1)) || !ex_to<numeric>(e.op(1)).is_rational())
      throw DimensionError("'" + text(e.op(0)) + "' (" + b.str() +
                           ") is raised to a non-numeric power '" + text(e.op(1)) + "'");
    return b.pow(ex_to<numeric>(e.op(1)));
  }
  if (is_a<function>(e)) {
    std::string n = ex_to<function>(e).get_name();
    if (n == "abs") return dimension(e.op(0));
    if (numerics::is_integral(e)) {
      // ∫_a^b f(ξ) dξ: f's dimension (ξ standing for an end) times the ends'
      Dimension a = dimension(e.op(2)), b = dimension(e.op(3));
      if (a != b) throw DimensionError("the ends of '" + text(e) + "' differ in dimension (" + a.str() + ", " + b.str() + ")");
      return dimension(e.op(0).subs(e.op(1) == e.op(2))) * a;
    }
    if (n == "atan2") {
      Dimension a = dimension(e.op(0)), b = dimension(e.op(1));
      if (a != b)
        throw DimensionError("atan2 arguments '" + text(e.op(0)) + "' (" + a.str() + ") and '" +
                             text(e.op(1)) + "' (" + b.str() + ") differ in dimension");
      return {};
    }
    for (std::size_t i = 0; i < e.nops(); ++i) {
      Dimension a = dimension(e.op(i));
      if (!a.dimensionless())
        throw DimensionError(n + "('" + text(e.op(i)) + "') takes a pure number or an angle, but '" +
                             text(e.op(i)) + "' has dimension " + a.str());
    }
    return {};
  }
  if (is_a<integral>(e)) return dimension(e.op(3)) * dimension(e.op(0));
  throw DimensionError("cannot tell the dimension of '" + text(e) + "'");
}

// ---------------------------------------------------------------- kinematics

ex Model::rate(const ex& e) const {
  // d/dt e(q, t) = Σ ∂e/∂q_i q̇_i + ∂e/∂t
  ex r = e.diff(t);
  for (auto& c : coords) r += e.diff(c.q) * c.qd;
  return r;
}

ex Model::d_dt(const ex& e) const {
  // d/dt e(q, q̇, t) = Σ ∂e/∂q_i q̇_i + Σ ∂e/∂q̇_i q̈_i + ∂e/∂t
  ex r = rate(e);
  for (auto& c : coords) r += e.diff(c.qd) * c.qdd;
  return r;
}

std::pair<ex, ex> Model::position(const PointRef& p) const {
  if (p.body < 0 || p.world_place) return {p.wx, p.wy};
  const Body& b = bodies[p.body];
  // r_P = r_G + R(φ) p_local,  R(φ) = [[cos φ, −sin φ], [sin φ, cos φ]]
  ex c = cos(b.angle), s = sin(b.angle);
  return {b.x + c * p.lx - s * p.ly, b.y + s * p.lx + c * p.ly};
}

ex Model::omega(int body) const { return rate(bodies[body].angle); }

std::pair<ex, ex> Model::velocity(const PointRef& p) const {
  if (p.body < 0) return {0, 0};
  if (p.world_place) {
    // material point of the body at world place w:  v = v̄ + ω k × (w − r_G)
    const Body& b = bodies[p.body];
    ex w = omega(p.body);
    return {rate(b.x) - w * (p.wy - b.y), rate(b.y) + w * (p.wx - b.x)};
  }
  auto [x, y] = position(p);
  return {rate(x), rate(y)};
}

lst Model::rates() const {
  lst l;
  for (auto& c : coords) l.append(c.qd);
  return l;
}

ex Model::kinetic_energy(int i) const {
  // T = ½ m v̄² + ½ Ī ω²
  const Body& b = bodies[i];
  ex vx = rate(b.x), vy = rate(b.y), w = omega(i);
  ex T = b.mass * (vx * vx + vy * vy) / 2 + b.inertia * w * w / 2;
  return collect_simplify(T, rates());
}

ex Model::kinetic_energy() const {
  ex T = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i) T += kinetic_energy(static_cast<int>(i));
  return collect_simplify(T, rates());
}

matrix Model::mass_matrix() const {
  // M(q) = Σ_bodies  m Jᵀ J + Ī Jωᵀ Jω,   J = ∂r_G/∂q,  Jω = ∂φ/∂q
  // (each body's J and Jω taken once per coordinate; the upper triangle mirrored)
  std::size_t n = coords.size();
  matrix M(n, n);
  std::vector<ex> jx(n), jy(n), jw(n);
  for (auto& b : bodies) {
    for (std::size_t i = 0; i < n; ++i) {
      jx[i] = b.x.diff(coords[i].q);
      jy[i] = b.y.diff(coords[i].q);
      jw[i] = b.angle.diff(coords[i].q);
    }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i; j < n; ++j)
        M(i, j) += b.mass * (jx[i] * jx[j] + jy[i] * jy[j]) + b.inertia * jw[i] * jw[j];
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) M(j, i) = M(i, j) = trig_simplify(M(i, j));
  return M;
}

ex Model::spring_length(const ex& d2) const {
  // |r_A − r_B| = √d². When d² is c·p² (a spring along a line), the length is ±√c·p with the
  // sign p has at the first state that fixes it: a spring does not pass through zero length.
  bool poly = true;
  for (auto& c : coords) poly = poly && d2.is_polynomial(c.q);
  if (poly) {
    ex f;
    try {
      // numerator and denominator factored apart, functions of parameters (sin β) standing in as
      // symbols, after sin² + cos² = 1: (x cos β + D cos β)² + (x sin β + D sin β)² is (x + D)²
      ex nd = numer_denom(trig_simplify(d2.expand()));
      f = factor_any(nd.op(0)) / factor_any(nd.op(1));
    } catch (const std::exception&) {
      return sqrt(d2);
    }
    ex c = 1, p;
    for (auto& x : factors_of(f)) {
      if (is_a<GiNaC::power>(x) && x.op(1).is_equal(2) && p.is_zero()) p = x.op(0);
      else c *= x;
    }
    bool c_free = true;
    for (auto& co : coords) c_free = c_free && !c.has(co.q);
    if (!p.is_zero() && c_free) {
      exmap env = numeric_environment();
      for (std::size_t s = 0; s < states.size(); ++s) {
        ex v;
        try {
          v = bind(p, static_cast<int>(s)).subs(states[s].given).subs(env).evalf();
        } catch (const std::exception&) {
          continue;  // undefined at this state: let another state decide
        }
        // (the sign chosen by is noted for a sweep: numeric/trace.hpp)
        if (is_a<numeric>(v) && numerics::tracing())
          numerics::note(bind(p, static_cast<int>(s)).subs(states[s].given),
                         ex_to<numeric>(v).is_real() ? std::optional<numeric>(ex_to<numeric>(v)) : std::nullopt);
        if (is_a<numeric>(v) && ex_to<numeric>(v).is_real() && !ex_to<numeric>(v).is_zero())
          return sqrt(c) * (ex_to<numeric>(v).is_positive() ? p : -p);
      }
    }
  }
  return sqrt(d2);
}

ex Model::potential_energy() const {
  ex V = 0;
  for (auto& e : effects) V += e.potential(*this);
  return V;
}

ex Model::angular_momentum(const PointRef& p) const {
  std::vector<int> all;
  for (std::size_t i = 0; i < bodies.size(); ++i) all.push_back(static_cast<int>(i));
  return angular_momentum(p, all);
}

int Model::state_index(const std::string& n) const {
  for (std::size_t i = 0; i < states.size(); ++i)
    if (states[i].name == n) return static_cast<int>(i);
  return -1;
}

ex Model::bind(const ex& e, int s) const {
  const State& st = states[s];
  exmap m;
  for (auto& c : coords) {
    auto& [q, qd] = st.sym.at(c.name);
    m[c.q] = q;
    m[c.qd] = qd;
  }
  m[t] = st.t;
  for (auto& [g, v] : st.instant) m[g] = v;
  return e.subs(m);
}

exmap Model::parameter_values() const {
  exmap m;
  for (auto& p : params)
    if (p.value) m[p.sym] = *p.value;
  return m;
}

exmap Model::given_values() const {
  exmap g;
  for (auto& s : states)
    for (auto& [k, v] : s.given) g[k] = v;
  return g;
}

exmap Model::numeric_environment() const {
  exmap m;
  int i = 0;
  for (auto& p : params) {
    if (p.value) m[p.sym] = *p.value;
    else if (!p.unknown) m[p.sym] = sample == 0 && !p.in ? numeric(1) + numeric(37 * (++i) % 97, 97) : sample_value(p, 0, sample);  // (the first in (1, 2))
  }
  return m;
}

namespace {
numeric pow_ten(int n) {
  numeric r = 1;
  for (int i = 0; i < n; ++i) r *= 10;
  return r;
}
}  // namespace

numeric Model::sample_value(const Parameter& p, int stream, int k) {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a of the name, then split-mix of (h, stream, k)
  for (unsigned char c : p.name) h = (h ^ c) * 1099511628211ULL;
  std::uint64_t z = h + 0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(k + 1) + 0xD1B54A32D192ED03ULL * static_cast<std::uint64_t>(stream);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  const double u = static_cast<double>(z >> 11) / 9007199254740992.0;  // in [0, 1)
  // where it has a range `in: [lo, hi]`: inside its middle 90 % (the ends are often where the
  // motion starts or a form is singular), log-evenly for a positive range of a quantity with a
  // dimension, else evenly
  double lo = 0, hi = 0, v = 0;
  if (p.in) {
    lo = ex_to<numeric>(p.in->first.evalf()).to_double();
    hi = ex_to<numeric>(p.in->second.evalf()).to_double();
    const double w = 0.05 + 0.9 * u;
    v = !p.dim.dimensionless() && lo > 0 ? std::exp(std::log(lo) + w * (std::log(hi) - std::log(lo))) : lo + w * (hi - lo);
  } else {
    v = p.angle ? 0.2 + 1.2 * u : p.dim.dimensionless() ? 0.1 + 0.8 * u : std::exp(std::log(0.1) + u * std::log(100.0));
  }
  // three significant digits (more where three would take it out of its range)
  for (int digits = 3;; ++digits) {
    if (v == 0) return numeric(0);
    const double e = std::floor(std::log10(std::fabs(v)));
    const numeric r = digits - 1 - e >= 0 ? numeric(static_cast<long>(std::llround(v * std::pow(10.0, digits - 1 - e)))) / pow_ten(static_cast<int>(digits - 1 - e))
                                           : numeric(static_cast<long>(std::llround(v * std::pow(10.0, digits - 1 - e)))) * pow_ten(static_cast<int>(e + 1 - digits));
    if (!p.in || digits >= 15 || (r.to_double() > lo && r.to_double() < hi)) return r;
  }
}

int Model::sample_digits(const numeric& v) {
  if (v.is_zero()) return 1;
  for (int digits = 3; digits < 15; ++digits) {
    const int e = static_cast<int>(std::floor(std::log10(std::fabs(v.to_double()))));
    const numeric scaled = v * (digits - 1 - e >= 0 ? pow_ten(digits - 1 - e) : numeric(1) / pow_ten(e + 1 - digits));
    if (scaled.is_integer()) return digits;
  }
  return 15;
}

bool Model::unvalued(const ex& e) const {
  return std::any_of(params.begin(), params.end(), [&](const Parameter& p) { return p.without_value() && e.has(p.sym); });
}
bool Model::unvalued() const {
  return std::any_of(params.begin(), params.end(), [](const Parameter& p) { return p.without_value(); });
}

int Model::fixed_sign(const ex& e) const {
  exmap vals;
  for (auto& p : params)
    if (p.value) vals[p.sym] = *p.value;
  try {
    ex v = e.subs(vals).evalf();
    if (is_a<numeric>(v) && numerics::tracing()) numerics::note(e, ex_to<numeric>(v).is_real() ? std::optional<numeric>(ex_to<numeric>(v)) : std::nullopt);
    if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real() || ex_to<numeric>(v).is_zero()) return 0;
    return ex_to<numeric>(v).is_positive() ? 1 : -1;
  } catch (const std::exception&) {
    return 0;
  }
}

const Parameter* Model::parameter(const std::string& n) const {
  for (auto& p : params)
    if (p.name == n) return &p;
  return nullptr;
}

int Model::body_index(const std::string& n) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == n) return static_cast<int>(i);
  return -1;
}

bool Analysis::instant() const { return type && type->instant(); }
bool Analysis::takes_blows() const { return type && type->impulsive() && !type->at_state(); }

Model::Contact Model::contact(int i) const {
  const Effect& e = effects[static_cast<std::size_t>(i)];
  auto r = e.reaction(*this);
  if (!r || r->kind != Reaction::Kind::Contact) throw std::logic_error("effect '" + e.name + "' is not a contact");
  return {e.name, e.pos, r->a, r->b, r->dir_x, r->dir_y, r->e, r->stick, r->lodged};
}

bool Model::is_contact(const Effect& e) const {
  auto r = e.reaction(*this);
  return r && r->kind == Reaction::Kind::Contact;
}

const Effect* Model::carrier(std::size_t k) const {
  for (auto& e : effects)
    if (auto r = e.reaction(*this)) {
      if (r->kind == Reaction::Kind::Relation && r->constraint == k) return &e;
      if (std::find(r->holds.begin(), r->holds.end(), k) != r->holds.end()) return &e;
    }
  return nullptr;
}

int Model::closed_from(const Effect& e) const {
  if (const auto r = e.reaction(*this); !r || r->holds.empty()) return -1;  // it does not stay closed
  const int self = effect_index(e.name);
  for (auto& a : analyses)
    if (const Struck* s = a.struck(); s && std::find(s->contacts.begin(), s->contacts.end(), self) != s->contacts.end()) {
      // closed for the analyses that follow its impact (none: the impact alone, nothing held)
      const int S = a.to;
      for (auto& b : analyses)
        if (&b != &a && std::min(b.from, b.to) >= S) return S;
      return -1;
    }
  return -1;
}

std::pair<ex, ex> Model::closed_normal(const Effect& e) const {
  const auto r = e.reaction(*this);
  if (!r || r->turns < 0) return {r ? r->dir_x : ex(0), r ? r->dir_y : ex(0)};
  const ex& phi = bodies[static_cast<std::size_t>(r->turns)].angle;
  const int S = closed_from(e);
  const ex turn = S >= 0 ? phi - bind(phi, S) : ex(0);
  // Rot(Δ) n̂₀ = (n_x cos Δ − n_y sin Δ, n_x sin Δ + n_y cos Δ)
  return {r->dir_x * cos(turn) - r->dir_y * sin(turn), r->dir_x * sin(turn) + r->dir_y * cos(turn)};
}

bool Model::constraint_at(std::size_t k, int s, bool rate) const {
  const Effect* e = carrier(k);
  if (!e) return true;
  if (auto r = e->reaction(*this); r && !r->holds.empty()) {
    const int S = closed_from(*e);  // a contact that has closed: from its impact's last state on
    return S >= 0 && s >= S;
  }
  if ((e->on >= 0 && s < e->on) || (e->off >= 0 && s > e->off)) return false;
  if (rate && s == e->on)
    for (auto& a : analyses)
      if (a.instant() && a.from == s) return false;  // it engages in that impact: its rates hold after it
  return true;
}

Effect::Activity Model::constraint_activity(std::size_t k, const Analysis& a) const {
  const Effect* e = carrier(k);
  if (e)
    if (auto r = e->reaction(*this); r && !r->holds.empty()) {
      // a contact that has closed holds over an analysis after its impact, not over one before
      const int S = closed_from(*e), lo = std::min(a.from, a.to), hi = std::max(a.from, a.to);
      if (S < 0) return Effect::Activity::None;
      if (lo >= S) return Effect::Activity::Whole;
      return hi <= S ? Effect::Activity::None : Effect::Activity::Part;
    }
  return e ? e->activity(a) : Effect::Activity::Whole;
}

std::vector<std::pair<ex, SourcePos>> Model::constraints_over(const Analysis& a) const {
  std::vector<std::pair<ex, SourcePos>> out;
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const auto act = constraint_activity(k, a);
    if (act == Effect::Activity::Part) {
      const Effect& e = *carrier(k);
      const int at = e.on > std::min(a.from, a.to) && e.on < std::max(a.from, a.to) ? e.on : e.off;
      throw SceneError(a.pos, "constraint effect '" + e.name + "' is switched " + (at == e.on ? "on" : "off") + " at state '" +
                                  states[at].name + "', inside this " + a.kind + " analysis (" + states[a.from].name + " -> " +
                                  states[a.to].name + "): the motion has other coordinates on either side of it",
                       "split the analysis at state '" + states[at].name + "'");
    }
    if (act == Effect::Activity::Whole) out.push_back(constraints[k]);
  }
  return out;
}

std::vector<std::pair<ex, SourcePos>> Model::constraints_between(int s1, int s2) const {
  std::vector<std::pair<ex, SourcePos>> out;
  for (std::size_t k = 0; k < constraints.size(); ++k)
    if (constraint_at(k, s1, false) && constraint_at(k, s2, false)) out.push_back(constraints[k]);
  return out;
}

int Model::effect_index(const std::string& n) const {
  for (std::size_t i = 0; i < effects.size(); ++i)
    if (effects[i].name == n) return static_cast<int>(i);
  return -1;
}

PointRef Model::point(const std::string& text) const {
  PointRef p;
  p.text = text;
  auto dot = text.find('.');
  if (dot == std::string::npos) {
    auto f = fixed_points.find(text);
    if (f != fixed_points.end()) {
      p.wx = f->second.first;
      p.wy = f->second.second;
      return p;
    }
    int b = body_index(text);
    if (b >= 0) {
      p.body = b;
      return p;
    }
    std::vector<std::string> names;
    for (auto& [k, v] : fixed_points) names.push_back(k);
    for (auto& b2 : bodies) names.push_back(b2.name);
    std::string near = scene::closest(text, names);
    throw InputError("'" + text + "' is neither a fixed point nor a body",
                     near.empty() ? "name a point under 'points', a body, or body.point"
                                  : "did you mean '" + near + "'?");
  }
  std::string bn = text.substr(0, dot), pn = text.substr(dot + 1);
  int b = body_index(bn);
  if (b < 0) {
    std::string near = nearest(bn, bodies);
    throw InputError("no body named '" + bn + "'",
                     near.empty() ? "define it under 'bodies'" : "did you mean '" + near + "'?");
  }
  auto it = bodies[b].points.find(pn);
  if (it == bodies[b].points.end()) {
    std::vector<std::string> names;
    for (auto& [k, v] : bodies[b].points) names.push_back(k);
    std::string near = scene::closest(pn, names);
    throw InputError("body '" + bn + "' has no point '" + pn + "'",
                     near.empty() ? "add it under " + bn + ".points, e.g. " + pn + ": [l/2, 0]"
                                  : "did you mean '" + bn + "." + near + "'?");
  }
  p.body = b;
  p.lx = it->second.first;
  p.ly = it->second.second;
  return p;
}

ex Model::parse(const std::string& text, const SourcePos& pos, bool allow_states) const {
  SceneContext ctx(*this, SceneContext::Quantities, allow_states);
  try {
    return guard_powers(*this, expr::parse(text, ctx));
  } catch (const InputError& e) {
    rethrow_at(pos, e);
  }
}

}  // namespace kinergy::model
