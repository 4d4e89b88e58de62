#include "kinergy/common/process.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

namespace kinergy {

int run_program(const std::filesystem::path& dir, const std::vector<std::string>& argv,
                const std::filesystem::path& out_file) {
  pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(127);
    int in = open("/dev/null", O_RDONLY);
    int out = open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in >= 0) dup2(in, 0);
    if (out >= 0) {
      dup2(out, 1);
      dup2(out, 2);
    }
    std::vector<char*> args;
    for (auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  int st = 0;
  if (waitpid(pid, &st, 0) != pid) return -1;
  if (!WIFEXITED(st)) return -1;
  return WEXITSTATUS(st);
}

}  // namespace kinergy

namespace kinergy {

namespace {

/// Write all of s, or fail (the reader is gone).
bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

/// Read exactly n bytes, or fail (the writer ended).
bool read_all(int fd, char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t r = read(fd, p, n);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r;
    n -= static_cast<std::size_t>(r);
  }
  return true;
}

/// One answer down the pipe: a flag (0 an answer, 1 an error's message), its length, its bytes.
bool send(int fd, char flag, const std::string& s) {
  const std::uint64_t n = s.size();
  return write_all(fd, &flag, 1) && write_all(fd, reinterpret_cast<const char*>(&n), sizeof n) && write_all(fd, s.data(), s.size());
}

/// The workers of one call: killed and reaped however the call ends.
struct Workers {
  std::vector<pid_t> pids;
  std::vector<int> fds;
  ~Workers() {
    for (int fd : fds) close(fd);
    for (pid_t p : pids) kill(p, SIGKILL);
    for (pid_t p : pids) waitpid(p, nullptr, 0);
  }
};

}  // namespace

void ordered_in_processes(std::size_t n, int jobs, const std::function<std::string(std::size_t)>& produce,
                          const std::function<void(std::size_t, const std::string&)>& consume) {
  const std::size_t k = std::min<std::size_t>(jobs < 1 ? 1 : static_cast<std::size_t>(jobs), n);
  if (k <= 1) {
    for (std::size_t i = 0; i < n; ++i) consume(i, produce(i));
    return;
  }
  Workers w;
  for (std::size_t j = 0; j < k; ++j) {
    int fd[2];
    if (pipe(fd) != 0) throw std::runtime_error(std::string("cannot make a pipe for a worker process: ") + std::strerror(errno));
    const pid_t pid = fork();
    if (pid < 0) {
      close(fd[0]);
      close(fd[1]);
      throw std::runtime_error(std::string("cannot start a worker process: ") + std::strerror(errno));
    }
    if (pid == 0) {
      // the worker: its share, then _exit (no destructor or atexit handler of the parent's runs
      // twice, and no stdio buffer it inherited is flushed again)
      close(fd[0]);
      for (int other : w.fds) close(other);
      signal(SIGPIPE, SIG_DFL);
      int status = 0;
      for (std::size_t i = j; i < n; i += k) {
        std::string answer;
        char flag = 0;
        try {
          answer = produce(i);
        } catch (const std::exception& e) {
          flag = 1;
          answer = e.what();
        } catch (...) {
          flag = 1;
          answer = "stopped";
        }
        if (!send(fd[1], flag, answer)) {
          status = 1;
          break;
        }
        if (flag) break;
      }
      close(fd[1]);
      _exit(status);
    }
    close(fd[1]);
    w.pids.push_back(pid);
    w.fds.push_back(fd[0]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const int fd = w.fds[i % k];
    char flag = 0;
    std::uint64_t len = 0;
    if (!read_all(fd, &flag, 1) || !read_all(fd, reinterpret_cast<char*>(&len), sizeof len))
      throw std::runtime_error("a worker process ended without answering item " + std::to_string(i) + " (killed, or out of memory)");
    std::string answer(len, '\0');
    if (!read_all(fd, answer.data(), len)) throw std::runtime_error("a worker process ended in the middle of item " + std::to_string(i));
    if (flag) throw std::runtime_error(answer);
    consume(i, answer);
  }
}

int available_cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  const long n = sysconf(_SC_NPROCESSORS_ONLN);
  return n > 0 ? static_cast<int>(n) : 1;
}

}  // namespace kinergy
