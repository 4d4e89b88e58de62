/// @file emit.hpp  Results as text for terminals and as JSON for tools.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "kinergy/print/plain.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/verify/verify.hpp"

namespace kinergy::emit {

struct Options {
  int digits = 15;  ///< significant digits of values
  /// false: the compiled double evaluator where its error bound fixes every digit printed (else
  /// CLN); true (`--digits N`): CLN with the working precision raised until the N digits settle,
  /// and that precision reported beside each value.
  bool guaranteed = false;
};


/// Each result's closed form and value with its unit.
std::string text(const Solution& s, const Options& o);

/// The checks of `verify`, one line each.
std::string text(const std::vector<verify::Check>& checks, const std::string& file);

/// {"title", "results": [{name, closed_form, closed, value, unit}], "checks": […]}.
std::string json(const Solution& s, const Options& o, const std::vector<verify::Check>* checks = nullptr);

}  // namespace kinergy::emit
