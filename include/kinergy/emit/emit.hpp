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
/// The same with each result's value given (one a result, in order) and the confirmations given:
/// a solution carried to other parameter values (batch/carry.hpp) writes its own.
std::string json(const Solution& s, const Options& o, const std::vector<std::optional<Value>>& values,
                 const std::vector<Confirmed>& confirmed, const std::vector<verify::Check>* checks = nullptr);

/// That JSON cut where each result's value and evaluation go (pieces: before value 1, between
/// value 1 and its evaluation, …, after the last): written once for a solution whose values
/// change from request to request (a batch's shared solution), then filled.
struct JsonTemplate {
  std::vector<std::string> pieces;
  int digits = 15;
};
JsonTemplate json_template(const Solution& s, const Options& o, const std::vector<Confirmed>& confirmed);
/// The template with each result's value (the same text as json() with these values).
std::string fill(const JsonTemplate& t, const std::vector<Value>& values);

}  // namespace kinergy::emit
