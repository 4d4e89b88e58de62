/// @file factors.hpp  (the printers' own) How the printers split a product: numerator,
/// denominator and square-root groups, with sums oriented so that r − R and −(R − r) print alike.
/// One rule for the plain and the LaTeX printer, so their forms agree.
#pragma once
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace kinergy::emit::detail {

/// How tightly the context of a printed form binds (both printers, plain text and TeX): a sum
/// inside a product or a power is put in parentheses, a product inside a power.
enum Prec { kSum = 1, kProduct = 2, kPower = 3, kAtom = 4 };

/// A base raised to a rational power, kept apart so that GiNaC does not re-normalise it.
struct Factor {
  GiNaC::ex base;
  GiNaC::numeric k = 1;
};

/// The factors of a product, sorted into numerator, denominator and square-root groups.
struct Factors {
  GiNaC::numeric coef = 1;
  std::vector<Factor> num, den;
  GiNaC::exvector root_num, root_den;
};

/// A sum and its negative print alike but for the sign: true when the negative is the one to
/// print (more negative terms; ties: the first term in plain-text order is negative).
bool flip_sum(const GiNaC::ex& b);

/// The number of a sum's terms that print positive less the number that print negative.
int sum_orientation(const GiNaC::ex& b);

/// Multiply the integers under the root into rn (above the bar) and rd (below), take them out
/// of the groups, and reduce rn/rd.
void take_root_numbers(Factors& f, GiNaC::numeric& rn, GiNaC::numeric& rd);

/// The products in a root's groups taken apart: a factor x^−k goes to the other group as x^k, a
/// fraction's numerator and denominator to their groups. A number's sign is kept apart and
/// returned (GiNaC gives a product's coefficient the sign that makes up for the signs it chose
/// for the sums in it), so that the numbers reduced next are the same in every run.
bool flatten_roots(Factors& f);

/// Whether a power prints as a product does (split into groups): a negative or half-integer
/// exponent (x/y, √x), or an integer power of a sum (the sum oriented as a factor is).
bool printed_as_product(const GiNaC::ex& power);

/// A term of a sum as it prints: its sign, the text that orders it and its text without the sign.
struct Term {
  bool negative = false;
  std::string key, text;
};

/// The terms of a sum joined: positive ones first ("g*m + sqrt(…)", not "-… + …"), each group in
/// the order of its keys: "a + b - c - d".
std::string join_terms(std::vector<Term> terms);

/// Sort one factor of a product into `out`.
void classify(const GiNaC::ex& f, Factors& out);

/// Every factor of a product (or the one expression) sorted into its groups. With
/// `turn_positive` (a product that stands alone, not a term of a sum) a negative product turns
/// a sum in it round instead, when that sum reads about as well either way.
Factors split(const GiNaC::ex& e, bool turn_positive = false);

}  // namespace kinergy::emit::detail
