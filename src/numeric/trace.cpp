// The numbers a solve's choices read, recorded with their forms (numeric/trace.hpp).
#include "kinergy/numeric/trace.hpp"

namespace kinergy::numerics {

using namespace GiNaC;

namespace {
thread_local Trace* current = nullptr;
thread_local std::vector<const exmap*> forms;
}  // namespace

Tracing::Tracing(Trace& t) : outer_(current) { current = &t; }
Tracing::~Tracing() { current = outer_; }

TraceForms::TraceForms(const exmap& f) { forms.push_back(&f); }
TraceForms::~TraceForms() { forms.pop_back(); }

bool tracing() { return current != nullptr; }

bool holds_symbol(const ex& e) {
  if (is_a<symbol>(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (holds_symbol(e.op(i))) return true;
  return false;
}

namespace {
/// e with the TraceForms in scope put in, innermost first.
ex with_forms(const ex& e) {
  ex form = e;
  try {
    for (auto it = forms.rbegin(); it != forms.rend(); ++it) form = form.subs(**it);
  } catch (const std::exception&) {
    // a form undefined where put in: kept as read (the reader finds symbols it cannot follow)
    form = e;
  }
  return form;
}
}  // namespace

void note_path(const ex& K, const ex& q, const ex& q1, const ex& q2) {
  if (current) current->paths.push_back({with_forms(K), q, with_forms(q1), with_forms(q2)});
}

void note_untraced(const std::string& what) {
  if (current && current->untraced.empty()) current->untraced = what;
}

void note(const ex& e, const std::optional<numeric>& v) {
  if (!current) return;
  const ex form = with_forms(e);
  int sign = Note::kUndefined;
  if (v) sign = v->is_zero() ? 0 : (v->is_positive() ? 1 : -1);
  current->notes.push_back({form, sign});
}

std::optional<numeric> noted(const ex& e, const exmap& values) {
  std::optional<numeric> out;
  bool free = false;
  try {
    ex s = e.subs(values);
    free = holds_symbol(s);
    ex v = s.evalf();
    if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) out = ex_to<numeric>(v);
  } catch (const std::exception&) {
    out.reset();
  }
  // (a form with symbols left has no number at any parameter values: nothing to choose by)
  if (!free) note(e, out);
  return out;
}

}  // namespace kinergy::numerics
