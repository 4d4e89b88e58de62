/// @file helpers.hpp  Small helpers shared by the physics tests (header only: tests/CMakeLists.txt
/// globs *.cpp, so this file adds no translation unit).
#pragma once
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/model/model.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"

namespace kt {

using GiNaC::ex;
using GiNaC::exmap;
using GiNaC::numeric;

inline std::string str(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

/// The whole content of a file ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// Every scene file (*.yaml) below `dir` of the source tree ("derivations", "tests/stability"), sorted.
inline std::vector<std::string> scene_files(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  for (auto& e : fs::recursive_directory_iterator(fs::path(KINERGY_SOURCE_DIR) / dir))
    if (e.path().extension() == ".yaml") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// The same, relative to the source directory ("derivations/energy/sliding_rod.yaml").
inline std::vector<std::string> relative_scene_files(const std::string& dir) {
  std::vector<std::string> out;
  for (auto& f : scene_files(dir)) out.push_back(std::filesystem::relative(f, KINERGY_SOURCE_DIR).generic_string());
  return out;
}

/// Every scene file of derivations/energy, sorted.
inline std::vector<std::string> derivation_scenes() { return scene_files("derivations/energy"); }

/// The result called `name` of a solution. @throws std::runtime_error when there is none.
inline const kinergy::Result& result(const kinergy::Solution& s, const std::string& name) {
  for (auto& r : s.results)
    if (r.name == name) return r;
  throw std::runtime_error("no result " + name);
}

/// A scene solved from its text (named test.yaml in messages).
inline kinergy::Solution solve_text(const std::string& text) {
  return kinergy::solve_scene(kinergy::scene::load_string(text, "test.yaml"));
}

/// `text` with the first `from` replaced by `to`. @throws std::runtime_error when `from` is not in it.
inline std::string edit(std::string text, const std::string& from, const std::string& to) {
  auto i = text.find(from);
  if (i == std::string::npos) throw std::runtime_error("edit: '" + from + "' is not in the text");
  return text.replace(i, from.size(), to);
}

/// The text of a derivation scene, by its path under derivations/ ("energy/sliding_rod.yaml").
inline std::string derivation(const std::string& rel) {
  return read_file(std::filesystem::path(KINERGY_SOURCE_DIR) / "derivations" / rel);
}

inline kinergy::model::Model model_of(const std::string& yaml) {
  return kinergy::model::Model::build(kinergy::scene::load_string(yaml, "<test>"));
}

inline kinergy::model::Model model_of_file(const std::string& path) {
  return kinergy::model::Model::build(kinergy::scene::load_file(path));
}

/// The symbol of a named parameter (fails the test through an exception when absent).
inline ex param(const kinergy::model::Model& m, const std::string& name) {
  const auto* p = m.parameter(name);
  if (!p) throw std::runtime_error("test scene has no parameter " + name);
  return p->sym;
}

inline const kinergy::model::Coordinate& coord(const kinergy::model::Model& m, const std::string& name) {
  for (auto& c : m.coords)
    if (c.name == name) return c;
  throw std::runtime_error("test scene has no coordinate " + name);
}

inline const kinergy::model::Effect& effect(const kinergy::model::Model& m, const std::string& name) {
  int i = m.effect_index(name);
  if (i < 0) throw std::runtime_error("test scene has no effect " + name);
  return m.effects[static_cast<std::size_t>(i)];
}

/// State symbol q@S (rate = false) or q_dot@S (rate = true).
inline ex at(const kinergy::model::Model& m, const std::string& q, const std::string& state, bool rate = false) {
  int s = m.state_index(state);
  if (s < 0) throw std::runtime_error("test scene has no state " + state);
  auto& p = m.states[static_cast<std::size_t>(s)].sym.at(q);
  return rate ? ex(p.second) : ex(p.first);
}

/// Zero after expansion and removal of sin² + cos² (the library's own normal form for
/// polynomials in sin and cos), falling back to GiNaC's rational normal form.
inline bool symbolically_zero(const ex& e) {
  ex x = kinergy::model::trig_simplify(e.expand());
  if (x.is_zero()) return true;
  return GiNaC::normal(x).is_zero();
}

/// Every symbol in e.
inline std::set<ex, GiNaC::ex_is_less> symbols_in(const ex& e) {
  std::set<ex, GiNaC::ex_is_less> out;
  if (GiNaC::is_a<GiNaC::symbol>(e)) out.insert(e);
  for (std::size_t i = 0; i < e.nops(); ++i) {
    auto s = symbols_in(e.op(i));
    out.insert(s.begin(), s.end());
  }
  return out;
}

/// A random exact rational in [lo, hi] with denominator 1000.
inline numeric random_rational(std::mt19937& rng, int lo, int hi) {
  std::uniform_int_distribution<int> d(lo * 1000, hi * 1000);
  return numeric(d(rng), 1000);
}

/// Numeric value of e at `values`, `digits` working digits; throws when not a real number.
inline numeric value(const ex& e, const exmap& values, int digits = 50) {
  auto v = kinergy::numerics::evaluate(e, values, digits);
  if (!v) throw std::runtime_error("not a real number: " + str(e.subs(values)));
  return *v;
}

/// 10^-n, exact.
inline numeric tol(int n) { return GiNaC::pow(numeric(10), numeric(-n)); }

/// |a − b| ≤ rel · max(1, |a|, |b|)
inline bool close(const numeric& a, const numeric& b, const numeric& rel) {
  numeric scale = std::max({numeric(1), GiNaC::abs(a), GiNaC::abs(b)});
  return GiNaC::abs(a - b) <= rel * scale;
}

inline bool close(double a, double b, double rel) {
  return std::abs(a - b) <= rel * std::max({1.0, std::abs(a), std::abs(b)});
}

inline double to_double(const ex& e, const exmap& values = {}) { return value(e, values, 30).to_double(); }

/// The value in SI of the result `name` of a solved scene: its closed form at the parameters'
/// values (fails the test when the scene has no such result).
inline double result_si(const kinergy::Solution& s, const std::string& name) {
  for (auto& r : s.results)
    if (r.name == name) return GiNaC::ex_to<numeric>(r.closed.subs(s.model.parameter_values()).evalf()).to_double();
  throw std::runtime_error("no result " + name);
}

}  // namespace kt

#include <csignal>
#include <functional>
#include <sys/wait.h>
#include <unistd.h>

namespace kt {

/// What happened to a computation run in a child process.
struct ChildResult {
  enum class Status { Ok, Failed, Threw, Timeout, Crashed } status = Status::Crashed;
  std::string message;
};

/// Run `f` in a forked child so that a computation that never returns cannot hang the test
/// run: the child is killed after `seconds`. f returns true for success and may write a
/// message for the report.
inline ChildResult in_child(const std::function<bool(std::string&)>& f, int seconds) {
  int fd[2];
  if (pipe(fd) != 0) return {ChildResult::Status::Crashed, "pipe() failed"};
  pid_t pid = fork();
  if (pid < 0) return {ChildResult::Status::Crashed, "fork() failed"};
  if (pid == 0) {
    ::close(fd[0]);
    std::string msg;
    int code = 3;
    try {
      code = f(msg) ? 0 : 1;
    } catch (const std::exception& e) {
      msg = e.what();
      code = 2;
    }
    ssize_t w = write(fd[1], msg.data(), msg.size());
    (void)w;
    ::close(fd[1]);
    _exit(code);
  }
  ::close(fd[1]);
  int st = 0;
  bool done = false;
  for (int i = 0; i < seconds * 20; ++i) {
    if (waitpid(pid, &st, WNOHANG) == pid) {
      done = true;
      break;
    }
    usleep(50000);
  }
  ChildResult r;
  if (!done) {
    kill(pid, SIGKILL);
    waitpid(pid, &st, 0);
    ::close(fd[0]);
    r.status = ChildResult::Status::Timeout;
    r.message = "no answer after " + std::to_string(seconds) + " s";
    return r;
  }
  char buf[4096];
  ssize_t n;
  while ((n = read(fd[0], buf, sizeof buf)) > 0) r.message.append(buf, static_cast<std::size_t>(n));
  ::close(fd[0]);
  if (!WIFEXITED(st)) r.status = ChildResult::Status::Crashed;
  else if (WEXITSTATUS(st) == 0) r.status = ChildResult::Status::Ok;
  else if (WEXITSTATUS(st) == 1) r.status = ChildResult::Status::Failed;
  else r.status = ChildResult::Status::Threw;
  return r;
}

/// s in single quotes for the shell.
inline std::string shell_quoted(const std::string& s) {
  std::string o = "'";
  for (char c : s) o += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return o + "'";
}

/// `text` written to NAME.yaml in the temporary directory's `dir`, for the command line: its
/// path, quoted for the shell.
inline std::string written(const std::string& dir, const std::string& name, const std::string& text) {
  const auto d = std::filesystem::temp_directory_path() / dir;
  std::filesystem::create_directories(d);
  const std::string path = (d / (name + ".yaml")).string();
  std::ofstream(path) << text;
  return shell_quoted(path);
}

/// Standard output of a shell command; its exit status in `status` (when given).
inline std::string run_command(const std::string& cmd, int* status = nullptr) {
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) {
    if (status) *status = -1;
    return "";
  }
  std::string out;
  char buf[8192];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  int st = pclose(p);
  if (status) *status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return out;
}

/// Standard output and error of `kinergy ARGS` run in the source directory; exit status in `status`.
inline std::string run_cli(const std::string& args, int& status) {
  return run_command("cd " + shell_quoted(KINERGY_SOURCE_DIR) + " && " + shell_quoted(KINERGY_CLI) + " " + args + " 2>&1", &status);
}

/// Debian's headless browser for the pages' tests: its path, or "" when it is not installed.
inline std::string chromium() {
  std::string path = run_command("command -v chromium 2>/dev/null");
  while (!path.empty() && (path.back() == '\n' || path.back() == ' ')) path.pop_back();
  return path;
}

}  // namespace kt
