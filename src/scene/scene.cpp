#include "kinergy/scene/scene.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace kinergy::scene {

const Node* Node::get(const std::string& key) const {
  for (auto& [k, v] : entries)
    if (k.scalar == key) return &v;
  return nullptr;
}

std::string Node::kind_name() const {
  switch (kind) {
    case Kind::Scalar: return "a text";
    case Kind::List: return "a list";
    case Kind::Map: return "a map";
    default: return "empty";
  }
}

SourcePos StateDef::key_pos(const std::string& key) const {
  for (auto& [k, v] : values)
    if (k == key) return v.pos;
  return pos;
}

const std::vector<std::string>& effect_kinds() {
  static const std::vector<std::string> k = {
      "gravity", "spring", "torsion_spring", "couple", "force", "friction", "friction_couple",
      "power",   "pin"};
  return k;
}

std::string closest(const std::string& word, const std::vector<std::string>& options) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (auto& o : options) {
    // Levenshtein distance
    std::vector<std::size_t> prev(o.size() + 1), cur(o.size() + 1);
    for (std::size_t j = 0; j <= o.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= word.size(); ++i) {
      cur[0] = i;
      for (std::size_t j = 1; j <= o.size(); ++j)
        cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (word[i - 1] != o[j - 1])});
      std::swap(prev, cur);
    }
    if (prev[o.size()] < best_d) {
      best_d = prev[o.size()];
      best = o;
    }
  }
  return best;
}

namespace {

struct Loader {
  std::string file;

  SourcePos at(const YAML::Mark& m) const {
    return {file, m.line < 0 ? 0 : m.line + 1, m.column < 0 ? 0 : m.column + 1};
  }

  Node convert(const YAML::Node& y) const {
    Node n;
    n.pos = at(y.Mark());
    switch (y.Type()) {
      case YAML::NodeType::Scalar:
        n.kind = Node::Kind::Scalar;
        n.scalar = y.Scalar();
        break;
      case YAML::NodeType::Sequence:
        n.kind = Node::Kind::List;
        for (const auto& it : y) n.items.push_back(convert(it));
        break;
      case YAML::NodeType::Map: {
        n.kind = Node::Kind::Map;
        std::set<std::string> seen;
        for (const auto& it : y) {
          Node k = convert(it.first);
          if (!k.is_scalar())
            throw SceneError(k.pos, "a map key must be a plain name", "write 'name: value'");
          if (!seen.insert(k.scalar).second)
            throw SceneError(k.pos, "duplicate key '" + k.scalar + "'",
                             "give each key once (rename or merge the two entries)");
          Node v = convert(it.second);
          if (v.kind == Node::Kind::Null) v.pos = k.pos;
          n.entries.emplace_back(std::move(k), std::move(v));
        }
        break;
      }
      default:
        n.kind = Node::Kind::Null;
    }
    return n;
  }

  [[noreturn]] void wrong_type(const Node& n, const std::string& key, const std::string& want,
                               const std::string& example) const {
    throw SceneError(n.pos, "'" + key + "' must be " + want + ", not " + n.kind_name(),
                     "write e.g. " + example);
  }

  void only_keys(const Node& map, const std::string& where, const std::vector<std::string>& keys) const {
    for (auto& [k, v] : map.entries) {
      if (std::find(keys.begin(), keys.end(), k.scalar) != keys.end()) continue;
      std::string near = closest(k.scalar, keys);
      std::string list;
      for (auto& s : keys) list += (list.empty() ? "" : ", ") + s;
      throw SceneError(k.pos, "unknown key '" + k.scalar + "' in " + where,
                       near.empty() ? "use one of: " + list : "did you mean '" + near + "'?");
    }
  }

  const Node& need_map(const Node& n, const std::string& key, const std::string& example) const {
    if (!n.is_map()) wrong_type(n, key, "a map", example);
    return n;
  }

  Text text(const Node& n, const std::string& key, const std::string& example) const {
    if (!n.is_scalar()) wrong_type(n, key, "a single value", example);
    if (n.scalar.find_first_not_of(" \t") == std::string::npos)
      throw SceneError(n.pos, "'" + key + "' is empty", "write e.g. " + example);
    return {n.scalar, n.pos};
  }

  std::pair<Text, Text> pair(const Node& n, const std::string& key, const std::string& example) const {
    if (!n.is_list() || n.items.size() != 2) {
      if (n.is_list())
        throw SceneError(n.pos, "'" + key + "' must have 2 entries [x, y], not " + std::to_string(n.items.size()),
                         "write e.g. " + example);
      wrong_type(n, key, "a list [x, y]", example);
    }
    return {text(n.items[0], key + "[0]", example), text(n.items[1], key + "[1]", example)};
  }

  static void check_name(const Node& k, const std::string& what) {
    const std::string& s = k.scalar;
    bool ok = !s.empty() && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_');
    for (char c : s) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!ok)
      throw SceneError(k.pos, "'" + s + "' is not a valid " + what + " name",
                       "use letters, digits and '_', starting with a letter");
  }

  InertiaDef inertia(const Node& n) const {
    static const std::vector<std::string> kinds = {
        "slender_rod", "disk", "cylinder", "ring", "hoop", "plate", "sphere", "spherical_shell",
        "gyration",    "centroidal", "particle"};
    InertiaDef d;
    d.pos = n.pos;
    if (n.is_scalar()) {
      if (n.scalar != "particle")
        throw SceneError(n.pos, "inertia '" + n.scalar + "' needs a size",
                         "write e.g. {slender_rod: l}, {disk: r}, {gyration: k} or particle");
      d.kind = "particle";
      return d;
    }
    if (!n.is_map() || n.entries.size() != 1)
      throw SceneError(n.pos, "'inertia' must name one shape",
                       "write e.g. {slender_rod: l}, {disk: r}, {centroidal: I_G} or particle");
    const auto& [k, v] = n.entries[0];
    if (std::find(kinds.begin(), kinds.end(), k.scalar) == kinds.end()) {
      std::string near = closest(k.scalar, kinds);
      throw SceneError(k.pos, "unknown inertia shape '" + k.scalar + "'",
                       near.empty() ? "use slender_rod, disk, cylinder, ring, hoop, plate, sphere, spherical_shell, gyration, centroidal or particle"
                                    : "did you mean '" + near + "'?");
    }
    d.kind = k.scalar;
    d.pos = k.pos;
    if (d.kind == "plate") {
      auto [a, b] = pair(v, "plate", "{plate: [a, b]}");
      d.args = {a, b};
    } else {
      d.args = {text(v, d.kind, "{" + d.kind + ": r}")};
    }
    return d;
  }

  SceneDef load(const YAML::Node& root) const {
    SceneDef s;
    s.file = file;
    Node r = convert(root);
    if (!r.is_map())
      throw SceneError({file, 1, 1}, "a scene must be a map of sections",
                       "start with 'title:' and add parameters, bodies, states, analyses, find");
    only_keys(r, "the scene", {"title", "description", "parameters", "points", "coordinates", "bodies",
                               "constraints", "effects", "states", "analyses", "find", "expect"});
    const Node* t = r.get("title");
    if (!t) throw SceneError({file, 1, 1}, "the scene has no 'title'", "add 'title: what the problem is'");
    s.title = text(*t, "title", "title: Rod sliding on two tracks").s;
    if (auto* d = r.get("description")) s.description = text(*d, "description", "description: …").s;

    if (auto* p = r.get("parameters")) {
      need_map(*p, "parameters", "parameters: {m: 5 kg, l: 1.2 m}");
      for (auto& [k, v] : p->entries) {
        check_name(k, "parameter");
        s.parameters.push_back({k.scalar, k.pos, text(v, k.scalar, k.scalar + ": 5 kg")});
      }
    }
    if (auto* p = r.get("points")) {
      need_map(*p, "points", "points: {O: [0, 0]}");
      for (auto& [k, v] : p->entries) {
        check_name(k, "point");
        auto [x, y] = pair(v, k.scalar, k.scalar + ": [0, 0]");
        s.points.push_back({k.scalar, k.pos, x, y});
      }
    }
    if (auto* p = r.get("coordinates")) {
      need_map(*p, "coordinates", "coordinates: {theta: rad, x: m}");
      for (auto& [k, v] : p->entries) {
        check_name(k, "coordinate");
        s.coordinates.push_back({k.scalar, k.pos, text(v, k.scalar, k.scalar + ": rad")});
      }
    }
    if (auto* p = r.get("bodies")) {
      need_map(*p, "bodies", "bodies: {rod: {mass: m, inertia: {slender_rod: l}, position: [x, y]}}");
      for (auto& [k, v] : p->entries) {
        check_name(k, "body");
        need_map(v, k.scalar, "{mass: m, inertia: {disk: r}, position: [x, y], angle: phi}");
        only_keys(v, "body '" + k.scalar + "'", {"mass", "inertia", "position", "angle", "points"});
        BodyDef b;
        b.name = k.scalar;
        b.pos = k.pos;
        auto* m = v.get("mass");
        if (!m) throw SceneError(k.pos, "body '" + k.scalar + "' has no 'mass'", "add 'mass: m'");
        b.mass = text(*m, "mass", "mass: m");
        auto* in = v.get("inertia");
        if (!in)
          throw SceneError(k.pos, "body '" + k.scalar + "' has no 'inertia'",
                           "add e.g. 'inertia: {slender_rod: l}' or 'inertia: particle'");
        b.inertia = inertia(*in);
        auto* pos = v.get("position");
        if (!pos)
          throw SceneError(k.pos, "body '" + k.scalar + "' has no 'position'",
                           "add 'position: [x, y]' of its mass centre in the coordinates");
        auto [x, y] = pair(*pos, "position", "position: [l/2*cos(theta), l/2*sin(theta)]");
        b.x = x;
        b.y = y;
        if (auto* a = v.get("angle")) b.angle = text(*a, "angle", "angle: theta");
        if (auto* pts = v.get("points")) {
          need_map(*pts, "points", "points: {A: [l/2, 0]}");
          for (auto& [pk, pv] : pts->entries) {
            check_name(pk, "point");
            auto [px, py] = pair(pv, pk.scalar, pk.scalar + ": [l/2, 0]");
            b.points.push_back({pk.scalar, pk.pos, px, py});
          }
        }
        s.bodies.push_back(std::move(b));
      }
    }
    if (auto* p = r.get("constraints")) {
      if (!p->is_list()) wrong_type(*p, "constraints", "a list", "constraints: [x + r*phi = 0]");
      for (auto& c : p->items) s.constraints.push_back(text(c, "constraint", "x + r*phi = 0"));
    }
    if (auto* p = r.get("effects")) {
      need_map(*p, "effects", "effects: {gravity: {g: g}}");
      const auto& kinds = effect_kinds();
      for (auto& [k, v] : p->entries) {
        check_name(k, "effect");
        if (!v.is_map())
          wrong_type(v, k.scalar, "a map", k.scalar + ": {couple: disk, M: M0}");
        EffectDef e;
        e.name = k.scalar;
        e.pos = k.pos;
        e.options = v;
        for (auto& [ok, ov] : v.entries) {
          if (std::find(kinds.begin(), kinds.end(), ok.scalar) == kinds.end()) continue;
          if (!e.kind.empty())
            throw SceneError(ok.pos, "effect '" + k.scalar + "' names two kinds, '" + e.kind + "' and '" + ok.scalar + "'",
                             "give each effect one kind; split it into two effects");
          e.kind = ok.scalar;
          e.arg = ov;
        }
        if (e.kind.empty()) {
          if (std::find(kinds.begin(), kinds.end(), k.scalar) != kinds.end()) {
            e.kind = k.scalar;
          } else {
            std::string list;
            for (auto& s2 : kinds) list += (list.empty() ? "" : ", ") + s2;
            throw SceneError(k.pos, "effect '" + k.scalar + "' has no kind",
                             "add one of: " + list + " (e.g. '" + k.scalar + ": {couple: disk, M: M0}')");
          }
        }
        s.effects.push_back(std::move(e));
      }
    }
    if (auto* p = r.get("states")) {
      need_map(*p, "states", "states: {1: {theta: 0, theta_dot: 0}, 2: {theta: theta2}}");
      for (auto& [k, v] : p->entries) {
        StateDef st;
        st.name = k.scalar;
        st.pos = k.pos;
        bool ok = !k.scalar.empty();
        for (char c : k.scalar) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
        if (!ok)
          throw SceneError(k.pos, "'" + k.scalar + "' is not a valid state name",
                           "use letters, digits and '_' (e.g. 1, 2, before, after)");
        if (v.kind != Node::Kind::Null) {
          need_map(v, k.scalar, k.scalar + ": {theta: 0, theta_dot: 0}");
          for (auto& [sk, sv] : v.entries) {
            if (sk.scalar == "where") {
              if (sv.is_scalar()) st.where.push_back(text(sv, "where", "where: [x_dot + r*phi_dot = 0]"));
              else if (sv.is_list())
                for (auto& w : sv.items) st.where.push_back(text(w, "where", "x_dot + r*phi_dot = 0"));
              else wrong_type(sv, "where", "a list of equations", "where: [x_dot + r*phi_dot = 0]");
            } else {
              st.values.emplace_back(sk.scalar, text(sv, sk.scalar, sk.scalar + ": 0"));
              st.values.back().second.pos = sv.pos;
            }
          }
        }
        s.states.push_back(std::move(st));
      }
    }
    if (auto* p = r.get("analyses")) {
      if (!p->is_list()) wrong_type(*p, "analyses", "a list", "analyses: [{energy: {from: 1, to: 2}}]");
      for (auto& a : p->items) {
        if (!a.is_map() || a.entries.size() != 1)
          throw SceneError(a.pos, "each analysis must be one principle",
                           "write e.g. '- energy: {from: 1, to: 2}'");
        AnalysisDef d;
        d.kind = a.entries[0].first.scalar;
        d.pos = a.entries[0].first.pos;
        d.options = a.entries[0].second;
        s.analyses.push_back(std::move(d));
      }
    }
    if (auto* p = r.get("find")) {
      need_map(*p, "find", "find: {omega2: theta_dot@2}");
      for (auto& [k, v] : p->entries) {
        check_name(k, "result");
        FindDef f;
        f.name = k.scalar;
        f.pos = k.pos;
        if (v.is_map()) {
          only_keys(v, "find '" + k.scalar + "'", {"value", "root", "unit"});
          auto* val = v.get("value");
          if (!val)
            throw SceneError(k.pos, "find '" + k.scalar + "' has no 'value'",
                             "write '" + k.scalar + ": {value: theta_dot@2, root: positive}'");
          f.value = text(*val, "value", "value: theta_dot@2");
          if (auto* rt = v.get("root")) f.root = *rt;
          if (auto* u = v.get("unit")) f.unit = text(*u, "unit", "unit: rad/s");
        } else {
          f.value = text(v, k.scalar, k.scalar + ": theta_dot@2");
        }
        s.finds.push_back(std::move(f));
      }
    }
    if (auto* p = r.get("expect")) {
      need_map(*p, "expect", "expect: {omega2: {form: sqrt(3*g/l), value: 3.50 rad/s}}");
      for (auto& [k, v] : p->entries) {
        ExpectDef e;
        e.name = k.scalar;
        e.pos = k.pos;
        need_map(v, k.scalar, k.scalar + ": {form: sqrt(3*g/l), value: 3.50 rad/s}");
        only_keys(v, "expect '" + k.scalar + "'", {"form", "value"});
        if (auto* f = v.get("form")) e.form = text(*f, "form", "form: sqrt(3*g/l)");
        if (auto* f = v.get("value")) e.value = text(*f, "value", "value: 3.50 rad/s");
        if (!e.form && !e.value)
          throw SceneError(k.pos, "expect '" + k.scalar + "' claims nothing",
                           "add 'form: …' or 'value: NUMBER UNIT'");
        s.expects.push_back(std::move(e));
      }
    }
    return s;
  }
};

}  // namespace

SceneDef load_string(const std::string& text, const std::string& file) {
  Loader l{file};
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    std::string msg = e.msg;
    throw SceneError(l.at(e.mark), "YAML syntax error: " + msg,
                     "fix the indentation, brackets or quotes near here");
  }
  if (!root || root.IsNull())
    throw SceneError({file, 1, 1}, "the scene is empty", "write a scene: title, parameters, bodies, states, analyses, find");
  return l.load(root);
}

SceneDef load_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError({path, 0, 0}, "cannot open the scene file", "check the path");
  std::stringstream ss;
  ss << in.rdbuf();
  return load_string(ss.str(), path);
}

}  // namespace kinergy::scene
