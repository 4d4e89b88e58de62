// A solution carried to other parameter values (batch/carry.hpp).
#include "kinergy/batch/carry.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <set>

#include "kinergy/numeric/roots.hpp"

namespace kinergy::batch {

using namespace GiNaC;

namespace {

void collect(const Inputs& in, const ex& e, exmap& sub, bool& lost) {
  if (is_a<symbol>(e)) {
    auto it = in.by_name.find(ex_to<symbol>(e).get_name());
    if (it == in.by_name.end()) lost = true;
    else sub[e] = it->second;
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect(in, e.op(i), sub, lost);
}

/// Does e hold one of the inputs?
bool holds_input(const ex& e, const Inputs& in) {
  return std::any_of(in.x.begin(), in.x.end(), [&](const symbol& s) { return e.has(s); });
}

}  // namespace

std::optional<ex> Inputs::map(const ex& e) const {
  exmap sub;
  bool lost = false;
  collect(*this, e, sub, lost);
  if (lost) return std::nullopt;
  try {
    return e.subs(sub);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

Inputs Inputs::of(const model::Model& m, const std::vector<std::string>& varying, const std::vector<ex>& factor) {
  Inputs in;
  for (std::size_t i = 0; i < varying.size(); ++i) in.x.push_back(symbol("x" + std::to_string(i)));
  for (auto& p : m.params)
    if (p.value) in.by_name[p.name] = *p.value;
  for (std::size_t i = 0; i < varying.size(); ++i) in.by_name[varying[i]] = factor[i] * in.x[i];
  return in;
}

void carry(Region& r, const numerics::Trace& t, const Solution* s, const Inputs& in) {
  if (!t.untraced.empty()) {
    r.unusable = "a choice depends on " + t.untraced;
    r.nowhere = true;
    return;
  }
  std::set<std::pair<ex, int>, bool (*)(const std::pair<ex, int>&, const std::pair<ex, int>&)> seen(
      [](const std::pair<ex, int>& a, const std::pair<ex, int>& b) {
        if (a.second != b.second) return a.second < b.second;
        return ex_is_less()(a.first, b.first);
      });
  std::vector<ex> forms;
  for (const numerics::Note& n : t.notes) {
    auto f = in.map(n.e);
    if (!f) {
      r.unusable = "a choice reads a value whose form in the parameters is not followed";
      return;
    }
    if (!holds_input(*f, in)) continue;  // the same at every point
    if (!seen.insert({*f, n.sign}).second) continue;
    if (n.sign == 0 || n.sign == numerics::Note::kUndefined) {
      // a zero (or an undefined value) is shown nowhere by intervals: unless the form is zero
      // itself, the solution holds at its own point only
      ex z;
      try {
        z = normal(*f);
      } catch (const std::exception&) {
        z = *f;
      }
      if (n.sign == 0 && z.is_zero()) continue;
      r.unusable = "a choice reads a value that is zero (or undefined) there";
      return;
    }
    forms.push_back(*f);
    r.signs.push_back(n.sign);
  }
  std::vector<ex> xs(in.x.begin(), in.x.end());
  try {
    if (!forms.empty()) r.notes = numerics::Tape::compile(forms, xs);
    for (const numerics::PathNote& p : t.paths) {
      // (the coordinate is not a parameter: an input of K's own)
      const symbol q("q_path");
      auto q1 = in.map(p.q1), q2 = in.map(p.q2);
      if (!q1 || !q2) throw std::invalid_argument("ends");
      Inputs with_q = in;
      with_q.by_name["q_path"] = q;
      auto K = with_q.map(p.K.subs(p.q == q));
      if (!K) throw std::invalid_argument("K");
      std::vector<ex> kin{q};
      kin.insert(kin.end(), xs.begin(), xs.end());
      r.paths.push_back({numerics::Tape::compile(*K, kin), numerics::Tape::compile(std::vector<ex>{*q1, *q2}, xs)});
    }
    if (s) {
      for (const Result& res : s->results) {
        auto f = in.map(res.closed / res.unit_factor);
        if (!res.closed_form || !f) {
          r.unusable = "'" + res.name + "' has no closed form (a number found numerically)";
          r.nowhere = true;
          return;
        }
        r.results.push_back(numerics::Tape::compile(*f, xs));
      }
    }
  } catch (const std::exception&) {
    r.unusable = "a form the compiled doubles do not take";
    r.nowhere = true;
    r.paths.clear();
    r.results.clear();
  }
  if (!r.ok && !r.paths.empty()) r.unusable = "where a state is not reached is not shown by intervals";
}

bool holds(const Region& r, const std::vector<double>& mid, const std::vector<double>& rad) {
  if (!r.unusable.empty()) return false;
  if (r.notes) {
    std::vector<numerics::Enclosed> out(r.signs.size());
    r.notes->enclose(mid.data(), rad.data(), out.data());
    for (std::size_t k = 0; k < out.size(); ++k) {
      const auto& e = out[k];
      if (e.maybe_undefined || !std::isfinite(e.value) || !std::isfinite(e.bound)) return false;
      if (r.signs[k] > 0 ? !(e.value - e.bound > 0) : !(e.value + e.bound < 0)) return false;
    }
  }
  // the kinetic energy ≥ 0 along every way: q over the ends' hull, in 16 pieces
  for (const Region::Path& p : r.paths) {
    numerics::Enclosed ends[2];
    p.ends.enclose(mid.data(), rad.data(), ends);
    if (ends[0].maybe_undefined || ends[1].maybe_undefined) return false;
    const double lo = std::min(ends[0].value - ends[0].bound, ends[1].value - ends[1].bound);
    const double hi = std::max(ends[0].value + ends[0].bound, ends[1].value + ends[1].bound);
    if (!std::isfinite(lo) || !std::isfinite(hi)) return false;
    std::vector<double> m(mid.size() + 1), w(rad.size() + 1);
    std::copy(mid.begin(), mid.end(), m.begin() + 1);
    std::copy(rad.begin(), rad.end(), w.begin() + 1);
    // pieces of the hull, halved where K's enclosure does not stay ≥ 0 (at most 256 of them)
    std::vector<std::pair<double, double>> pieces{{lo, hi}};
    for (int tried = 0; !pieces.empty(); ++tried) {
      if (tried == 256) return false;
      auto [a, b] = pieces.back();
      pieces.pop_back();
      m[0] = (a + b) / 2;
      w[0] = (b - a) / 2 * (1 + 1e-12) + 1e-300;
      numerics::Enclosed K;
      p.K.enclose(m.data(), w.data(), &K);
      if (K.maybe_undefined) return false;
      if (K.value - K.bound >= 0) continue;
      if (!(b - a > 1e-9 * (std::fabs(a) + std::fabs(b)))) return false;
      pieces.push_back({m[0], b});
      pieces.push_back({a, m[0]});
    }
  }
  return true;
}

std::optional<std::vector<numerics::Bounded>> values_at(const Region& r, const double* x, const double* dx) {
  std::vector<numerics::Bounded> out;
  for (const numerics::Tape& t : r.results) {
    const numerics::Bounded b = t.bounded(x, dx);
    if (!std::isfinite(b.value) || !(b.bound <= kRelBound * std::fabs(b.value))) return std::nullopt;
    out.push_back(b);
  }
  return out;
}

numeric decimal_of(double d) {
  // the shortest decimal that reads back as d: D × 10^E
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, d, std::chars_format::scientific);
  const std::string t(buf, r.ptr);
  const std::size_t e = t.find('e');
  std::string digits;
  for (std::size_t i = 0; i < e; ++i)
    if (std::isdigit(static_cast<unsigned char>(t[i]))) digits += t[i];
  const long exp10 = std::stol(t.substr(e + 1)) - static_cast<long>(digits.size()) + 1;
  const numeric mantissa(digits.c_str());
  return (t[0] == '-' ? -mantissa : mantissa) * pow(numeric(10), numeric(exp10));
}

std::optional<std::vector<double>> precise_values_at(const Region& r, const std::vector<double>& x) {
  std::vector<cln::cl_R> in;
  for (double v : x) in.push_back(cln::the<cln::cl_R>(decimal_of(v).to_cl_N()));
  std::vector<double> out;
  try {
    for (const numerics::Tape& t : r.results) {
      auto a = t.precise(in, 30), b = t.precise(in, 45);
      if (!a || !b) return std::nullopt;
      const numeric na(*a), nb(*b);
      if (!(abs(na - nb) <= abs(nb) * numerics::tenth(20))) return std::nullopt;
      out.push_back(nb.to_double());
    }
  } catch (const numerics::NeedsPrecision&) {
    return std::nullopt;
  }
  return out;
}

}  // namespace kinergy::batch
