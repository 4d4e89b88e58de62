#include "kinergy/common/error.hpp"

#include <algorithm>

namespace kinergy {

std::string SourcePos::str() const {
  std::string s = file.empty() ? std::string("<scene>") : file;
  s.append(":").append(std::to_string(line)).append(":").append(std::to_string(col));
  return s;
}

static std::string format(const SourcePos& p, const std::string& w, const std::string& fix) {
  std::string s = p.str();
  s.append(": ").append(w);
  if (!fix.empty()) s.append(" \u2014 ").append(fix);
  return s;
}

// A message is one line a person reads: control characters (a NUL byte, a newline) are shown
// escaped, and a token longer than kLongToken characters (a 20 000-character name echoed back) is
// shortened to its start and its length.
static std::string one_line(const std::string& text) {
  constexpr std::size_t kLongToken = 60, kKeep = 40;
  std::string out, token;
  auto flush = [&] {
    std::size_t b = token.find_first_not_of("'\"([{"), e = token.find_last_not_of("'\")]}.,:;");
    if (token.size() > kLongToken && b != std::string::npos && e != std::string::npos && e >= b) {
      // the quotes and punctuation around it stay: 'aaaa… (500 characters)',
      std::string core = token.substr(b, e + 1 - b);
      std::size_t keep = std::min(kKeep, core.size());
      while (keep > 0 && keep < core.size() && (static_cast<unsigned char>(core[keep]) & 0xC0) == 0x80) --keep;  // whole UTF-8 characters
      // characters, not bytes: a UTF-8 character's continuation bytes are not counted
      std::size_t chars = 0;
      for (char ch : core) chars += (static_cast<unsigned char>(ch) & 0xC0) != 0x80;
      out += token.substr(0, b) + core.substr(0, keep) + "… (" + std::to_string(chars) + " characters)" +
             token.substr(e + 1);
    } else {
      out += token;
    }
    token.clear();
  };
  for (char c : text) {
    unsigned char u = static_cast<unsigned char>(c);
    if (c == ' ') {
      flush();
      out += c;
    } else if (u < 0x20 || u == 0x7f) {
      static const char* hex = "0123456789abcdef";
      token += c == '\n' ? std::string("\\n") : c == '\t' ? std::string("\\t") : std::string("\\x") + hex[u >> 4] + hex[u & 15];
    } else {
      token += c;
    }
  }
  flush();
  return out;
}

SceneError::SceneError(SourcePos pos, std::string what_wrong, std::string fix)
    : std::runtime_error(format(pos, one_line(what_wrong), one_line(fix))),
      pos_(std::move(pos)),
      problem_(one_line(what_wrong)),
      fix_(one_line(fix)) {}

void rethrow_at(const SourcePos& pos, const InputError& e) {
  SourcePos p = pos;
  if (e.column() > 0 && p.line > 0) p.col += e.column() - 1;
  throw SceneError(p, e.what(), e.fix());
}

}  // namespace kinergy
