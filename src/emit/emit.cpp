#include "kinergy/emit/emit.hpp"

#include <sstream>

#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::emit {

using namespace GiNaC;

static std::string value_text(const Solution& s, const Result& r, int digits) {
  if (!r.si) return "";
  auto v = r.value(s.model.numeric_environment(), digits);
  if (!v) return "";
  return numerics::format(*v, digits);
}

std::string text(const Solution& s, const Options& o) {
  std::ostringstream os;
  os << s.model.title << "\n";
  std::size_t w = 0;
  for (auto& r : s.results) w = std::max(w, r.name.size());
  for (auto& r : s.results) {
    std::string pad(w - r.name.size(), ' ');
    std::string v = value_text(s, r, o.digits);
    if (r.closed_form) {
      os << "  " << r.name << pad << " = " << plain(r.closed) << "\n";
      if (!v.empty()) os << "  " << std::string(w, ' ') << " = " << v << (r.unit.empty() ? "" : " " + r.unit) << "\n";
      else os << "  " << std::string(w, ' ') << "   (no number: some parameters have no value)\n";
    } else {
      os << "  " << r.name << pad << " = " << v << (r.unit.empty() ? "" : " " + r.unit)
         << "   (no closed form: numeric root)\n";
    }
  }
  return os.str();
}

std::string text(const std::vector<verify::Check>& checks, const std::string& file) {
  std::ostringstream os;
  for (auto& c : checks)
    os << file << ": " << c.name << " (" << c.what << "): " << c.detail << "\n";
  return os.str();
}

static std::string quote(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    switch (c) {
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      case '\n': o += "\\n"; break;
      case '\t': o += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          o += buf;
        } else {
          o += c;
        }
    }
  }
  return o + "\"";
}

std::string json(const Solution& s, const Options& o, const std::vector<verify::Check>* checks) {
  std::ostringstream os;
  os << "{\"file\": " << quote(s.model.file) << ", \"title\": " << quote(s.model.title) << ", \"results\": [";
  for (std::size_t i = 0; i < s.results.size(); ++i) {
    const Result& r = s.results[i];
    std::string v = value_text(s, r, o.digits);
    os << (i ? ", " : "") << "{\"name\": " << quote(r.name) << ", \"closed_form\": "
       << (r.closed_form ? quote(plain(r.closed)) : std::string("null"))
       << ", \"value\": " << (v.empty() ? std::string("null") : quote(v)) << ", \"unit\": " << quote(r.unit)
       << ", \"dimension\": " << quote(r.dim.str()) << "}";
  }
  os << "]";
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
