#include "kinergy/numeric/native.hpp"

#include "kinergy/common/process.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

#ifndef KINERGY_CXX
#define KINERGY_CXX "c++"
#endif

namespace kinergy::numerics {

namespace fs = std::filesystem;

namespace {

fs::path cache_dir() {
  if (const char* d = std::getenv("KINERGY_CACHE"); d && *d) return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return fs::path(d) / "kinergy";
  if (const char* d = std::getenv("HOME"); d && *d) return fs::path(d) / ".cache" / "kinergy";
  return fs::temp_directory_path() / ("kinergy-" + std::to_string(getuid()));
}

std::string first_line(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line))
    if (line.find("error") != std::string::npos) return line;
  return "no message";
}

// Compile `src` (or take it from the cache), load it, and find `name` in it.
std::pair<std::shared_ptr<void>, void*> load(const std::string& src, const std::string& name) {
  char key[32];
  std::snprintf(key, sizeof key, "%016zx", std::hash<std::string>{}(src + KINERGY_CXX));
  const fs::path dir = cache_dir();
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path so = dir / (std::string("fn_") + key + ".so");
  if (!fs::exists(so)) {
    // write, compile to a private name, then rename: two processes never load a half-written file
    const std::string tag = std::to_string(getpid());
    const fs::path cpp = dir / (std::string("fn_") + key + "." + tag + ".cpp");
    const fs::path tmp = dir / (std::string("fn_") + key + "." + tag + ".so");
    const fs::path log = dir / (std::string("fn_") + key + "." + tag + ".log");
    {
      std::ofstream out(cpp);
      out << src;
      if (!out) throw std::runtime_error("cannot write " + cpp.string() + " (set KINERGY_CACHE to a writable folder)");
    }
    // the flags of a Release build: the same arithmetic as the tape (no fast-math, no contraction)
    int rc = run_program(dir, {KINERGY_CXX, "-O2", "-ffp-contract=off", "-fPIC", "-shared", "-o", tmp.string(), cpp.string()},
                         log);
    std::string why = rc == 0 ? "" : first_line(log);
    fs::remove(cpp, ec);
    fs::remove(log, ec);
    if (rc != 0) {
      fs::remove(tmp, ec);
      throw std::runtime_error(std::string("the C++ compiler ") + KINERGY_CXX + " could not build the evaluator: " + why);
    }
    fs::rename(tmp, so, ec);
    if (ec && !fs::exists(so)) throw std::runtime_error("cannot place " + so.string() + ": " + ec.message());
  }
  void* h = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!h) throw std::runtime_error(std::string("cannot load ") + so.string() + ": " + dlerror());
  std::shared_ptr<void> handle(h, [](void* p) { dlclose(p); });
  void* fn = dlsym(h, name.c_str());
  if (!fn) throw std::runtime_error("no function " + name + " in " + so.string());
  return {handle, fn};
}

}  // namespace

// The loaded code (kept open while a copy of the handle lives) and its function.
template <class Native, class Fn>
Native loaded(const std::string& src, const std::string& name) {
  auto [handle, fn] = load(src, name);
  Native out;
  out.handle_ = handle;
  out.fn_ = reinterpret_cast<Fn>(fn);
  return out;
}

NativeFunction NativeFunction::build(const Tape& t) {
  return loaded<NativeFunction, Fn>(t.cpp("kinergy_fn"), "kinergy_fn");
}

NativeKernel NativeKernel::build(const Tape& t, const std::string& epilogue) {
  return loaded<NativeKernel, Fn>(t.cpp_vector("kinergy_kernel", epilogue), "kinergy_kernel");
}

}  // namespace kinergy::numerics
