/// @file plain.hpp  Closed forms as plain text, as a person writes them — the printer every layer
/// that shows an expression uses (emit's reports, verify's verdicts, the simulator's equations).
/// The namespace is emit's: the LaTeX printer (emit/latex.hpp) shares its rules for products
/// (print/factors.hpp), so that both forms agree.
#pragma once
#include <map>
#include <string>

#include <ginac/ginac.h>

namespace kinergy::emit {

/// Texts to print in place of symbols (a parameter's value with its unit, say).
using SymbolTexts = std::map<GiNaC::ex, std::string, GiNaC::ex_is_less>;

/// A closed form in plain text, as a person writes it ("sqrt(3*g*sin(theta2)/l)").
std::string plain(const GiNaC::ex& e);

/// The same with some symbols replaced by texts ("sqrt(3*(9.81 m/s^2)*sin(30 deg)/(1.2 m))");
/// terms and factors keep the order of the form without the replacements.
std::string plain(const GiNaC::ex& e, const SymbolTexts& names);

}  // namespace kinergy::emit
