/// @file names.hpp  Names as a textbook writes them (issue 47): θ for theta, φ_A for phiA, W_A for
/// the weight of gearA — for the labels of figures.
#pragma once
#include <optional>
#include <string>

namespace kinergy::draw {

/// A label's words: `text` for SVG (a '_' before a subscript, "φ_A"), `tex` in TeX's math mode
/// ("\varphi_{A}").
struct Name {
  std::string text, tex;
};

/// An identifier read as a symbol: a Greek letter spelled out (theta → θ, phiA → φ_A, mus → μ_s)
/// or one letter, with what follows as its subscript — digits, capitals (with digits after them),
/// or one small letter (xA → x_A, v0 → v_0, kd → k_d, OA → O_A, L → L). A word (rod, bumper,
/// ball1) is no symbol: nullopt.
std::optional<Name> textbook(const std::string& identifier);

/// A body's short name, to subscript its weight and its momentum with and to label it by: the
/// capitals or digits a word ends in (gearA → A, blockB → B, ball2 → 2), or the body's name read
/// as a symbol (A → A); nullopt for a word alone (rod, disk).
std::optional<Name> short_name(const std::string& body);

/// A name given in TeX's math mode (a scene's `label:`), with its text for SVG: Greek commands as
/// letters, subscripts after '_', other commands and braces dropped ("\\theta_{A}" → "θ_A").
Name from_tex(const std::string& tex);

/// `base` (TeX, and its text) with subscript `sub` — a short name, or a word set upright.
Name subscripted(const Name& base, const std::string& sub);
/// `base` with the subscript `sub` given as a name (empty: none); a base with a subscript of its
/// own (M_c) is braced, as TeX takes one subscript at a time.
Name subscripted(const Name& base, const Name& sub);

}  // namespace kinergy::draw
