/// @file mathml.hpp  The LaTeX kinergy writes (emit/latex.hpp), as presentation MathML: typeset by
/// the browser itself (MathML Core), so an HTML page or a notebook's output shows mathematics
/// without a script (a notebook prefers text/html, where TeX stays text).
#pragma once
#include <string>

namespace kinergy::emit {

/// `tex` (math mode, the subset emit::latex and tex_quantity write: \frac, \sqrt[n]{}, ^ _,
/// \left( \right), functions, Greek letters, \mathrm{}, \dot{}, \int, spaces, \times, \circ) as a
/// <math> element, display block or inline. @throws InputError naming a command outside that
/// subset (a gap to close here, not a page to print half-typeset).
std::string mathml(const std::string& tex, bool block = false);

}  // namespace kinergy::emit
