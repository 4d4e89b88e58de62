/// @file native.hpp  A tape turned into machine code: its straight-line C++ compiled once by the
/// C++ compiler kinergy was built with, loaded with dlopen, cached by the hash of the source.
#pragma once
#include <memory>
#include <string>

#include "kinergy/numeric/tape.hpp"

namespace kinergy::numerics {

template <class Native, class Fn>
Native loaded(const std::string& src, const std::string& name);  ///< (native.cpp)

class NativeFunction {
public:
  /// Compile (or take from the cache) the tape's C++. The cache is $KINERGY_CACHE, else
  /// $XDG_CACHE_HOME/kinergy, else ~/.cache/kinergy.
  /// @throws std::runtime_error naming the compiler and its first error line when there is no
  /// compiler or the code does not compile (the tape itself still evaluates).
  static NativeFunction build(const Tape& t);

  double operator()(const double* x) const { return fn_(x); }
  /// The compiled function itself, for loops that call it directly.
  using Fn = double (*)(const double*);
  Fn function() const { return fn_; }

private:
  std::shared_ptr<void> handle_;  ///< dlclose when the last copy goes
  Fn fn_ = nullptr;
  template <class Native, class F>
  friend Native loaded(const std::string&, const std::string&);
};

/// A multi-output tape as machine code: `void f(const double* x, double* out)` writes every
/// output (a right-hand side, a mass matrix and its forcing terms in one call).
class NativeKernel {
public:
  /// `epilogue`: C++ statements run after the outputs are written (Tape::cpp_vector).
  /// @throws std::runtime_error as NativeFunction::build.
  static NativeKernel build(const Tape& t, const std::string& epilogue = "");

  void operator()(const double* x, double* out) const { fn_(x, out); }
  using Fn = void (*)(const double*, double*);
  Fn function() const { return fn_; }

private:
  std::shared_ptr<void> handle_;
  Fn fn_ = nullptr;
  template <class Native, class F>
  friend Native loaded(const std::string&, const std::string&);
};

}  // namespace kinergy::numerics
