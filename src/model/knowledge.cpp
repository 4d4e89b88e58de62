// What is known numerically at each state before solving: the given values, and what the
// constraints that hold there give from them.
#include "kinergy/model/model.hpp"
#include "kinergy/model/work.hpp"
#include "kinergy/numeric/trace.hpp"

namespace kinergy::model {

using namespace GiNaC;

Knowledge::Knowledge(const Model& m) : env_(m.numeric_environment()) {
  const exmap& env = env_;
  // a value known, and its form in the parameters (noted: what is known decides later choices)
  auto num = [&](const ex& e, const ex& form) -> std::optional<numeric> {
    ex v = e.subs(known_).subs(env).evalf();
    std::optional<numeric> out;
    if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) out = ex_to<numeric>(v);
    if (is_a<numeric>(v) && numerics::tracing()) numerics::note(form, out);
    return out;
  };
  for (auto& s : m.states)
    for (auto& [sym, val] : s.given)
      if (auto v = num(val, numerics::tracing() ? val.subs(forms_) : ex())) {
        known_[sym] = *v;
        if (numerics::tracing()) forms_[sym] = val.subs(forms_);
      }
  // what constraints give at each state from the given values (one unknown, linear)
  for (int pass = 0; pass < 4; ++pass)
    for (std::size_t si = 0; si < m.states.size(); ++si)
      for (std::size_t ck = 0; ck < m.constraints.size(); ++ck)
        for (const bool rate : {false, true}) {
          if (!m.constraint_at(ck, static_cast<int>(si), rate)) continue;  // switched off there
          const ex& c = m.constraints[ck].first;
          const ex bound = m.bind(rate ? m.rate(c) : c, static_cast<int>(si));
          ex r = bound.subs(known_).subs(env);
          std::vector<ex> unknown;
          for (auto& [name, qs] : m.states[si].sym) {
            if (r.has(qs.first)) unknown.push_back(qs.first);
            if (r.has(qs.second)) unknown.push_back(qs.second);
          }
          if (unknown.size() != 1) continue;
          ex a = r.diff(ex_to<symbol>(unknown[0]));
          if (a.has(unknown[0]) || a.is_zero()) continue;
          // its form: the same linear equation in the forms of what is known
          ex form;
          if (numerics::tracing()) {
            try {
              const ex rf = bound.subs(forms_);
              form = -rf.subs(unknown[0] == 0) / rf.diff(ex_to<symbol>(unknown[0]));
            } catch (const std::exception&) {
              form = unknown[0];  // (a form the reader cannot follow: it holds a state symbol)
            }
          }
          if (auto v = num(-r.subs(unknown[0] == 0) / a, form)) {
            known_[unknown[0]] = *v;
            if (numerics::tracing()) forms_[unknown[0]] = form;
          }
        }
}

std::optional<numeric> Knowledge::value(const ex& e) const {
  ex v = e.subs(known_).subs(env_).evalf();
  std::optional<numeric> out;
  if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) out = ex_to<numeric>(v);
  // a choice reads it: noted in the forms of what is known (numeric/trace.hpp)
  if (numerics::tracing() && is_a<numeric>(v)) numerics::note(e.subs(forms_), out);
  return out;
}

}  // namespace kinergy::model
