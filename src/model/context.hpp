// The expression context of a scene (private to src/model): which names an expression may use
// where it stands, and the built-in quantities (T, V, speed(P), impulse(effect, S1, S2), …).
#pragma once
#include <optional>
#include <string>

#include "kinergy/common/error.hpp"
#include "kinergy/expr/parser.hpp"
#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"

namespace kinergy::model {

using namespace GiNaC;

/// The list of a model's states, for a fix.
/// Exact arithmetic with b^n takes time and memory in proportion to n (0.5^1000000000 has a
/// billion-bit denominator): an integer exponent beyond 10^5, written or given by the parameters'
/// values, is refused. @returns e. @throws InputError.
inline ex guard_powers(const Model& m, const ex& e) {
  std::optional<exmap> params, given;  // built once, and only for an exponent that is not a number
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!is_a<GiNaC::power>(*it)) continue;
    ex n = it->op(1);
    if (!is_a<numeric>(n)) {
      if (!params) {
        params = m.parameter_values();
        given = m.given_values();
      }
      try {
        // with the parameters' values and the values given at the states (x@1 in an exponent)
        n = n.subs(*params).subs(*given).subs(*params);
      } catch (const std::exception&) {
        continue;  // undefined for the values: reported where it is used
      }
    }
    // any real exponent: GiNaC splits 0.5^(10^9 + 1/2) into an integer power and a root
    if (!is_a<numeric>(n) || !ex_to<numeric>(n).is_real() || abs(ex_to<numeric>(n)) <= expr::kMaxExponent) continue;
    // (the power itself is not printed: GiNaC's own printer orders its terms by addresses)
    throw InputError("a power here has the exponent " + text(n) + ", too large for exact arithmetic",
                     "check the exponent: at most " + std::to_string(expr::kMaxExponent) + " in size (no physical quantity needs more)");
  }
  return e;
}

/// The name among `items` (each with a `name`) nearest to n, or "" when none is near.
template <class C>
std::string nearest(const std::string& n, const C& items) {
  std::vector<std::string> names;
  for (auto& x : items) names.push_back(x.name);
  return scene::closest(n, names);
}

inline std::string state_list(const Model& m) {
  std::string s;
  for (auto& st : m.states) s += (s.empty() ? "" : ", ") + st.name;
  return s.empty() ? std::string("none yet") : s;
}

/// Names a scene expression may use, by where it stands.
class SceneContext : public expr::Context {
public:
  enum Level { ParamsOnly, Geometry, Quantities };
  SceneContext(const Model& m, Level lv, bool states) : m_(m), level_(lv), states_(states) {}

  ex name(const std::string& id) override {
    if (id.find('.') != std::string::npos)
      throw InputError("'" + id + "' is a point, not a number",
                       "use x(" + id + "), y(" + id + "), speed(" + id + ") …");
    auto it = m_.names_.find(id);
    if (it != m_.names_.end()) {
      bool is_param = false;
      for (auto& p : m_.params) is_param = is_param || p.name == id;
      if (!is_param && level_ == ParamsOnly)
        throw InputError("'" + id + "' is a coordinate or rate; only parameters may stand here",
                         "write this in parameters only");
      bool is_rate = id.size() > 4 && id.compare(id.size() - 4, 4, "_dot") == 0;
      if (is_rate && level_ == Geometry)
        throw InputError("a rate '" + id + "' cannot stand in geometry",
                         "write positions in coordinates; velocities follow by differentiation");
      return it->second;
    }
    if (id == "t") {
      if (level_ == ParamsOnly)
        throw InputError("time 't' cannot stand here", "write this in parameters only");
      return m_.t;
    }
    if (level_ == Quantities) {
      if (id == "T") return m_.kinetic_energy();
      if (id == "V") return m_.potential_energy();
      if (id == "px" || id == "py") return quantity(id, {});
    }
    std::vector<std::string> names;
    for (auto& [k, v] : m_.names_) names.push_back(k);
    std::string near = scene::closest(id, names);
    throw InputError("unknown name '" + id + "'",
                     near.empty() ? "define it under parameters or coordinates"
                                  : "did you mean '" + near + "'?");
  }

  ex quantity(const std::string& f, const std::vector<std::string>& args) override {
    if (level_ != Quantities)
      throw InputError("'" + f + "(…)' is not a function here",
                       "use sin, cos, tan, asin, acos, atan, atan2, sqrt, exp, log, abs");
    auto one = [&](const char* what) -> const std::string& {
      if (args.size() != 1)
        throw InputError(f + " takes one argument, not " + std::to_string(args.size()),
                         std::string("write ") + f + "(" + what + ")");
      return args[0];
    };
    auto body = [&](const std::string& n) { return body_index(n); };
    if (f == "T") {
      if (args.empty()) return m_.kinetic_energy();
      // T(string): the tension of a cord (no body has the name), as N(string)
      if (args.size() == 1 && m_.body_index(args[0]) < 0)
        if (int e = m_.effect_index(args[0]); e >= 0)
          if (auto r = m_.effects[e].reaction(m_); r && r->pulls) return reaction("N", args[0]);
      return m_.kinetic_energy(body(one("body")));
    }
    if (f == "V") {
      if (args.empty()) return m_.potential_energy();
      int e = m_.effect_index(one("effect"));
      if (e < 0) throw InputError("no effect named '" + args[0] + "'", "name an effect of the scene");
      return m_.potential_energy(m_.effects[e]);
    }
    if (f == "omega") return m_.omega(body(one("body")));
    if (f == "x" || f == "y" || f == "vx" || f == "vy" || f == "speed") {
      PointRef p = m_.point(one("P"));
      if (f == "x") return m_.position(p).first;
      if (f == "y") return m_.position(p).second;
      auto [vx, vy] = m_.velocity(p);
      if (f == "vx") return vx;
      if (f == "vy") return vy;
      return sqrt(trig_simplify(vx * vx + vy * vy));
    }
    if (f == "alpha") return m_.d_dt(m_.omega(body(one("body"))));
    if (f == "ax" || f == "ay" || f == "a") {
      // a_P = d v_P / dt (q̈ at the state: kinetics at that instant)
      auto [vx, vy] = m_.velocity(m_.point(one("P")));
      ex ax = m_.d_dt(vx), ay = m_.d_dt(vy);
      if (f == "ax") return ax;
      if (f == "ay") return ay;
      return sqrt(ax * ax + ay * ay);
    }
    if (f == "Rx" || f == "Ry" || f == "R" || f == "N" || f == "F") return reaction(f, one("support"));
    if (f == "power") {
      int e = m_.effect_index(one("effect"));
      if (e < 0) throw InputError("no effect named '" + args[0] + "'", "name an effect of the scene");
      return m_.power(m_.effects[e]);
    }
    if (f == "H") {
      if (args.size() == 2) return m_.angular_momentum(m_.point(args[0]), {body(args[1])});
      return m_.angular_momentum(m_.point(one("P")));
    }
    if (f == "I" || f == "k") return inertia(f, args);
    if (f == "px" || f == "py") {
      std::vector<int> set;
      if (args.empty())
        for (std::size_t i = 0; i < m_.bodies.size(); ++i) set.push_back(static_cast<int>(i));
      else
        set.push_back(body(one("body")));
      auto [Lx, Ly] = m_.linear_momentum(set);
      return f == "px" ? Lx : Ly;
    }
    if (f == "force") {
      // the average force of an interaction across an energy analysis' body set (over distance)
      if (args.size() != 3) throw InputError("force takes an effect and two states", "write force(mesh, 1, 2)");
      int e = m_.effect_index(args[0]);
      if (e < 0) throw InputError("no effect named '" + args[0] + "'", "name an effect of the scene");
      int s1 = m_.state_index(args[1]), s2 = m_.state_index(args[2]);
      if (s1 < 0 || s2 < 0)
        throw InputError("no state named '" + (s1 < 0 ? args[1] : args[2]) + "'", "name two states of the scene");
      for (auto& a : m_.analyses)
        if (a.from == s1 && a.to == s2 && !a.type->impulsive())
          if (auto it = a.reactions.find(args[0]); it != a.reactions.end()) return sqrt(pow(it->second[0], 2));  // its size
      throw InputError("no energy analysis from state '" + args[1] + "' to '" + args[2] + "' isolates bodies that '" + args[0] +
                           "' joins to the rest",
                       "add '- energy: {from: " + args[1] + ", to: " + args[2] + ", bodies: [...]}' with one of its parties listed, "
                       "or over a duration write impulse(" + args[0] + ", " + args[1] + ", " + args[2] + ")/(t@" + args[2] + " - t@" +
                           args[1] + ")");
    }
    if (f == "impulse_x" || f == "impulse_y" || f == "impulse" || f == "loss") {
      if (args.size() != 3)
        throw InputError(f + " takes an effect and two states", "write " + f + "(hit, before, after)");
      int e = m_.effect_index(args[0]);
      if (e < 0) throw InputError("no effect named '" + args[0] + "'", "name an effect of the scene");
      int s1 = m_.state_index(args[1]), s2 = m_.state_index(args[2]);
      if (s1 < 0 || s2 < 0)
        throw InputError("no state named '" + (s1 < 0 ? args[1] : args[2]) + "'", "name two states of the scene");
      int ai = m_.analysis_between(s1, s2, args[0]);
      if (ai < 0)
        throw InputError("no momentum or impact analysis goes from state '" + args[1] + "' to '" + args[2] + "'",
                         "add one, e.g. '- impact: {from: " + args[1] + ", to: " + args[2] + ", contact: …}'");
      if (f == "loss") return m_.impact_loss(e, ai);
      auto [x, y] = m_.impulse(e, ai);
      if (f == "impulse_x") return x;
      if (f == "impulse_y") return y;
      return m_.effects[e].impulse_size(m_, ai, x, y);
    }
    throw InputError("unknown function '" + f + "'",
                     "use T, V, T(body), omega(body), alpha(body), x(P), y(P), vx(P), vy(P), speed(P), ax(P), ay(P), a(P), "
                     "Rx(pin), Ry(pin), R(pin), N(track), F(constraint), power(effect), "
                     "H(P), H(P, body), I(body), I(body, P), k(body), px, py, impulse(effect, S1, S2), impulse_x, impulse_y, loss(contact, S1, S2), "
                     "force(effect, S1, S2) "
                     "or a math function");
  }

  /// The body named n. @throws InputError naming the nearest body where there is none.
  int body_index(const std::string& n) const {
    int b = m_.body_index(n);
    if (b < 0) {
      std::string near = nearest(n, m_.bodies);
      throw InputError("no body named '" + n + "'", near.empty() ? "name a body of the scene" : "did you mean '" + near + "'?");
    }
    return b;
  }

  /// I(body [, P]) and k(body [, P]): the moment of inertia about the mass centre, Ī, or about a
  /// point P by the parallel-axis theorem, I_P = Ī + m d², d = |r_P − r_G| (at a state where P is
  /// not on the body); the radius of gyration k = √(I/m).
  ex inertia(const std::string& f, const std::vector<std::string>& args) const {
    if (args.empty() || args.size() > 2)
      throw InputError(f + " takes a body and, optionally, a point, not " + std::to_string(args.size()) + " arguments",
                       "write " + f + "(rod) about its mass centre, or " + f + "(rod, O) about a point");
    const Body& B = m_.bodies[static_cast<std::size_t>(body_index(args[0]))];
    ex I = B.inertia;
    if (args.size() == 2) {
      const auto [xp, yp] = m_.position(m_.point(args[1]));
      const ex dx = xp - B.x, dy = yp - B.y;
      I = I + B.mass * trig_simplify(dx * dx + dy * dy);
    }
    if (f == "I") return I;
    if (B.mass.is_zero())
      throw InputError("'" + args[0] + "' is a light body (no mass): it has no radius of gyration", "ask for I(" + args[0] + ") instead");
    return sqrt(I / B.mass);
  }

  /// What a support pushes with at an instant (kinetics at a state): a pin's Rx, Ry on its first
  /// party that is a body and R = |(Rx, Ry)|, a track's N along its normal (positive when a
  /// surface pushes), a constraint's F along û (up, or along +x), on its first party that is a body.
  ex reaction(const std::string& f, const std::string& name) const {
    int e = m_.effect_index(name);
    if (e < 0) throw InputError("no effect named '" + name + "'", "name a pin, a track or a constraint of the scene");
    auto it = m_.instant_reactions.find(name);
    auto r = m_.effects[e].reaction(m_);
    const bool closed = r && r->kind == Reaction::Kind::Contact && !r->holds.empty();
    if (closed && it != m_.instant_reactions.end()) {
      // a contact closed after its impact: R on its second party; N = R·n̂, F = R·t̂ with
      // t̂ = (−n_y, n_x), n̂ turning with the body whose surface it is; Rx, Ry reported on its
      // first party that is a body (the sign rule): −R where that is the first
      const auto& p = it->second;
      const auto [nx, ny] = m_.closed_normal(m_.effects[e]);
      if (f == "Rx") return r->a_first() ? -p[0] : p[0];
      if (f == "Ry") return r->a_first() ? -p[1] : p[1];
      if (f == "R") return sqrt(p[0] * p[0] + p[1] * p[1]);
      if (f == "N") return p[0] * nx + p[1] * ny;
      return -p[0] * ny + p[1] * nx;
    }
    const bool pin = r && r->kind == Reaction::Kind::Pin, track = r && r->kind == Reaction::Kind::Track,
               relation = r && r->kind == Reaction::Kind::Relation;
    if (it == m_.instant_reactions.end() || (f == "N" && !track) || (f == "F" && !relation) || ((f == "Rx" || f == "Ry" || f == "R") && !pin)) {
      const std::string forces = pin ? "Rx(" + name + "), Ry(" + name + "), R(" + name + ")"
                                 : track ? "N(" + name + ")"
                                 : relation ? "F(" + name + ")"
                                            : "";
      const std::string what = pin ? "a pin" : track ? "a track" : relation ? "a constraint" : "no support";
      throw InputError(f + "(" + name + ") is not a force '" + name + "' exerts: it is " + what,
                       forces.empty() ? "name a pin, a track or a constraint" : "write " + forces);
    }
    const auto& p = it->second;
    if (f == "Rx") return p[0];
    if (f == "Ry") return p[1];
    if (f == "R") return sqrt(p[0] * p[0] + p[1] * p[1]);
    return p[0];
  }

  ex at_state(const ex& e, const std::string& s) override {
    if (!states_)
      throw InputError("'@" + s + "' binds to a state, which cannot be done here",
                       "remove '@" + s + "'");
    int i = m_.state_index(s);
    if (i < 0) {
      std::string near = nearest(s, m_.states);
      throw InputError("no state named '" + s + "'",
                       near.empty() ? "define it under 'states' (the states are " + state_list(m_) + ")"
                                    : "did you mean '@" + near + "'?");
    }
    return m_.bind(e, i);
  }

private:
  const Model& m_;
  Level level_;
  bool states_;
};

}  // namespace kinergy::model
