// Many scenes in one process: JSON Lines of requests in, JSON Lines of results out.
#include "kinergy/app/app.hpp"
#include "kinergy/batch/batch.hpp"

#include "kinergy/confirm/confirm.hpp"

#include <istream>
#include <ostream>
#include <regex>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "kinergy/common/error.hpp"
#include "kinergy/common/markup.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/emit/emit.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"
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

Outcome run_request(const std::string& request, std::size_t number) {
  const std::string where = "<batch line " + std::to_string(number) + ">";
  std::string id = "null";
  auto head = [&]() { return "{\"line\": " + std::to_string(number) + ", \"id\": " + id; };
  auto failed = [&](const std::string& error) { return Outcome{false, head() + ", \"ok\": false, \"error\": " + error + "}"}; };
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
    scene::SceneDef def = q["scene"] ? scene::load_file(scalar(q["scene"], "scene")) : scene::load_string(scalar(q["yaml"], "yaml"), where);
    // parameter values replaced, as the scene writes them (units and all)
    if (const YAML::Node set = q["set"]) {
      if (!set.IsMap()) throw BadRequest{"\"set\" is not an object", "write \"set\": {\"m\": \"2 kg\"}"};
      for (const auto& kv : set) {
        const std::string name = kv.first.as<std::string>();
        app::set_parameter(def, name, scalar(kv.second, "set." + name));
      }
    }
    bool solve = false, verify = false, derive = false, latex = false;
    if (const YAML::Node produce = q["produce"]) {
      if (!produce.IsSequence()) throw BadRequest{"\"produce\" is not a list", "write \"produce\": [\"solve\", \"derive\"]"};
      for (const auto& p : produce) {
        const std::string what = scalar(p, "produce");
        if (what == "solve") solve = true;
        else if (what == "verify") verify = true;
        else if (what == "derive") derive = true;
        else if (what == "latex") latex = true;
        else throw BadRequest{"cannot produce \"" + what + "\"", "produce solve, verify, derive or latex"};
      }
    } else {
      solve = true;
    }
    emit::Options o;
    if (const YAML::Node d = q["digits"]) {
      int digits = 0;
      try {
        digits = d.as<int>();
      } catch (const YAML::Exception&) {
        digits = 0;
      }
      if (!numerics::valid_digits(digits)) throw BadRequest{numerics::digits_fault("\"digits\"").first, "write \"digits\": 15"};
      o.digits = digits;
      o.guaranteed = true;
    }
    // each analysis confirmed a second way unless the request says "confirm": false
    bool confirmed = true;
    if (const YAML::Node c = q["confirm"]) {
      const std::string v = c.IsScalar() ? c.as<std::string>() : "";
      if (v != "true" && v != "false") throw BadRequest{"\"confirm\" is not true or false", "write \"confirm\": false"};
      confirmed = v == "true";
    }
    Solution s = solve_scene(def);
    if (confirmed) confirm(s);
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

std::string run_line(const std::string& request, std::size_t number) { return run_request(request, number).line; }

Summary run(std::istream& in, std::ostream& out, const std::function<void(const Summary&)>& progress) {
  Summary sum;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank lines are no requests
    const Outcome result = run_request(line, number);
    out << result.line << "\n" << std::flush;
    ++sum.requests;
    if (result.ok) ++sum.ok;
    else ++sum.failed;
    if (progress) progress(sum);
  }
  return sum;
}

}  // namespace kinergy::batch
