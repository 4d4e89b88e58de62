// The TeX of a derivation's mathematics, shared by the LaTeX document (derive_latex.cpp) and the
// HTML page (derive_html.cpp, where KaTeX typesets it).
#pragma once
#include <string>
#include <vector>

#include "kinergy/emit/derive.hpp"

namespace kinergy::emit {

/// A piece of mathematics in TeX (names as the derivation writes them).
std::string math_tex(const Math& m, const Derivation& d);
/// The width of the left column of a block of equations (em).
double left_column(const Block& b, const Derivation& d);
/// One tagged row as aligned lines ("lhs &= rhs"), broken so that each fits a line.
std::vector<std::string> row_lines(const Row& r, const Derivation& d, double left);

}  // namespace kinergy::emit
