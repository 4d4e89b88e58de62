#include "kinergy/common/process.hpp"

#include <fcntl.h>
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
