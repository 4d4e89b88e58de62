#include "kinergy/common/error.hpp"

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

SceneError::SceneError(SourcePos pos, std::string what_wrong, std::string fix)
    : std::runtime_error(format(pos, what_wrong, fix)),
      pos_(std::move(pos)),
      problem_(std::move(what_wrong)),
      fix_(std::move(fix)) {}

void rethrow_at(const SourcePos& pos, const InputError& e) {
  SourcePos p = pos;
  if (e.column() > 0 && p.line > 0) p.col += e.column() - 1;
  throw SceneError(p, e.what(), e.fix());
}

}  // namespace kinergy

#include <sys/personality.h>
#include <unistd.h>

#include <cstdlib>

namespace kinergy {

void reproducible_process(int /*argc*/, char** argv) {
  int current = personality(0xffffffff);
  if (current == -1 || (current & ADDR_NO_RANDOMIZE)) return;
  if (std::getenv("KINERGY_NO_REEXEC")) return;
  if (personality(static_cast<unsigned long>(current) | ADDR_NO_RANDOMIZE) == -1) return;
  setenv("KINERGY_NO_REEXEC", "1", 1);  // never loop, even if the flag does not stick
  execv("/proc/self/exe", argv);
  // execv failed: go on as we are
}

}  // namespace kinergy
