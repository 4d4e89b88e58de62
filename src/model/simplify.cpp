#include "kinergy/model/simplify.hpp"

namespace kinergy::model {

using namespace GiNaC;

std::size_t ex_size(const ex& e) {
  std::size_t n = 1;
  for (std::size_t i = 0; i < e.nops(); ++i) n += ex_size(e.op(i));
  return n;
}

namespace {

// Replace f(a)^n (n ≥ 2) by f(a)^(n mod 2) · (1 − g(a)²)^(n div 2), where {f, g} = {cos, sin}.
struct reduce_power : public map_function {
  bool cos_to_sin;
  explicit reduce_power(bool c) : cos_to_sin(c) {}
  ex operator()(const ex& e) override {
    if (is_a<power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_pos_integer()) {
      const ex& b = e.op(0);
      long n = ex_to<numeric>(e.op(1)).to_long();
      bool match = cos_to_sin ? is_ex_the_function(b, cos) : is_ex_the_function(b, sin);
      if (match && n >= 2) {
        ex other = cos_to_sin ? sin(b.op(0)) : cos(b.op(0));
        return pow(b, n % 2) * pow(1 - pow(other, 2), n / 2);
      }
    }
    return e.map(*this);
  }
};

}  // namespace

ex trig_simplify(const ex& e) {
  ex x = e.expand();
  if (!x.has(sin(wild())) && !x.has(cos(wild()))) return x;
  reduce_power c2s(true), s2c(false);
  ex a = c2s(x).expand();
  ex b = s2c(x).expand();
  std::size_t sx = ex_size(x), sa = ex_size(a), sb = ex_size(b);
  if (sa <= sb && sa <= sx) return a;
  if (sb <= sx) return b;
  return x;
}

ex collect_simplify(const ex& e, const lst& rates) {
  // distributed collection in the rates, then simplify each coefficient
  ex c = collect(e.expand(), rates, true);
  exvector terms;
  if (is_a<add>(c))
    for (std::size_t i = 0; i < c.nops(); ++i) terms.push_back(c.op(i));
  else
    terms.push_back(c);
  exmap by_mono;  // monomial in the rates → coefficient
  for (const ex& term : terms) {
    exvector factors;
    if (is_a<mul>(term))
      for (std::size_t j = 0; j < term.nops(); ++j) factors.push_back(term.op(j));
    else
      factors.push_back(term);
    ex mono = 1, coef = 1;
    for (const ex& f : factors) {
      bool is_rate = false;
      for (const auto& r : rates)
        if (f.is_equal(r) || (is_a<power>(f) && f.op(0).is_equal(r))) is_rate = true;
      (is_rate ? mono : coef) *= f;
    }
    by_mono[mono] += coef;
  }
  ex out = 0;
  for (auto& [mono, coef] : by_mono) out += mono * trig_simplify(coef);
  return out;
}

}  // namespace kinergy::model
