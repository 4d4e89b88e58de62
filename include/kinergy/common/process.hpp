/// @file process.hpp  Running another program (pdflatex, the C++ compiler) without a shell, and
/// items computed in forked worker processes.
#pragma once
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace kinergy {

/// Run `argv` (argv[0] looked up in PATH) in `dir`, with stdin from /dev/null and stdout and
/// stderr into `out_file`. @returns the exit status; 127 when it could not be executed, -1 when
/// it could not be started or did not exit normally.
int run_program(const std::filesystem::path& dir, const std::vector<std::string>& argv,
                const std::filesystem::path& out_file);

/// The items 0 … n−1 computed in `jobs` forked processes, handed back in order: worker w computes
/// `produce(i)` for every i ≡ w (mod jobs), in increasing i, and sends each answer down a pipe;
/// this process passes answer i to `consume(i, answer)`, in increasing i, as it comes (a long
/// run streams). Processes, not threads: GiNaC's expressions share reference counts that are not
/// atomic. The workers are copies of this process at the call: `produce` may read anything it
/// had, and what a worker changes stays in the worker. A worker's exception is thrown here as
/// std::runtime_error with its message, after the answers before it are consumed; a worker that
/// ends without answering (killed, out of memory) is an error too. An exception out of `consume`
/// (an interrupt) kills and reaps every worker. With `jobs` ≤ 1, or n < 2: all here, in order.
void ordered_in_processes(std::size_t n, int jobs, const std::function<std::string(std::size_t)>& produce,
                          const std::function<void(std::size_t, const std::string&)>& consume);

/// The cores this process may run on (1 at least).
int available_cores();

}  // namespace kinergy
