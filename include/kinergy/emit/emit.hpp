/// @file emit.hpp  Results as text for terminals and as JSON for tools.
#pragma once
#include <map>
#include <string>
#include <vector>

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

/// Texts to print in place of symbols (a parameter's value with its unit, say).
using SymbolTexts = std::map<GiNaC::ex, std::string, GiNaC::ex_is_less>;

/// A closed form in plain text, as a person writes it ("sqrt(3*g*sin(theta2)/l)").
std::string plain(const GiNaC::ex& e);

/// The same with some symbols replaced by texts ("sqrt(3*(9.81 m/s^2)*sin(30 deg)/(1.2 m))");
/// terms and factors keep the order of the form without the replacements.
std::string plain(const GiNaC::ex& e, const SymbolTexts& names);

/// Each result's closed form and value with its unit.
std::string text(const Solution& s, const Options& o);

/// The checks of `verify`, one line each.
std::string text(const std::vector<verify::Check>& checks, const std::string& file);

/// {"title", "results": [{name, closed_form, closed, value, unit}], "checks": […]}.
std::string json(const Solution& s, const Options& o, const std::vector<verify::Check>* checks = nullptr);

}  // namespace kinergy::emit
