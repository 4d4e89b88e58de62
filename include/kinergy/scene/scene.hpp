/// @file scene.hpp  Scene text → SceneDef: plain structs with source positions (no GiNaC).
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kinergy/common/error.hpp"

namespace kinergy::scene {

struct Entry;

/// A YAML value with the place it was written: a scalar, a list or a map (keys in order).
struct Node {
  enum class Kind { Null, Scalar, List, Map };
  Kind kind = Kind::Null;
  std::string scalar;
  std::vector<Node> items;
  std::vector<Entry> entries;  ///< map: (key, value), in file order (std::pair<Node, Node> of a Node
                              ///< still incomplete here is not portable: libstdc++ 12 with clang 14 refuses it)
  SourcePos pos;

  bool is_scalar() const { return kind == Kind::Scalar; }
  bool is_list() const { return kind == Kind::List; }
  bool is_map() const { return kind == Kind::Map; }
  const Node* get(const std::string& key) const;  ///< map entry or nullptr
  std::string kind_name() const;                  ///< "a text", "a list", "a map", "empty"
};

/// A key and its value in a map.
struct Entry {
  Node first, second;
};

/// A scalar text and where it stands.
struct Text {
  std::string s;
  SourcePos pos;
};

/// `m: 5 kg` | `m: kg` | `k: unknown N/m`, or `theta2: {value: 210 deg, in: [180 deg, 270 deg]}`:
/// the same text under `value:`, with the range the parameter lies in.
struct ParameterDef {
  std::string name;
  SourcePos pos;
  Text value;
  std::optional<std::pair<Text, Text>> in;  ///< [lo, hi] it lies in (checked on a value, sampled in without one)
  SourcePos in_pos;
};
/// A point (fixed, or of a body) and a coordinate; `label`: how figures name it (TeX's math mode),
/// "" for the name derived from its own.
struct PointDef { std::string name; SourcePos pos; Text x, y; std::string label = {}; };
struct CoordinateDef { std::string name; SourcePos pos; Text unit; std::string label = {}; };

struct InertiaDef {
  std::string kind;  ///< slender_rod, disk, cylinder, ring, hoop, plate, sphere, spherical_shell, gyration, centroidal, particle
  std::vector<Text> args;
  SourcePos pos;
};

/// A part of a composite body: its own mass and shape, its centre and turn in the body's axes.
struct PartDef {
  std::string name;
  SourcePos pos;
  Text mass;
  InertiaDef inertia;
  Text x, y;                 ///< its centre, from the body's reference point
  std::optional<Text> angle;  ///< its turn in body axes (how it is drawn; 0 by default)
};

struct BodyDef {
  std::string name;
  SourcePos pos;
  Text mass;
  InertiaDef inertia;
  Text x, y;                     ///< mass-centre position (a composite body: its reference point's)
  std::optional<Text> angle;
  std::vector<PointDef> points;  ///< in body axes through G (a composite body: through its reference point)
  std::vector<PartDef> parts;    ///< a composite body's parts (then mass and inertia are theirs)
  /// `drawn_as: {circle: R}` or `{rectangle: [w, h]}`: how a body whose inertia has no outline (a
  /// particle, a radius of gyration, a given Ī) is drawn; for drawing only
  std::optional<InertiaDef> drawn_as;
  /// `label: "W_A"`: how figures name it (TeX's math mode), instead of a name derived from its own
  std::string label;
};

/// A `label:` — a name in TeX's math mode for figures — read and checked (`whose` names its owner
/// in the error). @throws SceneError when it is empty, too long, holds $ % # & ~ ^ or a line
/// break, or has braces that do not close.
std::string read_label(const Node& n, const std::string& whose);

/// An effect: its name, its kind and the rest of its map (checked by the model per kind).
struct EffectDef {
  std::string name;
  std::string kind;
  SourcePos pos;
  Node arg;      ///< the value of the kind key (e.g. the body, the point pair), Null when name = kind
  Node options;  ///< the whole map
};

struct StateDef {
  std::string name;
  SourcePos pos;
  std::vector<std::pair<std::string, Text>> values;  ///< q, q_dot, t → expression
  SourcePos key_pos(const std::string& key) const;
  std::vector<Text> where;
};

struct AnalysisDef {
  std::string kind;  ///< energy, …
  SourcePos pos;
  Node options;
};

struct FindDef {
  std::string name;
  SourcePos pos;
  Text value;
  std::optional<Node> root;  ///< positive | negative | {in: [lo, hi]}
  std::optional<Text> unit;
  /// max | min | at_max | at_min over a parameter (its name), within `over_range`
  std::optional<std::pair<std::string, Text>> extreme;
  std::optional<Node> over_range;
  /// least | greatest → a parameter (its name): its bound for which state `reaches` is reached,
  /// checked at every position `along` a parameter placing that state (within `over_range`)
  std::optional<std::pair<std::string, Text>> reach;
  std::optional<Text> reaches, along;
};

struct ExpectDef {
  std::string name;
  SourcePos pos;
  std::optional<Text> form;
  std::optional<Text> value;
  std::optional<Text> rtol;
};

struct SceneDef {
  std::string file;
  std::string title, description;
  std::vector<ParameterDef> parameters;
  std::vector<PointDef> points;
  std::vector<CoordinateDef> coordinates;
  std::vector<BodyDef> bodies;
  std::vector<Text> constraints;
  std::vector<EffectDef> effects;
  std::vector<StateDef> states;
  std::vector<AnalysisDef> analyses;
  std::vector<FindDef> finds;
  std::vector<ExpectDef> expects;
};

/// Effect kinds a scene may name (the table of kinds, src/effects/registry.cpp).
const std::vector<std::string>& effect_kinds();

/// Inertia shapes a body may name, with how many sizes each takes (the table of shapes,
/// src/model/inertia.cpp).
const std::vector<std::pair<std::string, int>>& inertia_shapes();

/// The limits of a scene's text (each refused with its own error).
constexpr std::size_t kMaxBytes = 1 << 20;   ///< 1 MiB
constexpr std::size_t kMaxNodes = 100000;    ///< YAML values, aliases expanded
constexpr int kMaxDepth = 64;                ///< nesting of lists and maps
constexpr std::size_t kMaxName = 64;         ///< characters of a name

/// Read a scene file. @throws SceneError (file:line:col) on any malformed input.
SceneDef load_file(const std::string& path);
/// Read scene text; `file` names it in errors.
SceneDef load_string(const std::string& text, const std::string& file = "<scene>");

/// A key no name can be: an expression's tail after YAML split `{value: f(a, b)}` at the comma.
bool looks_cut(const std::string& key);

/// The closest of `options` to `word` by edit distance, or "" when none is near.
std::string closest(const std::string& word, const std::vector<std::string>& options);

}  // namespace kinergy::scene
