/// @file process.hpp  Running another program (pdflatex, the C++ compiler) without a shell.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace kinergy {

/// Run `argv` (argv[0] looked up in PATH) in `dir`, with stdin from /dev/null and stdout and
/// stderr into `out_file`. @returns the exit status; 127 when it could not be executed, -1 when
/// it could not be started or did not exit normally.
int run_program(const std::filesystem::path& dir, const std::vector<std::string>& argv,
                const std::filesystem::path& out_file);

}  // namespace kinergy
