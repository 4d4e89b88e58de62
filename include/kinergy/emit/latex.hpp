/// @file latex.hpp  Closed forms as LaTeX, as a person writes them: \frac, \sqrt{}, \cos\theta_2,
/// products in a fixed order (the plain printer's order is GiNaC-independent; so is this one).
#pragma once
#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace kinergy::emit {

/// TeX for a symbol written in place of its name: a parameter's value with its unit, or a
/// name chosen to avoid a clash. `atomic` is false when it must be parenthesised in a product
/// or under a power ("9.81\,\mathrm{m/s^{2}}").
struct TexSymbol {
  std::string tex;
  bool atomic = true;
};
using TexSymbols = std::map<GiNaC::ex, TexSymbol, GiNaC::ex_is_less>;

/// TeX of a scene name: theta → \theta, theta2 → \theta_{2}, omega_A → \omega_{A},
/// mu_k → \mu_{k}, m1 → m_{1}, xA → x_{A}, phi_dot → \dot{\phi}, theta_dot@2 → \dot{\theta}_{2},
/// xA_dot@before → (\dot{x}_{A})_{\mathrm{before}}, J_hit[before,after] → J_{\mathrm{hit}},
/// lost → \mathrm{lost}.
std::string tex_name(const std::string& name);

/// The same name as a drawing's label writes it (what follows its '_' set as a subscript),
/// subscripted as tex_name does, without its states: Rx_axle → R_x,axle, J_hit[before,after] →
/// J_hit, xA → x_A; a Greek or word head as written (theta2 → theta2).
std::string plain_name(const std::string& name);

/// TeX of a state-bound quantity: base at state S ("T", "1" → T_{1}; "L_{x}", "after" →
/// (L_{x})_{\mathrm{after}}).
std::string tex_at(const std::string& base_tex, const std::string& state);

/// A closed form in LaTeX (math mode).
std::string latex(const GiNaC::ex& e, const TexSymbols* symbols = nullptr);

/// A unit as written in a scene ("m/s^2", "N*m", "deg") in math mode: \mathrm{m/s^{2}}.
std::string tex_unit(const std::string& unit);

/// A quantity "NUMBER UNIT" in math mode: 9.81\,\mathrm{m/s^{2}}, 30^{\circ}, 1.5\times 10^{-3}.
std::string tex_quantity(const std::string& number, const std::string& unit);

/// A decimal number ("1.5e-12") in math mode (1.5\times 10^{-12}).
std::string tex_number(const std::string& decimal);

/// Text for a text-mode paragraph: TeX's special characters escaped, common Unicode
/// (— – → θ ω ² · ≤ …) turned into TeX.
std::string tex_text(const std::string& s);

/// Estimated width of math-mode TeX in em (display style), for line breaking.
double tex_width(const std::string& tex);

/// The top-level terms of a sum in TeX: "a + b - c" → {"a", "+ b", "- c"}; the whole text
/// when it is not a sum at the top.
std::vector<std::string> tex_terms(const std::string& tex);

}  // namespace kinergy::emit
