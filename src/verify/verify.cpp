#include "kinergy/verify/verify.hpp"

#include <random>
#include <sstream>

#include "kinergy/print/plain.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/roots.hpp"

namespace kinergy::verify {

using namespace GiNaC;

namespace {


constexpr int kDigits = 50;

Check form_check(const Solution& s, const Result& r, const model::Expect& x) {
  const model::Model& m = s.model;
  Check c{r.name, "form", Check::Status::Fails, "", x.form_pos};
  const exmap given = m.given_values();
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
  bool equal_at_scene = false;  // the claim holds at the scene's own values
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
    if (tries == 1 && d && !cl) {
      c.detail = "FAILS: derived " + emit::plain(derived) + ", claimed " + emit::plain(claimed) +
                 ", at the scene's values (derived " + numerics::format(*d, 12) + ", claimed: no real value)";
      return c;
    }
    if (!d || !cl) {
      if (tries == 1 && !d) break;
      continue;  // outside the admissible region (complex or undefined): not a test point
    }
    ++points;
    numeric scale = std::max(abs(*d), abs(*cl));
    numeric rel = scale.is_zero() ? numeric(0) : abs(*d - *cl) / scale;
    if (tries == 1) equal_at_scene = rel <= numerics::tenth(kDigits - 10);
    if (rel > worst) {
      worst = rel;
      std::ostringstream os;
      bool first = true;
      for (auto& p : m.params)
        if (at.count(p.sym) && (derived.has(p.sym) || claimed.has(p.sym))) {
          os << (first ? "" : ", ") << p.name << " = " << numerics::format(*numerics::evaluate(at[p.sym], {}, 20), 6);
          first = false;
        }
      where = (os.str().empty() ? std::string("the scene's values") : os.str()) + " (derived " + numerics::format(*d, 12) +
              ", claimed " + numerics::format(*cl, 12) + ")";
    }
    if (!r.closed_form) break;  // a numeric root holds at the scene's values only
  }
  numeric tol = numerics::tenth(kDigits - 10);
  if (points == 0) {
    c.detail = "FAILS: no admissible point to compare at";
    return c;
  }
  if (worst > tol) {
    c.detail = "FAILS: derived " + emit::plain(derived) + ", claimed " + emit::plain(claimed) + ", at " + where;
    if (equal_at_scene) c.detail += "; they agree at the scene's values only";
    return c;
  }
  c.status = Check::Status::Checked;
  std::ostringstream os;
  // the difference itself is rounding noise at the working precision, and its digits follow the
  // order GiNaC adds terms in (so addresses): the bound it stays below is what is reported
  os << "checked at " << points << " point" << (points > 1 ? "s" : "") << ", relative difference below 1e-"
     << (kDigits - 10) << (points > 1 ? " at each" : "");
  c.detail = os.str();
  return c;
}

/// A root of r(u) = 0 near `start` (Newton's method at `digits`; nothing when it does not settle).
std::optional<numeric> newton(const ex& r, const symbol& u, numeric x, const exmap& env, int digits) {
  ex dr = r.diff(u);
  for (int it = 0; it < 60; ++it) {
    exmap at = env;
    at[u] = x;
    auto f = numerics::evaluate(r, at, digits), d = numerics::evaluate(dr, at, digits);
    if (!f || !d) return std::nullopt;
    if (f->is_zero()) return x;
    if (d->is_zero()) return std::nullopt;
    numeric step = *f / *d;
    x = ex_to<numeric>((x - step).evalf());
    if (abs(step) <= abs(x) * numerics::tenth(digits - 5)) return x;
  }
  return std::nullopt;
}

/// The result as a book computes it: one equation with one unknown left at a time, each value
/// found rounded to `figs` significant figures (SI) before it is used further, then the result
/// from the rounded values. Where only equations with several unknowns are left (a system solved
/// together), the unknowns of the smallest one take their exact values, unrounded. Nothing when
/// no value was rounded on the way, or the replay cannot give a number.
std::optional<numeric> rounded_replay(const Solution& s, const Result& r, int figs) {
  const model::Model& m = s.model;
  const model::Find* f = nullptr;
  for (auto& x : m.finds)
    if (x.name == r.name) f = &x;
  if (!f) return std::nullopt;
  const exmap env = m.numeric_environment(), given = m.given_values();
  const int digits = 40;
  exmap known;  // unknown → the value the book uses
  int rounded = 0;
  try {
    std::vector<ex> eqs;
    for (auto& q : s.equations) eqs.push_back(q.residual().subs(given));
    auto unknowns_in = [&](const ex& e) {
      std::vector<ex> out;
      for (auto& [k, v] : s.branch.sol)
        if (!known.count(k) && e.has(k)) out.push_back(k);
      return out;
    };
    for (std::size_t round = 0; round < s.branch.sol.size() + 1; ++round) {
      int pick = -1;
      std::size_t fewest = 0;
      for (std::size_t i = 0; i < eqs.size(); ++i) {
        auto us = unknowns_in(eqs[i]);
        if (us.empty()) continue;
        if (pick < 0 || us.size() < fewest) {
          pick = static_cast<int>(i);
          fewest = us.size();
        }
      }
      if (pick < 0) break;
      auto us = unknowns_in(eqs[static_cast<std::size_t>(pick)]);
      if (us.size() > 1) {  // solved together: exact values, not rounded
        for (auto& u : us) known[u] = s.branch.sol.at(u);
        continue;
      }
      const ex& u = us[0];
      if (!is_a<symbol>(u) || s.branch.numeric_only.count(u)) return std::nullopt;
      auto exact = numerics::evaluate(s.branch.sol.at(u), env, digits);
      auto root = exact ? newton(eqs[static_cast<std::size_t>(pick)].subs(known), ex_to<symbol>(u), *exact, env, digits)
                        : std::nullopt;
      if (!root) {  // not a number (a time nothing fixes), or no root near it: as it is
        known[u] = s.branch.sol.at(u);
        continue;
      }
      known[u] = numerics::round_sig(*root, figs);
      ++rounded;
    }
    if (rounded == 0) return std::nullopt;  // nothing rounded on the way to the result
    ex v = f->value.subs(given).subs(known);
    exmap rest;
    for (auto& [k, val] : s.branch.sol)
      if (v.has(k)) rest[k] = val;
    return numerics::evaluate(v.subs(rest) / r.unit_factor, env, digits);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

Check value_check(const Solution& s, const Result& r, const model::Expect& x, double rtol) {
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
  std::string figs = std::to_string(q.sig_figs) + (q.sig_figs == 1 ? " significant figure" : " significant figures");
  if (rounded == q.number) {
    c.status = Check::Status::Checked;
    c.detail = "matches to " + figs + " (derived " + numerics::format(*v, std::max(q.sig_figs + 3, 6)) + unit + ")";
    return c;
  }
  // by how much: |claimed − derived| / |derived|
  numeric rel = v->is_zero() ? (q.number.is_zero() ? numeric(0) : numeric(1)) : abs(q.number - *v) / abs(*v);
  std::string diff = "relative difference " + numerics::format(rel * 100, 2) + "%";
  if (rtol > 0 && rel.to_double() <= rtol) {
    c.status = Check::Status::Checked;
    c.detail = "within rtol " + numerics::format(numeric(rtol), 3) + ": derived " +
               numerics::format(*v, std::max(q.sig_figs + 3, 6)) + unit + ", claimed " + figures(q.number, q.sig_figs) + unit +
               " (" + diff + ")";
    return c;
  }
  // the derived value to the claim's figures, trailing zeros kept: 3.50, not 3.5
  c.detail = "FAILS: derived " + figures(*v, q.sig_figs) + unit + ", claimed " + figures(q.number, q.sig_figs) + unit +
             ", at the scene's values (to " + figs + "; derived " + numerics::format(*v, std::max(q.sig_figs + 3, 6)) + unit +
             ", " + diff + ")";
  // books round the values they find on the way: does that explain the claim?
  if (auto b = rounded_replay(s, r, q.sig_figs)) {
    numeric br = numerics::round_sig(*b, q.sig_figs);
    if (br == q.number)
      c.detail += "; rounding each intermediate value to " + figs + ", as a book does, gives " + figures(*b, q.sig_figs) + unit +
                  ": the method is right, the claim carries the rounding (accept it with --rtol " +
                  numerics::format(numeric(rel * numeric(11, 10)), 2) + ")";
    else
      c.detail += "; rounding each intermediate value to " + figs + " gives " + figures(*b, q.sig_figs) + unit + ", not the claim either";
  }
  return c;
}

}  // namespace

std::string figures(const numeric& v, int n) {
  if (n < 1) n = 1;
  numeric r = numerics::round_sig(v, n);
  if (r.is_zero()) return n > 1 ? "0." + std::string(static_cast<std::size_t>(n - 1), '0') : "0";
  std::string s = numerics::format(r, n);
  auto e = s.find('e');
  std::string mant = e == std::string::npos ? s : s.substr(0, e), tail = e == std::string::npos ? "" : s.substr(e);
  int shown = 0;
  bool started = false;
  for (char ch : mant) {
    if (ch < '0' || ch > '9') continue;
    if (ch != '0') started = true;
    if (started) ++shown;
  }
  if (shown >= n) return s;
  if (mant.find('.') == std::string::npos) mant += ".";
  return mant + std::string(static_cast<std::size_t>(n - shown), '0') + tail;
}

std::vector<Check> verify(const Solution& s, double rtol) {
  std::vector<Check> out;
  for (auto& x : s.model.expects) {
    const Result* r = nullptr;
    for (auto& res : s.results)
      if (res.name == x.name) r = &res;
    if (!r) continue;  // the model guarantees a find of that name
    if (x.form) out.push_back(form_check(s, *r, x));
    if (x.value) out.push_back(value_check(s, *r, x, std::max(rtol, x.rtol)));
  }
  return out;
}

}  // namespace kinergy::verify
