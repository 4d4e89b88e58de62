// The builder: SceneDef → Model (symbols, units, bodies, effects, states, analyses, results),
// every input checked where it stands.
#include "kinergy/model/model.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "kinergy/common/error.hpp"
#include "kinergy/expr/parser.hpp"
#include "kinergy/model/inertia.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/trace.hpp"

#include "context.hpp"

namespace kinergy::model {

using namespace GiNaC;
using scene::Node;
using scene::Text;

/// The unit to write for a dimension, in words for a fix ("m/s"; angles: "rad or deg").
/// A unit or a quantity parsed from a text, an error placed at the text.
template <class F>
static auto read_at(const Text& t, F parse) {
  try {
    return parse(t.s);
  } catch (const InputError& e) {
    rethrow_at(t.pos, e);
  }
}

static std::string unit_words(const Dimension& d) {
  std::string n = units::si_name(d);
  return n.empty() ? std::string("rad or deg (or a pure number)") : n;
}

/// A dimension as a student reads it: "a pure number", "N (kg·m/s^2)", "m".
static std::string dim_words(const Dimension& d) {
  if (d.dimensionless()) return "a pure number (or an angle)";
  std::string n = units::si_name(d), s = d.str();
  if (n == "J") n = "J = N\u00b7m";  // a couple and an energy share it
  return "in " + (n == s ? s : n + " (" + s + ")");
}

/// An expression YAML cut at a comma inside `{…}` or `[…]` (its '(' is never closed): the error.
static void check_cut(const Node& n) {
  if (!n.is_scalar()) return;
  int depth = 0;
  for (char c : n.scalar) depth += c == '(' ? 1 : c == ')' ? -1 : 0;
  if (depth > 0)
    throw SceneError(n.pos, "'" + n.scalar + "' is cut at a comma: inside {…} and […] a comma separates entries, even within f(a, b)",
                     "put the expression in quotes, e.g. \"" + n.scalar + ", …)\"");
}

// ---------------------------------------------------------------- builder

class Builder : public EffectReader {
public:
  explicit Builder(const scene::SceneDef& d) : d_(d) {}
  std::set<std::size_t> added_kinetics_;  ///< kinetics analyses added for a result (kinetics_for)

  Model run() {
    m_.file = d_.file;
    m_.title = d_.title;
    m_.description = d_.description;
    // each part of the scene in the order later parts refer to earlier ones
    for (auto part : {&Builder::parameters, &Builder::coordinates, &Builder::fixed_points, &Builder::bodies,
                      &Builder::constraints, &Builder::effects, &Builder::light_coordinates, &Builder::states, &Builder::analyses, &Builder::finds,
                      &Builder::expects})
      (this->*part)();
    return std::move(m_);
  }

private:
  const scene::SceneDef& d_;
  Model m_;
  std::set<std::string> taken_;

  void reserve(const std::string& n, const SourcePos& pos, const std::string& what) {
    static const std::set<std::string> reserved = {"t", "pi", "T", "V"};
    if (reserved.count(n) || expr::is_math_function(n))
      throw SceneError(pos, "'" + n + "' is a reserved name and cannot name a " + what,
                       "choose another name, e.g. '" + n + "_1'");
    if (!taken_.insert(n).second)
      throw SceneError(pos, "the name '" + n + "' is used twice",
                       "give each parameter, coordinate and rate its own name");
  }

  ex parse(const Text& t, SceneContext::Level lv, bool states = false, const std::string& key = "") {
    SceneContext ctx(m_, lv, states);
    try {
      return guard_powers(m_, expr::parse(t.s, ctx));
    } catch (const InputError& e) {
      // "3 N*m" where an expression of parameters stands: say so, not "unexpected 'N'"
      std::optional<units::Quantity> q;
      try {
        q = units::parse_quantity(t.s);
      } catch (const InputError&) {
      }
      if (q && q->has_number && !q->unit.text.empty()) {
        bool name_ok = !key.empty() && std::isalpha(static_cast<unsigned char>(key[0]));
        for (char c : key) name_ok = name_ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
        std::string p = name_ok ? key + "0" : std::string("q0");
        // "2 m" may mean 2 times the parameter m
        std::string u = q->unit.text, also;
        if (m_.names_.count(u)) {
          std::string num = t.s.substr(0, t.s.find(u));
          while (!num.empty() && num.back() == ' ') num.pop_back();
          while (!num.empty() && num.front() == ' ') num.erase(0, 1);
          also = ", or write '" + num + "*" + u + "' for " + num + " times the parameter '" + u + "'";
        }
        throw SceneError(t.pos, "'" + t.s + "' is a number with a unit, but " +
                                    (key.empty() ? std::string("this") : "'" + key + "'") +
                                    " takes an expression of parameters",
                         "add a parameter '" + p + ": " + t.s + "' under parameters and write '" + p + "' here" + also);
      }
      rethrow_at(t.pos, e);
    }
  }

  Dimension dim(const ex& e, const SourcePos& pos, const std::string& key) {
    try {
      return m_.dimension(e);
    } catch (const DimensionError& err) {
      throw SceneError(pos, std::string("inconsistent units in '") + key + "': " + err.what(),
                       "make every term of a sum the same kind of quantity");
    }
  }

  void expect_dim(const ex& e, const Dimension& want, const SourcePos& pos, const std::string& key,
                  const std::string& fix) {
    Dimension got = dim(e, pos, key);
    if (!e.is_zero() && got != want)
      throw SceneError(pos, "'" + key + "' is " + dim_words(got) + " but must be " + dim_words(want), fix);
  }

  ex checked(const Text& t, SceneContext::Level lv, const Dimension& want, const std::string& key,
             const std::string& fix) {
    ex e = parse(t, lv, false, key);
    expect_dim(e, want, t.pos, key, fix);
    return e;
  }

  /// Numeric value with the parameters' values, if all are known. @throws SceneError when it
  /// is undefined (a division by zero) or not a real number.
  std::optional<numeric> value_of(const ex& e, const SourcePos& pos, const std::string& what) override {
    ex v;
    try {
      v = e.subs(m_.parameter_values()).evalf();
    } catch (const std::exception& err) {
      throw SceneError(pos, what + " is undefined for the parameters' values (" + math_fault(err) + ")",
                       "check the values of the parameters it uses");
    }
    if (!is_a<numeric>(v)) return std::nullopt;
    if (!ex_to<numeric>(v).is_real())
      throw SceneError(pos, what + " is not a real number for the parameters' values (it is " + text(v) + ")",
                       "check the values of the parameters it uses (a square root of a negative number?)");
    return ex_to<numeric>(v);
  }

  /// Where a value is written: a lone parameter's value, else the place that uses it.
  SourcePos value_place(const ex& e, const SourcePos& use) override {
    if (is_a<symbol>(e))
      for (auto& pd : d_.parameters)
        if (const Parameter* p = m_.parameter(pd.name); p && p->sym.is_equal(e)) return pd.value.pos;
    return use;
  }

  void positive(const ex& e, const SourcePos& pos, const std::string& what, bool allow_zero = false) override {
    auto v = value_of(e, pos, what);
    if (!v || !(allow_zero ? v->is_negative() : !v->is_positive())) return;
    const std::string must = allow_zero ? "zero or positive" : "positive";
    // a single parameter: the fix is where its value is written
    if (is_a<symbol>(e))
      for (auto& pd : d_.parameters)
        if (const Parameter* p = m_.parameter(pd.name); p && p->sym.is_equal(e))
          throw SceneError(pd.value.pos, "parameter '" + pd.name + "' is " + pd.value.s + ", but it stands for " + what +
                                             ", which must be " + must,
                           "give '" + pd.name + "' a " + (allow_zero ? "non-negative" : "positive") + " value");
    throw SceneError(pos, what + " must be " + must + ", but it is " + numerics::format(*v, 6),
                     "give it a " + std::string(allow_zero ? "non-negative" : "positive") + " value");
  }

  void parameters() {
    for (auto& p : d_.parameters) {
      reserve(p.name, p.pos, "parameter");
      units::Quantity q = read_at(p.value, units::parse_quantity);
      Parameter par;
      par.name = p.name;
      par.pos = p.pos;
      par.dim = q.unit.dim;
      par.unknown = q.unknown;
      // an angle (written in rad, deg or rev), not a pure number: where it has no value, sampled
      // as an angle is (Model::sample_value)
      const std::string& u = p.value.s;
      par.angle = par.dim.dimensionless() && (u.find("rad") != std::string::npos || u.find("deg") != std::string::npos ||
                                              u.find("rev") != std::string::npos);
      if (q.has_number) par.value = q.si;
      if (p.in) par.in = parameter_range(p, par);
      bool pos = !q.unknown && (!q.has_number ? !par.in || !ex_to<numeric>(par.in->first.evalf()).is_negative() : q.number.is_positive());
      if (pos) par.sym = possymbol(p.name);
      else par.sym = realsymbol(p.name);
      // the symbol's kind follows the value's sign (a positive symbol's simplifications hold only
      // for positive values): a choice, noted for a sweep (numeric/trace.hpp)
      if (q.has_number && numerics::tracing()) numerics::note(par.sym, q.number);
      m_.add_symbol(par.sym, par.dim);
      m_.names_[p.name] = par.sym;
      m_.params.push_back(par);
    }
  }

  /// `in: [lo, hi]` of parameter p: numbers in p's unit (an angle's bounds with their angle unit,
  /// `180 deg`), lo < hi, p's value inside; an unknown's range is its result's root choice.
  std::pair<ex, ex> parameter_range(const scene::ParameterDef& p, const Parameter& par) {
    const auto kind = [](const units::Dimension& d) {
      return d.dimensionless() ? std::string("a pure number (or an angle)") : "in " + units::si_name(d);
    };
    if (par.unknown)
      throw SceneError(p.in_pos, "'in' gives the range of a parameter with or without a value, and '" + p.name + "' is an unknown",
                       "remove 'in', and choose the unknown's root on its result: 'root: {in: [lo, hi]}'");
    auto bound = [&](const Text& b, const char* end) {
      // an end names a parameter (read as a unit otherwise): a range of numbers only
      if (std::any_of(d_.parameters.begin(), d_.parameters.end(), [&](const scene::ParameterDef& x) { return x.name == b.s; }))
        throw SceneError(b.pos, std::string("the ") + end + " end of 'in' of parameter '" + p.name + "' is not a number: '" + b.s + "' is a parameter",
                         "write a number with the parameter's unit, e.g. 'in: [0, 90 deg]'");
      units::Quantity q = read_at(b, units::parse_quantity);
      if (!q.has_number || q.unknown)
        throw SceneError(b.pos, std::string("the ") + end + " end of 'in' of parameter '" + p.name + "' is not a number",
                         "write a number with the parameter's unit, e.g. 'in: [0, 90 deg]'");
      if (q.unit.dim != par.dim)
        throw SceneError(b.pos, std::string("the ") + end + " end of 'in' of parameter '" + p.name + "' is " + kind(q.unit.dim) + ", and the parameter " +
                                    kind(par.dim),
                         "write it with a unit of the parameter's kind" + (par.dim.dimensionless() ? std::string(" (a bare number)") : " (" + units::si_name(par.dim) + ")"));
      // a bare number is an angle in rad: said with its unit, as the parameter is (0 alone is plain)
      if (par.angle && q.unit.text.empty() && !q.si.is_zero())
        throw SceneError(b.pos, std::string("the ") + end + " end of 'in' of angle '" + p.name + "' has no unit",
                         "write its unit, e.g. '" + b.s + " deg' or '" + b.s + " rad'");
      return q.si;
    };
    std::pair<ex, ex> r{bound(p.in->first, "lower"), bound(p.in->second, "upper")};
    auto num = [](const ex& e) { return ex_to<numeric>(e.evalf()); };
    if (!(num(r.first) < num(r.second)))
      throw SceneError(p.in_pos, "'in' of parameter '" + p.name + "' must be a range [lo, hi] with lo < hi", "write e.g. 'in: [0, 90 deg]'");
    if (par.value && (num(*par.value) < num(r.first) || num(*par.value) > num(r.second)))
      throw SceneError(p.value.pos, "parameter '" + p.name + "' = " + p.value.s + " lies outside its range 'in: [" + p.in->first.s + ", " +
                                        p.in->second.s + "]'",
                       "give a value inside the range, or widen the range");
    return r;
  }

  void coordinates() {
    for (auto& c : d_.coordinates) {
      reserve(c.name, c.pos, "coordinate");
      reserve(c.name + "_dot", c.pos, "rate");
      reserve(c.name + "_ddot", c.pos, "second rate");
      units::Unit u = read_at(c.unit, units::parse_unit);
      if (!u.dim.dimensionless() && u.dim != Dimension::length())
        throw SceneError(c.unit.pos, "coordinate '" + c.name + "' has unit '" + c.unit.s +
                                         "'; a coordinate is a length or an angle",
                         "write 'm' (or ft, in …) or 'rad'");
      Coordinate co{c.name, c.pos, realsymbol(c.name), realsymbol(c.name + "_dot"), u.dim, realsymbol(c.name + "_ddot"), c.label};
      m_.add_symbol(co.q, co.dim);
      m_.add_symbol(co.qd, co.dim / Dimension::time());
      m_.names_[c.name] = co.q;
      m_.names_[c.name + "_dot"] = co.qd;
      m_.add_symbol(co.qdd, co.dim / (Dimension::time() * Dimension::time()));
      m_.names_[c.name + "_ddot"] = co.qdd;
      m_.coords.push_back(co);
    }
    m_.add_symbol(m_.t, Dimension::time());
  }

  void fixed_points() {
    for (auto& p : d_.points) {
      ex x = checked(p.x, SceneContext::ParamsOnly, Dimension::length(), p.name + "[0]",
                     "a point's coordinates are lengths");
      ex y = checked(p.y, SceneContext::ParamsOnly, Dimension::length(), p.name + "[1]",
                     "a point's coordinates are lengths");
      if (m_.fixed_points.count(p.name))
        throw SceneError(p.pos, "point '" + p.name + "' is defined twice", "rename one of them");
      m_.fixed_points[p.name] = {x, y};
      if (!p.label.empty()) m_.point_labels[p.name] = p.label;
    }
  }

  void bodies() {
    const Dimension L = Dimension::length();
    for (auto& bd : d_.bodies) {
      if (m_.fixed_points.count(bd.name))
        throw SceneError(bd.pos, "'" + bd.name + "' names both a point and a body", "rename one");
      Body b;
      b.name = bd.name;
      b.pos = bd.pos;
      b.label = bd.label;
      if (bd.parts.empty()) {
        b.mass = mass(bd.mass, "the mass of '" + bd.name + "'");
        std::tie(b.shape, b.sizes, b.inertia) = shape_inertia(bd.inertia, b.mass);
      } else {
        compose(bd, b);
      }
      b.x = checked(bd.x, SceneContext::Geometry, L, "position[0]", "positions are lengths");
      b.y = checked(bd.y, SceneContext::Geometry, L, "position[1]", "positions are lengths");
      b.angle = bd.angle ? checked(*bd.angle, SceneContext::Geometry, Dimension{}, "angle",
                                   "an angle is a pure number (rad)")
                         : ex(0);
      if (!bd.parts.empty()) {
        // the scene places a composite body by its reference point O; its mass centre is
        // r̄ = r_O + R(φ) c, c = Σ m_i a_i / Σ m_i in body axes (b.ref = −c: O seen from G)
        const ex cx = -b.ref_x, cy = -b.ref_y;
        b.x = b.x + cos(b.angle) * cx - sin(b.angle) * cy;
        b.y = b.y + sin(b.angle) * cx + cos(b.angle) * cy;
      }
      if (bd.drawn_as) drawn_as(bd, b);
      for (auto& p : bd.points) {
        ex px = checked(p.x, SceneContext::ParamsOnly, L, p.name + "[0]",
                        "body points are lengths in body axes (parameters only)");
        ex py = checked(p.y, SceneContext::ParamsOnly, L, p.name + "[1]",
                        "body points are lengths in body axes (parameters only)");
        b.points[p.name] = {px + b.ref_x, py + b.ref_y};  // (through G)
        if (!p.label.empty()) m_.point_labels[bd.name + "." + p.name] = p.label;
      }
      if (m_.body_index(bd.name) >= 0)
        throw SceneError(bd.pos, "body '" + bd.name + "' is defined twice", "rename one");
      m_.bodies.push_back(b);
    }
    if (m_.bodies.empty() && !d_.analyses.empty())
      throw SceneError({d_.file, 1, 1}, "the scene has no bodies", "add a 'bodies:' section");
  }

  /// A body's or a part's mass: ≥ 0. 0 is a light body, no kinetic energy and no weight; a mass
  /// that is 0 by its parameters' values is written 0, so that no closed form divides by it
  /// (m g h = m v²/2 would give v for m = 0, where nothing determines it).
  ex mass(const Text& t, const std::string& what) {
    ex m = checked(t, SceneContext::ParamsOnly, Dimension::mass(), "mass", "a mass is in kg, g or slug");
    positive(m, t.pos, what, true);
    if (auto v = value_of(m, t.pos, what); v && v->is_zero()) m = 0;
    return m;
  }

  /// `drawn_as`: the outline of a body whose inertia has none (a particle, a radius of gyration,
  /// a given Ī), as a disk's or a plate's; refused for a body whose shape is its outline.
  void drawn_as(const scene::BodyDef& bd, Body& b) {
    const scene::InertiaDef& d = *bd.drawn_as;
    if (!bd.parts.empty() || (b.shape != "particle" && b.shape != "gyration" && b.shape != "centroidal"))
      throw SceneError(d.pos, "body '" + bd.name + "' is drawn as its " + (bd.parts.empty() ? "shape (" + b.shape + ")" : std::string("parts")) +
                                  ", so 'drawn_as' would draw something else",
                       "remove 'drawn_as': it is for a particle or a body known by its radius of gyration or its Ī");
    // drawn as the inertia shape whose outline it is (the scene allows these two)
    static const std::map<std::string, std::string> outline_of = {{"circle", "disk"}, {"rectangle", "plate"}};
    b.drawn_shape = outline_of.at(d.kind);
    for (auto& t : d.args) {
      ex e = checked(t, SceneContext::ParamsOnly, Dimension::length(), "drawn_as", "a drawn size is a length");
      positive(e, t.pos, "the size '" + t.s + "' of " + d.kind);
      b.drawn_sizes.push_back(e);
    }
  }

  /// An inertia shape's name, sizes and Ī for mass m (model/inertia.cpp).
  std::tuple<std::string, std::vector<ex>, ex> shape_inertia(const scene::InertiaDef& in, const ex& m) {
    const Dimension L = Dimension::length(), M = Dimension::mass();
    const InertiaShape& shape = inertia_shape(in.kind);
    std::vector<ex> a;
    for (auto& t : in.args) {
      Dimension want = shape.given ? M * L * L : L;
      ex e = checked(t, SceneContext::ParamsOnly, want, in.kind, shape.given ? "Ī is in kg·m^2" : "a size is a length");
      positive(e, t.pos, "the size '" + t.s + "' of " + in.kind);
      a.push_back(e);
    }
    return {shape.name, a, shape.inertia(m, a)};
  }

  /// A composite body from its parts (each welded to the others, its centre a_i in body axes
  /// from the reference point O):
  ///   m = Σ m_i,  c = Σ m_i a_i / m,  Ī = Σ (Ī_i + m_i |a_i − c|²)  (the parallel-axis theorem)
  void compose(const scene::BodyDef& bd, Body& b) {
    const Dimension L = Dimension::length();
    ex m = 0, sx = 0, sy = 0;
    for (auto& pd : bd.parts) {
      Body::Part p;
      p.name = pd.name;
      p.mass = mass(pd.mass, "the mass of part '" + pd.name + "' of '" + bd.name + "'");
      std::tie(p.shape, p.sizes, p.inertia) = shape_inertia(pd.inertia, p.mass);
      p.lx = checked(pd.x, SceneContext::ParamsOnly, L, "at[0]", "a part's centre is a length in body axes (parameters only)");
      p.ly = checked(pd.y, SceneContext::ParamsOnly, L, "at[1]", "a part's centre is a length in body axes (parameters only)");
      p.angle = pd.angle ? checked(*pd.angle, SceneContext::ParamsOnly, Dimension{}, "angle", "a part's turn in body axes is an angle (parameters only)")
                         : ex(0);
      m += p.mass;
      sx += p.mass * p.lx;
      sy += p.mass * p.ly;
      b.parts.push_back(p);
    }
    const auto total = value_of(m, bd.pos, "the mass of '" + bd.name + "'");
    if (m.is_zero() || (total && total->is_zero()))
      throw SceneError(bd.parts.front().pos, "the parts of body '" + bd.name + "' have no mass together, so it has no mass centre",
                       "give a part its mass (a light body of one shape is written 'mass: 0' without parts)");
    const ex cx = normal(sx / m), cy = normal(sy / m);
    ex I = 0;
    for (auto& p : b.parts) {
      p.lx = normal(p.lx - cx);  // (through G)
      p.ly = normal(p.ly - cy);
      I += p.inertia + p.mass * (p.lx * p.lx + p.ly * p.ly);
    }
    b.mass = m;
    b.inertia = factor(normal(I));
    b.ref_x = -cx;
    b.ref_y = -cy;
  }

  /// "lhs = rhs" as lhs − rhs, with its units checked; errors at the text's place.
  ex equation(const Text& t, SceneContext::Level lv, const std::string& key) {
    SceneContext ctx(m_, lv, false);
    ex e;
    try {
      e = guard_powers(m_, expr::parse_equation(t.s, ctx));
    } catch (const InputError& err) {
      rethrow_at(t.pos, err);
    }
    dim(e, t.pos, key);
    return e;
  }

  void constraints() {
    for (auto& c : d_.constraints) constraint(c, "constraint");
  }

  std::size_t constraint(const Text& c, const std::string& key) override {
    ex e = equation(c, SceneContext::Geometry, key);
    if (e.is_zero())
      throw SceneError(c.pos, "the constraint '" + c.s + "' says nothing (0 = 0)",
                       "write a relation between coordinates, e.g. x + r*phi = 0");
    bool has_q = false;
    for (auto& co : m_.coords) has_q = has_q || e.has(co.q);
    if (!has_q)
      throw SceneError(c.pos, "the constraint '" + c.s + "' has no coordinate",
                       "a constraint relates coordinates, e.g. x + r*phi = 0");
    // the same relation twice (up to a factor) would make the constraints dependent
    for (auto& [o, opos] : m_.constraints) {
      ex ratio = GiNaC::normal(e / o);
      if (is_a<numeric>(ratio))
        throw SceneError(c.pos, "the relation '" + c.s + "' is already the constraint on line " + std::to_string(opos.line),
                         "write it once: remove it from 'constraints:' when an effect holds it (its reaction can then be asked for)");
    }
    m_.constraints.push_back({e, c.pos});
    return m_.constraints.size() - 1;
  }
  std::size_t relation(const ex& c, const SourcePos& pos) override {
    m_.constraints.push_back({c, pos});
    return m_.constraints.size() - 1;
  }

  // --- effects: each kind reads its own options (src/effects/) through these ---
  const Model& model() const override { return m_; }
  const Node& option(const scene::EffectDef& e, const std::string& key, const std::string& example) override {
    const Node* n = e.options.get(key);
    if (!n)
      throw SceneError(e.pos, "effect '" + e.name + "' (" + e.kind + ") has no '" + key + "'",
                       "add '" + key + ": " + example + "'");
    return *n;
  }
  Text text_of(const Node& n, const std::string& key, const std::string& example) override {
    if (!n.is_scalar())
      throw SceneError(n.pos, "'" + key + "' must be a single value, not " + n.kind_name(),
                       "write e.g. '" + key + ": " + example + "'");
    return {n.scalar, n.pos};
  }
  void only(const scene::EffectDef& e, std::vector<std::string> keys) override {
    keys.push_back(e.kind);
    for (std::size_t i = 0; i + 1 < e.options.entries.size(); ++i)
      if (e.options.entries[i + 1].second.kind == Node::Kind::Null) check_cut(e.options.entries[i].second);
    for (auto& [k, v] : e.options.entries)
      if (std::find(keys.begin(), keys.end(), k.scalar) == keys.end()) {
        if (v.kind == Node::Kind::Null && scene::looks_cut(k.scalar))
          throw SceneError(k.pos, "'" + k.scalar + "' looks like the end of an expression cut at a comma: inside {…} a comma separates entries",
                           "put the expression in quotes, e.g. M: \"atan2(y, x)*M0\"");
        std::string list;
        for (auto& s : keys) list += (list.empty() ? "" : ", ") + s;
        std::string near = scene::closest(k.scalar, keys);
        throw SceneError(k.pos, "unknown key '" + k.scalar + "' in " + e.kind + " effect '" + e.name + "'",
                         near.empty() ? "use: " + list : "did you mean '" + near + "'?");
      }
  }
  PointRef point_ref(const Node& n, const std::string& key) override {
    if (!n.is_scalar())
      throw SceneError(n.pos, "'" + key + "' must name a point, not " + n.kind_name(),
                       "write body.point, a body, or a fixed point");
    try {
      return m_.point(n.scalar);
    } catch (const InputError& err) {
      rethrow_at(n.pos, err);
    }
  }
  /// `direction: positive|negative` of a friction effect: the sign of the motion it opposes.
  std::optional<int> direction_of(const scene::EffectDef& ed) override {
    const Node* d = ed.options.get("direction");
    if (!d) return std::nullopt;
    if (!d->is_scalar() || (d->scalar != "positive" && d->scalar != "negative"))
      throw SceneError(d->pos, "'direction' must be positive or negative",
                       "write 'direction: positive' (the motion the friction opposes goes the positive way)");
    return d->scalar == "positive" ? 1 : -1;
  }

  // A contact party: a point, a body, or the ground (a line, no point).
  PointRef party(const Node& n) override {
    if (n.is_scalar() && n.scalar == "ground") {
      PointRef p;
      p.ground = true;
      p.text = "ground";
      return p;
    }
    return point_ref(n, "contact");
  }

  int body_ref(const Node& n, const std::string& key) override {
    if (!n.is_scalar())
      throw SceneError(n.pos, "'" + key + "' must name a body, not " + n.kind_name(), "write the body's name");
    int b = m_.body_index(n.scalar);
    if (b < 0) {
      std::string near = nearest(n.scalar, m_.bodies);
      throw SceneError(n.pos, "no body named '" + n.scalar + "'",
                       near.empty() ? "name a body of the scene" : "did you mean '" + near + "'?");
    }
    return b;
  }
  std::pair<ex, ex> vec(const Node& n, const std::string& key, const Dimension& d, bool geometry,
                        const std::string& fix) override {
    return vec(n, key, d, geometry ? SceneContext::Geometry : SceneContext::ParamsOnly, fix);
  }
  std::pair<ex, ex> vec(const Node& n, const std::string& key, const Dimension& d, SceneContext::Level lv,
                        const std::string& fix) {
    const std::string example = key == "along" ? "along: x, y or a direction [nx, ny] such as [1, 1]"
                                : key == "normal" || key == "direction" ? key + ": [0, 1]"
                                : key == "J"     ? "J: [J0, 0]"
                                : key == "about" ? "about: {C: [-r, y]}"
                                                 : key + ": [0, -P]";
    if (!n.is_list() || n.items.size() != 2) {
      for (auto& it : n.items) check_cut(it);
      if (n.is_list())
        throw SceneError(n.pos, "'" + key + "' must have 2 entries [x, y], not " + std::to_string(n.items.size()),
                         "write e.g. " + example);
      throw SceneError(n.pos, "'" + key + "' must be a list [x, y], not " + n.kind_name(), "write e.g. " + example);
    }
    ex x = checked(text_of(n.items[0], key, "0"), lv, d, key + "[0]", fix);
    ex y = checked(text_of(n.items[1], key, "0"), lv, d, key + "[1]", fix);
    return {x, y};
  }

  ex quantity(const Text& t, bool geometry, const Dimension& want, const std::string& key,
             const std::string& fix) override {
    return checked(t, geometry ? SceneContext::Geometry : SceneContext::ParamsOnly, want, key, fix);
  }

  // `KIND: body` (acts on the body) or `KIND: [a, b]` (between two bodies: relative angle)
  std::pair<int, int> one_or_two_bodies(const scene::EffectDef& ed, const std::string& what) override {
    if (ed.arg.is_list()) {
      if (ed.arg.items.size() != 2)
        throw SceneError(ed.arg.pos, what + " acts on one body or between two", "write '" + ed.kind + ": [a, b]'");
      int b1 = body_ref(ed.arg.items[0], ed.kind);
      return {b1, body_ref(ed.arg.items[1], ed.kind)};
    }
    return {body_ref(ed.arg, ed.kind), -1};
  }

  // `KIND: body.P` (a body point or mass centre), or `KIND: body` with `at: [x, y]` (the body's
  // material point at that world place: a cord leaving a hub, a fixed brake shoe)
  PointRef acting_point(const scene::EffectDef& ed) override {
    if (auto* at = ed.options.get("at")) {
      PointRef a;
      a.body = body_ref(ed.arg, ed.kind);
      a.world_place = true;
      a.text = ed.arg.scalar + " at " + "place";
      auto [wx, wy] = vec(*at, "at", Dimension::length(), SceneContext::Geometry, "a place is a pair of lengths");
      a.wx = wx;
      a.wy = wy;
      return a;
    }
    PointRef a = point_ref(ed.arg, ed.kind);
    if (a.body < 0)
      throw SceneError(ed.arg.pos, "a " + ed.kind + " acts on a body, but '" + ed.arg.scalar + "' is a fixed point",
                       "name body.point or a body (its mass centre)");
    return a;
  }

  void effects() {
    const auto& kinds = effect_kinds();
    for (auto& ed : d_.effects) {
      // the scene has checked the kind's name against the same table
      auto kind = std::find_if(kinds.begin(), kinds.end(), [&](const EffectKind& k) { return k.name == ed.kind; });
      if (kind == kinds.end()) throw std::logic_error("effect kind '" + ed.kind + "' is not in the table");
      // 'on', 'off' and 'label' are every kind's: the states it acts between, how figures name it;
      // the kind reads the rest
      scene::EffectDef own = ed;
      const scene::Node *on = nullptr, *off = nullptr, *label = nullptr;
      std::vector<scene::Entry> kept;
      for (auto& entry : ed.options.entries) {
        if (entry.first.scalar == "on") on = &entry.second;
        else if (entry.first.scalar == "off") off = &entry.second;
        else if (entry.first.scalar == "label") label = &entry.second;
        else kept.push_back(entry);
      }
      own.options.entries = kept;
      std::shared_ptr<Effect> e = kind->read(*this, own);
      if (label) e->label = scene::read_label(*label, "effect '" + ed.name + "'");
      auto state_at = [&](const Node* n, const std::string& key) {
        if (!n) return -1;
        if (!n->is_scalar())
          throw SceneError(n->pos, "'" + key + "' names a state, not " + n->kind_name(), "write e.g. '" + key + ": 2'");
        std::vector<std::string> names;
        for (std::size_t i = 0; i < d_.states.size(); ++i) {
          if (d_.states[i].name == n->scalar) return static_cast<int>(i);
          names.push_back(d_.states[i].name);
        }
        std::string near = scene::closest(n->scalar, names), all;
        for (auto& x : names) all += (all.empty() ? "" : ", ") + x;
        throw SceneError(n->pos, "effect '" + ed.name + "': no state named '" + n->scalar + "'",
                         near.empty() ? "name one of the states: " + all : "did you mean '" + near + "'?");
      };
      e->on = state_at(on, "on");
      e->off = state_at(off, "off");
      if (e->on >= 0 && e->off >= 0 && e->off <= e->on)
        throw SceneError(off->pos, "effect '" + ed.name + "' is switched off at state '" + off->scalar + "', not after it is switched on (state '" +
                                       on->scalar + "'); states are in the order they are listed",
                         "switch it off at a later state, or list the states in the order they happen");
      if (m_.effect_index(e->name) >= 0)
        throw SceneError(ed.pos, "effect '" + e->name + "' is defined twice", "rename one");
      m_.effects.push_back(e);
    }
    for (auto& e : m_.effects) e.check(m_, -1, {});
  }

  /// Kinetics at an instant: each support's reaction as generic unknowns (a pin's Rx, Ry, a
  /// track's N, a relation's F along û; a contact acts in impacts only), and a multiplier λ_k for
  /// each constraint no effect holds.
  /// A coordinate that moves only bodies without mass (∂T/∂q̇ ≡ 0) and that no constraint ties to
  /// the others is fixed by those bodies' balance alone (Q = 0 at every instant: two springs in
  /// series with a light connector), which no analysis here derives: refused at the coordinate,
  /// naming what would be needed.
  void light_coordinates() {
    const ex T = m_.kinetic_energy();
    for (auto& co : m_.coords) {
      if (T.has(co.qd)) continue;
      std::string light;
      for (auto& b : m_.bodies)
        if (b.x.has(co.q) || b.y.has(co.q) || b.angle.has(co.q)) light += (light.empty() ? "" : ", ") + b.name;
      if (light.empty()) continue;
      bool tied = false;
      for (auto& [c, pos] : m_.constraints) tied = tied || c.has(co.q);
      if (tied) continue;
      // no load on them along it (Q ≡ 0): their place is indifferent, and nothing depends on it
      const std::size_t i = static_cast<std::size_t>(&co - m_.coords.data());
      ex Q = -m_.potential_energy().diff(co.q);
      for (auto& e : m_.effects)
        for (const Load& l : e.loads(m_)) Q += generalized_force(m_, l, i);
      if (normal(expand(Q)).is_zero()) continue;
      throw SceneError(co.pos, "coordinate '" + co.name + "' moves only bodies without mass (" + light +
                                   "), and no constraint ties it to the others: it follows from their balance (no mass, so the forces on them "
                                   "balance at every instant), which kinergy does not derive for a light body with a coordinate of its own",
                       "write the light body's position in the other coordinates from its balance (two springs in series: the connector "
                       "sits where their forces are equal), tie it by a constraint, or give it a mass");
    }
  }

  void instant_unknowns() {
    const Dimension F = Dimension::mass() * Dimension::length() / (Dimension::time() * Dimension::time());
    for (auto& e : m_.effects) {
      auto r = e.reaction(m_);
      if (!r) continue;
      std::vector<std::string> parts;
      switch (r->kind) {
        case Reaction::Kind::Pin: parts = {"Rx", "Ry"}; break;
        case Reaction::Kind::Track: parts = {"N"}; break;
        case Reaction::Kind::Relation: parts = {"F"}; break;
        case Reaction::Kind::Contact:
          if (!r->holds.empty()) parts = {"Rx", "Ry"};  // once it has closed: a pin's force on b
          break;
      }
      for (auto& p : parts) {
        realsymbol x(p + "_" + e.name);
        m_.add_symbol(x, F);
        m_.instant_reactions[e.name].push_back(x);
      }
    }
    // λ_k ∂c_k/∂q_i is a generalized force (energy / [q_i]): λ_k has energy / [c_k]
    const Dimension E = F * Dimension::length();
    for (std::size_t k = 0; k < m_.constraints.size(); ++k) {
      realsymbol lam("lambda" + std::to_string(k + 1));
      m_.add_symbol(lam, E / m_.dimension(m_.constraints[k].first));
      m_.instant_lambdas.push_back(lam);
    }
  }

  void states() {
    instant_unknowns();
    for (auto& sd : d_.states) {
      State s;
      s.name = sd.name;
      s.pos = sd.pos;
      for (auto& c : m_.coords) {
        realsymbol q(c.name + "@" + sd.name), qd(c.name + "_dot@" + sd.name), qdd(c.name + "_ddot@" + sd.name);
        m_.add_symbol(q, c.dim);
        m_.add_symbol(qd, c.dim / Dimension::time());
        m_.add_symbol(qdd, c.dim / (Dimension::time() * Dimension::time()));
        s.sym.emplace(c.name, std::make_pair(q, qd));
        s.instant[c.qdd] = qdd;
      }
      for (auto& [name, parts] : m_.instant_reactions)
        for (auto& g : parts) {
          realsymbol x(g.get_name() + "@" + sd.name);
          m_.add_symbol(x, m_.dimension(g));
          s.instant[g] = x;
        }
      for (auto& g : m_.instant_lambdas) {
        realsymbol x(g.get_name() + "@" + sd.name);
        m_.add_symbol(x, m_.dimension(g));
        s.instant[g] = x;
      }
      s.t = realsymbol("t@" + sd.name);
      m_.add_symbol(s.t, Dimension::time());
      if (m_.state_index(sd.name) >= 0)
        throw SceneError(sd.pos, "state '" + sd.name + "' is defined twice", "rename one");
      m_.states.push_back(s);
    }
    for (std::size_t si = 0; si < d_.states.size(); ++si) {
      auto& sd = d_.states[si];
      State& s = m_.states[si];
      for (auto& [key, val] : sd.values) {
        ex sym;
        Dimension want;
        for (auto& c : m_.coords) {
          if (key == c.name) { sym = s.sym.at(c.name).first; want = c.dim; }
          if (key == c.name + "_dot") { sym = s.sym.at(c.name).second; want = c.dim / Dimension::time(); }
        }
        if (key == "t") { sym = s.t; want = Dimension::time(); }
        if (sym.is_zero()) {
          std::vector<std::string> names = {"t", "where"};
          for (auto& c : m_.coords) { names.push_back(c.name); names.push_back(c.name + "_dot"); }
          std::string near = scene::closest(key, names);
          throw SceneError(sd.key_pos(key), "state '" + sd.name + "' gives '" + key + "', which is not a coordinate, rate or t",
                           near.empty() ? "give coordinates (theta), rates (theta_dot), t or where" : "did you mean '" + near + "'?");
        }
        ex v;
        // "NUMBER UNIT" is a quantity; anything else an expression of parameters
        bool done = false;
        try {
          units::Quantity q = units::parse_quantity(val.s);
          if (q.has_number && !q.unit.text.empty()) {
            v = q.si;
            if (q.unit.dim != want)
              throw SceneError(val.pos, "'" + key + "' is given in " + q.unit.text +
                                            (q.unit.text == q.unit.dim.str() ? std::string() : " (" + q.unit.dim.str() + ")") +
                                            " but must be " + (want.dimensionless() ? std::string("an angle or pure number") : want.str()),
                               "give it in " + unit_words(want));
            done = true;
          } else if (q.has_number && !q.number.is_zero() && !want.dimensionless()) {
            throw SceneError(val.pos, "'" + key + ": " + val.s + "' has no unit, but '" + key + "' is in " + units::si_name(want),
                             "write it with its unit, e.g. '" + key + ": " + val.s + " " + units::si_name(want) + "'");
          }
        } catch (const InputError&) {
        }
        if (!done)
          v = checked(val, SceneContext::ParamsOnly, want, key,
                      want.dimensionless() ? std::string("give an angle: a value such as 30 deg, a parameter in rad or deg, or a pure number")
                                           : "give it in " + units::si_name(want) + " (a parameter with that unit, or NUMBER UNIT)");
        value_of(v, val.pos, "'" + key + "' at state '" + sd.name + "'");  // defined and real
        s.given[sym] = v;
      }
      for (auto& w : sd.where) {
        ex e = equation(w, SceneContext::Quantities, "where");
        s.where.push_back({m_.bind(e, static_cast<int>(si)), w.pos});
      }
    }
  }

  int state_ref(const Node& opts, const std::string& key, const SourcePos& pos, const std::string& kind) {
    const Node* n = opts.get(key);
    if (!n)
      throw SceneError(pos, kind + " analysis has no '" + key + "'",
                       key == "at" ? "write '" + kind + ": {at: 2}'" : "write '" + kind + ": {from: 1, to: 2}'");
    if (!n->is_scalar()) throw SceneError(n->pos, "'" + key + "' must name a state", "write '" + key + ": 1'");
    int i = m_.state_index(n->scalar);
    if (i < 0) {
      std::string near = nearest(n->scalar, m_.states);
      throw SceneError(n->pos, "no state named '" + n->scalar + "'",
                       near.empty() ? "define it under 'states' (the states are " + state_list(m_) + ")"
                                    : "did you mean '" + near + "'?");
    }
    return i;
  }

  std::vector<int> body_set(const Node& n) {
    std::vector<int> out;
    if (n.is_scalar()) out.push_back(body_ref(n, "bodies"));
    else if (n.is_list())
      for (auto& it : n.items) out.push_back(body_ref(it, "bodies"));
    else
      throw SceneError(n.pos, "'bodies' must list bodies", "write 'bodies: [disk, block]'");
    if (out.empty()) throw SceneError(n.pos, "'bodies' is empty", "list at least one body");
    return out;
  }

  ex impulse_symbol(const std::string& name, const Dimension& d) {
    realsymbol s(name);
    m_.add_symbol(s, d);
    return s;
  }

  ex unknown(const std::string& name, const Dimension& d) override { return impulse_symbol(name, d); }

  // the second state of an analysis over a duration comes after its first: t₂ ≥ t₁ where both are given
  void time_order(const Analysis& a) {
    const State &s1 = m_.states[a.from], &s2 = m_.states[a.to];
    auto g1 = s1.given.find(s1.t), g2 = s2.given.find(s2.t);
    if (g1 == s1.given.end() || g2 == s2.given.end()) return;
    SourcePos at = d_.states[a.to].key_pos("t");
    for (auto& [key, val] : d_.states[a.to].values)
      if (key == "t") at = val.pos;
    auto t1 = value_of(g1->second, at, "t at state '" + s1.name + "'");
    auto t2 = value_of(g2->second, at, "t at state '" + s2.name + "'");
    if (t1 && t2 && *t2 < *t1)
      throw SceneError(at, "state '" + s2.name + "' is at t = " + numerics::format(*t2, 6) + " s, before state '" + s1.name +
                               "' (t = " + numerics::format(*t1, 6) + " s), but the " + a.kind + " analysis goes from '" +
                               s1.name + "' to '" + s2.name + "'",
                       "give state '" + s2.name + "' a later time, or swap 'from' and 'to'");
  }

  void analyses() {
    const auto& kinds = analysis_kinds();
    std::vector<std::string> names;
    for (auto* k : kinds) names.push_back(k->name);
    const Dimension P = Dimension::mass() * Dimension::length() / Dimension::time();  // impulse
    std::map<std::string, std::vector<ex>> known_reactions;  // "effect|S1|S2" → its unknowns (Rx, Ry or J)
    for (auto& ad : d_.analyses) {
      auto kind = std::find_if(kinds.begin(), kinds.end(), [&](const AnalysisKind* k) { return k->name == ad.kind; });
      if (kind == kinds.end()) {
        std::string near = scene::closest(ad.kind, names), all;
        for (std::size_t i = 0; i < names.size(); ++i)
          all += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
        throw SceneError(ad.pos, "unknown analysis '" + ad.kind + "'",
                         near.empty() ? "use: " + all : "did you mean '" + near + "'?");
      }
      if (!ad.options.is_map())
        throw SceneError(ad.pos, "'" + ad.kind + "' needs its states", "write '" + ad.kind + ": {from: 1, to: 2}'");
      const bool one = (*kind)->at_state();
      std::vector<std::string> keys = one ? std::vector<std::string>{"at"} : std::vector<std::string>{"from", "to"};
      for (auto& k : (*kind)->keys()) keys.push_back(k);
      for (auto& [k, v] : ad.options.entries)
        if (std::find(keys.begin(), keys.end(), k.scalar) == keys.end()) {
          std::string list, near = scene::closest(k.scalar, keys);
          for (auto& x : keys) list += (list.empty() ? "" : ", ") + x;
          throw SceneError(k.pos, "unknown key '" + k.scalar + "' in " + ad.kind + " analysis",
                           near.empty() ? "use: " + list : "did you mean '" + near + "'?");
        }
      Analysis a;
      a.kind = ad.kind;
      a.type = *kind;
      a.pos = ad.pos;
      a.from = state_ref(ad.options, one ? "at" : "from", ad.pos, ad.kind);
      a.to = one ? a.from : state_ref(ad.options, "to", ad.pos, ad.kind);
      if (!one && a.from == a.to)
        throw SceneError(ad.options.get("to")->pos, "'from' and 'to' are the same state", "name two different states");
      const std::string S1 = m_.states[a.from].name, S2 = m_.states[a.to].name;
      if (auto* b = ad.options.get("bodies")) a.bodies = body_set(*b);
      else
        for (std::size_t i = 0; i < m_.bodies.size(); ++i) a.bodies.push_back(static_cast<int>(i));
      if (auto* c = ad.options.get("conserved")) {
        if (!c->is_scalar() || (c->scalar != "true" && c->scalar != "false"))
          throw SceneError(c->pos, "'conserved' must be true or false", "write 'conserved: true'");
        a.conserved = c->scalar == "true";
      }
      a.type->read(*this, ad, a);
      if (!a.instant() && !one) time_order(a);
      if (a.type->takes_reactions()) {
        // supports between the body set and the rest (pins, constraints) carry unknown reactions
        for (auto& e : m_.effects) {
          auto r = e.reaction(m_);
          if (!r || !r->across(a.bodies) || e.activity(a) == Effect::Activity::None) continue;
          std::string key = e.name + "|" + S1 + "|" + S2;
          if (!known_reactions.count(key))
            for (auto& part : r->parts())
              known_reactions[key].push_back(impulse_symbol(part + "_" + e.name + "[" + S1 + "," + S2 + "]", P));
          a.reactions[e.name] = known_reactions[key];
          for (auto& u : known_reactions[key]) a.unknowns.push_back(u);
        }
      }
      m_.analyses.push_back(a);
    }
    // a contact that closes in its impact holds in the analyses after it (Model::closed_from),
    // known only once all are read: the unknowns of an analysis at a state are read again with it
    bool closes = false;
    for (auto& e : m_.effects)
      if (auto r = e.reaction(m_); r && !r->holds.empty()) closes = true;
    if (closes)
      for (std::size_t i = 0; i < m_.analyses.size(); ++i)
        if (model::Analysis& a = m_.analyses[i]; a.type && a.type->at_state()) a.type->read(*this, d_.analyses[i], a);
    closed_contacts_across();
  }

  /// A contact that has closed in its impact holds its parties as a pin from then on: its force
  /// between a body set and the rest is not an unknown of a momentum analysis over a duration,
  /// nor is its work across an energy analysis whose set leaves out a body it holds — refused,
  /// where it would be silently left out.
  void closed_contacts_across() {
    for (auto& e : m_.effects) {
      const auto r = e.reaction(m_);
      if (!r || r->holds.empty()) continue;
      const int S = m_.closed_from(e);
      if (S < 0) continue;
      for (auto& a : m_.analyses) {
        if (a.instant() || (a.type && a.type->at_state()) || std::min(a.from, a.to) < S) continue;
        auto in = [&](const PointRef& p) { return p.body >= 0 && std::find(a.bodies.begin(), a.bodies.end(), p.body) != a.bodies.end(); };
        if (in(r->a) == in(r->b)) continue;
        const bool momentum = a.type && a.type->takes_reactions();
        const bool other_body = (in(r->a) ? r->b : r->a).body >= 0;
        if (!momentum && !other_body) continue;  // energy: a fixed party's point does not move, its force does no work
        throw SceneError(a.pos, "contact '" + e.name + "' holds " + r->b.text + " at " + r->a.text + " from state '" + m_.states[static_cast<std::size_t>(S)].name +
                                    "' on (it closed in its impact), and it acts between this " + a.kind +
                                    " analysis' bodies and the rest: its force over the motion is not one of the unknowns kinergy takes there",
                         momentum ? "use an energy analysis (and kinetics at the states) for the motion while it holds, or take both of its parties in 'bodies'"
                                  : "take both of its parties in 'bodies'");
      }
    }
  }

  bool has_generic(const ex& e) {
    for (auto& c : m_.coords)
      if (e.has(c.q) || e.has(c.qd)) return true;
    return e.has(m_.t);
  }

  ex bound_expr(const Text& t, const std::string& key) {
    ex e = m_.parse(t.s, t.pos, true);
    if (has_generic(e))
      throw SceneError(t.pos, "'" + key + "' depends on the motion but names no state",
                       "bind it to a state with @, e.g. theta_dot@2 or (T + V)@1");
    return e;
  }

  /// A bound of a range (a root's, an extreme's): a number with its unit, or an expression of
  /// parameters. `what` and `example` name it in the error.
  ex range_bound(const Node& b, const std::string& what, const std::string& example) {
    if (!b.is_scalar()) throw SceneError(b.pos, what + " must be a value", "write e.g. " + example);
    try {
      units::Quantity q = units::parse_quantity(b.scalar);
      if (q.has_number) return ex(q.si);
    } catch (const InputError&) {
    }
    return parse(Text{b.scalar, b.pos}, SceneContext::ParamsOnly);
  }

  RootSpec root_spec(const Node& n) {
    RootSpec r;
    if (n.is_scalar() && n.scalar == "positive") r.kind = RootSpec::Kind::Positive;
    else if (n.is_scalar() && n.scalar == "negative") r.kind = RootSpec::Kind::Negative;
    else if (n.is_map() && n.get("in") && n.entries.size() == 1 && n.get("in")->is_list() &&
             n.get("in")->items.size() == 2) {
      r.kind = RootSpec::Kind::Interval;
      auto& it = n.get("in")->items;
      auto bound = [&](const Node& b) { return range_bound(b, "a root bound", "{in: [0, 2 m]}"); };
      r.lo = bound(it[0]);
      r.hi = bound(it[1]);
    } else {
      throw SceneError(n.pos, "'root' must be positive, negative or {in: [lo, hi]}",
                       "write 'root: positive'");
    }
    return r;
  }

  /// A parameter without a value, named by `key` (a range runs over it, a bound is found for it).
  const Parameter& free_parameter(const Text& name, const std::string& key, const std::string& use, const std::string& verb = "runs over") {
    const Parameter* p = m_.parameter(name.s);
    if (!p || p->value || p->unknown)
      throw SceneError(name.pos, "'" + key + "' " + verb + " a parameter without a value, and '" + name.s + "' is " +
                                     (!p ? "no parameter" : p->value ? "given a value" : "an unknown"),
                       "declare it as 'NAME: UNIT' under parameters (e.g. '" + use + "'), use it at a state, and name it here");
    for (auto& q : m_.params)
      if (q.name == p->name) q.ranged = true;
    return *p;
  }

  /// [lo, hi] of numbers or of parameters, lo < hi: checked here where the parameters have
  /// values, else at the values the solve and its confirmation take for them (SceneSolver).
  std::pair<ex, ex> range_of(const Node& r, const std::string& key) {
    if (!r.is_list() || r.items.size() != 2)
      throw SceneError(r.pos, "'" + key + "' is a range [lo, hi]", "write e.g. '" + key + ": [0, 90 deg]'");
    auto bound = [&](const Node& b) { return range_bound(b, "a bound of '" + key + "'", "'" + key + ": [0, 90 deg]'"); };
    std::pair<ex, ex> x{bound(r.items[0]), bound(r.items[1])};
    auto lo = value_of(x.first, r.items[0].pos, "the lower end of '" + key + "'"),
         hi = value_of(x.second, r.items[1].pos, "the upper end of '" + key + "'");
    if (m_.unvalued(x.first) || m_.unvalued(x.second)) return x;
    if (!lo || !hi || !(*lo < *hi))
      throw SceneError(r.pos, "'" + key + "' must be a range [lo, hi] of numbers with lo < hi", "write e.g. '" + key + ": [0, 90 deg]'");
    return x;
  }

  /// `least|greatest: p, reaches: S [, along: th, over: [lo, hi]]`: the value is the kinetic energy
  /// at S, T@S; the result has p's dimension.
  void reach(const scene::FindDef& fd, Find& f) {
    const auto& [ask, ptext] = *fd.reach;
    Find::Reach x;
    x.least = ask == "least";
    x.pos = ptext.pos;
    x.p_name = ptext.s;
    const Parameter& p = free_parameter(ptext, ask, "v0: m/s", "asks for the value of");
    x.p = p.sym;
    x.state = m_.state_index(fd.reaches->s);
    if (x.state < 0)
      throw SceneError(fd.reaches->pos, "'reaches' names state '" + fd.reaches->s + "', which the scene does not have",
                       "name one of the states under 'states'");
    f.value = bound_expr(Text{"T@" + fd.reaches->s, fd.reaches->pos}, fd.name);
    f.dim = p.dim;
    if (fd.along) {
      const Parameter& a = free_parameter(*fd.along, "along", "th: rad");
      if (a.sym.is_equal(p.sym))
        throw SceneError(fd.along->pos, "'along' names the parameter whose " + ask + " value is asked", "name the parameter that places state '" + fd.reaches->s + "'");
      x.along = a.sym;
      x.along_name = a.name;
      std::tie(x.lo, x.hi) = range_of(*fd.over_range, "over");
    }
    f.reach = x;
  }

  void finds() {
    // a condition on a support's force at a state (a contact lost where N(dome)@2 = 0) needs the
    // kinetics there too
    for (auto& st : m_.states)
      for (auto& [e, pos] : st.where) {
        kinetics_for(e, pos, "the condition at state '" + st.name + "'");
        positions_for(e);  // (the time to travel a distance: t@2 where x = d)
      }
    for (auto& fd : d_.finds) {
      Find f;
      f.name = fd.name;
      f.pos = fd.pos;
      if (fd.reach) {
        reach(fd, f);
      } else {
        f.value = bound_expr(fd.value, fd.name);
        f.dim = dim(f.value, fd.value.pos, fd.name);
      }
      if (fd.root) f.root = root_spec(*fd.root);
      if (fd.extreme) {
        const auto& [ask, ptext] = *fd.extreme;
        Find::Extreme x;
        x.largest = ask == "max" || ask == "at_max";
        x.location = ask == "at_max" || ask == "at_min";
        x.pos = ptext.pos;
        x.p_name = ptext.s;
        const Parameter& p = free_parameter(ptext, ask, "th: rad");
        x.p = p.sym;
        std::tie(x.lo, x.hi) = range_of(*fd.over_range, "over");
        if (x.location) f.dim = p.dim;
        f.extreme = x;
      }
      if (fd.unit) {
        units::Unit u = read_at(*fd.unit, units::parse_unit);
        if (f.value.is_zero()) f.dim = u.dim;  // an exact 0 has every dimension: take the unit's
        if (u.dim != f.dim)
          throw SceneError(fd.unit->pos, "the unit '" + u.text + "'" +
                                             (u.text == u.dim.str() ? std::string() : " (" + u.dim.str() + ")") +
                                             " does not fit find '" + fd.name + "', which has dimension " + f.dim.str(),
                           "use " + (units::si_name(f.dim).empty() ? std::string("rad, deg or no unit") : "a unit of " + units::si_name(f.dim)));
        f.unit = u;
      }
      kinetics_for(f.value, f.pos, "'" + f.name + "'");
      positions_for(f.value);
      m_.finds.push_back(f);
    }
  }

  /// A result that asks for an acceleration or a support's force at a state (alpha(bar)@2,
  /// Rx(pivot)@2, theta_ddot@2) needs Newton's second law there. Where the scene has no kinetics
  /// analysis at that state one is added, over the bodies the asked supports act on (none: the
  /// equations of motion alone give the accelerations); one the scene declares must solve for
  /// what is asked.
  void kinetics_for(const ex& value, const SourcePos& pos, const std::string& what) {
    const auto& kinds = analysis_kinds();
    auto kind = std::find_if(kinds.begin(), kinds.end(), [](const AnalysisKind* k) { return k->at_state(); });
    if (kind == kinds.end()) return;
    for (std::size_t si = 0; si < m_.states.size(); ++si) {
      const int S = static_cast<int>(si);
      std::vector<ex> asked;
      for (auto& [generic, bound] : m_.states[si].instant)
        if (value.has(bound)) asked.push_back(bound);
      if (asked.empty()) continue;
      std::vector<int> bodies;  // the bodies the asked supports act on
      for (auto& [name, parts] : m_.instant_reactions)
        for (auto& g : parts)
          if (value.has(m_.states[si].instant.at(g)))
            if (auto r = m_.effects[static_cast<std::size_t>(m_.effect_index(name))].reaction(m_))
              for (int b : r->bodies())
                if (std::find(bodies.begin(), bodies.end(), b) == bodies.end()) bodies.push_back(b);
      auto it = std::find_if(m_.analyses.begin(), m_.analyses.end(), [&](const Analysis& a) { return a.type->at_state() && a.from == S; });
      if (it == m_.analyses.end()) {
        Analysis a;
        a.kind = (*kind)->name;
        a.type = *kind;
        a.pos = pos;
        a.from = a.to = S;
        a.bodies = bodies;
        std::sort(a.bodies.begin(), a.bodies.end());
        a.type->read(*this, scene::AnalysisDef{}, a);
        added_kinetics_.insert(m_.analyses.size());
        m_.analyses.push_back(a);
        continue;
      }
      Analysis& a = *it;
      if (added_kinetics_.count(static_cast<std::size_t>(it - m_.analyses.begin()))) {
        for (int b : bodies)
          if (std::find(a.bodies.begin(), a.bodies.end(), b) == a.bodies.end()) a.bodies.push_back(b);
        std::sort(a.bodies.begin(), a.bodies.end());
        a.unknowns.clear();
        a.type->read(*this, scene::AnalysisDef{}, a);
        continue;
      }
      for (auto& x : asked)
        if (std::none_of(a.unknowns.begin(), a.unknowns.end(), [&](const ex& u) { return u.is_equal(x); }))
          throw SceneError(pos, what + " asks for " + model::text(x) + ", which the kinetics analysis at state '" + m_.states[si].name +
                                      "' does not solve for: the support acts on no body of its 'bodies'",
                           "list in that analysis' 'bodies' a body the support holds, or leave its 'bodies' out (all bodies)");
    }
  }

  /// A result that asks for a position at a state of an analysis that integrates its momenta to
  /// positions (the distance a disk slid before it rolls: x@2), which the state does not give:
  /// that analysis adds the equations that give it.
  /// A coordinate asked at one state is asked at the states of every such analysis, so that a
  /// chain of them (1 → 2 → 3, x@3 asked) carries the position through.
  void positions_for(const ex& value) {
    for (auto& c : m_.coords) {
      const bool asked = std::any_of(m_.states.begin(), m_.states.end(), [&](const State& st) {
        const ex q = st.sym.at(c.name).first;
        return value.has(q) && !st.given.count(q);
      });
      if (!asked) continue;
      for (Analysis& a : m_.analyses) {
        if (!a.type->gives_positions() || a.instant()) continue;
        for (int s : {a.from, a.to}) {
          const State& st = m_.states[static_cast<std::size_t>(s)];
          const ex q = st.sym.at(c.name).first;
          if (!st.given.count(q) && std::none_of(a.positions_asked.begin(), a.positions_asked.end(), [&](const ex& x) { return x.is_equal(q); }))
            a.positions_asked.push_back(q);
        }
      }
    }
  }

  void expects() {
    for (auto& xd : d_.expects) {
      auto it = std::find_if(m_.finds.begin(), m_.finds.end(), [&](const Find& f) { return f.name == xd.name; });
      if (it == m_.finds.end()) {
        std::vector<std::string> names;
        for (auto& f : m_.finds) names.push_back(f.name);
        std::string near = scene::closest(xd.name, names);
        throw SceneError(xd.pos, "expect '" + xd.name + "' names no result under find",
                         near.empty() ? "add '" + xd.name + "' under find" : "did you mean '" + near + "'?");
      }
      Expect x;
      x.name = xd.name;
      x.pos = xd.pos;
      if (xd.form) {
        x.form = bound_expr(*xd.form, "form");
        x.form_pos = xd.form->pos;
        Dimension d = dim(*x.form, xd.form->pos, "form");
        if (d != it->dim && !x.form->is_zero())
          throw SceneError(xd.form->pos, "the claimed form has dimension " + d.str() + " but '" + xd.name +
                                             "' has " + it->dim.str(),
                           "check the claimed formula");
      }
      if (xd.value) {
        units::Quantity q = read_at(*xd.value, units::parse_quantity);
        if (!q.has_number)
          throw SceneError(xd.value->pos, "the claimed value has no number", "write e.g. 'value: 3.50 rad/s'");
        if (q.unit.dim != it->dim)
          throw SceneError(xd.value->pos, "the claimed value is in " + (q.unit.text.empty() ? std::string("no unit") : q.unit.text) +
                                              (q.unit.text == q.unit.dim.str() ? std::string() : " (" + q.unit.dim.str() + ")") +
                                              " but '" + xd.name + "' has " + it->dim.str(),
                           "give the value in " + (units::si_name(it->dim).empty() ? std::string("rad or deg, or as a pure number") : "a unit of " + units::si_name(it->dim)));
        x.value = q;
        x.value_pos = xd.value->pos;
      }
      if (xd.rtol) {
        if (!xd.value)
          throw SceneError(xd.rtol->pos, "'rtol' loosens a claimed value, and '" + xd.name + "' claims none",
                           "add 'value: NUMBER UNIT', or remove 'rtol'");
        std::optional<units::Quantity> q;
        try {
          q = units::parse_quantity(xd.rtol->s);
        } catch (const InputError&) {
        }
        if (!q || !q->has_number || !q->unit.text.empty() || q->number.is_negative() || q->number > 1)
          throw SceneError(xd.rtol->pos, "'rtol' must be a relative difference from 0 to 1, not '" + xd.rtol->s + "'",
                           "write e.g. 'rtol: 0.005' (half a percent)");
        x.rtol = q->number.to_double();
      }
      m_.expects.push_back(x);
    }
  }
};

Model Model::build(const scene::SceneDef& def) { return Builder(def).run(); }

}  // namespace kinergy::model
