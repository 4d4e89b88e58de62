#include "kinergy/scene/scene.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

namespace kinergy::scene {

/// `label: "\\theta_A"`: a name in TeX's math mode for figures — letters, digits, subscripts,
/// primes and commands (\\alpha), braces that close, nothing a LaTeX document would take for
/// another thing ($ % # & ~ ^ or a line break).
std::string read_label(const Node& n, const std::string& whose) {
  const std::string fix = "write it as TeX's math mode writes a name, e.g. 'label: \"W_A\"' or 'label: \"\\\\theta_1\"'";
  if (!n.is_scalar() || n.scalar.empty()) throw SceneError(n.pos, "the label of " + whose + " is a name in TeX", fix);
  if (n.scalar.size() > 64) throw SceneError(n.pos, "the label of " + whose + " is longer than 64 characters", fix);
  int depth = 0;
  for (char c : n.scalar) {
    if (std::string("$%#&~^\n").find(c) != std::string::npos)
      throw SceneError(n.pos, "the label of " + whose + " holds '" + std::string(1, c) + "', which TeX would not take as part of a name", fix);
    depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    if (depth < 0) break;
  }
  if (depth != 0) throw SceneError(n.pos, "the label of " + whose + " has braces that do not close", fix);
  return n.scalar;
}


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

bool looks_cut(const std::string& k) {
  int depth = 0;
  for (char c : k) {
    if (c == '(') ++depth;
    if (c == ')') --depth;
  }
  return depth < 0 || k.find_first_of("()@*/^+") != std::string::npos;
}

std::string closest(const std::string& word, const std::vector<std::string>& options) {
  auto lower = [](std::string x) {
    for (auto& c : x) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return x;
  };
  // a name that differs only in case is the one meant ('L' for 'l')
  for (auto& o : options)
    if (o != word && lower(o) == lower(word)) return o;
  std::string best;
  // near enough: a few edits, and never every character of the word (for 'q', 'g' is no hint)
  std::size_t best_d = std::min(std::max<std::size_t>(2, word.size() / 3) + 1, word.size());
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
  std::vector<std::string> lines;  ///< the source, for places inside quoted and block scalars
  mutable std::size_t nodes = 0;   ///< YAML values converted so far (aliases repeat what they name)

  SourcePos at(const YAML::Mark& m) const {
    return {file, m.line < 0 ? 0 : m.line + 1, m.column < 0 ? 0 : m.column + 1};
  }

  char char_at(const SourcePos& p) const {
    if (p.line < 1 || p.line > static_cast<int>(lines.size())) return '\0';
    const std::string& l = lines[p.line - 1];
    return p.col >= 1 && p.col <= static_cast<int>(l.size()) ? l[p.col - 1] : '\0';
  }

  /// The place where a scalar's text begins: after an opening quote, or on the first line of
  /// a block scalar (`|`, `>`), so that a column inside an expression lands on the character.
  SourcePos text_start(SourcePos p) const {
    char c = char_at(p);
    if (c == '"' || c == '\'') {
      ++p.col;
    } else if (c == '|' || c == '>') {
      for (int l = p.line + 1; l <= static_cast<int>(lines.size()); ++l) {
        auto k = lines[l - 1].find_first_not_of(" \t\r");
        if (k == std::string::npos) continue;
        p.line = l;
        p.col = static_cast<int>(k) + 1;
        break;
      }
    }
    return p;
  }

  Node convert(const YAML::Node& y, int depth = 0) const {
    Node n;
    n.pos = at(y.Mark());
    // an alias '*a' repeats the whole value its anchor '&a' names, so a few hundred bytes of
    // nested aliases can stand for billions of values: bounded, as the nesting is
    if (++nodes > kMaxNodes)
      throw SceneError(n.pos, "the scene holds more than " + std::to_string(kMaxNodes) + " YAML values (aliases '*name' repeat the value they name)",
                       "write the scene without nested aliases: a scene needs a few hundred values");
    if (depth > kMaxDepth)
      throw SceneError(n.pos, "the scene nests lists and maps more than " + std::to_string(kMaxDepth) + " deep",
                       "a scene nests a few levels: close the lists and maps opened above");
    switch (y.Type()) {
      case YAML::NodeType::Scalar:
        n.kind = Node::Kind::Scalar;
        n.scalar = y.Scalar();
        n.pos = text_start(n.pos);
        break;
      case YAML::NodeType::Sequence:
        n.kind = Node::Kind::List;
        for (const auto& it : y) n.items.push_back(convert(it, depth + 1));
        break;
      case YAML::NodeType::Map: {
        n.kind = Node::Kind::Map;
        std::set<std::string> seen;
        for (const auto& it : y) {
          Node k = convert(it.first, depth + 1);
          if (!k.is_scalar())
            throw SceneError(k.pos, "a map key must be a plain name", "write 'name: value'");
          if (!seen.insert(k.scalar).second)
            throw SceneError(k.pos, "duplicate key '" + k.scalar + "'",
                             "give each key once (rename or merge the two entries)");
          Node v = convert(it.second, depth + 1);
          if (v.kind == Node::Kind::Null) v.pos = k.pos;
          n.entries.push_back({std::move(k), std::move(v)});
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
    // "{value: f(a, b)}" reads as value "f(a" and a key "b)" without a value
    for (std::size_t i = 0; i + 1 < map.entries.size(); ++i)
      if (unclosed_paren(map.entries[i].second) && map.entries[i + 1].second.kind == Node::Kind::Null)
        cut_at_comma(map.entries[i].second);
    for (auto& [k, v] : map.entries) {
      if (std::find(keys.begin(), keys.end(), k.scalar) != keys.end()) continue;
      if (v.kind == Node::Kind::Null && looks_cut(k.scalar))
        throw SceneError(k.pos, "'" + k.scalar + "' looks like the end of an expression cut at a comma: inside {…} a comma separates entries",
                         "put the expression in quotes, e.g. value: \"atan2(y@2, x@2)\"");
      std::string near = closest(k.scalar, keys);
      std::string list;
      for (auto& s : keys) list += (list.empty() ? "" : ", ") + s;
      throw SceneError(k.pos, "unknown key '" + k.scalar + "' in " + where,
                       near.empty() ? "use one of: " + list : "did you mean '" + near + "'?");
    }
  }

  /// An expression YAML cut at a comma inside `{…}` or `[…]`: its '(' is never closed.
  [[noreturn]] static void cut_at_comma(const Node& n) {
    throw SceneError(n.pos, "'" + n.scalar + "' is cut at a comma: inside {…} and […] a comma separates entries, even within f(a, b)",
                     "put the expression in quotes, e.g. value: \"" + n.scalar + ", …)\"");
  }
  static bool unclosed_paren(const Node& n) {
    if (!n.is_scalar()) return false;
    int depth = 0;
    for (char c : n.scalar) depth += c == '(' ? 1 : c == ')' ? -1 : 0;
    return depth > 0;
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
      for (auto& it : n.items)
        if (unclosed_paren(it)) cut_at_comma(it);
      if (n.is_list())
        throw SceneError(n.pos, "'" + key + "' must have 2 entries [x, y], not " + std::to_string(n.items.size()),
                         "write e.g. " + example);
      wrong_type(n, key, "a list [x, y]", example);
    }
    return {text(n.items[0], key + "[0]", example), text(n.items[1], key + "[1]", example)};
  }

  /// A point: `[x, y]`, or `{at: [x, y], label: "P_1"}` with its name for figures.
  PointDef point(const Node& k, const Node& v, const std::string& example) const {
    if (!v.is_map()) {
      auto [x, y] = pair(v, k.scalar, k.scalar + ": " + example);
      return {k.scalar, k.pos, x, y};
    }
    only_keys(v, "point '" + k.scalar + "'", {"at", "label"});
    const Node* at = v.get("at");
    if (!at) throw SceneError(v.pos, "point '" + k.scalar + "' has no 'at'", "write '" + k.scalar + ": {at: " + example + ", label: \"P_1\"}'");
    auto [x, y] = pair(*at, k.scalar, k.scalar + ": {at: " + example + "}");
    PointDef p{k.scalar, k.pos, x, y};
    if (const Node* l = v.get("label")) p.label = read_label(*l, "point '" + k.scalar + "'");
    return p;
  }

  /// A section name met inside another section: its line is indented under the section above.
  void not_a_section(const Node& k, const Node& root, const std::string& inside) const {
    static const std::vector<std::string> sections = {"parameters", "points", "coordinates", "bodies", "constraints",
                                                      "effects", "states", "analyses", "find", "expect"};
    if (std::find(sections.begin(), sections.end(), k.scalar) == sections.end() || root.get(k.scalar)) return;
    throw SceneError(k.pos, "'" + k.scalar + "' is indented, so it stands inside '" + inside + "' instead of being a section",
                     "start '" + k.scalar + ":' at the beginning of its line, and indent what belongs to it");
  }

  static void check_name(const Node& k, const std::string& what) {
    const std::string& s = k.scalar;
    bool ok = !s.empty() && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_');
    for (char c : s) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!ok)
      throw SceneError(k.pos, "'" + s + "' is not a valid " + what + " name",
                       "use letters, digits and '_', starting with a letter");
    if (s.size() > kMaxName)
      throw SceneError(k.pos, "the " + what + " name '" + s + "' is " + std::to_string(s.size()) + " characters long, more than " +
                                  std::to_string(kMaxName),
                       "use a shorter name");
  }

  InertiaDef inertia(const Node& n) const {
    const auto& shapes = inertia_shapes();
    std::vector<std::string> kinds;
    for (auto& [name, sizes] : shapes) kinds.push_back(name);
    auto sizes_of = [&](const std::string& name) {
      for (auto& [k, sizes] : shapes)
        if (k == name) return sizes;
      return -1;
    };
    InertiaDef d;
    d.pos = n.pos;
    if (n.is_scalar()) {
      if (sizes_of(n.scalar) != 0)
        throw SceneError(n.pos, "inertia '" + n.scalar + "' needs a size",
                         "write e.g. {slender_rod: l}, {disk: r}, {gyration: k} or particle");
      d.kind = n.scalar;
      return d;
    }
    if (!n.is_map() || n.entries.size() != 1)
      throw SceneError(n.pos, "'inertia' must name one shape",
                       "write e.g. {slender_rod: l}, {disk: r}, {centroidal: I_G} or particle");
    const auto& [k, v] = n.entries[0];
    int sizes = sizes_of(k.scalar);
    if (sizes < 0) {
      std::string near = closest(k.scalar, kinds), all;
      for (std::size_t i = 0; i < kinds.size(); ++i)
        all += (i == 0 ? "" : i + 1 == kinds.size() ? " or " : ", ") + kinds[i];
      throw SceneError(k.pos, "unknown inertia shape '" + k.scalar + "'",
                       near.empty() ? "use " + all : "did you mean '" + near + "'?");
    }
    d.kind = k.scalar;
    d.pos = k.pos;
    if (sizes == 2) {
      auto [a, b] = pair(v, d.kind, "{" + d.kind + ": [a, b]}");
      d.args = {a, b};
    } else {
      d.args = {text(v, d.kind, "{" + d.kind + ": r}")};
    }
    return d;
  }

  /// `drawn_as: {circle: R}` or `drawn_as: {rectangle: [w, h]}`: an outline and its sizes.
  InertiaDef drawn_as(const Node& n) const {
    static const std::map<std::string, int> outlines = {{"circle", 1}, {"rectangle", 2}};
    const auto o = n.is_map() && n.entries.size() == 1 ? outlines.find(n.entries[0].first.scalar) : outlines.end();
    if (o == outlines.end())
      throw SceneError(n.pos, "'drawn_as' names one outline: a circle or a rectangle", "write 'drawn_as: {circle: R}' or 'drawn_as: {rectangle: [w, h]}'");
    const auto& [k, v] = n.entries[0];
    InertiaDef d;
    d.kind = k.scalar;
    d.pos = k.pos;
    if (o->second == 2) {
      auto [a, b] = pair(v, d.kind, "drawn_as: {rectangle: [w, h]}");
      d.args = {a, b};
    } else {
      d.args = {text(v, d.kind, "drawn_as: {circle: R}")};
    }
    return d;
  }

  /// `NAME: {least|greatest: p, reaches: S, along: th, over: [lo, hi], unit: U}`: the least
  /// (greatest) value of the parameter p for which state S is reached. @returns false when v asks
  /// for none of this (an ordinary result or an extreme).
  bool read_reach(const Node& k, const Node& v, FindDef& f) const {
    const Node* ask = v.get("least");
    const Node* other = v.get("greatest");
    if (ask && other)
      throw SceneError(other->pos, "find '" + k.scalar + "' asks for both the least and the greatest value", "ask for one of them");
    std::string which = ask ? "least" : "greatest";
    if (!ask) ask = other;
    const Node* reaches = v.get("reaches");
    if (!ask) {
      if (reaches) throw SceneError(reaches->pos, "'reaches' names the state of a least or greatest parameter value, and find '" + k.scalar + "' asks for none",
                                    "add 'least: PARAMETER' (or greatest), or remove 'reaches'");
      if (auto* a = v.get("along")) throw SceneError(a->pos, "'along' belongs with 'least' or 'greatest' and 'reaches'", "remove 'along'");
      return false;
    }
    for (const char* x : {"value", "root", "max", "min", "at_max", "at_min"})
      if (auto* e = v.get(x))
        throw SceneError(e->pos, "find '" + k.scalar + "' asks for the " + which + " value of a parameter, which has no '" + x + "'",
                         "remove '" + std::string(x) + "': the value found is the parameter's, from the kinetic energy at the state named by 'reaches'");
    if (!reaches)
      throw SceneError(k.pos, "find '" + k.scalar + "' asks for the " + which + " value of a parameter without the state to reach",
                       "add 'reaches: S', the state that must be reached");
    f.reach = {which, text(*ask, which, which + ": v0")};
    f.reaches = text(*reaches, "reaches", "reaches: 2");
    f.value = *f.reaches;
    auto* along = v.get("along");
    auto* over = v.get("over");
    if (along && !over)
      throw SceneError(along->pos, "'along' needs the range of the path: 'over: [lo, hi]'", "add e.g. 'over: [0, 180 deg]'");
    if (over && !along)
      throw SceneError(over->pos, "'over' gives the range of the parameter named by 'along', and find '" + k.scalar + "' has none",
                       "add 'along: PARAMETER' (the parameter that places the state), or remove 'over'");
    if (along) {
      f.along = text(*along, "along", "along: th");
      f.over_range = *over;
    }
    if (auto* u = v.get("unit")) f.unit = text(*u, "unit", "unit: m/s");
    return true;
  }

  /// A composite body's parts: `parts: {rod: {mass: m1, inertia: {slender_rod: L}, at: [L/2, 0]}, …}`.
  void read_parts(const Node& parts, BodyDef& b) const {
    const std::string example = "parts: {rod: {mass: m1, inertia: {slender_rod: L}, at: [L/2, 0]}, disk: {mass: m2, inertia: {disk: r}, at: [L + r, 0]}}";
    need_map(parts, "parts", example);
    if (parts.entries.empty()) throw SceneError(parts.pos, "body '" + b.name + "' has no parts", "list its parts: " + example);
    for (auto& [k, v] : parts.entries) {
      check_name(k, "part");
      need_map(v, k.scalar, "{mass: m1, inertia: {slender_rod: L}, at: [L/2, 0]}");
      only_keys(v, "part '" + k.scalar + "' of body '" + b.name + "'", {"mass", "inertia", "at", "angle"});
      PartDef p;
      p.name = k.scalar;
      p.pos = k.pos;
      for (const char* key : {"mass", "inertia", "at"})
        if (!v.get(key))
          throw SceneError(k.pos, "part '" + k.scalar + "' of body '" + b.name + "' has no '" + key + "'",
                           std::string("add '") + (std::string(key) == "mass" ? "mass: m1'" : std::string(key) == "inertia" ? "inertia: {disk: r}'" : "at: [x, y]' (its centre, from the body's reference point, in body axes)"));
      p.mass = text(*v.get("mass"), "mass", "mass: m1");
      p.inertia = inertia(*v.get("inertia"));
      std::tie(p.x, p.y) = pair(*v.get("at"), "at", "at: [L/2, 0]");
      if (auto* a = v.get("angle")) p.angle = text(*a, "angle", "angle: 90 deg");
      b.parts.push_back(std::move(p));
    }
  }

  /// The bodies: mass, inertia, position, angle, points.
  void read_bodies(const Node& r, SceneDef& s) const {
    if (auto* p = r.get("bodies")) {
      need_map(*p, "bodies", "bodies: {rod: {mass: m, inertia: {slender_rod: l}, position: [x, y]}}");
      for (auto& [k, v] : p->entries) {
        not_a_section(k, r, "bodies");
        check_name(k, "body");
        need_map(v, k.scalar, "{mass: m, inertia: {disk: r}, position: [x, y], angle: phi}");
        only_keys(v, "body '" + k.scalar + "'", {"mass", "inertia", "position", "angle", "points", "parts", "drawn_as", "label"});
        BodyDef b;
        b.name = k.scalar;
        b.pos = k.pos;
        if (auto* parts = v.get("parts")) {
          // a composite body: its mass, mass centre and Ī are its parts'
          for (const char* key : {"mass", "inertia"})
            if (auto* x = v.get(key))
              throw SceneError(x->pos, "body '" + k.scalar + "' has 'parts', so its " + key + " is theirs",
                               std::string("remove '") + key + "' (each part has its own 'mass' and 'inertia')");
          read_parts(*parts, b);
        } else {
          auto* m = v.get("mass");
          if (!m) throw SceneError(k.pos, "body '" + k.scalar + "' has no 'mass'", "add 'mass: m'");
          b.mass = text(*m, "mass", "mass: m");
          auto* in = v.get("inertia");
          if (!in)
            throw SceneError(k.pos, "body '" + k.scalar + "' has no 'inertia'",
                             "add e.g. 'inertia: {slender_rod: l}' or 'inertia: particle'");
          b.inertia = inertia(*in);
        }
        auto* pos = v.get("position");
        if (!pos)
          throw SceneError(k.pos, "body '" + k.scalar + "' has no 'position'",
                           b.parts.empty() ? "add 'position: [x, y]' of its mass centre in the coordinates"
                                           : "add 'position: [x, y]' of its reference point (where its parts' 'at' are measured from) in the coordinates");
        auto [x, y] = pair(*pos, "position", "position: [l/2*cos(theta), l/2*sin(theta)]");
        b.x = x;
        b.y = y;
        if (auto* a = v.get("angle")) b.angle = text(*a, "angle", "angle: theta");
        if (auto* d = v.get("drawn_as")) b.drawn_as = drawn_as(*d);
        if (auto* l = v.get("label")) b.label = read_label(*l, "body '" + k.scalar + "'");
        if (auto* pts = v.get("points")) {
          need_map(*pts, "points", "points: {A: [l/2, 0]}");
          for (auto& [pk, pv] : pts->entries) {
            check_name(pk, "point");
            b.points.push_back(point(pk, pv, "[l/2, 0]"));
          }
        }
        s.bodies.push_back(std::move(b));
      }
    }
  }

  /// The effects: each one's kind (named by a key of the table of kinds) and its options.
  void read_effects(const Node& r, SceneDef& s) const {
    if (auto* p = r.get("effects")) {
      need_map(*p, "effects", "effects: {gravity: {g: g}}");
      const auto& kinds = effect_kinds();
      for (auto& [k, v] : p->entries) {
        not_a_section(k, r, "effects");
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
  }

  /// The states: the values given there and their `where` conditions.
  void read_states(const Node& r, SceneDef& s) const {
    if (auto* p = r.get("states")) {
      need_map(*p, "states", "states: {1: {theta: 0, theta_dot: 0}, 2: {theta: theta2}}");
      for (auto& [k, v] : p->entries) {
        not_a_section(k, r, "states");
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
              // a key that names no coordinate, rate or t is blamed where it is written
              std::vector<std::string> keys = {"t", "where"};
              for (auto& c : s.coordinates) {
                keys.push_back(c.name);
                keys.push_back(c.name + "_dot");
              }
              if (std::find(keys.begin(), keys.end(), sk.scalar) == keys.end()) {
                std::string near = closest(sk.scalar, keys);
                throw SceneError(sk.pos, "state '" + st.name + "' gives '" + sk.scalar + "', which is not a coordinate, rate or t",
                                 near.empty() ? "give coordinates (theta), rates (theta_dot), t or where"
                                              : "did you mean '" + near + "'?");
              }
              st.values.emplace_back(sk.scalar, text(sv, sk.scalar, sk.scalar + ": 0"));
            }
          }
        }
        s.states.push_back(std::move(st));
      }
    }
  }

  /// The results asked for: values, extremes, least and greatest values.
  void read_finds(const Node& r, SceneDef& s) const {
    if (auto* p = r.get("find")) {
      need_map(*p, "find", "find: {omega2: theta_dot@2}");
      for (auto& [k, v] : p->entries) {
        not_a_section(k, r, "find");
        check_name(k, "result");
        FindDef f;
        f.name = k.scalar;
        f.pos = k.pos;
        if (v.is_map()) {
          only_keys(v, "find '" + k.scalar + "'",
                    {"value", "root", "unit", "max", "min", "at_max", "at_min", "over", "least", "greatest", "reaches", "along"});
          if (read_reach(k, v, f)) {
            s.finds.push_back(std::move(f));
            continue;
          }
          for (const char* x : {"max", "min", "at_max", "at_min"})
            if (auto* e = v.get(x)) {
              if (f.extreme)
                throw SceneError(e->pos, "find '" + k.scalar + "' asks for two extremes", "ask for one of max, min, at_max, at_min");
              f.extreme = {x, text(*e, x, std::string(x) + ": theta")};
            }
          if (auto* o = v.get("over")) f.over_range = *o;
          if (f.extreme && !f.over_range)
            throw SceneError(k.pos, "find '" + k.scalar + "' asks for an extreme without its range",
                             "add 'over: [lo, hi]', the range of " + f.extreme->second.s + " to look in");
          if (f.over_range && !f.extreme)
            throw SceneError(f.over_range->pos, "'over' gives the range of an extreme, and find '" + k.scalar + "' asks for none",
                             "add 'max: PARAMETER' (or min, at_max, at_min), or remove 'over'");
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
  }

  /// The claims to verify: forms and values.
  void read_expects(const Node& r, SceneDef& s) const {
    if (auto* p = r.get("expect")) {
      need_map(*p, "expect", "expect: {omega2: {form: sqrt(3*g/l), value: 3.50 rad/s}}");
      for (auto& [k, v] : p->entries) {
        not_a_section(k, r, "expect");
        ExpectDef e;
        e.name = k.scalar;
        e.pos = k.pos;
        need_map(v, k.scalar, k.scalar + ": {form: sqrt(3*g/l), value: 3.50 rad/s}");
        only_keys(v, "expect '" + k.scalar + "'", {"form", "value", "rtol"});
        if (auto* f = v.get("form")) e.form = text(*f, "form", "form: sqrt(3*g/l)");
        if (auto* f = v.get("value")) e.value = text(*f, "value", "value: 3.50 rad/s");
        if (auto* f = v.get("rtol")) e.rtol = text(*f, "rtol", "rtol: 0.005");
        if (!e.form && !e.value)
          throw SceneError(k.pos, "expect '" + k.scalar + "' claims nothing",
                           "add 'form: …' or 'value: NUMBER UNIT'");
        s.expects.push_back(std::move(e));
      }
    }
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
        not_a_section(k, r, "parameters");
        check_name(k, "parameter");
        if (v.is_map()) {  // {value: 210 deg, in: [180 deg, 270 deg]}
          for (auto& [kk, vv] : v.entries)
            if (kk.scalar == "unit")
              throw SceneError(kk.pos, "parameter '" + k.scalar + "' takes its unit in its value, not under 'unit'",
                               "write the unit after the number: '" + k.scalar + ": {value: 5 kg}' (or '" + k.scalar + ": 5 kg')");
          only_keys(v, "parameter '" + k.scalar + "'", {"value", "in"});
          auto* val = v.get("value");
          auto* in = v.get("in");
          if (!val)
            throw SceneError(v.pos, "parameter '" + k.scalar + "' has no 'value'",
                             "write '" + k.scalar + ": {value: 30 deg, in: [0, 90 deg]}' (or 'value: deg' for one without a number)");
          ParameterDef d{k.scalar, k.pos, text(*val, "value", k.scalar + ": {value: 5 kg}"), std::nullopt, v.pos};
          if (in) {
            d.in = pair(*in, "in", "'in: [0, 90 deg]'");
            d.in_pos = in->pos;
          }
          s.parameters.push_back(d);
          continue;
        }
        s.parameters.push_back({k.scalar, k.pos, text(v, k.scalar, k.scalar + ": 5 kg"), std::nullopt, {}});
      }
    }
    if (auto* p = r.get("points")) {
      need_map(*p, "points", "points: {O: [0, 0]}");
      for (auto& [k, v] : p->entries) {
        not_a_section(k, r, "points");
        check_name(k, "point");
        s.points.push_back(point(k, v, "[0, 0]"));
      }
    }
    if (auto* p = r.get("coordinates")) {
      need_map(*p, "coordinates", "coordinates: {theta: rad, x: m}");
      for (auto& [k, v] : p->entries) {
        not_a_section(k, r, "coordinates");
        check_name(k, "coordinate");
        if (!v.is_map()) {
          s.coordinates.push_back({k.scalar, k.pos, text(v, k.scalar, k.scalar + ": rad")});
          continue;
        }
        // {unit: rad, label: "\\theta_1"}
        only_keys(v, "coordinate '" + k.scalar + "'", {"unit", "label"});
        const Node* unit = v.get("unit");
        if (!unit) throw SceneError(v.pos, "coordinate '" + k.scalar + "' has no 'unit'", "write '" + k.scalar + ": {unit: rad, label: \"\\\\theta_1\"}'");
        CoordinateDef c{k.scalar, k.pos, text(*unit, "unit", k.scalar + ": {unit: rad}")};
        if (const Node* l = v.get("label")) c.label = read_label(*l, "coordinate '" + k.scalar + "'");
        s.coordinates.push_back(c);
      }
    }
    read_bodies(r, s);
    if (auto* p = r.get("constraints")) {
      if (!p->is_list()) wrong_type(*p, "constraints", "a list", "constraints: [x + r*phi = 0]");
      for (auto& c : p->items) s.constraints.push_back(text(c, "constraint", "x + r*phi = 0"));
    }
    read_effects(r, s);
    read_states(r, s);
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
    read_finds(r, s);
    read_expects(r, s);
    return s;
  }
};

}  // namespace

namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : text) {
    if (c == '\n') {
      if (!cur.empty() && cur.back() == '\r') cur.pop_back();
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

/// A line that opens a block scalar (`key: |`, `key: >-`, `- >`): its content follows, indented.
bool opens_block_scalar(const std::string& l) {
  auto k = l.find_last_not_of(" \t");
  if (k == std::string::npos) return false;
  std::size_t e = k + 1;
  // strip a trailing comment
  auto hash = l.find(" #");
  if (hash != std::string::npos && hash < e) {
    k = l.find_last_not_of(" \t", hash);
    if (k == std::string::npos) return false;
    e = k + 1;
  }
  std::size_t b = e;
  while (b > 0 && (std::isdigit(static_cast<unsigned char>(l[b - 1])) || l[b - 1] == '-' || l[b - 1] == '+')) --b;
  if (b == 0 || (l[b - 1] != '|' && l[b - 1] != '>')) return false;
  --b;
  if (b == 0) return true;
  if (l[b - 1] != ' ') return false;
  // before the indicator: "key:" or "-", with an anchor (&name) or a tag (!tag) between them
  std::size_t p = l.find_last_not_of(' ', b - 1);
  while (p != std::string::npos) {
    std::size_t start = l.find_last_of(' ', p);
    start = start == std::string::npos ? 0 : start + 1;
    if (l[start] != '&' && l[start] != '!') break;
    if (start == 0) return true;
    p = l.find_last_not_of(' ', start - 1);
  }
  return p != std::string::npos && (l[p] == ':' || l[p] == '-');
}

std::size_t indentation(const std::string& l) {
  auto k = l.find_first_not_of(' ');
  return k == std::string::npos ? l.size() : k;
}

/// What is still open at (line, col) — brackets of flow lists and maps, a quoted text — by a
/// light scan that skips comments and block scalars. (yaml-cpp reports an unclosed bracket
/// where it notices it, lines later, and takes a quote left open up to the end of the file
/// for one long text.)
struct Open {
  char c;
  int line, col;
};
struct OpenAt {
  std::vector<Open> brackets;
  std::optional<Open> quote;
  /// The first ',' outside every [ ] and { } where a value would start (a YAML syntax error that
  /// sends yaml-cpp 0.7's LoadAll into an endless loop that eats memory: refused before it runs).
  std::optional<Open> stray_comma;
};

OpenAt scan_open(const std::vector<std::string>& lines, int line, int col) {
  OpenAt st;
  std::optional<std::size_t> block;  // indentation of the line that opened a block scalar
  // Where the current document is: nothing yet but anchors, tags and '---' (Empty); one whole
  // value in [ ], { } or quotes (Value); anything else (Content). A ',' outside brackets before
  // Content sends yaml-cpp 0.7's LoadAll into an endless loop, at any indentation.
  enum class Doc { Empty, Value, Content } doc = Doc::Empty;
  bool top_flow = false;   // the outermost open bracket was opened where the document's value starts
  bool top_quote = false;  // the open quote was opened there
  for (int li = 0; li < static_cast<int>(lines.size()) && li < line; ++li) {
    const std::string& l = lines[li];
    if (block) {
      if (l.find_first_not_of(" \t\r") == std::string::npos || indentation(l) > *block) continue;
      block.reset();
    }
    // a line that opens a block scalar (key: >) is scanned too: a ',' at its start loops yaml-cpp
    bool opens_block = !st.quote && st.brackets.empty() && opens_block_scalar(l);
    if (!st.quote && st.brackets.empty()) {
      if (l.rfind("...", 0) == 0 && (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r')) {
        doc = Doc::Empty;  // the end of a document
        continue;
      }
      if (!l.empty() && l[0] == '%' && doc == Doc::Empty) continue;  // a directive
    }
    char prev = 0;  // previous non-space character on this line (0: line start)
    bool spaced = false;  // white space since prev
    std::size_t end = li + 1 == line ? std::min<std::size_t>(l.size(), static_cast<std::size_t>(std::max(col, 1))) : l.size();
    for (std::size_t i = 0; i < end; ++i) {
      char c = l[i];
      if (st.quote) {
        if (st.quote->c == '"' && c == '\\') { ++i; continue; }
        if (c == st.quote->c) {
          if (c == '\'' && i + 1 < l.size() && l[i + 1] == '\'') { ++i; continue; }
          st.quote.reset();
          if (top_quote) doc = Doc::Value;
          top_quote = false;
          prev = c;
          spaced = false;
        }
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r') {
        spaced = true;
        continue;
      }
      // ':', '-' and '?' are indicators only when white space follows them
      // after one whole value at the document's level, yaml-cpp takes a quote, a bracket, an
      // anchor or a tag for the start of another document's value, even with no space between
      bool at_top = st.brackets.empty() && doc != Doc::Content;
      bool node_start = prev == 0 || prev == ',' || prev == '[' || prev == '{' ||
                        ((prev == ':' || prev == '-' || prev == '?') && spaced) || (at_top && doc == Doc::Value);
      if (c == '#' && (i == 0 || l[i - 1] == ' ' || l[i - 1] == '\t')) break;
      if ((c == '"' || c == '\'') && node_start) {
        st.quote = Open{c, li + 1, static_cast<int>(i) + 1};
        top_quote = at_top;
        continue;
      }
      // a ',' where the document's value would start, or right after a whole value in [ ], { } or
      // quotes; and a ',' at the start of a line (always an error)
      if (c == ',' && st.brackets.empty() && !st.stray_comma && (i == 0 || doc != Doc::Content))
        st.stray_comma = Open{c, li + 1, static_cast<int>(i) + 1};
      if ((c == '[' || c == '{') && node_start) {
        if (st.brackets.empty()) top_flow = at_top;
        st.brackets.push_back({c, li + 1, static_cast<int>(i) + 1});
      } else if ((c == ']' || c == '}') && !st.brackets.empty()) {
        st.brackets.pop_back();
        if (st.brackets.empty() && top_flow) doc = Doc::Value;
      } else if (st.brackets.empty()) {
        // a token of the document prefix: &anchor, !tag, '---' (which starts a new document)
        bool prefix_token = at_top && node_start && (c == '&' || c == '!');
        bool new_doc = prev == 0 && i == 0 && l.compare(0, 3, "---") == 0 &&
                       (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r');
        if (prefix_token || new_doc) {
          if (new_doc) doc = Doc::Empty;
          // an anchor's or a tag's name ends at white space or at a ',' (yaml-cpp's own rule)
          while (i + 1 < end && l[i + 1] != ' ' && l[i + 1] != '\t' && (new_doc || l[i + 1] != ',')) ++i;
          prev = 0;  // what follows starts a value, as at the start of the line
          spaced = false;
          continue;
        }
        doc = Doc::Content;
      }
      prev = c;
      spaced = false;
    }
    if (opens_block) {
      block = indentation(l);
      doc = Doc::Content;
    }
  }
  return st;
}

/// The innermost '[' or '{' still open at (line, col): where a student must add the closing bracket.
std::optional<SourcePos> unclosed_bracket(const std::vector<std::string>& lines, int line, int col,
                                          const std::string& file) {
  OpenAt st = scan_open(lines, line, col);
  if (st.brackets.empty()) return std::nullopt;
  return SourcePos{file, st.brackets.back().line, st.brackets.back().col};
}

/// The first tab in the indentation of a line up to `line`, where YAML allows only spaces.
std::optional<SourcePos> tab_in_indentation(const std::vector<std::string>& lines, int line, const std::string& file) {
  for (int li = 0; li < static_cast<int>(lines.size()) && li < line; ++li) {
    const std::string& l = lines[li];
    auto k = l.find_first_not_of(" \t");
    if (k == std::string::npos) continue;
    auto tab = l.find('\t');
    if (tab != std::string::npos && tab < k) return SourcePos{file, li + 1, static_cast<int>(tab) + 1};
  }
  return std::nullopt;
}

/// yaml-cpp's message turned into what a student should look for, and where.
[[noreturn]] void yaml_error(const Loader& l, const YAML::Exception& e) {
  const std::string& m = e.msg;
  SourcePos pos = l.at(e.mark);
  if (pos.line == 0) pos = {l.file, 1, 1};
  if (pos.col == 0) pos.col = 1;
  auto has = [&](const char* s) { return m.find(s) != std::string::npos; };
  if (dynamic_cast<const YAML::DeepRecursion*>(&e))
    throw SceneError(pos, "YAML syntax error: lists and maps nested too deeply", "a scene nests a few levels; check the brackets");
  if (auto tab = tab_in_indentation(l.lines, pos.line, l.file); tab && !has(YAML::ErrorMsg::EOF_IN_SCALAR))
    throw SceneError(*tab, "YAML syntax error: a tab in the indentation", "indent with spaces; YAML does not allow tabs there");
  if (has(YAML::ErrorMsg::END_OF_SEQ_FLOW) || has(YAML::ErrorMsg::END_OF_MAP_FLOW)) {
    char open = has(YAML::ErrorMsg::END_OF_SEQ_FLOW) ? '[' : '{';
    if (auto b = unclosed_bracket(l.lines, pos.line, pos.col, l.file)) {
      open = l.char_at(*b) ? l.char_at(*b) : open;
      pos = *b;
    }
    std::string close = open == '[' ? "]" : "}";
    throw SceneError(pos, std::string("YAML syntax error: unclosed '") + open + "'",
                     "close it with '" + close + "'");
  }
  if (has(YAML::ErrorMsg::FLOW_END))
    throw SceneError(pos, "YAML syntax error: a closing bracket that closes nothing",
                     "remove it, or add the '[' or '{' it belongs to");
  if (has(YAML::ErrorMsg::MAP_VALUE) && pos.line >= 1 && pos.line <= static_cast<int>(l.lines.size())) {
    // "mass:m" is one text, not a key and a value: the ':' of a key needs a space after it
    for (int li = pos.line; li >= std::max(1, pos.line - 1); --li) {
      const std::string& t = l.lines[li - 1];
      std::size_t b = t.find_first_not_of(' '), k = b;
      if (k == std::string::npos || !(std::isalpha(static_cast<unsigned char>(t[k])) || t[k] == '_')) continue;
      while (k < t.size() && (std::isalnum(static_cast<unsigned char>(t[k])) || t[k] == '_')) ++k;
      if (k + 1 < t.size() && t[k] == ':' && t[k + 1] != ' ' && t[k + 1] != '\r')
        throw SceneError({l.file, li, static_cast<int>(k) + 1},
                         "YAML syntax error: '" + t.substr(b, t.find(' ', k) == std::string::npos ? std::string::npos : t.find(' ', k) - b) +
                             "' has no space after ':', so it is not a key",
                         "write a space after the ':' ('" + t.substr(b, k - b) + ": …')");
    }
  }
  if (has(YAML::ErrorMsg::MAP_VALUE) && pos.line >= 2 && pos.line <= static_cast<int>(l.lines.size())) {
    // "key: value" followed by a line indented deeper: YAML reads that line as more of the value
    const std::string& here = l.lines[pos.line - 1];
    int pl = pos.line - 1;
    while (pl >= 1 && (l.lines[pl - 1].find_first_not_of(" \t\r") == std::string::npos ||
                       l.lines[pl - 1][l.lines[pl - 1].find_first_not_of(" \t\r")] == '#'))
      --pl;
    if (pl >= 1) {
      const std::string& above = l.lines[pl - 1];
      auto colon = above.find(": ");
      bool has_value = colon != std::string::npos && above.find_first_not_of(" \t\r", colon + 1) != std::string::npos &&
                       !opens_block_scalar(above);
      if (has_value && indentation(here) > indentation(above) && above[indentation(above)] != '-')
        throw SceneError({l.file, pos.line, static_cast<int>(indentation(here)) + 1},
                         "YAML syntax error: this line is indented deeper than line " + std::to_string(pl) +
                             ", which already has its value",
                         "indent the keys of one map by the same number of spaces");
    }
  }
  if (has(YAML::ErrorMsg::MAP_VALUE) || has(YAML::ErrorMsg::MAP_KEY))
    throw SceneError(pos, "YAML syntax error: a 'key:' where no key may stand",
                     "indent the keys of one map by the same number of spaces, or quote a value that holds ': '");
  if ((has(YAML::ErrorMsg::END_OF_MAP) || has(YAML::ErrorMsg::END_OF_SEQ) || has(YAML::ErrorMsg::BLOCK_ENTRY)) &&
      pos.line >= 2 && pos.line <= static_cast<int>(l.lines.size())) {
    // "- a: 1" then "b: 2" at one indentation: a list item and a map key side by side
    const std::string& here = l.lines[pos.line - 1];
    std::size_t ind = indentation(here);
    bool item_here = here.compare(ind, 2, "- ") == 0;
    for (int pl = pos.line - 1; pl >= 1 && ind < here.size(); --pl) {
      const std::string& above = l.lines[pl - 1];
      if (above.find_first_not_of(" \t\r") == std::string::npos) continue;
      if (indentation(above) < ind) break;
      if (indentation(above) > ind) continue;
      bool item_above = above.compare(ind, 2, "- ") == 0;
      if (item_above != item_here)
        throw SceneError({l.file, pos.line, static_cast<int>(ind) + 1},
                         std::string("YAML syntax error: ") +
                             (item_here ? "a '- ' list item among the keys of a map" : "a key among the '- ' items of a list") +
                             " (line " + std::to_string(pl) + ")",
                         "a section is a map ('name: value' entries) or a list ('- ' items), not both; "
                         "remove the '- ' or add it to every entry");
      break;
    }
  }
  if (has(YAML::ErrorMsg::END_OF_MAP) || has(YAML::ErrorMsg::END_OF_SEQ) || has(YAML::ErrorMsg::BLOCK_ENTRY))
    throw SceneError(pos, "YAML syntax error: this line is indented where no entry can start",
                     "indent the keys of one map (and the '- ' items of one list) by the same number of spaces");
  if (has(YAML::ErrorMsg::UNKNOWN_ANCHOR) || has(YAML::ErrorMsg::ALIAS_NOT_FOUND) || has(YAML::ErrorMsg::ANCHOR_NOT_FOUND) ||
      has("alias") || has("anchor"))
    throw SceneError(pos, "YAML syntax error: a value starting with '*' or '&' is a YAML alias or anchor",
                     "put the value in quotes, e.g. \"*x\"");
  if (has(YAML::ErrorMsg::EOF_IN_SCALAR))
    throw SceneError(pos, "YAML syntax error: a quoted text is not closed", "close it with the same quote it opens with");
  if (has(YAML::ErrorMsg::INVALID_ESCAPE))
    throw SceneError(pos, "YAML syntax error: " + m, "in double quotes write '\\\\' for a backslash, or use single quotes");
  throw SceneError(pos, "YAML syntax error: " + m, "fix the indentation, brackets or quotes near here");
}

/// Where the second YAML document of a file begins (its '---'), if the file holds one.
SourcePos second_document(const std::vector<std::string>& lines, const std::string& file) {
  bool content = false;
  for (int li = 0; li < static_cast<int>(lines.size()); ++li) {
    const std::string& l = lines[li];
    bool marker = l.compare(0, 3, "---") == 0 && (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r');
    if (marker && content) return {file, li + 1, 1};
    auto k = l.find_first_not_of(" \t\r");
    if (!marker && k != std::string::npos && l[k] != '#' && l[k] != '%') content = true;
  }
  return {file, 1, 1};
}

}  // namespace

/// The starts of a text's YAML documents, read one document at a time without building nodes, and
/// no more than `cap` + 1 of them. yaml-cpp 0.7's LoadAll never ends on some syntax errors (a ','
/// where a document's value starts): it reads one empty document after another, each one ending,
/// and keeps them all. Counting first bounds that loop, whatever form of it the scan for stray
/// commas above does not know.
struct DocumentStarts : YAML::EventHandler {
  std::vector<YAML::Mark> starts;
  void OnDocumentStart(const YAML::Mark& mark) override { starts.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

constexpr std::size_t kMaxDocuments = 64;

SceneDef load_string(const std::string& text, const std::string& file) {
  if (text.size() > kMaxBytes)
    throw SceneError({file, 1, 1}, "the scene is " + std::to_string(text.size()) + " bytes long, more than the " +
                                       std::to_string(kMaxBytes) + " a scene may have",
                     "check that this is a scene file; a scene is a few kilobytes");
  Loader l{file, split_lines(text)};
  if (auto nul = text.find('\0'); nul != std::string::npos) {
    int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(nul), '\n'));
    std::size_t start = text.rfind('\n', nul);
    int col = static_cast<int>(nul - (start == std::string::npos ? 0 : start + 1)) + 1;
    throw SceneError({file, line, col}, "the file holds a NUL byte: it is not a text file", "save the scene as plain text (UTF-8)");
  }
  if (auto comma = scan_open(l.lines, static_cast<int>(l.lines.size()) + 1, 0).stray_comma)
    throw SceneError({file, comma->line, comma->col}, "YAML syntax error: a ',' outside [ ] and { }, where a value should start",
                     "remove it, or quote the text it belongs to: a comma separates the entries of a list in [ ] or of a map in { }");
  {
    std::istringstream in(text);
    YAML::Parser parser(in);
    DocumentStarts ds;
    try {
      while (ds.starts.size() <= kMaxDocuments && parser.HandleNextDocument(ds)) {
      }
    } catch (const YAML::Exception& e) {
      yaml_error(l, e);
    }
    if (ds.starts.size() > kMaxDocuments) {
      const YAML::Mark& m = ds.starts.back();
      throw SceneError({file, m.line + 1, m.column + 1},
                       "YAML syntax error: the text from here reads as document after document (more than " +
                           std::to_string(kMaxDocuments) + ")",
                       "a scene is one document: remove what starts here, or quote it (a ',' separates entries only "
                       "inside [ ] and { })");
    }
  }
  std::vector<YAML::Node> docs;
  try {
    docs = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    yaml_error(l, e);
  }
  // a quote left open runs to the end of the file, and yaml-cpp takes it all for one text
  OpenAt open = scan_open(l.lines, static_cast<int>(l.lines.size()) + 1, 0);
  if (open.quote && open.quote->line < static_cast<int>(l.lines.size()))
    throw SceneError({file, open.quote->line, open.quote->col},
                     std::string("YAML syntax error: the quoted text opened here with ") + open.quote->c + " is never closed",
                     std::string("close it with ") + open.quote->c + " where the text ends");
  std::vector<YAML::Node> real;
  for (auto& d : docs)
    if (d && !d.IsNull()) real.push_back(d);
  if (real.empty())
    throw SceneError({file, 1, 1}, "the scene is empty", "write a scene: title, parameters, bodies, states, analyses, find");
  if (real.size() > 1)
    throw SceneError(second_document(l.lines, file), "the file holds more than one YAML document ('---')",
                     "keep one scene per file: remove the second '---' and what follows, or move it to a file of its own");
  try {
    return l.load(real.front());
  } catch (const YAML::Exception& e) {
    yaml_error(l, e);
  }
}

SceneDef load_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st))
    throw SceneError({path, 1, 1}, "the scene file does not exist", "check the path and the file name");
  if (fs::is_directory(st))
    throw SceneError({path, 1, 1}, "this is a directory, not a scene file", "name a .yaml file inside it");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError({path, 1, 1}, "cannot read the scene file", "check that you may read it (permissions)");
  // at most one byte more than a scene may have (a device such as /dev/zero never ends)
  std::string text(kMaxBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  std::stringstream ss;
  ss << text;
  if (in.bad()) throw SceneError({path, 1, 1}, "cannot read the scene file", "check that it is a readable file");
  return load_string(ss.str(), path);
}

}  // namespace kinergy::scene
