// Many scenes in one process: JSON Lines of requests in, JSON Lines of results out.
#include "kinergy/app/app.hpp"
#include "kinergy/batch/batch.hpp"

#include "kinergy/confirm/confirm.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <istream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <regex>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "kinergy/batch/carry.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/common/markup.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/emit/emit.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/units/units.hpp"
#include "kinergy/verify/verify.hpp"

namespace kinergy::batch {

namespace {

// A request that cannot be run: what is wrong with it (a SceneError names its own place).
struct BadRequest {
  std::string message, fix;
};

std::string error_json(const std::string& file, int line, int col, const std::string& message, const std::string& fix) {
  return "{\"file\": " + json_quote(file) + ", \"line\": " + std::to_string(line) + ", \"column\": " + std::to_string(col) +
         ", \"message\": " + json_quote(message) + ", \"fix\": " + json_quote(fix) + "}";
}

std::string trim_newline(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}

std::string scalar(const YAML::Node& n, const std::string& key) {
  if (!n.IsScalar()) throw BadRequest{"\"" + key + "\" is not a string or a number", "write \"" + key + "\": \"…\""};
  return n.as<std::string>();
}

// A request's result line, and whether it succeeded.
struct Outcome {
  bool ok = false;
  std::string line;
};

/// Requests that differ from an earlier one only in the values `set` gives (the same scene file,
/// the same names set, the solution alone asked for) share its solution: the first is solved
/// with its choices traced (numeric/trace.hpp), and a later one whose values every choice falls
/// the same way at (batch/carry.hpp) gets the closed forms' values there, each to 1e-13. A sample
/// of those (take_sample) is also solved in full and confirmed, and must agree to 1e-12.
class Shared {
public:
  /// The solution found at batch line `line` with trace t, carried in the parameters `names`.
  Shared(Solution s, const numerics::Trace& t, std::vector<std::string> names, std::size_t line)
      : base_(std::move(s)), names_(std::move(names)), line_(line) {
    // (each set value is read in SI: its number times its unit's factor)
    in_ = Inputs::of(base_.model, names_, std::vector<GiNaC::ex>(names_.size(), 1));
    for (std::size_t i = 0; i < names_.size(); ++i) {
      const model::Parameter* p = base_.model.parameter(names_[i]);
      if (!p || !p->value) {
        region_.unusable = "'" + names_[i] + "' is not a parameter with a value";
        return;
      }
      params_.push_back(p);
      positive_.push_back(numerics::to_double(*p->value) > 0);
    }
    region_.ok = true;
    carry(region_, t, &base_, in_);
  }

  bool usable() const { return region_.unusable.empty(); }

  /// The result line of a request with these set values (as written), when the solution holds
  /// there; nothing when it is to be solved in full.
  std::optional<std::string> line(const std::map<std::string, std::string>& set, const emit::Options& o, const std::string& head) {
    std::vector<double> x, rad;
    for (std::size_t i = 0; i < names_.size(); ++i) {
      // "NUMBER UNIT": the number's double, the unit's factor to SI (kept by its text)
      const std::string& text = set.at(names_[i]);
      const std::size_t gap = text.find(' ');
      double number = 0;
      const auto r = std::from_chars(text.data(), text.data() + (gap == std::string::npos ? text.size() : gap), number);
      if (r.ec != std::errc() || r.ptr != text.data() + (gap == std::string::npos ? text.size() : gap)) return std::nullopt;
      const Unit* u = unit(gap == std::string::npos ? std::string() : text.substr(gap + 1));
      // (an expression, a bad value or unit: the full solve says what it is)
      // the same dimension, and the same sign as where it was solved (a positive symbol's
      // simplifications hold for a positive value only)
      if (!u || !(u->dim == params_[i]->dim)) return std::nullopt;
      // (the SI value's double: the number's, times the unit's factor's, two roundings at most)
      const double v = number * u->factor;
      if (!std::isfinite(v) || v == 0 || (v > 0) != positive_[i]) return std::nullopt;
      x.push_back(v);
      rad.push_back(4 * std::numeric_limits<double>::epsilon() * std::fabs(v) + 1e-300);
    }
    if (!holds(region_, x, rad)) return std::nullopt;
    // (each input's double within two roundings of the value written)
    std::vector<double> dx;
    for (double v : x) dx.push_back(2.3e-16 * std::fabs(v));
    auto b = values_at(region_, x.data(), dx.data());
    if (!b) return std::nullopt;
    std::vector<Value> values;
    for (auto& v : *b) values.push_back(Value{GiNaC::numeric(v.value), Value::How::Double, 0, v.bound, false, {}, {}});
    if (!template_) {
      std::vector<Confirmed> confirmed;
      for (const Confirmed& c : base_.confirmed)
        confirmed.push_back({c.analysis, c.by == Confirmed::By::None ? c.by : Confirmed::By::Shared, c.difference, c.tolerance,
                             "the solution found at batch line " + std::to_string(line_) + " (confirmed there " +
                                 (c.by == Confirmed::By::None ? std::string("not at all") : "by " + Confirmed::name(c.by)) +
                                 "), shown to hold at these values: every choice it made falls the same way",
                             {}, {}, false});
      template_ = emit::json_template(base_, o, confirmed);
    }
    last_.clear();
    for (auto& v : *b) last_.push_back(v.value);
    return head + ", \"ok\": true, \"solution\": " + trim_newline(emit::fill(*template_, values)) + "}";
  }

  /// Count a request answered by line(): is it one of the sample to be solved in full as well?
  /// The 1st, 16th, 256th, 4096th, … (a solve takes as long as some 10⁴ shared answers: a fixed
  /// share of them would set the pace).
  bool take_sample() {
    const std::size_t n = ++carried_;
    return (n & (n - 1)) == 0 && (n & 0x11111111u) != 0;
  }
  std::size_t carried() const { return carried_; }

  /// The values just carried against a full solve's at the same values: each the same to 1e-12.
  /// @throws SceneError showing both when one is not.
  void compare(const Solution& full) const {
    for (std::size_t k = 0; k < full.results.size() && k < last_.size(); ++k) {
      const Result& r = full.results[k];
      std::optional<Value> v = r.si ? r.evaluate(full.model.numeric_environment(), 15, true) : std::nullopt;
      const double a = last_[k], b = v ? v->v.to_double() : std::nan("");
      if (std::fabs(a - b) <= 1e-12 * std::fabs(b)) continue;
      std::ostringstream w;
      w << std::setprecision(17) << "the solution shared from batch line " << line_ << " gives " << r.name << " = " << a
        << ", a full solve at these values gives " << b;
      throw SceneError(r.pos, w.str(), "report this request; meanwhile give each variant a scene of its own (\"yaml\")");
    }
  }

private:
  Solution base_;
  std::vector<std::string> names_;
  std::vector<const model::Parameter*> params_;
  std::size_t line_;
  Inputs in_;
  Region region_;
  std::size_t carried_ = 0;
  std::vector<double> last_;  ///< the values last carried
  std::optional<emit::JsonTemplate> template_;  ///< the result's JSON, made once
  std::vector<bool> positive_;  ///< each parameter's sign where it was solved
  struct Unit {
    units::Dimension dim;
    double factor = 1;  ///< to SI
  };
  std::map<std::string, std::optional<Unit>> units_;  ///< units as written (nothing: not a unit)

  const Unit* unit(const std::string& text) {
    auto it = units_.find(text);
    if (it == units_.end()) {
      std::optional<Unit> u;
      try {
        const units::Quantity q = units::parse_quantity("1 " + text);
        if (q.has_number && text.find_first_not_of(' ') != std::string::npos) u = Unit{q.unit.dim, numerics::to_double(q.unit.factor)};
        if (text.empty()) u = Unit{units::Dimension{}, 1};
      } catch (const std::exception&) {
      }
      it = units_.emplace(text, u).first;
    }
    return it->second ? &*it->second : nullptr;
  }
};

using SharedSolutions = std::map<std::string, std::unique_ptr<Shared>>;
constexpr std::size_t kMostShared = 256;

/// A request of the plain form a bank of variants writes, read without a JSON library:
/// {"id": N or "…", "scene": "…", "set": {"name": "value", …}, "confirm": true|false}, strings
/// without escapes. Anything else is read by the full reader (which also says what is wrong).
struct Plain {
  std::string id = "null", scene;
  std::map<std::string, std::string> set;
  bool confirmed = true;
};

std::optional<Plain> read_plain(const std::string& r) {
  std::size_t i = 0;
  auto space = [&]() {
    while (i < r.size() && (r[i] == ' ' || r[i] == '\t' || r[i] == '\r')) ++i;
  };
  auto eat = [&](char c) {
    space();
    if (i >= r.size() || r[i] != c) return false;
    ++i;
    return true;
  };
  auto string = [&](std::string& out) {
    space();
    if (i >= r.size() || r[i] != '"') return false;
    const std::size_t end = r.find('"', i + 1);
    if (end == std::string::npos) return false;
    out = r.substr(i + 1, end - i - 1);
    if (out.find('\\') != std::string::npos) return false;
    i = end + 1;
    return true;
  };
  Plain p;
  bool scene = false;
  if (!eat('{')) return std::nullopt;
  do {
    std::string key;
    if (!string(key) || !eat(':')) return std::nullopt;
    space();
    if (key == "scene" && !scene) {
      if (!string(p.scene)) return std::nullopt;
      scene = true;
    } else if (key == "id") {
      std::string v;
      if (i < r.size() && r[i] == '"') {
        if (!string(v)) return std::nullopt;
        p.id = json_quote(v);
      } else {
        const std::size_t start = i;
        while (i < r.size() && (std::isdigit(static_cast<unsigned char>(r[i])) || r[i] == '-')) ++i;
        if (i == start || (i < r.size() && r[i] != ',' && r[i] != '}' && r[i] != ' ')) return std::nullopt;
        p.id = r.substr(start, i - start);
        if (p.id == "-" || (p.id.size() > 1 && p.id[p.id[0] == '-'] == '0')) return std::nullopt;
      }
    } else if (key == "set" && p.set.empty()) {
      if (!eat('{')) return std::nullopt;
      do {
        std::string name, value;
        if (!string(name) || !eat(':') || !string(value) || p.set.count(name)) return std::nullopt;
        p.set[name] = value;
      } while (eat(','));
      if (!eat('}') || p.set.empty()) return std::nullopt;
    } else if (key == "confirm") {
      if (r.compare(i, 4, "true") == 0) i += 4, p.confirmed = true;
      else if (r.compare(i, 5, "false") == 0) i += 5, p.confirmed = false;
      else return std::nullopt;
    } else {
      return std::nullopt;
    }
  } while (eat(','));
  if (!eat('}')) return std::nullopt;
  space();
  if (i != r.size() || !scene || p.set.empty()) return std::nullopt;
  return p;
}

/// The key under which variants share a solution: the scene file, whether confirmed, the names set.
std::string shared_key(const std::string& scene, bool confirmed, const std::map<std::string, std::string>& set) {
  std::string key = scene + '\0' + (confirmed ? "confirmed" : "");
  for (auto& [name, v] : set) key += '\0' + name;
  return key;
}

/// What a request asks for: produce, digits, confirm. @throws BadRequest saying what is wrong.
struct Asked {
  bool solve = false, verify = false, derive = false, latex = false, confirmed = true;
  emit::Options o;
};

Asked read_asked(const YAML::Node& q) {
  Asked a;
  if (const YAML::Node produce = q["produce"]) {
    if (!produce.IsSequence()) throw BadRequest{"\"produce\" is not a list", "write \"produce\": [\"solve\", \"derive\"]"};
    for (const auto& p : produce) {
      const std::string what = scalar(p, "produce");
      if (what == "solve") a.solve = true;
      else if (what == "verify") a.verify = true;
      else if (what == "derive") a.derive = true;
      else if (what == "latex") a.latex = true;
      else throw BadRequest{"cannot produce \"" + what + "\"", "produce solve, verify, derive or latex"};
    }
  } else {
    a.solve = true;
  }
  if (const YAML::Node d = q["digits"]) {
    int digits = 0;
    try {
      digits = d.as<int>();
    } catch (const YAML::Exception&) {
      digits = 0;
    }
    if (!numerics::valid_digits(digits)) throw BadRequest{numerics::digits_fault("\"digits\"").first, "write \"digits\": 15"};
    a.o.digits = digits;
    a.o.guaranteed = true;
  }
  // each analysis confirmed a second way unless the request says "confirm": false
  if (const YAML::Node c = q["confirm"]) {
    const std::string v = c.IsScalar() ? c.as<std::string>() : "";
    if (v != "true" && v != "false") throw BadRequest{"\"confirm\" is not true or false", "write \"confirm\": false"};
    a.confirmed = v == "true";
  }
  return a;
}

/// A variant of a scene solved before, written plainly (read_plain), answered from its shared
/// solution; nothing when it is to be read and solved in full.
std::optional<Outcome> answer_plain(const std::string& request, std::size_t number, SharedSolutions& shared) {
  auto p = read_plain(request);
  if (!p) return std::nullopt;
  auto it = shared.find(shared_key(p->scene, p->confirmed, p->set));
  if (it == shared.end() || !it->second->usable()) return std::nullopt;
  const std::string head = "{\"line\": " + std::to_string(number) + ", \"id\": " + p->id;
  try {
    auto line = it->second->line(p->set, emit::Options{}, head);
    if (!line) return std::nullopt;
    if (it->second->take_sample()) {
      // one of the sample: solved in full as well, and compared
      scene::SceneDef def = scene::load_file(p->scene);
      for (auto& [name, v] : p->set) app::set_parameter(def, name, v);
      Solution full = solve_scene(def);
      if (p->confirmed) confirm(full);
      it->second->compare(full);
    }
    return Outcome{true, *line};
  } catch (const SceneError& e) {
    return Outcome{false, head + ", \"ok\": false, \"error\": " + error_json(e.pos().file, e.pos().line, e.pos().col, e.problem(), e.fix()) + "}"};
  } catch (const std::exception&) {
    return std::nullopt;  // (read again in full)
  }
}

Outcome run_request(const std::string& request, std::size_t number, SharedSolutions* shared) {
  std::string id = "null";
  auto head = [&]() { return "{\"line\": " + std::to_string(number) + ", \"id\": " + id; };
  auto failed = [&](const std::string& error) { return Outcome{false, head() + ", \"ok\": false, \"error\": " + error + "}"}; };
  // a variant of a scene solved before, written plainly: its shared solution where that holds
  if (shared)
    if (auto answer = answer_plain(request, number, *shared)) return *answer;
  const std::string where = "<batch line " + std::to_string(number) + ">";
  try {
    YAML::Node q;
    try {
      q = YAML::Load(request);
    } catch (const YAML::Exception& e) {
      throw BadRequest{"the request is not JSON (" + e.msg + ")", "write one JSON object a line: {\"scene\": \"FILE.yaml\"}"};
    }
    if (!q.IsMap()) throw BadRequest{"the request is not a JSON object", "write one JSON object a line: {\"scene\": \"FILE.yaml\"}"};
    for (const auto& kv : q) {
      const std::string key = kv.first.as<std::string>();
      if (key != "scene" && key != "yaml" && key != "id" && key != "set" && key != "produce" && key != "digits" && key != "confirm")
        throw BadRequest{"unknown key \"" + key + "\"", "use scene or yaml, and id, set, produce, digits, confirm"};
    }
    if (q["id"]) {
      if (!q["id"].IsScalar()) throw BadRequest{"\"id\" is not a string or a number", "write \"id\": \"a name\""};
      // echoed as it came: a number as a number, anything else as a string
      const std::string v = q["id"].as<std::string>();
      static const std::regex json_number("-?(0|[1-9][0-9]*)(\\.[0-9]+)?([eE][+-]?[0-9]+)?");
      id = q["id"].Tag() != "!" && std::regex_match(v, json_number) ? v : json_quote(v);
    }
    if (static_cast<bool>(q["scene"]) == static_cast<bool>(q["yaml"]))
      throw BadRequest{"a request names a scene file or gives a scene inline, one of the two",
                       "write {\"scene\": \"FILE.yaml\"} or {\"yaml\": \"…\"}"};
    // parameter values to replace, as the scene writes them (units and all)
    std::map<std::string, std::string> values;
    if (const YAML::Node set = q["set"]) {
      if (!set.IsMap()) throw BadRequest{"\"set\" is not an object", "write \"set\": {\"m\": \"2 kg\"}"};
      for (const auto& kv : set) {
        const std::string name = kv.first.as<std::string>();
        values[name] = scalar(kv.second, "set." + name);
      }
    }
    const Asked asked = read_asked(q);
    const bool solve = asked.solve, verify = asked.verify, derive = asked.derive, latex = asked.latex, confirmed = asked.confirmed;
    const emit::Options& o = asked.o;
    // a variant of an earlier request: its solution shared where it holds
    const bool variant = shared && q["scene"] && !values.empty() && solve && !verify && !derive && !latex && !q["digits"];
    std::string key;
    Shared* earlier = nullptr;
    if (variant) {
      key = shared_key(scalar(q["scene"], "scene"), confirmed, values);
      if (auto it = shared->find(key); it != shared->end()) earlier = it->second.get();
    }
    std::optional<std::string> carried;
    if (earlier && earlier->usable()) carried = earlier->line(values, o, head());
    if (carried && !earlier->take_sample()) return {true, *carried};
    scene::SceneDef def = q["scene"] ? scene::load_file(scalar(q["scene"], "scene")) : scene::load_string(scalar(q["yaml"], "yaml"), where);
    for (auto& [name, v] : values) app::set_parameter(def, name, v);
    numerics::Trace trace;
    std::optional<Solution> solved;
    {
      std::optional<numerics::Tracing> tracing;
      if (variant && !earlier) tracing.emplace(trace);
      solved = solve_scene(def);
    }
    Solution& s = *solved;
    if (confirmed) confirm(s);
    if (carried) {
      // one of the sample: the shared values against the full solve's
      earlier->compare(s);
      return {true, *carried};
    }
    // (at most kMostShared scenes' solutions kept: a bank of many scenes holds no more)
    if (variant && !earlier && shared->size() < kMostShared) {
      std::vector<std::string> names;
      for (auto& [name, v] : values) names.push_back(name);
      (*shared)[key] = std::make_unique<Shared>(s, trace, names, number);
    }
    std::ostringstream out;
    out << head() << ", \"ok\": true";
    std::vector<verify::Check> checks;
    if (verify) checks = verify::verify(s);
    if (solve || verify) out << ", \"solution\": " << trim_newline(emit::json(s, o, verify ? &checks : nullptr));
    if (verify) {
      bool all = true;
      for (auto& c : checks) all = all && c.ok();
      out << ", \"verified\": " << (all ? "true" : "false");
    }
    if (derive || latex) {
      const emit::Derivation d = emit::derive(s);
      if (derive) out << ", \"derive\": " << json_quote(emit::text(d));
      if (latex) out << ", \"latex\": " << json_quote(emit::latex(d));
    }
    out << "}";
    return {true, out.str()};
  } catch (const BadRequest& e) {
    return failed(error_json(where, 1, 0, e.message, e.fix));
  } catch (const SceneError& e) {
    return failed(error_json(e.pos().file, e.pos().line, e.pos().col, e.problem(), e.fix()));
  } catch (const InputError& e) {
    return failed(error_json(where, 1, 0, e.what(), e.fix()));
  } catch (const std::exception& e) {
    return failed(error_json(where, 1, 0, std::string("internal error: ") + e.what(), "report it with this request"));
  }
}

}  // namespace

std::string run_line(const std::string& request, std::size_t number) { return run_request(request, number, nullptr).line; }

Summary run(std::istream& in, std::ostream& out, const std::function<void(const Summary&)>& progress) {
  Summary sum;
  SharedSolutions shared;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank lines are no requests
    const Outcome result = run_request(line, number, &shared);
    // (flushed when no more requests wait: a client sending one at a time gets each answer)
    out << result.line << "\n";
    if (in.rdbuf()->in_avail() <= 0) out << std::flush;
    ++sum.requests;
    if (result.ok) ++sum.ok;
    else ++sum.failed;
    if (progress) progress(sum);
  }
  return sum;
}

}  // namespace kinergy::batch
