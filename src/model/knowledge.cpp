// What is known numerically at each state before solving: the given values, and what the
// constraints that hold there give from them.
#include "kinergy/model/model.hpp"
#include "kinergy/model/work.hpp"

namespace kinergy::model {

using namespace GiNaC;

Knowledge::Knowledge(const Model& m) : env_(m.numeric_environment()) {
  const exmap& env = env_;
  auto num = [&](const ex& e) -> std::optional<numeric> {
    ex v = e.subs(known_).subs(env).evalf();
    if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) return ex_to<numeric>(v);
    return std::nullopt;
  };
  for (auto& s : m.states)
    for (auto& [sym, val] : s.given)
      if (auto v = num(val)) known_[sym] = *v;
  // what constraints give at each state from the given values (one unknown, linear)
  for (int pass = 0; pass < 4; ++pass)
    for (std::size_t si = 0; si < m.states.size(); ++si)
      for (std::size_t ck = 0; ck < m.constraints.size(); ++ck)
        for (const bool rate : {false, true}) {
          if (!m.constraint_at(ck, static_cast<int>(si), rate)) continue;  // switched off there
          const ex& c = m.constraints[ck].first;
          ex r = m.bind(rate ? m.rate(c) : c, static_cast<int>(si)).subs(known_).subs(env);
          std::vector<ex> unknown;
          for (auto& [name, qs] : m.states[si].sym) {
            if (r.has(qs.first)) unknown.push_back(qs.first);
            if (r.has(qs.second)) unknown.push_back(qs.second);
          }
          if (unknown.size() != 1) continue;
          ex a = r.diff(ex_to<symbol>(unknown[0]));
          if (a.has(unknown[0]) || a.is_zero()) continue;
          if (auto v = num(-r.subs(unknown[0] == 0) / a)) known_[unknown[0]] = *v;
        }
}

std::optional<numeric> Knowledge::value(const ex& e) const {
  ex v = e.subs(known_).subs(env_).evalf();
  if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) return ex_to<numeric>(v);
  return std::nullopt;
}

}  // namespace kinergy::model
