/// @file trace.hpp  The numbers a solve reads to make its choices, recorded: which branch, which
/// root, which case of a force that switches, whether a state is reached, whether friction holds.
/// Each choice reads the sign of a value (or whether it has one). With the forms of those values
/// in the parameters recorded, another set of parameter values whose every form keeps its sign
/// makes every choice the same, so the solution found once (its closed forms) holds there too:
/// what lets a sweep evaluate a closed form at a million points instead of solving at each.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace kinergy::numerics {

/// One value a choice read: its form (in the parameters, and whatever else the site's values held)
/// and its sign there: −1, 0, +1, or kUndefined (no real number: a division by zero, a root of a
/// negative).
struct Note {
  static constexpr int kUndefined = 2;
  GiNaC::ex e;
  int sign = 0;
};

/// A choice that reads a whole path, not one value: the kinetic energy K(q) stays ≥ 0 while the
/// one coordinate q runs over the points sampled between two states (a state is reached). Where
/// K ≥ 0 on every q from q1 to q2 (the first and last points sampled), the check passes
/// (principles::check_reached), whatever else it reads.
struct PathNote {
  GiNaC::ex K;       ///< in q and the parameters
  GiNaC::ex q;       ///< the coordinate (a symbol)
  GiNaC::ex q1, q2;  ///< the first and last points sampled, in the parameters
};

/// The notes of one solve, in order (with repeats: the reader removes them).
struct Trace {
  std::vector<Note> notes;
  std::vector<PathNote> paths;
  /// A choice that no note follows (the kinetic energy along a path that constraints bend): a
  /// solution with this trace holds only at its own values. Empty when every choice is noted.
  std::string untraced;
};

/// While it lives, this thread's choices are noted in `t` (the innermost Tracing when nested).
class Tracing {
public:
  explicit Tracing(Trace& t);
  ~Tracing();
  Tracing(const Tracing&) = delete;
  Tracing& operator=(const Tracing&) = delete;

private:
  Trace* outer_;
};

/// While it lives, a note's form has these forms put in for symbols whose values a site holds as
/// numbers (a value found by an earlier analysis, a state's solved place): the note is then in the
/// parameters, as the choice depends on them. Nested scopes apply innermost first.
class TraceForms {
public:
  explicit TraceForms(const GiNaC::exmap& forms);
  ~TraceForms();
  TraceForms(const TraceForms&) = delete;
  TraceForms& operator=(const TraceForms&) = delete;
};

/// Is a Tracing alive on this thread?
bool tracing();

/// Does e hold a symbol (a form not yet a number)?
bool holds_symbol(const GiNaC::ex& e);

/// A choice read the value `v` of form `e` (nothing: e has no real value there). Called by
/// numerics::evaluate, and by sites that evaluate otherwise (noted()). No-op without a Tracing.
void note(const GiNaC::ex& e, const std::optional<GiNaC::numeric>& v);

/// A path choice (PathNote; K, q1 and q2 with the TraceForms put in). No-op without a Tracing.
void note_path(const GiNaC::ex& K, const GiNaC::ex& q, const GiNaC::ex& q1, const GiNaC::ex& q2);

/// A choice no note can follow (`what` it reads). No-op without a Tracing.
void note_untraced(const std::string& what);

/// `e.subs(values).evalf()` as a real number, noted: the form every site that reads a sign of a
/// value in the parameters evaluates through (numerics::evaluate does, at a given precision).
std::optional<GiNaC::numeric> noted(const GiNaC::ex& e, const GiNaC::exmap& values);

}  // namespace kinergy::numerics
