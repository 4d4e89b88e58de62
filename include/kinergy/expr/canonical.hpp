/// @file canonical.hpp  Names for expressions that do not depend on GiNaC's term order.
///
/// GiNaC keeps the terms of a sum and the factors of a product in an order set by hashes that
/// mix in type-information addresses, which change from run to run under address
/// randomisation. It also writes a sum that is a factor of a product, or the base of an integer
/// power, with the sign that makes its first term (in that order) positive: (a − b)·x in one
/// run is −(b − a)·x in another. Everything kinergy prints or chooses must be blind to both.
#pragma once
#include <string>

#include <ginac/ginac.h>

namespace kinergy::expr {

/// An expression's magnitude as one text, and the sign in front of it. Two forms that differ
/// only by GiNaC's term order, or by the signs GiNaC gave the sums inside them, have the same
/// key: operands are sorted by their own keys, and every sum is oriented by one rule (more
/// positive terms than negative; on a tie, its first term by key positive).
struct Key {
  bool negative = false;
  std::string text;
  std::string full() const { return (negative ? "-" : "") + text; }
};

Key key(const GiNaC::ex& e);

/// Whether a sum, written as GiNaC keeps it, is the negative of its oriented form.
bool reversed(const GiNaC::ex& sum);

}  // namespace kinergy::expr
