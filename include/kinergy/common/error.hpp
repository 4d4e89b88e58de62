/// @file error.hpp  Source positions and the one-line error every bad input ends with.
#pragma once
#include <stdexcept>
#include <string>

namespace kinergy {

/// A place in a scene file (1-based line and column; 0 when unknown).
struct SourcePos {
  std::string file;
  int line = 0;
  int col = 0;
  std::string str() const;  ///< "FILE:LINE:COL"
};

/// The error of a bad scene: `FILE:LINE:COL: what is wrong — what would fix it`.
class SceneError : public std::runtime_error {
public:
  SceneError(SourcePos pos, std::string what_wrong, std::string fix);
  const SourcePos& pos() const { return pos_; }
  const std::string& problem() const { return problem_; }
  const std::string& fix() const { return fix_; }
private:
  SourcePos pos_;
  std::string problem_, fix_;
};

/// An error without a position yet (thrown by units, expressions); callers that know the
/// place rethrow it as a SceneError.
class InputError : public std::runtime_error {
public:
  InputError(std::string what_wrong, std::string fix, int column = 0)
      : std::runtime_error(what_wrong), fix_(std::move(fix)), column_(column) {}
  const std::string& fix() const { return fix_; }
  int column() const { return column_; }  ///< 1-based column inside the text, 0 if none
private:
  std::string fix_;
  int column_;
};

/// Turn an InputError found inside a scalar that starts at `pos` into a SceneError.
[[noreturn]] void rethrow_at(const SourcePos& pos, const InputError& e);

}  // namespace kinergy
