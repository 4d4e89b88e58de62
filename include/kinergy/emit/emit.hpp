/// @file emit.hpp  Results as text for terminals and as JSON for tools.
#pragma once
#include <string>
#include <vector>

#include "kinergy/problem.hpp"
#include "kinergy/verify/verify.hpp"

namespace kinergy::emit {

struct Options {
  int digits = 15;  ///< significant digits of values
};

/// A closed form in plain text, as a person writes it ("sqrt(3*g*sin(theta2)/l)").
std::string plain(const GiNaC::ex& e);

/// Each result's closed form and value with its unit.
std::string text(const Solution& s, const Options& o);

/// The checks of `verify`, one line each.
std::string text(const std::vector<verify::Check>& checks, const std::string& file);

/// {"title", "results": [{name, closed_form, closed, value, unit}], "checks": […]}.
std::string json(const Solution& s, const Options& o, const std::vector<verify::Check>* checks = nullptr);

}  // namespace kinergy::emit
