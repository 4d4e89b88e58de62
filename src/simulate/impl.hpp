/// @file impl.hpp  The simulator's compiled equations, modes and workspace (private).
#pragma once
#include <array>
#include <cmath>
#include <optional>
#include <sstream>

#include <Eigen/Dense>

#include "kinergy/common/error.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/numeric/native.hpp"
#include "kinergy/numeric/tape.hpp"
#include "kinergy/principles/kinetics.hpp"
#include "kinergy/simulate/simulate.hpp"
#include "freed.hpp"

namespace kinergy::simulate {

using namespace GiNaC;
using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

namespace detail {

/// A multi-output tape, run as machine code when it can be compiled.
struct Kernel {
  numerics::Tape tape;
  std::optional<numerics::NativeKernel> native;
  void operator()(const double* x, double* out) const {
    if (native) (*native)(x, out);
    else tape.eval(x, out);
  }
};

// Offsets of a velocity v = J q̇ + b laid out as [v, J_0 … J_{n−1}, a0] in the kernel's outputs.
struct RateAt {
  std::size_t at = 0;
};

enum class FrictionMode { Slide, Stick };
enum class ContactMode { Open, Rest };

}  // namespace detail

using namespace detail;

struct Simulator::Impl {
  model::Model m;  ///< a copy: the simulator outlives the caller's model (freed: with the gaps)
  std::size_t scene_n = 0;  ///< the scene's coordinates (the first of m's)
  std::shared_ptr<const model::Model> freed_model;  ///< m, when it has gaps (a run's `model`)
  std::vector<int> freed;   ///< the surfaces whose bodies may leave them (effects), as contacts
  std::vector<std::pair<int, std::string>> kept;  ///< one-sided surfaces not freed, and why
  Options o;
  exmap values;  ///< parameter symbol → exact value
  Equations eq;
  std::size_t n = 0, nc = 0, nw = 0;
  // work states: one per non-conservative smooth force, then one per friction effect
  std::vector<std::pair<std::string, std::size_t>> work_names;
  // --- the right-hand side kernel: inputs [t, q, q̇] ---
  Kernel rhs_k, aux_k;
  std::size_t o_M = 0, o_f = 0, o_A = 0, o_gamma = 0;
  std::size_t o_qdd = 0;          // q̈, when the native kernel solves M q̈ = f itself
  bool solved_in_kernel = false;
  numerics::NativeKernel::Fn kernel_fn = nullptr;  // rhs_k's machine code, called directly
  // T at the call whose state is the buffer watch_y (a step's start: run.cpp), when solved_in_kernel
  const double* watch_y = nullptr;
  double watched_T = 0;
  bool watched = false;
  std::vector<std::size_t> o_power;                 // of each non-conservative force
  std::vector<std::pair<RateAt, RateAt>> o_fric;    // x, y
  std::vector<std::pair<RateAt, RateAt>> o_cont;    // normal, tangent
  // --- the auxiliary kernel: T, V, g, ∂g/∂t, gaps, the stop expression, impulses ---
  std::size_t a_T = 0, a_V = 0, a_g = 0, a_gt = 0, a_gap = 0, a_turn = 0, a_stop = 0, a_imp = 0;
  bool has_stop = false;
  std::optional<ex> aux_when;  ///< the stop expression the auxiliary kernel was built with
  std::shared_ptr<void> kept_stepper;  ///< the method's stepper, kept between runs (run.cpp)
  std::vector<double> x, out, aux, xa;
  // --- modes ---
  std::vector<FrictionMode> fmode;
  std::vector<std::array<double, 2>> fdir;    // sliding: last slip direction
  std::vector<Eigen::Matrix2d> fbasis;        // sticking: the held directions (rows), 1 or 2
  std::vector<int> frows;                     // sticking: how many rows
  std::vector<double> flimit;
  std::vector<ContactMode> cmode;
  std::vector<double> cturn0;  ///< a resting contact's surface angle when it came to rest (ContactTerm::turn)
  /// A contact whose surface turns (ContactTerm::turn) that has let go: its gap is its material
  /// point's along a normal that no longer says where the surface is, so it is not struck again
  std::vector<char> cgone;
  std::vector<double> ce;
  // --- a rolling contact on a freed surface (ContactTerm::rolling): sticking (0) or sliding ---
  std::vector<int> cslide;           ///< 0: its tangent row held; ±1: sliding, the sign of its slip ċ
  std::vector<double> cmu_s, cmu_k;  ///< its μ_s and μ_k (< 0: not said)
  std::vector<std::size_t> o_cfp;    ///< |f| (force per unit multiplier) of each contact in the right-hand side kernel
  std::vector<std::size_t> cwork;    ///< its work state (sliding friction), by contact (npos: none)
  // --- static friction that rolling contacts state: |F| ≤ μ_s |N| along the run ---
  struct Limit {
    std::string effect, normal;
    double mu = 0;
    bool one_sided = false;  ///< its track only pushes (model::Reaction::one_sided): N as the surface presses is N, |N| for a guide
    ex F, N;  ///< in closed form (t, q, q̇), from Newton–Euler for the rolling body
    SourcePos pos;
  };
  std::vector<Limit> limits;
  /// Rolling contact k's margin μ_s N − |F| and its F, N (as the surface presses) from the auxiliary kernel's last values.
  double limit_margin(std::size_t k, double* F = nullptr, double* N = nullptr) const {
    const double f = std::fabs(aux[a_lim + 2 * k]), n = aux[a_lim + 2 * k + 1], pressed = limits[k].one_sided ? n : std::fabs(n);
    if (F) *F = f;
    if (N) *N = pressed;
    return limits[k].mu * pressed - f;
  }
  std::size_t a_lim = 0;  ///< F, N of each limit in the auxiliary kernel
  // --- surfaces that can only push (one-sided tracks): N ≥ 0 along the run ---
  struct Release {
    std::string effect, body;
    ex N;  ///< in closed form (t, q, q̇), positive while it pushes: Newton–Euler for the body it holds
    SourcePos pos;
    std::string why_kept;  ///< why the run cannot go on with the body free of it ("": not asked to)
    bool pulls = false;    ///< a cord (N its tension)
  };
  std::vector<Release> releases;
  std::size_t a_rel = 0;  ///< N of each release in the auxiliary kernel
  double release_N(std::size_t k) const { return aux[a_rel + k]; }
  // --- workspace ---
  Mat M, B;
  Vec f, b, qdd, lambda;
  Eigen::LDLT<Mat> ldlt;
  std::size_t rhs_calls = 0;
  double rest_time = 0;

  Impl(const model::Model& mm, const exmap& vals, const Options& opt) : m(mm), o(opt), values(vals) {
    scene_n = m.coords.size();
    {
      // the surfaces that only push whose bodies may leave them: m with a gap for each
      // (the symplectic method has no events to switch at: it stops where a body leaves)
      const bool follow = o.rolling_limits && o.follow_releases && o.method != Method::Symplectic;
      const Freed fr = follow ? free_surfaces(mm, o.effects_on, values) : Freed{mm, {}, {}};
      kept = fr.kept;
      if (!fr.surfaces.empty()) {
        m = fr.m;
        freed_model = std::make_shared<const model::Model>(m);
      }
      // a relation that rolls a freed body on its surface is the surface's tangent row now
      for (auto& sf : fr.surfaces) {
        if (sf.rolling < 0) continue;
        if (o.effects_on.empty()) o.effects_on.assign(m.effects.size(), true);
        o.effects_on[static_cast<std::size_t>(sf.rolling)] = false;
      }
      eq = equations_of_motion(m, o.effects_on);
      for (auto& sf : fr.surfaces) {
        eq.contacts.push_back(surface_contact(fr, sf));
        freed.push_back(sf.effect);
      }
    }
    n = eq.q.size();
    nc = eq.g.size();
    if (n == 0) throw SimulationError("the scene has no coordinates: nothing moves", "add coordinates to the bodies");
    doubles_hold_parameters();
    static_friction();
    one_sided();
    compile();
    fmode.assign(eq.friction.size(), FrictionMode::Slide);
    fdir.assign(eq.friction.size(), {1, 0});
    fbasis.assign(eq.friction.size(), Eigen::Matrix2d::Zero());
    frows.assign(eq.friction.size(), 0);
    cmode.assign(eq.contacts.size(), ContactMode::Open);
    cturn0.assign(eq.contacts.size(), 0.0);
    cgone.assign(eq.contacts.size(), 0);
    cslide.assign(eq.contacts.size(), 0);
    M.resize(n, n);
    f.resize(n);
    qdd.resize(n);
    check_method();
  }

  // ------------------------------------------------------------ compiling
  ex value_of(const ex& e, const exmap& values, const std::string& what) const {
    ex v = e.subs(values);
    // every symbol left must be a coordinate, a rate or t
    exset syms;
    for (const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
      if (is_a<symbol>(*it)) syms.insert(*it);
    for (const ex& s : syms) {
      bool ok = s.is_equal(m.t);
      for (std::size_t i = 0; i < n && !ok; ++i) ok = s.is_equal(eq.q[i]) || s.is_equal(eq.qd[i]);
      if (ok) continue;
      for (auto& p : m.params)
        if (p.sym.is_equal(s))
          throw SceneError(p.pos, "parameter '" + p.name + "' has no value, and simulating needs a number for it (in " + what + ")",
                           "give '" + p.name + "' a value to simulate the scene");
      throw SceneError(SourcePos{m.file, 0, 0}, "'" + model::text(s) + "' in " + what + " has no value",
                       "give every quantity of the scene a value to simulate it");
    }
    return v;
  }

  std::size_t add_rate(std::vector<ex>& outs, const LinearRate& r, const exmap& values, const std::string& what) {
    std::size_t at = outs.size();
    outs.push_back(value_of(r.v, values, what));
    for (auto& j : r.J) outs.push_back(value_of(j, values, what));
    outs.push_back(value_of(r.a0, values, what));
    return at;
  }

  Kernel build(const std::vector<ex>& outs, const std::string& epilogue = "") const {
    std::vector<ex> inputs{m.t};
    for (auto& q : eq.q) inputs.push_back(q);
    for (auto& qd : eq.qd) inputs.push_back(qd);
    Kernel k{numerics::Tape::compile(outs, inputs), std::nullopt};
    if (o.native) k.native = numerics::NativeKernel::build(k.tape, epilogue);
    return k;
  }

  // M q̈ = f solved inside the generated kernel, for a system of n ≤ 4 coordinates without
  // constraint rows: M = L D Lᵀ (L unit lower triangular), unrolled,
  //   D_j = M_jj − Σ_{k<j} L_jk² D_k,   L_ij = (M_ij − Σ_{k<j} L_ik L_jk D_k) / D_j   (i > j),
  //   z_i = f_i − Σ_{k<i} L_ik z_k,   q̈_i = z_i / D_i − Σ_{k>i} L_ki q̈_k   (k from the last down).
  // M is read packed (row i holds M_i0 … M_ii at o_M + i(i+1)/2), q̈ written at o_qdd. A pivot that
  // is not positive (M not positive definite) writes NaN: the general path then says why.
  // Also T = ½ q̇ᵀ M q̇ at o_qdd + n (q̇ the inputs x[1 + n …]): the kinetic energy at the state
  // of the call, which the run takes as its energy scale without the auxiliary kernel.
  static std::string ldlt_epilogue(std::size_t n, std::size_t o_M, std::size_t o_f, std::size_t o_qdd) {
    auto M = [&](std::size_t i, std::size_t j) { return "out[" + std::to_string(o_M + i * (i + 1) / 2 + j) + "]"; };
    auto L = [](std::size_t i, std::size_t j) { return "l" + std::to_string(i) + std::to_string(j); };
    auto D = [](std::size_t j) { return "d" + std::to_string(j); };
    auto V = [&](std::size_t i) { return "x[" + std::to_string(1 + n + i) + "]"; };
    std::string s = "  out[" + std::to_string(o_qdd + n) + "] = 0.5 * (";
    for (std::size_t i = 0; i < n; ++i) {
      s += (i ? " + " : "") + V(i) + " * (" + M(i, i) + " * " + V(i);
      for (std::size_t j = 0; j < i; ++j) s += " + 2 * " + M(i, j) + " * " + V(j);
      s += ")";
    }
    s += ");\n";
    for (std::size_t j = 0; j < n; ++j) {
      s += "  const double " + D(j) + " = " + M(j, j);
      for (std::size_t k = 0; k < j; ++k) s += " - " + L(j, k) + " * " + L(j, k) + " * " + D(k);
      s += ";\n";
      s += "  if (!(" + D(j) + " > 0)) {\n";
      for (std::size_t i = 0; i < n; ++i) s += "    out[" + std::to_string(o_qdd + i) + "] = NAN;\n";
      s += "    return;\n  }\n";
      for (std::size_t i = j + 1; i < n; ++i) {
        s += "  const double " + L(i, j) + " = (" + M(i, j);
        for (std::size_t k = 0; k < j; ++k) s += " - " + L(i, k) + " * " + L(j, k) + " * " + D(k);
        s += ") / " + D(j) + ";\n";
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      s += "  const double z" + std::to_string(i) + " = out[" + std::to_string(o_f + i) + "]";
      for (std::size_t k = 0; k < i; ++k) s += " - " + L(i, k) + " * z" + std::to_string(k);
      s += ";\n";
    }
    for (std::size_t i = n; i-- > 0;) {
      s += "  const double a" + std::to_string(i) + " = z" + std::to_string(i) + " / " + D(i);
      for (std::size_t k = i + 1; k < n; ++k) s += " - " + L(k, i) + " * a" + std::to_string(k);
      s += ";\n  out[" + std::to_string(o_qdd + i) + "] = a" + std::to_string(i) + ";\n";
    }
    return s;
  }

  void compile() {
    std::vector<ex> outs;
    o_M = outs.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j <= i; ++j) outs.push_back(value_of(eq.M(i, j), values, "the mass matrix"));
    // f = Σ Q (smooth effects) − c
    o_f = outs.size();
    for (std::size_t i = 0; i < n; ++i) {
      ex fi = -eq.c[i];
      for (auto& F : eq.forces) fi += F.Q[i];
      outs.push_back(value_of(fi, values, "the equations of motion"));
    }
    for (auto& F : eq.forces) {
      if (F.conservative) continue;
      o_power.push_back(outs.size());
      outs.push_back(value_of(F.power, values, "the power of " + m.effects[F.effect].name));
      work_names.emplace_back(m.effects[F.effect].name, 0);
    }
    o_A = outs.size();
    for (std::size_t r = 0; r < nc; ++r)
      for (std::size_t i = 0; i < n; ++i) outs.push_back(value_of(eq.A(r, i), values, "a constraint"));
    o_gamma = outs.size();
    for (std::size_t r = 0; r < nc; ++r) outs.push_back(value_of(eq.gamma[r], values, "a constraint"));
    for (auto& F : eq.friction) {
      const std::string what = "friction '" + m.effects[F.effect].name + "'";
      RateAt rx{add_rate(outs, F.x, values, what)}, ry{};
      if (!F.rotary) ry.at = add_rate(outs, F.y, values, what);
      o_fric.emplace_back(rx, ry);
      work_names.emplace_back(m.effects[F.effect].name, 0);
      ex lim = value_of(F.limit, values, what);
      if (!is_a<numeric>(lim.evalf()))
        throw SceneError(m.effects[F.effect].pos, what + ": its normal force must be a number to simulate",
                         "give the normal force (or the friction couple) as a constant");
      flimit.push_back(ex_to<numeric>(lim.evalf()).to_double());
    }
    for (auto& C : eq.contacts) {
      const std::string what = "contact '" + m.effects[C.effect].name + "'";
      RateAt rn{add_rate(outs, C.normal, values, what)};
      RateAt rt{add_rate(outs, C.tangent, values, what)};
      o_cont.emplace_back(rn, rt);
      ex e = value_of(C.e, values, what).evalf();
      ce.push_back(is_a<numeric>(e) ? ex_to<numeric>(e).to_double() : 0);
      o_cfp.push_back(outs.size());
      outs.push_back(value_of(C.force_per, values, what));
      auto number = [&](const ex& x) {
        ex v = value_of(x, values, what).evalf();
        return is_a<numeric>(v) ? ex_to<numeric>(v).to_double() : -1.0;
      };
      cmu_s.push_back(number(C.mu_s));
      cmu_k.push_back(number(C.mu_k));
      cwork.push_back(std::string::npos);
      if (C.rolling >= 0 && cmu_k.back() >= 0) {
        cwork.back() = work_names.size();
        work_names.emplace_back(m.effects[static_cast<std::size_t>(C.rolling)].name, 0);
      }
    }
    for (std::size_t k = 0; k < work_names.size(); ++k) work_names[k].second = k;
    nw = work_names.size();
    // no constraint rows can ever be active, and the system is small: q̈ comes from the kernel
    solved_in_kernel = o.native && nc == 0 && eq.friction.empty() && eq.contacts.empty() && n >= 1 && n <= 4;
    o_qdd = outs.size();
    rhs_k = build(outs, solved_in_kernel ? ldlt_epilogue(n, o_M, o_f, o_qdd) : std::string());
    out.resize(outs.size() + (solved_in_kernel ? n + 1 : 0));
    kernel_fn = rhs_k.native ? rhs_k.native->function() : nullptr;

    build_aux(std::nullopt);
    x.resize(1 + 2 * n);
    xa.resize(1 + 2 * n);
  }

  // The effects that act in the run (by index) and the constraints that hold (a constraint
  // effect's, while it acts)
  std::pair<std::vector<bool>, std::vector<bool>> acting() const {
    std::vector<bool> on, held;
    for (std::size_t i = 0; i < m.effects.size(); ++i) on.push_back(o.effects_on.empty() || o.effects_on[i]);
    for (std::size_t k = 0; k < m.constraints.size(); ++k) {
      const model::Effect* c = m.carrier(k);
      // (a contact that stays closed: held by the run's contact rows, not as a relation)
      held.push_back(!c || (on[static_cast<std::size_t>(m.effect_index(c->name))] && c->reaction(m)->holds.empty()));
    }
    return {on, held};
  }

  // The relations held by static friction (a rolling contact with mu_s) among the effects that
  // act: F and N at a general instant, from Newton–Euler for every body (principles::support_forces).
  void static_friction() {
    if (!o.rolling_limits) return;
    const auto [on, held] = acting();
    for (std::size_t i = 0; i < m.effects.size(); ++i) {
      const model::Effect& e = m.effects[i];
      auto r = e.reaction(m);
      if (!r || r->kind != model::Reaction::Kind::Relation || r->mu_s.is_zero() || !on[i] ||
          !on[static_cast<std::size_t>(m.effect_index(r->normal))])
        continue;
      Limit l;
      l.effect = e.name;
      l.normal = r->normal;
      l.pos = r->limit_pos;
      l.one_sided = m.effects[static_cast<std::size_t>(m.effect_index(r->normal))].reaction(m)->one_sided;
      const ex mu = value_of(r->mu_s, values, "mu_s of '" + e.name + "'").evalf();
      l.mu = is_a<numeric>(mu) ? ex_to<numeric>(mu).to_double() : 0;
      try {
        auto FN = principles::support_forces(m, on, held, principles::friction_bodies(m, *r),
                                             {m.instant_reactions.at(e.name)[0], m.instant_reactions.at(r->normal)[0]}, "the simulated motion",
                                             r->limit_pos);
        l.F = FN[0];
        l.N = FN[1];
      } catch (const SceneError& err) {
        throw SimulationError("'" + e.name + "' states mu_s, which the simulation checks against the forces Newton's second law gives, but: " +
                                  err.problem(),
                              "declare every support of the rolling body and its parties (a pin, a track): the check writes Newton's second law "
                              "for each; or leave 'mu_s' out",
                              r->limit_pos);
      }
      limits.push_back(l);
    }
  }

  // The surfaces that can only push among the tracks that act: N at a general instant, from
  // Newton–Euler for the body each holds (principles::support_forces). Where Newton's law does
  // not give it in closed form (a force the scene does not declare on the body), not followed.
  void one_sided() {
    if (!o.rolling_limits) return;
    const auto [on, held] = acting();
    for (std::size_t i = 0; i < m.effects.size(); ++i) {
      const model::Effect& e = m.effects[i];
      auto r = e.reaction(m);
      if (!r || r->kind != model::Reaction::Kind::Track || !r->one_sided || !on[i]) continue;
      if (std::find(freed.begin(), freed.end(), static_cast<int>(i)) != freed.end()) continue;  // a contact: its gap may open
      Release l;
      l.pulls = r->pulls;
      for (auto& [k, why] : kept)
        if (k == static_cast<int>(i)) l.why_kept = why;
      l.effect = e.name;
      l.body = r->a.body >= 0 ? m.bodies[static_cast<std::size_t>(r->a.body)].name : r->a.text;
      l.pos = e.pos;
      try {
        l.N = principles::support_forces(m, on, held, r->bodies(), {m.instant_reactions.at(e.name)[0]}, "the simulated motion", e.pos)[0];
      } catch (const SceneError&) {
        continue;  // not in closed form: not followed (principles::one_sided_limits says why)
      }
      releases.push_back(l);
    }
  }

  // T, V, g, ∂g/∂t, the contact gaps, the impulses, F and N of the friction limits, N of the
  // surfaces that only push and (last) the stop expression
  void build_aux(const std::optional<ex>& when) {
    std::vector<ex> a;
    a_T = a.size();
    a.push_back(value_of(eq.T, values, "the kinetic energy"));
    a_V = a.size();
    a.push_back(value_of(eq.V, values, "the potential energy"));
    a_g = a.size();
    for (auto& g : eq.g) a.push_back(value_of(g, values, "a constraint"));
    a_gt = a.size();
    for (auto& g : eq.gt) a.push_back(value_of(g, values, "a constraint"));
    a_gap = a.size();
    for (auto& C : eq.contacts) a.push_back(value_of(C.gap, values, "contact '" + m.effects[C.effect].name + "'"));
    a_turn = a.size();
    for (auto& C : eq.contacts) a.push_back(value_of(C.turn, values, "contact '" + m.effects[C.effect].name + "'"));
    a_imp = a.size();
    for (auto& I : eq.impulses)
      for (auto& P : I.P) a.push_back(value_of(P, values, "impulse '" + m.effects[I.effect].name + "'"));
    a_lim = a.size();
    for (auto& l : limits) {
      a.push_back(value_of(l.F, values, "the friction that holds '" + l.effect + "'"));
      a.push_back(value_of(l.N, values, "the normal force of '" + l.normal + "'"));
    }
    a_rel = a.size();
    for (auto& l : releases) a.push_back(value_of(l.N, values, "the normal force of '" + l.effect + "'"));
    a_stop = a.size();
    has_stop = when.has_value();
    if (when) a.push_back(value_of(*when, values, "the stop condition"));
    aux_k = build(a);
    aux.resize(a.size());
  }

  void check_method() const {
    if (o.method != Method::Symplectic) return;
    // H = ½ pᵀ M⁻¹ p + V(q) is separable only with a constant M and forces of position alone
    std::string why;
    SourcePos at;
    for (std::size_t i = 0; i < n && why.empty(); ++i)
      for (std::size_t j = 0; j < n && why.empty(); ++j)
        for (auto& q : eq.q)
          if (eq.M(i, j).has(q)) why = "its mass matrix depends on " + model::text(q);
    for (auto& c : eq.c)
      if (!c.is_zero() && why.empty()) why = "it has velocity-product terms";
    for (auto& F : eq.forces)
      if (!F.conservative && why.empty()) {
        why = "effect '" + m.effects[F.effect].name + "' is not conservative";
        at = m.effects[F.effect].pos;
      }
    if (why.empty() && nc) why = "it has constraints";
    if (why.empty() && !eq.friction.empty()) why = "it has friction";
    if (why.empty() && !eq.contacts.empty()) why = "it has contacts";
    if (why.empty() && !eq.impulses.empty()) why = "it has impulses";
    if (!why.empty())
      throw SimulationError("the symplectic method needs a conservative scene with separable energy, but " + why,
                            "use --method dopri5, rkf78 or bs", at);
  }

  // ------------------------------------------------------------ evaluation
  void load(double t, const double* y) {
    double* to = x.data();
    to[0] = t;
    for (std::size_t i = 0; i < 2 * n; ++i) to[1 + i] = y[i];  // (a few doubles: no call to memmove)
  }
  // (its own inputs: x stays the last right-hand side call's, which out's values belong to)
  void eval_aux(double t, const double* y) {
    xa[0] = t;
    std::copy(y, y + 2 * n, xa.begin() + 1);
    aux_k(xa.data(), aux.data());
  }
  double T() const { return aux[a_T]; }
  double V() const { return aux[a_V]; }

  // the rows J of a velocity laid out at r, its value and a0
  double rate_v(const RateAt& r) const { return out[r.at]; }
  // Contact k comes to rest (aux evaluated at the instant): its surface's angle then
  void rest(std::size_t k) {
    cmode[k] = ContactMode::Rest;
    cturn0[k] = aux[a_turn + k];
  }
  // The push of resting contact k from its rows' multipliers (lam from contact_row(k)): along
  // its normal as it has turned since it came to rest, N = λ_n cos Δ + λ_t sin Δ (a rough contact;
  // λ_n alone for a smooth one or one whose surface does not turn)
  double push(std::size_t k, const double* lam) const {
    const double d = aux[a_turn + k] - cturn0[k];
    if (d == 0 || contact_rows(k) < 2) return lam[0];
    return lam[0] * std::cos(d) + lam[1] * std::sin(d);
  }
  const double* rate_J(const RateAt& r) const { return out.data() + r.at + 1; }
  double rate_a0(const RateAt& r) const { return out[r.at + 1 + n]; }

  // the slip velocity of friction k (a friction couple: ω, 0) from the last right-hand side
  std::array<double, 2> slip(std::size_t k) const {
    auto [rx, ry] = o_fric[k];
    return {rate_v(rx), eq.friction[k].rotary ? 0.0 : rate_v(ry)};
  }

  // Is any constraint row active: holonomic ones, sticking friction, resting contacts?
  bool rows_active() const {
    bool any = nc > 0;
    for (auto mo : fmode) any = any || mo == FrictionMode::Stick;
    for (auto mo : cmode) any = any || mo == ContactMode::Rest;
    return any;
  }
  // The rows of the active constraints, in the order constraint_rows() lays them out: the
  // holonomic ones, then each sticking friction's (frows), then each resting contact's (1, or
  // 2 when rough). friction_row(k) / contact_row(k): where friction k's / contact k's begin.
  std::size_t friction_row(std::size_t k) const {
    std::size_t row = nc;
    for (std::size_t j = 0; j < k; ++j)
      if (fmode[j] == FrictionMode::Stick) row += static_cast<std::size_t>(frows[j]);
    return row;
  }
  std::size_t contact_rows(std::size_t k) const {
    return cmode[k] == ContactMode::Rest ? (eq.contacts[k].stick && cslide[k] == 0 ? 2 : 1) : 0;
  }
  std::size_t contact_row(std::size_t k) const {
    std::size_t row = friction_row(eq.friction.size());
    for (std::size_t j = 0; j < k; ++j) row += contact_rows(j);
    return row;
  }

  void fill_M() {
    for (std::size_t i = 0, k = o_M; i < n; ++i)
      for (std::size_t j = 0; j <= i; ++j, ++k) M(i, j) = M(j, i) = out[k];
  }

  // The rows B q̈ = b of every constraint active now: holonomic ones, sticking friction and
  // resting contacts (with their tangential rows when rough).
  void constraint_rows() {
    const std::size_t r = contact_row(eq.contacts.size());
    B.setZero(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(n));
    b.setZero(static_cast<Eigen::Index>(r));
    std::size_t row = 0;
    for (std::size_t c = 0; c < nc; ++c, ++row) {
      for (std::size_t i = 0; i < n; ++i) B(row, i) = out[o_A + c * n + i];
      b(row) = out[o_gamma + c];
    }
    for (std::size_t k = 0; k < eq.friction.size(); ++k) {
      if (fmode[k] != FrictionMode::Stick) continue;
      auto [rx, ry] = o_fric[k];
      for (int s = 0; s < frows[k]; ++s, ++row) {
        // C v = 0 held: C (J q̈ + a0) = 0
        double cx = fbasis[k](s, 0), cy = eq.friction[k].rotary ? 0 : fbasis[k](s, 1);
        for (std::size_t i = 0; i < n; ++i)
          B(row, i) = cx * rate_J(rx)[i] + (eq.friction[k].rotary ? 0 : cy * rate_J(ry)[i]);
        b(row) = -(cx * rate_a0(rx) + (eq.friction[k].rotary ? 0 : cy * rate_a0(ry)));
      }
    }
    for (std::size_t k = 0; k < eq.contacts.size(); ++k) {
      if (cmode[k] != ContactMode::Rest) continue;
      auto [rn, rt] = o_cont[k];
      for (std::size_t i = 0; i < n; ++i) B(row, i) = rate_J(rn)[i];
      b(row++) = -rate_a0(rn);
      if (eq.contacts[k].stick && cslide[k] == 0) {
        for (std::size_t i = 0; i < n; ++i) B(row, i) = rate_J(rt)[i];
        b(row++) = -rate_a0(rt);
        }
    }
  }

  // M x = rhs + Cᵀ λ,  B x = c (C = B unless a rolling contact slides: its normal row's force
  // then carries the friction −μ_k N along its slip, C_n = J_n − s μ_k/|f| J_t): by the Schur
  // complement on M's LDLᵀ when M is positive definite, else the whole saddle-point system by
  // full-pivot LU.
  void solve_kkt(const Vec& rhs, const Mat& Bm, const Vec& c, Vec& xo, Vec& lam, double t, const Mat* Cm = nullptr) {
    const Mat& C = Cm ? *Cm : Bm;
    ldlt.compute(M);
    const bool pd = ldlt.info() == Eigen::Success && ldlt.isPositive() && (ldlt.vectorD().array() > 0).all() &&
                    ldlt.vectorD().minCoeff() > 1e-14 * ldlt.vectorD().maxCoeff();
    if (Bm.rows() == 0) {
      if (!pd) singular(t);
      xo = ldlt.solve(rhs);
      lam.resize(0);
      return;
    }
    if (pd) {
      // x = M⁻¹(rhs + Cᵀλ), B x = c  ⇒  (B M⁻¹ Cᵀ) λ = c − B M⁻¹ rhs
      Vec y = ldlt.solve(rhs);
      Mat X = ldlt.solve(C.transpose());
      Mat S = Bm * X;
      Eigen::FullPivLU<Mat> lu(S);
      if (!lu.isInvertible()) singular(t, "two constraints hold the same motion (their rows are dependent)");
      lam = lu.solve(c - Bm * y);
      xo = y + X * lam;
      return;
    }
    const Eigen::Index N = M.rows(), R = Bm.rows();
    Mat K = Mat::Zero(N + R, N + R);
    K.topLeftCorner(N, N) = M;
    K.topRightCorner(N, R) = -C.transpose();
    K.bottomLeftCorner(R, N) = Bm;
    Vec r(N + R);
    r << rhs, c;
    Eigen::FullPivLU<Mat> lu(K);
    if (!lu.isInvertible()) singular(t);
    Vec s = lu.solve(r);
    xo = s.head(N);
    lam = s.tail(R);
  }

  [[noreturn]] void singular(double t, const std::string& why = "") const {
    // a scene so small that M(q) underflows in doubles (a pendulum 1e-160 m long: m L²/3 ≈ 1e-320
    // kg·m²) is a matter of scale, not of a coordinate without mass
    for (std::size_t i = 0; i < n; ++i) {
      const double d = M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
      if (!eq.M(i, i).is_zero() && std::fabs(d) < 1e-250)
        throw SimulationError("the equations of motion cannot be formed in doubles at t = " + numerics::g_text(t, 6) + " s: the mass matrix entry M[" +
                                  m.coords[i].name + "," + m.coords[i].name + "]" +
                                  (d == 0 ? " underflows to 0" : " is " + numerics::g_text(d, 6) + " in SI units, at the edge of what a double holds"),
                              "simulate the scene at a larger scale: its masses and lengths are too small for doubles",
                              m.coords[i].pos);
    }
    throw SimulationError("the equations of motion are singular at t = " + numerics::g_text(t, 6) + " s" +
                              (why.empty() ? ": M(q) is not positive definite (a coordinate that moves no mass?)" : ": " + why),
                          "give every coordinate a body with mass or inertia, or remove the redundant constraint");
  }

  // dy/dt = [q̇, q̈, P…]
  void rhs(const double* y, double t, double* dy) {
    ++rhs_calls;
    load(t, y);
    if (kernel_fn) kernel_fn(x.data(), out.data());
    else rhs_k(x.data(), out.data());
    if (solved_in_kernel) {
      // q̈ from the kernel's own LDLᵀ (ldlt_epilogue); not finite: the general path below says why.
      // M and f are left as they were (out holds them): a caller that reads M after rhs() calls
      // fill_M() (jump, stick_or_slip)
      bool finite = true;
      for (std::size_t i = 0; i < n; ++i) {
        dy[i] = y[n + i];
        dy[n + i] = out[o_qdd + i];
        finite = finite && std::isfinite(dy[n + i]);
      }
      for (std::size_t k = 0; k < o_power.size(); ++k) dy[2 * n + k] = out[o_power[k]];
      if (y == watch_y) {
        watched_T = out[o_qdd + n];
        watched = true;
      }
      if (finite) return;
    }
    fill_M();
    for (std::size_t i = 0; i < n; ++i) f(static_cast<Eigen::Index>(i)) = out[o_f + i];
    std::size_t w = 0;
    for (std::size_t k = 0; k < o_power.size(); ++k) dy[2 * n + w++] = out[o_power[k]];
    // Coulomb friction while sliding: Q = −μN Jᵀ v̂ (v̂ the slip direction; at zero slip the
    // direction it starts to slip in), power −μN |v|
    for (std::size_t k = 0; k < eq.friction.size(); ++k, ++w) {
      auto [rx, ry] = o_fric[k];
      if (fmode[k] == FrictionMode::Stick) {
        dy[2 * n + w] = 0;  // the point (or body) does not move: no work
        continue;
      }
      const bool rot = eq.friction[k].rotary;
      auto [vx, vy] = slip(k);
      // Past the instant the slip stops (v·d ≤ 0 inside a trial step) the force keeps its
      // direction d, so the right-hand side stays smooth across the event and the event
      // locator, not the step-size control, finds where the slip stops.
      double sp = std::hypot(vx, vy);
      const bool along = sp > 0 && vx * fdir[k][0] + vy * fdir[k][1] > 0;
      double dx = along ? vx / sp : fdir[k][0], dy_ = along ? vy / sp : fdir[k][1];
      for (std::size_t i = 0; i < n; ++i)
        f(static_cast<Eigen::Index>(i)) -= flimit[k] * (dx * rate_J(rx)[i] + (rot ? 0 : dy_ * rate_J(ry)[i]));
      dy[2 * n + w] = -flimit[k] * (vx * dx + vy * dy_);  // P = −μN v·d (= −μN |v| while sliding)
    }
    for (std::size_t k = 0; k < cwork.size(); ++k)
      if (cwork[k] != std::string::npos) dy[2 * n + cwork[k]] = 0;  // (not sliding: no work)
    const bool rows = rows_active();
    if (!rows && n <= 4 && small_solve(dy + n)) {
      // no constraint: M q̈ = f by a fixed-size LDLᵀ (n ≤ 4)
      lambda.resize(0);
      for (std::size_t i = 0; i < n; ++i) dy[i] = y[n + i];
      for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(dy[n + i])) undefined(t);
      return;
    }
    if (rows) constraint_rows();
    else {
      B.resize(0, static_cast<Eigen::Index>(n));
      b.resize(0);
    }
    if (B.rows() == 0) {
      ldlt.compute(M);
      if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 0).all()) singular(t);
      qdd = ldlt.solve(f);
      lambda.resize(0);
    } else if (!sliding()) {
      solve_kkt(f, B, b, qdd, lambda, t);
    } else {
      solve_sliding(dy, t);
    }
    for (std::size_t i = 0; i < n; ++i) {
      dy[i] = y[n + i];
      dy[n + i] = qdd(static_cast<Eigen::Index>(i));
      if (!std::isfinite(dy[n + i])) undefined(t);
    }
  }

  /// One run from s0 (run.cpp).
  Run run(const State& s0, const Stop& stop);

  bool sliding() const {
    for (std::size_t k = 0; k < cslide.size(); ++k)
      if (cslide[k] != 0 && cmode[k] == ContactMode::Rest) return true;
    return false;
  }
  // A rolling contact k sliding with slip sign s: its friction −μ_k N along the slip, N its
  // normal multiplier λ_n: Q = −s (μ_k/|f|) λ_n J_tᵀ (F = λ f), so the normal row's column is
  // C_n = J_n − s μ_k/|f| J_t; its power −μ_k λ_n |ċ|/|f| (ċ the relation's rate, the slip).
  void solve_sliding(double* dy, double t) {
    Mat C = B;
    for (std::size_t k = 0; k < cslide.size(); ++k) {
      if (cslide[k] == 0 || cmode[k] != ContactMode::Rest) continue;
      const std::size_t row = contact_row(k);
      const double per = cmu_k[k] / out[o_cfp[k]];
      for (std::size_t i = 0; i < n; ++i) C(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(i)) -= cslide[k] * per * rate_J(o_cont[k].second)[i];
    }
    solve_kkt(f, B, b, qdd, lambda, t, &C);
    for (std::size_t k = 0; k < cslide.size(); ++k) {
      if (cslide[k] == 0 || cmode[k] != ContactMode::Rest || cwork[k] == std::string::npos) continue;
      const double N = lambda(static_cast<Eigen::Index>(contact_row(k)));
      dy[2 * n + cwork[k]] = -cmu_k[k] * N * std::fabs(rate_v(o_cont[k].second)) / out[o_cfp[k]];
    }
  }

  // q̈ = M⁻¹ f for small n with a fixed-size LDLᵀ (no allocation, unrolled); false when M is
  // not positive definite (the general path then reports it)
  bool small_solve(double* qdd_out) const {
    switch (n) {
      case 1: return small_solve_n<1>(qdd_out);
      case 2: return small_solve_n<2>(qdd_out);
      case 3: return small_solve_n<3>(qdd_out);
      case 4: return small_solve_n<4>(qdd_out);
      default: return false;
    }
  }
  template <int N>
  bool small_solve_n(double* qdd_out) const {
    Eigen::Matrix<double, N, N> Ms = M.template topLeftCorner<N, N>();
    Eigen::LDLT<Eigen::Matrix<double, N, N>> l(Ms);
    if (l.info() != Eigen::Success || !(l.vectorD().array() > 0).all()) return false;
    Eigen::Map<Eigen::Matrix<double, N, 1>> out(qdd_out);
    out = l.solve(f.template head<N>());
    return true;
  }

  // The run is in doubles: a parameter's SI value beyond their range (1e400 kg is inf, 1e-400 m is
  // 0) would make every step wrong, and its infinity would reach the generated C++.
  void doubles_hold_parameters() const {
    for (auto& p : m.params) {
      auto it = values.find(p.sym);
      if (it == values.end() || !is_a<numeric>(it->second)) continue;
      const numeric& v = ex_to<numeric>(it->second);
      if (!v.is_real() || v.is_zero()) continue;
      double d = v.to_double();
      if (std::isfinite(d) && std::isnormal(d)) continue;
      throw SimulationError("parameter '" + p.name + "' is " + numerics::format(v, 6) + " in SI units, " +
                                (std::isfinite(d) ? "below" : "beyond") + " what a double holds (1e-307 to 1e308), and the simulation runs in doubles",
                            "give it a value within the range of doubles", p.pos);
    }
  }

  [[noreturn]] void undefined(double t) const {
    std::string who;
    SourcePos at;
    for (auto& F : eq.forces)
      if (!F.singular.empty()) {
        who = " (" + F.singular + ")";
        at = m.effects[F.effect].pos;
      }
    throw SimulationError("the acceleration is not a number at t = " + numerics::g_text(t, 6) + " s" + who,
                          who.empty() ? "check the parameters and the start state: an effect or a body's motion is undefined there"
                                      : "start the motion where every effect is defined (a power drive needs the body turning)",
                          at);
  }
};

}  // namespace kinergy::simulate
