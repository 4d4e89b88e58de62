#include "kinergy/emit/emit.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "kinergy/common/markup.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::emit {

using namespace GiNaC;

static std::optional<Value> value_of(const Solution& s, const Result& r, const Options& o) {
  if (!r.si) return std::nullopt;
  return r.evaluate(s.model.numeric_environment(), o.digits, !o.guaranteed);
}

static std::string value_text(const std::optional<Value>& v, int digits) {
  if (!v) return std::string();
  // a double's text without CLN (the same text: numerics::format_double)
  if (v->how == Value::How::Double && digits <= 17) return numerics::format_double(v->v.to_double(), digits);
  return numerics::format(v->v, digits);
}

/// A confirmation's difference as the decade that bounds it ("1e-11"; "0" when exactly zero): the
/// same text on every machine, where the last digits of a simulation may differ with libm.
static std::string decade(double d) {
  if (!(d > 0)) return "0";
  if (!std::isfinite(d)) return "inf";
  return "1e" + std::to_string(static_cast<int>(std::ceil(std::log10(d) - 1e-9)));
}

/// "energy 1 -> 2" for analysis i.
static std::string analysis_name(const Solution& s, int i) {
  const auto& a = s.model.analyses[static_cast<std::size_t>(i)];
  if (a.type->at_state()) return a.kind + " at " + s.model.states[static_cast<std::size_t>(a.from)].name;
  return a.kind + " " + s.model.states[static_cast<std::size_t>(a.from)].name + " -> " + s.model.states[static_cast<std::size_t>(a.to)].name;
}

/// How an analysis was confirmed, in words.
static std::string confirmed_text(const Confirmed& c) {
  const std::string d = c.difference > 0 ? "<= " + decade(c.difference) : "0";
  using By = Confirmed::By;
  // closed forms in parameters without values: at sampled values of them
  const std::string at = c.sampled.empty() ? "" : " at " + std::to_string(c.samples.size()) + (c.samples.size() == 1 ? " sampled value of " : " sampled values of ") + c.sampled;
  std::string t = c.by == By::Simulation          ? "by simulation" + at + ", relative difference " + d
                  : c.by == By::Residuals         ? "by the equations' residuals at 50 digits" + at + ", relative " + d
                  : c.by == By::EquationsOfMotion ? "by the equations of motion" + at + ", relative difference " + d
                  : c.by == By::Shared            ? "by a shared solution, confirmed where it was found"
                                        : "not confirmed";
  return t + (c.note.empty() ? "" : " (" + c.note + ")");
}

std::string text(const Solution& s, const Options& o) {
  std::ostringstream os;
  os << s.model.title << "\n";
  std::size_t w = 0;
  for (auto& r : s.results) w = std::max(w, r.name.size());
  for (auto& r : s.results) {
    std::string pad(w - r.name.size(), ' ');
    auto val = value_of(s, r, o);
    std::string v = value_text(val, o.digits);
    // with --digits, how the digits were made sure of
    std::string how = val && o.guaranteed ? "   (" + val->note() + ")" : "";
    if (r.closed_form) {
      os << "  " << r.name << pad << " = " << plain(r.closed) << "\n";
      if (!v.empty()) os << "  " << std::string(w, ' ') << " = " << v << (r.unit.empty() ? "" : " " + r.unit) << how << "\n";
      else os << "  " << std::string(w, ' ') << "   (no number: some parameters have no value)\n";
    } else {
      os << "  " << r.name << pad << " = " << v << (r.unit.empty() ? "" : " " + r.unit)
         << "   (no closed form: taken numerically" << (val && o.guaranteed ? "; " + val->note() : std::string()) << ")\n";
    }
  }
  if (!s.valid_where.empty()) {
    os << "Valid only where (these hold parameters without values, so they are not checked here):\n";
    for (auto& c : s.valid_where) os << "  " << plain(c.e) << " >= 0   (" << c.assumed << ")\n";
  }
  // a rolling contact's static friction between states, where it changes with the motion, is
  // checked only by the simulation that confirms the analysis
  for (int ai : s.friction_along)
    if (std::none_of(s.confirmed.begin(), s.confirmed.end(), [&](const Confirmed& c) { return c.analysis == ai && c.by == Confirmed::By::Simulation; }))
      os << "Not checked: the static friction of the rolling between the states of the " << analysis_name(s, ai)
         << " analysis, where it changes with the motion (the simulation that checks it was not run: --no-confirm)\n";
  // a surface's push (a cord's pull) that Newton's law does not give in closed form is not
  // followed along the motion: said, with why
  for (auto& why : s.one_sided_unchecked) os << "Not checked: the push of " << why << "\n";
  if (!s.confirmed.empty()) {
    os << "Confirmed a second way:\n";
    for (auto& c : s.confirmed) os << "  " << analysis_name(s, c.analysis) << ": " << confirmed_text(c) << "\n";
  }
  return os.str();
}

std::string text(const std::vector<verify::Check>& checks, const std::string& file) {
  std::ostringstream os;
  for (auto& c : checks)
    os << file << ": " << c.name << " (" << c.what << "): " << c.detail << "\n";
  return os.str();
}

static std::string quote(const std::string& s) { return json_quote(s); }

std::string json(const Solution& s, const Options& o, const std::vector<verify::Check>* checks) {
  std::vector<std::optional<Value>> values;
  for (const Result& r : s.results) values.push_back(value_of(s, r, o));
  return json(s, o, values, s.confirmed, checks);
}

namespace {
/// Where a JSON template (json_template) takes each result's value and its evaluation's note.
constexpr char kMark = '\x01';
}  // namespace

/// The JSON of json() below; with `marks`, kMark in place of each value and each evaluation.
static std::string write_json(const Solution& s, const Options& o, const std::vector<std::optional<Value>>& values,
                              const std::vector<Confirmed>& confirmed, const std::vector<verify::Check>* checks, bool marks);

std::string json(const Solution& s, const Options& o, const std::vector<std::optional<Value>>& values,
                 const std::vector<Confirmed>& confirmed, const std::vector<verify::Check>* checks) {
  return write_json(s, o, values, confirmed, checks, false);
}

JsonTemplate json_template(const Solution& s, const Options& o, const std::vector<Confirmed>& confirmed) {
  std::vector<std::optional<Value>> values(s.results.size(), Value{});
  const std::string all = write_json(s, o, values, confirmed, nullptr, true);
  JsonTemplate t;
  std::size_t from = 0;
  for (std::size_t at = all.find(kMark); at != std::string::npos; at = all.find(kMark, from)) {
    t.pieces.push_back(all.substr(from, at - from));
    from = at + 1;
  }
  t.pieces.push_back(all.substr(from));
  t.digits = o.digits;
  return t;
}

std::string fill(const JsonTemplate& t, const std::vector<Value>& values) {
  std::string out = t.pieces[0];
  for (std::size_t i = 0; i < values.size() && 2 * i + 2 < t.pieces.size(); ++i) {
    out += value_text(values[i], t.digits);
    out += t.pieces[2 * i + 1];
    out += values[i].note();
    out += t.pieces[2 * i + 2];
  }
  return out;
}

static std::string write_json(const Solution& s, const Options& o, const std::vector<std::optional<Value>>& values,
                              const std::vector<Confirmed>& confirmed, const std::vector<verify::Check>* checks, bool marks) {
  std::ostringstream os;
  os << "{\"file\": " << quote(s.model.file) << ", \"title\": " << quote(s.model.title) << ", \"results\": [";
  for (std::size_t i = 0; i < s.results.size(); ++i) {
    const Result& r = s.results[i];
    const std::optional<Value>& val = values[i];
    std::string v = value_text(val, o.digits);
    os << (i ? ", " : "") << "{\"name\": " << quote(r.name) << ", \"closed_form\": "
       << (r.closed_form ? quote(plain(r.closed)) : std::string("null"))
       << ", \"value\": " << (marks ? "\"" + std::string(1, kMark) + "\"" : v.empty() ? std::string("null") : quote(v)) << ", \"unit\": " << quote(r.unit)
       << ", \"dimension\": " << quote(r.dim.str())
       << ", \"evaluation\": " << (marks ? "\"" + std::string(1, kMark) + "\"" : val ? quote(val->note()) : std::string("null"));
    // with --digits, the enclosure: the exact value lies within radius of midpoint
    if (val && o.guaranteed) {
      auto [mid, rad] = val->ball(o.digits);
      os << ", \"proven\": " << (val->proven ? "true" : "false") << ", \"midpoint\": " << quote(mid) << ", \"radius\": " << (rad.empty() ? std::string("null") : quote(rad));
    }
    os << "}";
  }
  os << "]";
  if (!s.valid_where.empty()) {
    os << ", \"valid_where\": [";
    for (std::size_t i = 0; i < s.valid_where.size(); ++i)
      os << (i ? ", " : "") << "{\"expression\": " << quote(plain(s.valid_where[i].e)) << ", \"at_least\": 0, \"means\": "
         << quote(s.valid_where[i].assumed) << "}";
    os << "]";
  }
  if (!confirmed.empty()) {
    os << ", \"confirmed\": [";
    for (std::size_t i = 0; i < confirmed.size(); ++i) {
      const Confirmed& c = confirmed[i];
      os << (i ? ", " : "") << "{\"analysis\": " << quote(analysis_name(s, c.analysis)) << ", \"by\": "
         << (c.by == Confirmed::By::None ? std::string("null") : quote(Confirmed::name(c.by))) << ", \"within\": "
         << (c.by == Confirmed::By::None ? std::string("null") : quote(decade(c.difference)))
         << ", \"note\": " << quote(c.note);
      if (!c.sampled.empty()) {  // the sampled values of parameters without values it was confirmed at
        os << ", \"sampled\": " << quote(c.sampled) << ", \"samples\": [";
        for (std::size_t k = 0; k < c.samples.size(); ++k) os << (k ? ", " : "") << quote(c.samples[k]);
        os << "]";
      }
      os << "}";
    }
    os << "]";
  }
  if (checks) {
    os << ", \"checks\": [";
    for (std::size_t i = 0; i < checks->size(); ++i) {
      auto& c = (*checks)[i];
      os << (i ? ", " : "") << "{\"name\": " << quote(c.name) << ", \"claim\": " << quote(c.what)
         << ", \"ok\": " << (c.ok() ? "true" : "false") << ", \"detail\": " << quote(c.detail) << "}";
    }
    os << "]";
  }
  os << "}\n";
  return os.str();
}

}  // namespace kinergy::emit
