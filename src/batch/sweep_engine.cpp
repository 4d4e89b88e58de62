// A sweep at the speed of the closed form: solve once, carry the solution wherever its choices
// are shown to fall the same way, solve again only where they may not.
//
// A solve chooses by signs: which root is positive, which way a coordinate moves, whether a
// state is reached, whether friction holds. Each choice's value is recorded with its form in the
// parameters (numeric/trace.hpp). Over a box of grid points, interval arithmetic on those forms
// (numerics::Tape::enclose) shows every sign the same as where the scene was solved: the same
// choices are made at every point of the box, so the same closed forms hold there. The values
// are then the closed forms in doubles, each with its running error bound.
#include "kinergy/batch/sweep.hpp"
#include "kinergy/batch/carry.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "kinergy/app/app.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/common/interrupt.hpp"
#include "kinergy/common/process.hpp"
#include "kinergy/confirm/confirm.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/tape.hpp"
#include "kinergy/numeric/trace.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/units/units.hpp"

namespace kinergy::batch {

using namespace GiNaC;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::uint8_t kOpen = 255;  ///< a grid point no region is shown to hold at (yet)
constexpr std::size_t kMaxRegions = 32;

/// The grid: COUNT values of each range, the last varying fastest.
struct Grid {
  const std::vector<Range>& ranges;
  double value(std::size_t i, std::size_t j) const {
    const Range& r = ranges[i];
    return r.lo + (r.hi - r.lo) * static_cast<double>(j) / static_cast<double>(r.count - 1);
  }
  std::size_t dims() const { return ranges.size(); }
  std::size_t count(std::size_t i) const { return static_cast<std::size_t>(ranges[i].count); }
  /// Point k's index along each range.
  std::vector<std::size_t> indices(std::size_t k) const {
    std::vector<std::size_t> j(dims());
    for (std::size_t i = dims(); i-- > 0;) {
      j[i] = k % count(i);
      k /= count(i);
    }
    return j;
  }
  /// Point k's values.
  std::vector<double> point(std::size_t k) const {
    const std::vector<std::size_t> j = indices(k);
    std::vector<double> v(dims());
    for (std::size_t i = 0; i < dims(); ++i) v[i] = value(i, j[i]);
    return v;
  }
};

/// A box of grid indices, lo[i] ≤ j ≤ hi[i].
struct Box {
  std::vector<std::size_t> lo, hi;
};

/// The box's centre and radius in swept values (the radius covers the grid values' doubles).
void centre(const Grid& g, const Box& b, std::vector<double>& mid, std::vector<double>& rad) {
  for (std::size_t i = 0; i < g.dims(); ++i) {
    const double a = g.value(i, b.lo[i]), c = g.value(i, b.hi[i]);
    mid[i] = (a + c) / 2;
    rad[i] = std::fabs(c - a) / 2 + 4 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(a), std::fabs(c)) + 1e-300;
  }
}

class Engine {
public:
  Engine(const scene::SceneDef& def, const std::vector<Range>& ranges, const SweepOptions& options, const Solution& base)
      : def_(def), grid_{ranges}, options_(options) {
    // a swept parameter is its input (in the scene's unit) times its unit's factor to SI
    std::vector<std::string> varying;
    std::vector<ex> factor;
    for (auto& r : ranges) {
      varying.push_back(r.name);
      factor.push_back(units::parse_quantity(app::parameter(def, r.name, "sweep").value.s).unit.factor);
    }
    in_ = Inputs::of(base.model, varying, factor);
    for (auto& res : base.results) names_.push_back(res.name);
  }

  Sweep::Summary run(const std::function<void(const Sweep::Row&)>& emit);

  /// The first region: the scene solved at its own values, traced.
  void start(const numerics::Trace& t, const Solution& base) {
    Region r;
    r.ok = true;
    for (std::size_t i = 0; i < grid_.dims(); ++i) {
      const units::Quantity q = units::parse_quantity(app::parameter(def_, grid_.ranges[i].name, "sweep").value.s);
      r.at.push_back(q.number.to_double());
    }
    carry(r, t, &base, in_);
    if (!r.unusable.empty()) sum_.note = "every point solved: " + r.unusable;
    solve_each_ = r.nowhere;
    regions_.push_back(std::move(r));
  }

private:
  const scene::SceneDef& def_;
  Grid grid_;
  const SweepOptions& options_;
  Inputs in_;
  std::vector<std::string> names_;
  std::vector<Region> regions_;
  Sweep::Summary sum_;
  bool solve_each_ = false;  ///< no solution is carried anywhere: every point solved, in parallel

  scene::SceneDef at_point(const std::vector<double>& values) const {
    scene::SceneDef at = def_;
    // (each value as the shortest decimal that reads back as its double: 179.99, not 179.99000000000001)
    for (std::size_t i = 0; i < values.size(); ++i) {
      char buf[40];
      const auto r = std::to_chars(buf, buf + sizeof buf, values[i]);
      app::set_parameter(at, grid_.ranges[i].name, std::string(buf, r.ptr) + (grid_.ranges[i].unit.empty() ? "" : " " + grid_.ranges[i].unit));
    }
    return at;
  }

  /// The scene solved at one point: its row, and (traced) a region to carry.
  Sweep::Row solve_at(const std::vector<double>& values, bool trace, bool confirm_it = false) {
    Sweep::Row row{values, std::vector<double>(names_.size(), kNaN), "", "solved"};
    numerics::Trace t;
    std::optional<Solution> s;
    try {
      const scene::SceneDef at = at_point(values);
      {
        std::optional<numerics::Tracing> on;
        if (trace) on.emplace(t);
        s = solve_scene(at);
      }
      if (confirm_it) confirm(*s);
      for (std::size_t k = 0; k < names_.size(); ++k)
        for (auto& res : s->results)
          if (res.name == names_[k] && res.si)
            if (auto v = res.evaluate(s->model.numeric_environment(), 15, true)) row.values[k] = v->v.to_double();
    } catch (const SceneError& e) {
      if (confirm_it && s) throw;  // the confirmation itself disagreed
      row.error = e.problem();
      s.reset();
    }
    if (trace && regions_.size() < kMaxRegions) {
      Region r;
      r.at = values;
      r.ok = s.has_value();
      r.error = row.error;
      carry(r, t, s ? &*s : nullptr, in_);
      regions_.push_back(std::move(r));
    }
    return row;
  }

  /// Classify the box: the first region shown to hold on all of it, else its halves; a single
  /// point none holds at stays open.
  void classify(const Box& b, std::vector<std::uint8_t>& id, const std::vector<std::size_t>& stride, std::size_t origin) {
    poll_interrupt();
    std::vector<double> mid(grid_.dims()), rad(grid_.dims());
    centre(grid_, b, mid, rad);
    for (std::size_t r = 0; r < regions_.size(); ++r)
      if (holds(regions_[r], mid, rad)) {
        fill(b, id, stride, origin, static_cast<std::uint8_t>(r));
        return;
      }
    std::size_t widest = 0, span = 0;
    for (std::size_t i = 0; i < grid_.dims(); ++i)
      if (b.hi[i] - b.lo[i] > span) span = b.hi[i] - b.lo[i], widest = i;
    if (span == 0) return;  // one point: open
    Box a = b, c = b;
    a.hi[widest] = b.lo[widest] + span / 2;
    c.lo[widest] = a.hi[widest] + 1;
    classify(a, id, stride, origin);
    classify(c, id, stride, origin);
  }

  static void fill(const Box& b, std::vector<std::uint8_t>& id, const std::vector<std::size_t>& stride, std::size_t origin, std::uint8_t r) {
    std::vector<std::size_t> j = b.lo;
    for (;;) {
      std::size_t k = 0;
      for (std::size_t i = 0; i < j.size(); ++i) k += j[i] * stride[i];
      id[k - origin] = r;
      std::size_t i = j.size();
      while (i-- > 0) {
        if (j[i] < b.hi[i]) {
          ++j[i];
          break;
        }
        j[i] = b.lo[i];
      }
      if (i == static_cast<std::size_t>(-1)) return;
    }
  }

  /// Row of a point that region r holds at (a closed form's values, each to 1e-13), or nothing
  /// when a double is not that accurate there.
  std::optional<Sweep::Row> carried(const Region& r, const std::vector<double>& values) const {
    Sweep::Row row{values, std::vector<double>(names_.size(), kNaN), "", "closed form"};
    if (!r.ok) {
      std::ostringstream at;
      for (std::size_t i = 0; i < values.size(); ++i)
        at << (i ? ", " : "") << grid_.ranges[i].name << " = " << std::setprecision(15) << r.at[i];
      row.error = "as solved at " + at.str() + " (every choice falls the same way here): " + r.error;
      row.how = "as solved at another point";
      return row;
    }
    // (a grid value's double is within half an ulp of the shortest decimal a solve at the point reads)
    std::vector<double> dx;
    for (double v : values) dx.push_back(1.2e-16 * std::fabs(v));
    if (auto v = values_at(r, values.data(), dx.data())) {
      for (std::size_t k = 0; k < v->size(); ++k) row.values[k] = (*v)[k].value;
      return row;
    }
    // a double not accurate enough there (a result that cancels): the same closed forms in CLN
    auto p = precise_values_at(r, values);
    if (!p) return std::nullopt;
    row.values = *p;
    row.how = "closed form (CLN)";
    return row;
  }

  void confirm_sample(const std::vector<std::uint8_t>& id, std::size_t origin);
  void open_point(const std::vector<double>& values, Sweep::Row& row);
  void solve_each(std::size_t origin, std::size_t count, std::size_t& done, const std::function<void(const Sweep::Row&)>& emit);
  void count(const Sweep::Row& row);
};

/// A row as bytes, for a worker process's pipe (the same machine reads it: doubles as they are).
std::string encode(const Sweep::Row& r) {
  std::string out;
  auto put = [&](const void* p, std::size_t n) { out.append(static_cast<const char*>(p), n); };
  auto put_string = [&](const std::string& t) {
    const std::uint64_t n = t.size();
    put(&n, sizeof n);
    out += t;
  };
  const std::uint64_t n = r.values.size();
  put(&n, sizeof n);
  put(r.values.data(), n * sizeof(double));
  put_string(r.error);
  put_string(r.how);
  return out;
}

Sweep::Row decode(const std::string& bytes, std::vector<double> params) {
  Sweep::Row r;
  r.at = std::move(params);
  std::size_t at = 0;
  auto get = [&](void* p, std::size_t n) {
    if (at + n > bytes.size()) throw std::runtime_error("a worker process's row is cut short");
    std::memcpy(p, bytes.data() + at, n);
    at += n;
  };
  auto get_string = [&]() {
    std::uint64_t n = 0;
    get(&n, sizeof n);
    std::string t(n, '\0');
    get(t.data(), n);
    return t;
  };
  std::uint64_t n = 0;
  get(&n, sizeof n);
  r.values.resize(n);
  get(r.values.data(), n * sizeof(double));
  r.error = get_string();
  r.how = get_string();
  return r;
}

/// The points origin … origin + count − 1, each solved (no solution carried between them), in
/// options_.jobs processes: the rows the same, in the same order, as solved one after the other.
void Engine::solve_each(std::size_t origin, std::size_t count, std::size_t& done, const std::function<void(const Sweep::Row&)>& emit) {
  ordered_in_processes(
      count, options_.jobs, [&](std::size_t k) { return encode(solve_at(grid_.point(origin + k), false)); },
      [&](std::size_t k, const std::string& bytes) {
        if ((done & 63) == 0) {
          poll_interrupt();
          if (options_.progress) options_.progress(done, sum_.points);
        }
        const Sweep::Row row = decode(bytes, grid_.point(origin + k));
        this->count(row);
        emit(row);
        ++done;
      });
}

void Engine::count(const Sweep::Row& row) {
  if (row.how == "solved") ++sum_.solved;
  else ++sum_.closed;
  if (!row.error.empty()) ++sum_.failed;
}

/// An open point: a region found since that holds at it, else solved here (and carried on).
void Engine::open_point(const std::vector<double>& values, Sweep::Row& row) {
  std::vector<double> rad(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) rad[i] = 4 * std::numeric_limits<double>::epsilon() * std::fabs(values[i]) + 1e-300;
  for (const Region& r : regions_)
    if (holds(r, values, rad))
      if (auto c = carried(r, values)) {
        row = *c;
        return;
      }
  row = solve_at(values, true);
}

/// A sample of the points the closed forms give, solved in full and confirmed a second way: each
/// value the same to 1e-12, each point without a solution without one there too.
void Engine::confirm_sample(const std::vector<std::uint8_t>& id, std::size_t origin) {
  std::vector<std::size_t> carried_at;
  for (std::size_t k = 0; k < id.size(); ++k)
    if (id[k] != kOpen) carried_at.push_back(k);
  if (carried_at.empty() || options_.samples <= 0) return;
  const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(options_.samples), carried_at.size());
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t k = carried_at[n == 1 ? 0 : s * (carried_at.size() - 1) / (n - 1)];
    const std::vector<double> values = grid_.point(origin + k);
    auto fast = carried(regions_[id[k]], values);
    if (!fast) continue;  // (solved there anyway)
    const Sweep::Row full = solve_at(values, false, options_.confirm);
    std::ostringstream at;
    for (std::size_t i = 0; i < values.size(); ++i) at << (i ? ", " : "") << grid_.ranges[i].name << " = " << std::setprecision(15) << values[i];
    auto disagree = [&](const std::string& what) {
      throw SceneError(SourcePos{def_.file, 1, 1}, "the sweep's closed form and a full solve disagree at " + at.str() + ": " + what,
                       "sweep with --per-point (the scene solved at every point), and report this scene");
    };
    if (fast->error.empty() != full.error.empty())
      disagree(fast->error.empty() ? "the closed form gives values, the solve says: " + full.error : "the solve gives values, the closed form says: " + fast->error);
    for (std::size_t r = 0; r < names_.size(); ++r) {
      const double a = fast->values[r], b = full.values[r];
      if (std::isnan(a) && std::isnan(b)) continue;
      const double d = std::fabs(a - b) / std::max(std::fabs(b), 1e-300);
      if (!(d <= 1e-12)) {
        std::ostringstream w;
        w << std::setprecision(17) << names_[r] << " = " << a << " by the closed form, " << b << " by the solve";
        disagree(w.str());
      }
      sum_.difference = std::max(sum_.difference, a == b ? 0.0 : d);
    }
    ++sum_.confirmed;
  }
}

Sweep::Summary Engine::run(const std::function<void(const Sweep::Row&)>& emit) {
  const std::size_t d = grid_.dims();
  std::size_t total = 1;
  for (std::size_t i = 0; i < d; ++i) total *= grid_.count(i);
  sum_.points = total;
  // slabs: the leading ranges fixed, the rest (at most 2^22 points) classified at once
  std::size_t lead = 0, inner = total;
  while (lead + 1 < d && inner > (std::size_t{1} << 22)) inner /= grid_.count(lead++);
  std::vector<std::size_t> stride(d, 1);
  for (std::size_t i = d - 1; i-- > 0;) stride[i] = stride[i + 1] * grid_.count(i + 1);
  std::size_t done = 0;
  for (std::size_t origin = 0; origin < total; origin += inner) {
    if (options_.per_point || solve_each_) {
      solve_each(origin, inner, done, emit);
      continue;
    }
    std::vector<std::uint8_t> id(inner, kOpen);
    if (!options_.per_point) {
      Box b;
      b.lo = b.hi = grid_.indices(origin);
      for (std::size_t i = lead; i < d; ++i) b.lo[i] = 0, b.hi[i] = grid_.count(i) - 1;
      classify(b, id, stride, origin);
      if (origin == 0) confirm_sample(id, origin);
    }
    for (std::size_t k = 0; k < inner; ++k) {
      if ((k & 1023) == 0) {
        poll_interrupt();
        if (options_.progress) options_.progress(done, total);
      }
      const std::vector<double> values = grid_.point(origin + k);
      Sweep::Row row;
      std::optional<Sweep::Row> c;
      if (id[k] != kOpen) c = carried(regions_[id[k]], values);
      if (c) row = std::move(*c);
      else open_point(values, row);
      count(row);
      emit(row);
      ++done;
    }
  }
  if (options_.progress) options_.progress(done, total);
  sum_.regions = regions_.size();
  if (options_.per_point) sum_.note = "every point solved (--per-point)";
  return sum_;
}

}  // namespace

Sweep::Summary sweep_rows(const scene::SceneDef& def, const std::vector<Range>& ranges, const SweepOptions& options,
                          std::vector<std::string>& parameters, std::vector<std::string>& results,
                          const std::function<void(const Sweep::Row&)>& row) {
  // the scene at its own values first (a bad scene is refused once, not at every point), its
  // choices traced: the first solution carried
  numerics::Trace t;
  std::optional<Solution> solved;
  {
    const numerics::Tracing on(t);
    solved = solve_scene(def);
  }
  const Solution& base = *solved;
  parameters.clear();
  results.clear();
  for (auto& r : ranges) parameters.push_back(r.name + (r.unit.empty() ? "" : " (" + r.unit + ")"));
  for (auto& res : base.results) results.push_back(res.name + (res.unit.empty() ? "" : " (" + res.unit + ")"));
  Engine e(def, ranges, options, base);
  if (!options.per_point) e.start(t, base);
  return e.run(row);
}

Sweep sweep(const scene::SceneDef& def, const std::vector<Range>& ranges, const SweepOptions& options) {
  Sweep out;
  out.summary = sweep_rows(def, ranges, options, out.parameters, out.results, [&](const Sweep::Row& r) { out.rows.push_back(r); });
  return out;
}

}  // namespace kinergy::batch
