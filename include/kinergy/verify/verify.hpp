/// @file verify.hpp  Check claimed closed forms and textbook numbers against a solution.
#pragma once
#include <string>
#include <vector>

#include "kinergy/problem.hpp"

namespace kinergy::verify {

struct Check {
  std::string name;     ///< the result's name
  std::string what;     ///< "form" or "value"
  enum class Status { Proved, Checked, Fails } status = Status::Fails;
  std::string detail;   ///< "proved", "checked at 24 points, worst relative difference 1e-48", "FAILS: …"
  SourcePos pos;
  bool ok() const { return status != Status::Fails; }
};

/// Every `expect` claim of the scene, checked. A value that is not the derived one to its figures
/// fails with its relative difference, and — where replaying the solution with each intermediate
/// value rounded to the claim's figures reproduces it — says so; with `rtol` > 0 a value within
/// that relative difference of the derived one passes (books round on the way).
std::vector<Check> verify(const Solution& s, double rtol = 0);

/// v rounded to n significant figures, written with its trailing zeros: "3.50", "20.00",
/// "0.0120", "1.50e-12" (as a claim to n figures is written).
std::string figures(const GiNaC::numeric& v, int n);

}  // namespace kinergy::verify
