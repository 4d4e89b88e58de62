#include "kinergy/verify/verify.hpp"

#include <random>
#include <sstream>

#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"

namespace kinergy::verify {

using namespace GiNaC;

namespace {


constexpr int kDigits = 50;

Check form_check(const Solution& s, const Result& r, const model::Expect& x) {
  const model::Model& m = s.model;
  Check c{r.name, "form", Check::Status::Fails, "", x.form_pos};
  exmap given;
  for (auto& st : m.states)
    for (auto& [k, v] : st.given) given[k] = v;
  ex claimed = x.form->subs(given).subs(s.branch.sol);
  ex derived = r.closed;
  // symbolic: the difference reduces to zero (parameters are positive where their values are)
  ex diff = model::trig_simplify(derived - claimed);
  if (!diff.is_zero() && model::ex_size(diff) < 2000) diff = normal(diff);
  if (diff.is_zero()) {
    c.status = Check::Status::Proved;
    c.detail = "proved";
    return c;
  }
  // numeric: at the scene's values and at random admissible points around them
  exmap env = m.numeric_environment();
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> u(-0.35, 0.35);
  int points = 0, tries = 0;
  numeric worst = 0;
  std::string where;
  const int want = 24;
  while (points < want && tries < 400) {
    exmap at = env;
    if (tries > 0)
      for (auto& p : m.params) {  // declaration order: the same points on every run
        if (!at.count(p.sym)) continue;
        // scale each parameter by e^u, |u| ≤ 0.35: same sign, same order of magnitude
        numeric f(static_cast<long>(std::lround(std::exp(u(rng)) * 1000000)), 1000000);  // exact
        at[p.sym] = at[p.sym] * f;
      }
    ++tries;
    auto d = numerics::evaluate(derived, at, kDigits), cl = numerics::evaluate(claimed, at, kDigits);
    if (!d || !cl) {
      if (tries == 1 && !d) break;
      continue;  // outside the admissible region (complex or undefined): not a test point
    }
    if (tries == 1 && !cl) {
      c.detail = "FAILS: the claimed form has no real value at the scene's parameters (derived " +
                 numerics::format(*d, 15) + ")";
      return c;
    }
    ++points;
    numeric scale = std::max(abs(*d), abs(*cl));
    numeric rel = scale.is_zero() ? numeric(0) : abs(*d - *cl) / scale;
    if (rel > worst) {
      worst = rel;
      std::ostringstream os;
      bool first = true;
      for (auto& p : m.params)
        if (at.count(p.sym) && (derived.has(p.sym) || claimed.has(p.sym))) {
          os << (first ? "" : ", ") << p.name << " = " << numerics::format(*numerics::evaluate(at[p.sym], {}, 20), 6);
          first = false;
        }
      where = os.str() + " (derived " + numerics::format(*d, 12) + ", claimed " + numerics::format(*cl, 12) + ")";
    }
    if (!r.closed_form) break;  // a numeric root holds at the scene's values only
  }
  numeric tol = GiNaC::pow(numeric(10), numeric(-(kDigits - 10)));
  if (points == 0) {
    c.detail = "FAILS: no admissible point to compare at";
    return c;
  }
  if (worst > tol) {
    c.detail = "FAILS: derived " + model::text(derived) + ", claimed " + model::text(claimed) + "; they differ at " + where;
    return c;
  }
  c.status = Check::Status::Checked;
  std::ostringstream os;
  os << "checked at " << points << " point" << (points > 1 ? "s" : "") << ", worst relative difference "
     << (worst.is_zero() ? std::string("0") : numerics::format(worst, 2));
  c.detail = os.str();
  return c;
}

Check value_check(const Solution& s, const Result& r, const model::Expect& x) {
  Check c{r.name, "value", Check::Status::Fails, "", x.value_pos};
  const units::Quantity& q = *x.value;
  exmap env = s.model.numeric_environment();
  // compare in the claimed unit, to the significant figures the claim is written with
  Result in_claim = r;
  in_claim.unit_factor = q.unit.factor;
  auto v = in_claim.value(env, q.sig_figs + 5);
  std::string unit = q.unit.text.empty() ? "" : " " + q.unit.text;
  if (!v) {
    c.detail = "FAILS: the derived value is not a number (parameters without values?)";
    return c;
  }
  numeric rounded = numerics::round_sig(*v, q.sig_figs);
  if (rounded == q.number) {
    c.status = Check::Status::Checked;
    c.detail = "matches to " + std::to_string(q.sig_figs) + " significant figures (derived " +
               numerics::format(*v, std::max(q.sig_figs + 3, 6)) + unit + ")";
  } else {
    c.detail = "FAILS: derived " + numerics::format(*v, std::max(q.sig_figs + 3, 6)) + unit + ", which is " +
               numerics::format(rounded, q.sig_figs) + unit + " to " + std::to_string(q.sig_figs) +
               " significant figures; claimed " + numerics::format(q.number, q.sig_figs) + unit;
  }
  return c;
}

}  // namespace

std::vector<Check> verify(const Solution& s) {
  std::vector<Check> out;
  for (auto& x : s.model.expects) {
    const Result* r = nullptr;
    for (auto& res : s.results)
      if (res.name == x.name) r = &res;
    if (!r) continue;  // the model guarantees a find of that name
    if (x.form) out.push_back(form_check(s, *r, x));
    if (x.value) out.push_back(value_check(s, *r, x));
  }
  return out;
}

}  // namespace kinergy::verify
