// One simulation run: steppers, events located to the tolerance, impacts, friction and contact
// modes, constraint projection, and the energy audit.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <type_traits>

#include <boost/numeric/odeint.hpp>

#include "kinergy/common/interrupt.hpp"
#include "impl.hpp"

namespace kinergy::simulate {

namespace odeint = boost::numeric::odeint;
using state_type = std::vector<double>;

namespace {

struct Sys {
  Simulator::Impl* p;
  void operator()(const state_type& y, state_type& dy, double t) const { p->rhs(y.data(), t, dy.data()); }
};

/// One step of a method: accepted (y, t advanced, dt the next step's suggestion) or rejected
/// (dt smaller). Fixed-step methods always accept and keep dt.
class Stepper {
public:
  virtual ~Stepper() = default;
  virtual bool step(Sys& s, state_type& y, double& t, double& dt) = 0;
  virtual void reset() = 0;
  virtual bool adaptive() const { return true; }
  /// Each step's first call of the right-hand side is at the step's start, in the buffer step()
  /// was given (the state accepted last): not so for a method whose last stage is the next step's
  /// first (first same as last), nor for one that calls the kernel past the right-hand side.
  virtual bool calls_at_start() const { return false; }
};

template <class C>
class Controlled : public Stepper {
public:
  explicit Controlled(C c) : c_(std::move(c)) {}
  bool step(Sys& s, state_type& y, double& t, double& dt) override {
    return c_.try_step(s, y, t, dt) == odeint::success;
  }
  void reset() override {
    if constexpr (requires(C& c) { c.reset(); }) c_.reset();
  }
  bool calls_at_start() const override {
    return !std::is_same_v<typename C::stepper_category, odeint::explicit_controlled_stepper_fsal_tag>;
  }
private:
  C c_;
};

class Rk4 : public Stepper {
public:
  bool step(Sys& s, state_type& y, double& t, double& dt) override {
    st_.do_step(s, y, t, dt);
    t += dt;
    return true;
  }
  void reset() override {}
  bool adaptive() const override { return false; }
  bool calls_at_start() const override { return true; }
private:
  odeint::runge_kutta4<state_type> st_;
};

/// McLachlan's 4th-order symplectic Runge–Kutta–Nyström method on H = ½ pᵀ M⁻¹ p + V(q),
/// M constant: q' = M⁻¹ p, p' = Q(q). Converts y = [q, q̇] to (q, p = M q̇) and back.
class Symplectic : public Stepper {
public:
  explicit Symplectic(Simulator::Impl& p) : p_(p) {}
  bool step(Sys&, state_type& y, double& t, double& dt) override {
    const std::size_t n = p_.n;
    if (!ready_) {
      // M is constant: take it (and its factorization) once
      p_.load(t, y.data());
      p_.rhs_k(p_.x.data(), p_.out.data());
      p_.fill_M();
      ldlt_.compute(p_.M);
      Minv_ = ldlt_.solve(Mat::Identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n)));
      M_ = p_.M;
      ready_ = true;
    }
    state_type q(y.begin(), y.begin() + static_cast<long>(n)), pm(n);
    Eigen::Map<const Vec> qd(y.data() + n, static_cast<Eigen::Index>(n));
    Eigen::Map<Vec>(pm.data(), static_cast<Eigen::Index>(n)) = M_ * qd;
    auto coord = [this](const state_type& pp, state_type& dq) {
      const auto k = static_cast<Eigen::Index>(pp.size());
      Eigen::Map<Vec>(dq.data(), k) = Minv_ * Eigen::Map<const Vec>(pp.data(), k);
    };
    auto momentum = [this, n, t](const state_type& qq, state_type& dp) {
      // p' = Q(q) (the forces depend on q alone: checked when the simulator was built)
      std::copy(qq.begin(), qq.end(), y0_.begin());
      std::fill(y0_.begin() + static_cast<long>(n), y0_.end(), 0.0);
      p_.load(t, y0_.data());
      p_.rhs_k(p_.x.data(), p_.out.data());
      ++p_.rhs_calls;
      for (std::size_t i = 0; i < n; ++i) dp[i] = p_.out[p_.o_f + i];
    };
    y0_.resize(2 * n);
    st_.do_step(std::make_pair(coord, momentum), std::make_pair(std::ref(q), std::ref(pm)), t, dt);
    t += dt;
    std::copy(q.begin(), q.end(), y.begin());
    Eigen::Map<Vec>(y.data() + n, static_cast<Eigen::Index>(n)) = Minv_ * Eigen::Map<const Vec>(pm.data(), static_cast<Eigen::Index>(n));
    return true;
  }
  void reset() override {}
  bool adaptive() const override { return false; }
private:
  Simulator::Impl& p_;
  odeint::symplectic_rkn_sb3a_mclachlan<state_type> st_;
  Eigen::LDLT<Mat> ldlt_;
  Mat M_, Minv_;
  bool ready_ = false;
  state_type y0_;
};

std::unique_ptr<Stepper> make_stepper(Simulator::Impl& p) {
  const double tol = p.o.tol, atol = p.o.atol < 0 ? tol : p.o.atol;
  switch (p.o.method) {
    case Method::Dopri5:
      return std::make_unique<Controlled<decltype(odeint::make_controlled(atol, tol, odeint::runge_kutta_dopri5<state_type>()))>>(
          odeint::make_controlled(atol, tol, odeint::runge_kutta_dopri5<state_type>()));
    case Method::Rkf78:
      return std::make_unique<Controlled<decltype(odeint::make_controlled(atol, tol, odeint::runge_kutta_fehlberg78<state_type>()))>>(
          odeint::make_controlled(atol, tol, odeint::runge_kutta_fehlberg78<state_type>()));
    case Method::BulirschStoer:
      return std::make_unique<Controlled<odeint::bulirsch_stoer<state_type>>>(odeint::bulirsch_stoer<state_type>(atol, tol));
    case Method::Rk4: return std::make_unique<Rk4>();
    case Method::Symplectic: return std::make_unique<Symplectic>(p);
  }
  return nullptr;
}

/// The run's stepper: an adaptive method's or RK4's is kept between runs of a simulator (its
/// coefficients and buffers made once) and reset at each start; the symplectic one, which takes M
/// at its first step, is made anew.
std::shared_ptr<Stepper> take_stepper(Simulator::Impl& p) {
  if (p.o.method == Method::Symplectic) return make_stepper(p);
  if (!p.kept_stepper) p.kept_stepper = std::shared_ptr<Stepper>(make_stepper(p));
  auto s = std::static_pointer_cast<Stepper>(p.kept_stepper);
  s->reset();
  return s;
}

}  // namespace

namespace {

/// The state of one run: the integration, its events and its bookkeeping.
class Runner {
public:
  Runner(Simulator::Impl& p, const Stop& stop) : p_(p), stop_(stop), sys_{&p} {}

  Run go(const State& s0) {
    const std::size_t n = p_.n;
    if (s0.q.size() != n || s0.qd.size() != n)
      throw SimulationError("the initial state has " + std::to_string(s0.q.size()) + " positions and " +
                                std::to_string(s0.qd.size()) + " rates for " + std::to_string(n) + " coordinates",
                            "give a position and a rate for every coordinate");
    t_ = s0.t;
    if (!std::isfinite(stop_.until))
      throw SimulationError("the run has no end (until = " + numerics::g_text(stop_.until, 6) + " s)", "give --until a finite time in s");
    span_ = stop_.until - t_;
    if (!(span_ >= 0)) throw SimulationError("the run ends before it starts (until = " + numerics::g_text(stop_.until, 6) + " s)", "give --until a time after the start");
    p_.rest_time = std::max(p_.o.tol, 1e-13) * span_;
    y_.assign(2 * n + p_.nw, 0.0);
    std::copy(s0.q.begin(), s0.q.end(), y_.begin());
    std::copy(s0.qd.begin(), s0.qd.end(), y_.begin() + static_cast<long>(n));
    check_finite(y_, "the initial state");
    stepper_ = take_stepper(p_);
    if (!stepper_->adaptive() && p_.o.step <= 0) fixed_dt_ = std::max(span_, 1e-300) / 1e4;
    else fixed_dt_ = p_.o.step;
    // a fixed step so small that the run would take more steps than the limit (or than t can
    // tell apart: t + dt == t) is refused before it starts
    if (!stepper_->adaptive() && span_ > 0 &&
        (!(span_ / fixed_dt_ <= static_cast<double>(p_.o.max_steps)) || stop_.until + fixed_dt_ == stop_.until))
      throw SimulationError("a fixed step of " + numerics::g_text(fixed_dt_, 6) + " s would take " + numerics::g_text(span_ / fixed_dt_, 6) + " steps to reach t = " +
                                numerics::g_text(stop_.until, 6) + " s, more than the " + std::to_string(p_.o.max_steps) + " a run may take",
                            "give a larger --step (at least " + numerics::g_text(span_ / static_cast<double>(p_.o.max_steps), 6) + " s)");

    p_.eval_aux(t_, y_.data());
    run_.E0 = p_.T() + p_.V();  // before what happens at the start (impulses, impacts)
    max_T_ = p_.T();
    const state_type before = y_;
    start();
    if (y_ != before) p_.eval_aux(t_, y_.data());  // (aux still holds the start's values when nothing moved)
    if (p_.has_stop) {
      double s = p_.aux[p_.a_stop];
      stop_sign_ = s > 0 ? 1 : (s < 0 ? -1 : 0);
    }
    max_T_ = std::max(max_T_, p_.T());
    record();
    t0_ = t_;
    next_k_ = 1;
    if (sampling() && span_ / p_.o.sample_dt > 1e7)
      throw SimulationError("sampling every " + numerics::g_text(p_.o.sample_dt, 6) + " s over " + numerics::g_text(span_, 6) + " s makes more than 10^7 samples",
                            "sample less often (a larger --dt, fewer --samples)");
    if (span_ > 0) integrate();
    finish();
    return std::move(run_);
  }

private:
  Simulator::Impl& p_;
  Stop stop_;
  Sys sys_;
  std::shared_ptr<Stepper> stepper_;
  state_type y_;
  double t_ = 0, span_ = 0, fixed_dt_ = 0, max_T_ = 0;
  int stop_sign_ = 0;
  double impulse_work_ = 0;
  Run run_;

  static bool finite(const state_type& y) {
    for (double v : y)
      if (!std::isfinite(v)) return false;
    return true;
  }
  static void check_finite(const state_type& y, const std::string& what) {
    if (!finite(y)) throw SimulationError(what + " is not a number", "give finite positions and rates");
  }

  std::string contact_name(std::size_t k) const { return p_.m.effects[p_.eq.contacts[k].effect].name; }
  std::string friction_name(std::size_t k) const { return p_.m.effects[p_.eq.friction[k].effect].name; }
  void note(const std::string& s) { run_.log.push_back("t = " + numerics::g_text(t_, 6) + " s: " + s); }
  /// A switch of effect `effect` (kind: leaves, strikes, rests, lets go, slips, sticks), logged.
  void note(const std::string& s, const std::string& effect, const std::string& kind) {
    note(s);
    run_.switches.push_back(Switch{t_, effect, kind, run_.log.back()});
  }
  /// The scene's coordinates now, "theta = 0.841069 rad (48.1897 deg), ..." (not the gaps).
  std::string place() const {
    std::string at;
    for (std::size_t i = 0; i < p_.scene_n; ++i) {
      const auto& c = p_.m.coords[i];
      const double q = y_[i];
      const std::string unit = units::si_name(c.dim).empty() ? "rad" : units::si_name(c.dim);
      at += (at.empty() ? "" : ", ") + c.name + " = " + numerics::g_text(q, 6) + " " + unit + (unit == "rad" ? " (" + numerics::g_text(q * 180 / M_PI, 6) + " deg)" : "");
    }
    return at;
  }
  /// The body a freed surface (contact k) holds.
  std::string surface_body(std::size_t k) const {
    const auto r = p_.m.effects[p_.eq.contacts[k].effect].reaction(p_.m);
    return r && r->a.body >= 0 ? p_.m.bodies[static_cast<std::size_t>(r->a.body)].name : "the body";
  }
  /// How contact k, a freed surface or cord, is spoken of.
  model::OneWay words(std::size_t k) const {
    const auto r = p_.m.effects[p_.eq.contacts[k].effect].reaction(p_.m);
    return model::one_way(r && r->pulls, surface_body(k), contact_name(k));
  }
  /// Contact k, a freed surface, opens now: the body leaves it (a cord goes slack).
  void leaves_surface(std::size_t k) {
    const model::OneWay w = words(k);
    note(w.lets_go + " at " + place() + ": its " + w.force + " has fallen to zero, and " + surface_body(k) + " goes on free of it", contact_name(k),
         w.verb == "leaves" ? "leaves" : "slack");
  }

  // ---------------------------------------------------------------- the start
  // Every track the run does not free must be kept by the coordinates and the constraints: its
  // distance d(q) may not change along any motion they allow, ∇d in the row space of A (the
  // constraints' Jacobian) at the start. A track the coordinates leave free (position: [x, y], y a
  // coordinate of its own, with no relation holding it) would let the body through it: refused.
  void tracks_held() {
    const std::size_t n = p_.n;
    std::vector<double> dydt(y_.size());
    bool rows = false;
    for (std::size_t i = 0; i < p_.m.effects.size(); ++i) {
      if (!p_.o.effects_on.empty() && !p_.o.effects_on[i]) continue;
      if (std::find(p_.freed.begin(), p_.freed.end(), static_cast<int>(i)) != p_.freed.end()) continue;
      const auto r = p_.m.effects[i].reaction(p_.m);
      if (!r || r->kind != model::Reaction::Kind::Track) continue;
      GiNaC::exmap at = p_.values;
      at[p_.m.t] = t_;
      for (std::size_t j = 0; j < n; ++j) at[p_.eq.q[j]] = y_[j];
      Vec grad(static_cast<Eigen::Index>(n));
      bool number = true;
      for (std::size_t j = 0; j < n && number; ++j) {
        const ex v = r->gap.diff(GiNaC::ex_to<GiNaC::symbol>(p_.eq.q[j])).subs(at).evalf();
        number = GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real();
        if (number) grad(static_cast<Eigen::Index>(j)) = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
      }
      if (!number || !(grad.norm() > 0)) continue;
      if (!rows) {
        p_.rhs(y_.data(), t_, dydt.data());
        rows = true;
      }
      Mat A(static_cast<Eigen::Index>(p_.nc), static_cast<Eigen::Index>(n));
      for (std::size_t c = 0; c < p_.nc; ++c)
        for (std::size_t j = 0; j < n; ++j) A(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(j)) = p_.out[p_.o_A + c * n + j];
      // the part of ∇d no combination of the constraints' rows gives: ∇d − Aᵀ μ, μ by least squares
      Vec rest = grad;
      if (p_.nc) rest -= A.transpose() * A.transpose().completeOrthogonalDecomposition().solve(grad);
      if (rest.norm() <= 1e-8 * grad.norm()) continue;
      throw SimulationError("track '" + p_.m.effects[i].name + "': the coordinates do not keep " + r->a.text + " on it (its distance from it changes with them)" +
                                (p_.nc ? ", nor do the scene's relations" : "") + ", and the simulation holds only what they hold: the body would pass through it",
                            "write the body's position so that the coordinates keep the point on the track (a wheel on a floor: position: [x, r])",
                            p_.m.effects[i].pos);
    }
  }

  void start() {
    const std::size_t n = p_.n;
    project();
    tracks_held();
    // given impulses act once, at the start:  M (q̇⁺ − q̇⁻) = Σ P_given + Aᵀ Λ
    if (!p_.eq.impulses.empty() && stop_.impulses) {
      p_.eval_aux(t_, y_.data());
      Vec P = Vec::Zero(static_cast<Eigen::Index>(n));
      for (std::size_t k = 0; k < p_.eq.impulses.size(); ++k)
        for (std::size_t i = 0; i < n; ++i) P(static_cast<Eigen::Index>(i)) += p_.aux[p_.a_imp + k * n + i];
      double T0 = p_.T();
      jump(P, {}, {});
      p_.eval_aux(t_, y_.data());
      impulse_work_ = p_.T() - T0;  // the work of the given impulses, ½ P·(q̇⁻ + q̇⁺)
      note("the given impulse(s) act");
    }
    holds_rolling();
    if (p_.eq.contacts.empty() && p_.eq.friction.empty()) return;  // nothing more to settle at the start
    // contacts: penetrated (an error), touching and approaching (an impact now), touching at rest
    p_.eval_aux(t_, y_.data());
    std::vector<double> dydt(y_.size());
    p_.rhs(y_.data(), t_, dydt.data());
    std::vector<std::size_t> strike;
    for (std::size_t k = 0; k < p_.eq.contacts.size(); ++k) {
      double gap = p_.aux[p_.a_gap + k], vn = p_.rate_v(p_.o_cont[k].first);
      double tol = gap_tol();
      if (gap < -tol)
        throw SimulationError("contact '" + contact_name(k) + "' is penetrated at the start (gap " + numerics::g_text(gap, 6) + " m)",
                              "start with the parties apart or touching", p_.m.effects[p_.eq.contacts[k].effect].pos);
      if (gap <= tol) {
        if (vn < 0) strike.push_back(k);
        else if (vn <= vel_tol()) p_.rest(k);
      }
    }
    if (!strike.empty()) impact(strike);
    settle_contacts();
    // a rolling contact that its static friction cannot hold at the start slips at once
    {
      std::vector<double> dy0(y_.size());
      p_.rhs(y_.data(), t_, dy0.data());
      for (std::size_t k = 0; k < p_.eq.contacts.size(); ++k) {
        if (p_.cmode[k] != ContactMode::Rest || p_.eq.contacts[k].rolling < 0 || p_.cslide[k] != 0) continue;
        // one that starts with its contact slipping (a ball thrown along a floor without spin)
        // slides from the start, against μ_k N, until its slip stops
        if (const double slip = p_.rate_v(p_.o_cont[k].second); std::fabs(slip) > vel_tol() && p_.cmu_k[k] >= 0) {
          p_.cslide[k] = slip > 0 ? 1 : -1;
          note("'" + p_.m.effects[static_cast<std::size_t>(p_.eq.contacts[k].rolling)].name + "' slides from the start (its slip is " + numerics::g_text(slip, 6) +
               "), against mu_k N");
          continue;
        }
        const std::size_t row = p_.contact_row(k);
        if (p_.cmu_s[k] * p_.lambda(static_cast<Eigen::Index>(row)) < std::fabs(p_.lambda(static_cast<Eigen::Index>(row + 1))) * p_.out[p_.o_cfp[k]])
          rolling_switch(k);
      }
    }
    // friction that starts without slip: sticks if it can, else slips the way the load pushes
    p_.rhs(y_.data(), t_, dydt.data());
    for (std::size_t k = 0; k < p_.eq.friction.size(); ++k) {
      auto [vx, vy] = p_.slip(k);
      double sp = std::hypot(vx, vy);
      if (sp <= vel_tol()) stick_or_slip(k, false);
      else p_.fdir[k] = {vx / sp, vy / sp};
    }
  }

  double gap_tol() const {
    // touching within rounding of the positions themselves
    return 1e-12 * std::max(scale_q(), 1.0);
  }
  double vel_tol() const {
    double s = 0;
    for (std::size_t i = 0; i < p_.n; ++i) s = std::max(s, std::fabs(y_[p_.n + i]));
    return 1e-13 * std::max(s, 1e-300);
  }

  // ---------------------------------------------------------------- the loop
  void integrate() {
    double dt = stepper_->adaptive() ? std::min(span_ * 1e-3, 1e-3) : fixed_dt_;
    // a scene without contacts, friction or a stop condition has no events to look for
    const bool watch = !p_.eq.contacts.empty() || !p_.eq.friction.empty() || !p_.limits.empty() || !p_.releases.empty() || p_.has_stop;
    std::vector<double> ev0 = watch ? events(t_, y_) : std::vector<double>{}, ev1;
    std::vector<double> vn0 = vn_last_;
    state_type y;  // the trial step (a buffer reused: no allocation per step)
    std::size_t since_progress = 0;
    while (t_ < stop_.until) {
      poll_interrupt();  // Ctrl-C from Python (common/interrupt.hpp)
      if (run_.steps >= p_.o.max_steps)
        throw SimulationError("the run took more than " + std::to_string(p_.o.max_steps) + " steps and stopped at t = " + numerics::g_text(t_, 6) + " s",
                              "loosen --tol, shorten --until, or raise the step limit");
      double remaining = stop_.until - t_;
      const double capped = p_.o.max_dt > 0 ? std::min(dt, p_.o.max_dt) : dt;
      bool last = capped >= remaining;
      double h = last ? remaining : capped;
      y = y_;
      double t = t_, hh = h;
      // a step's first call is at its start, the state accepted last: its T is taken there
      p_.watch_y = y.data();
      p_.watched = false;
      const bool stepped = stepper_->step(sys_, y, t, hh);
      p_.watch_y = nullptr;
      if (p_.watched) max_T_ = std::max(max_T_, p_.watched_T);
      if (!stepped) {
        ++run_.rejected;
        dt = hh;
        if (dt < 1e-14 * std::max(std::fabs(t_), span_))
          throw SimulationError("the step size fell to " + numerics::g_text(dt, 6) + " s at t = " + numerics::g_text(t_, 6) + " s: the motion is too stiff or singular there",
                                "loosen --tol, or look for an effect that grows without bound");
        continue;
      }
      if (last && stepper_->adaptive()) t = stop_.until;
      if (stepper_->adaptive()) dt = hh;
      if (!finite(y)) check_finite(y, "the state at t = " + numerics::g_text(t, 6) + " s");
      if (watch) ev1 = events(t, y);
      // the first event inside the step, located to the tolerance
      int which = -1;
      double when = t - t_;
      state_type ywhen;
      // (the stop condition, last, wins a tie: a state reached as a contact touches is the state)
      for (std::size_t i = 0; i < ev1.size(); ++i) {
        if (!(ev0[i] > 0 && ev1[i] <= 0)) continue;
        double s;
        state_type ys;
        locate(i, ev0[i], ev1[i], t - t_, s, ys);
        const bool is_stop = i + 1 == ev1.size();
        if (which < 0 || s < when || (is_stop && s <= when * (1 + 1e-12))) {
          which = static_cast<int>(i);
          when = s;
          ywhen = ys;
        }
      }
      std::vector<double> vn1 = vn_last_;
      // a contact that approaches and recedes inside the step (v_n from < 0 to > 0, the gap
      // positive at both ends) may have dipped below zero between: the cubic through the
      // ends' gaps and rates tells where its least gap is; a gap below zero there is a touch
      for (std::size_t k = 0; k < p_.eq.contacts.size() && which < 0; ++k) {
        if (p_.cmode[k] != ContactMode::Open || !(ev0[k] > 0 && ev1[k] > 0) || vn0.size() <= k || !(vn0[k] < 0 && vn1[k] > 0))
          continue;
        const double h = t - t_;
        double smin = 0, gmin = ev0[k];
        for (int j = 1; j < 64; ++j) {
          double u = j / 64.0, h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u), h01 = u * u * (3 - 2 * u),
                 h11 = u * u * (u - 1);
          double g = h00 * ev0[k] + h10 * h * vn0[k] + h01 * ev1[k] + h11 * h * vn1[k];
          if (g < gmin) {
            gmin = g;
            smin = u * h;
          }
        }
        if (!(gmin < 0.5 * ev0[k]) || smin <= 0) continue;
        state_type ym = advance(smin);
        double gm = events(t_ + smin, ym)[k];
        if (gm > 0) continue;
        double s;
        state_type ys;
        locate(k, ev0[k], gm, smin, s, ys);
        which = static_cast<int>(k);
        when = s;
        ywhen = ys;
      }
      ++run_.steps;
      if (which < 0) {
        if (sampling()) samples_between(t_, y_, t, y);
        t_ = t;
        y_.swap(y);
        if (after_step()) {
          if (watch) ev0 = events(t_, y_);  // projected: the state moved a little
        } else {
          ev0.swap(ev1);
          vn_last_ = vn1;
        }
        vn0 = vn_last_;
      } else {
        if (sampling()) samples_between(t_, y_, t_ + when, ywhen);
        t_ = t_ + when;
        y_ = ywhen;
        if (!handle(static_cast<std::size_t>(which))) break;  // the stop condition
        if (sampling()) record();  // after the event, at the same time (an impact's rebound)
        stepper_->reset();
        if (watch) ev0 = events(t_, y_);
        vn0 = vn_last_;
        dt = std::min(dt, next_dt_);
        next_dt_ = std::numeric_limits<double>::infinity();
      }
      if (p_.o.progress && ++since_progress >= 256) {
        since_progress = 0;
        p_.o.progress((t_ - (stop_.until - span_)) / span_);
      }
    }
    if (p_.o.progress) p_.o.progress(1.0);
  }

  double next_dt_ = std::numeric_limits<double>::infinity();
  std::vector<double> vn_last_;  ///< the contacts' normal rates at the last events() state

  /// @returns whether the state was projected (moved)
  bool after_step() {
    bool moved = project();
    // a sliding point's direction: the reference for "the slip has stopped" (v·d crosses zero)
    if (!p_.eq.friction.empty()) {
      std::vector<double> dydt(y_.size());
      p_.rhs(y_.data(), t_, dydt.data());
    }
    for (std::size_t k = 0; k < p_.eq.friction.size(); ++k) {
      if (p_.fmode[k] != FrictionMode::Slide) continue;
      auto [vx, vy] = p_.slip(k);
      double sp = std::hypot(vx, vy);
      if (sp > 0) p_.fdir[k] = {vx / sp, vy / sp};
    }
    // the largest T (the scale of the energy audit) is taken at every step: from the right-hand
    // side's kernel when its last call was at this state (a method whose last stage is the step's
    // end, as dopri5's), or at the next step's first call (a method that starts each step with a
    // call at its start: integrate() takes it; the run's end is taken by finish()), else from the
    // auxiliary kernel
    const std::size_t n = p_.n;
    const bool next_takes_it = p_.solved_in_kernel && stepper_->calls_at_start();
    if (p_.solved_in_kernel && p_.x[0] == t_ && std::equal(y_.begin(), y_.begin() + static_cast<long>(2 * n), p_.x.begin() + 1)) {
      max_T_ = std::max(max_T_, p_.out[p_.o_qdd + n]);
    } else if (!next_takes_it) {
      p_.eval_aux(t_, y_.data());
      max_T_ = std::max(max_T_, p_.T());
    }
    if (p_.o.record && !sampling()) record();
    holds_rolling();
    return moved;
  }

  // each rolling contact with μ_s: |F| ≤ μ_s |N| at the step's end (to a part in 10⁹ of μ_s |N|,
  // the equality of a contact on the point of slipping); past it the body slips, which this
  // simulation does not model
  // and each surface that can only push: N ≥ 0 (to a part in 10⁹ of the largest N seen, the
  // equality of a body on the point of leaving)
  void holds_rolling() {
    if (p_.limits.empty() && p_.releases.empty()) return;
    p_.eval_aux(t_, y_.data());
    for (std::size_t k = 0; k < p_.limits.size(); ++k) {
      double F = 0, N = 0;
      const double margin = p_.limit_margin(k, &F, &N);
      if (margin < -1e-9 * p_.limits[k].mu * std::fabs(N)) slips(k);
    }
    released_scale_.resize(p_.releases.size(), 0.0);
    for (std::size_t k = 0; k < p_.releases.size(); ++k) {
      const double N = p_.release_N(k);
      released_scale_[k] = std::max(released_scale_[k], std::fabs(N));
      if (N < -1e-9 * released_scale_[k]) leaves(k);
    }
  }
  std::vector<double> released_scale_;  ///< the largest |N| of each surface that only pushes so far
  std::vector<double> surface_scale_;   ///< the same for each contact (a freed surface's)

  // the body on surface k leaves it now (N has fallen to zero): the error, with where
  [[noreturn]] void leaves(std::size_t k) {
    const auto& l = p_.releases[k];
    const model::OneWay w = model::one_way(l.pulls, l.body, l.effect);
    const std::string fix = l.why_kept.empty() ? "the motion goes on there without it"
                                               : "the simulation cannot go on with " + l.body + " free of it: " + l.why_kept;
    throw ReleaseError(w.lets_go + " at t = " + numerics::g_text(t_, 6) + " s, " + place() + ": its " + w.force + " falls to zero there (" +
                           numerics::g_text(p_.release_N(k), 6) + " N), and " + w.only,
                       fix, l.pos, l.effect, t_, w);
  }

  // rolling contact k slips now (its F and N in aux): the error, with both numbers
  [[noreturn]] void slips(std::size_t k) {
    const auto& l = p_.limits[k];
    double F = 0, N = 0;
    p_.limit_margin(k, &F, &N);
    if (N <= 0 && l.one_sided)
      throw SlipError("'" + l.effect + "' loses its contact at t = " + numerics::g_text(t_, 6) + " s: the surface of '" + l.normal + "' would have to pull on the body (" +
                          numerics::g_text(N, 6) + " N as it presses), and holding it rolling takes a friction force of " + numerics::g_text(F, 6) + " N",
                      "the body leaves the surface there; the simulation does not go on with it free of it", l.pos);
    throw SlipError("'" + l.effect + "' slips at t = " + numerics::g_text(t_, 6) + " s: holding it takes a friction force of " + numerics::g_text(F, 6) + " N, " + numerics::g_text(F / N, 6) +
                        " times the normal force of '" + l.normal + "' (" + numerics::g_text(N, 6) + " N), and mu_s = " + numerics::g_text(l.mu, 6) +
                        " allows no more (the simulation does not go on with it sliding)",
                    "give a larger mu_s, or model the sliding: kinetic friction (a friction effect) in place of the constraint from that state on",
                    l.pos);
  }

  // ---------------------------------------------------------------- regular samples
  bool sampling() const { return p_.o.record && p_.o.sample_dt > 0; }
  double t0_ = 0;            ///< the run's start: samples at t0_ + k·sample_dt
  std::size_t next_k_ = 1;   ///< the next sample's k

  // the samples whose times fall in (ta, tb], from the cubic Hermite interpolant through the
  // step's ends: y(ta + u h) = h00 ya + h10 h ẏa + h01 yb + h11 h ẏb
  void samples_between(double ta, const state_type& ya, double tb, const state_type& yb) {
    const double dt = p_.o.sample_dt, h = tb - ta;
    if (!(h > 0)) return;
    std::vector<double> fa, fb;
    for (double tk = t0_ + static_cast<double>(next_k_) * dt; tk <= tb; tk = t0_ + static_cast<double>(++next_k_) * dt) {
      if (tk <= ta) continue;
      if (fa.empty()) {
        fa.resize(ya.size());
        fb.resize(yb.size());
        p_.rhs(ya.data(), ta, fa.data());
        p_.rhs(yb.data(), tb, fb.data());
      }
      const double u = (tk - ta) / h, h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u), h01 = u * u * (3 - 2 * u),
                   h11 = u * u * (u - 1);
      state_type y(ya.size());
      for (std::size_t i = 0; i < ya.size(); ++i) y[i] = h00 * ya[i] + h10 * h * fa[i] + h01 * yb[i] + h11 * h * fb[i];
      run_.samples.push_back(sample_at(tk, y));
    }
  }

  // The integration from (t_, y_) over s, by the same method (adaptive methods: as many
  // steps as the tolerance needs; fixed-step methods: one step of s).
  state_type advance(double s) {
    state_type y = y_;
    if (s <= 0) return y;
    auto st = make_stepper(p_);
    double t = t_, target = t_ + s, dt = s;
    if (!st->adaptive()) {
      st->step(sys_, y, t, s);
      return y;
    }
    for (int guard = 0; guard < 100000 && t < target; ++guard) {
      double rem = target - t;
      bool last = dt >= rem;
      double h = last ? rem : dt;
      if (st->step(sys_, y, t, h)) {
        if (last) t = target;
      }
      dt = h;
    }
    return y;
  }

  // Illinois (modified regula falsi) on the event's value along the step: φ(0) > 0 ≥ φ(h).
  void locate(std::size_t i, double fa, double fb, double h, double& s_out, state_type& y_out) {
    double a = 0, b = h;
    state_type yb;
    bool have_b = false;
    int side = 0;
    const double tiny = 4 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(t_) + h, 1e-300);
    for (int it = 0; it < 200 && b - a > tiny; ++it) {
      double s = b - fb * (b - a) / (fb - fa);
      if (!(s > a && s < b)) s = 0.5 * (a + b);
      state_type ys = advance(s);
      double fs = events(t_ + s, ys)[i];
      if (fs > 0) {
        a = s;
        fa = fs;
        if (side == -1) fb *= 0.5;
        side = -1;
      } else {
        b = s;
        fb = fs;
        yb = std::move(ys);
        have_b = true;
        if (side == 1) fa *= 0.5;
        side = 1;
        if (fs == 0) break;
      }
    }
    s_out = b;
    y_out = have_b ? yb : advance(b);
  }

  // ---------------------------------------------------------------- events
  // Each event's value is positive while the current mode holds: an open contact's gap, a
  // resting contact's normal force, a sliding point's v·d, a sticking point's μN − |F|, and
  // the stop condition (signed to start positive).
  // (A scene without contacts, friction or a stop condition has no events: nothing is evaluated.)
  std::vector<double> events(double t, const state_type& y) {
    std::vector<double> ev;
    const bool contacts = !p_.eq.contacts.empty(), friction = !p_.eq.friction.empty();
    if (!contacts && !friction && p_.limits.empty() && p_.releases.empty() && !p_.has_stop) return {1.0};
    std::vector<double> lam;
    if (contacts || friction) {
      std::vector<double> dydt(y.size());
      p_.rhs(y.data(), t, dydt.data());
      lam.assign(p_.lambda.data(), p_.lambda.data() + p_.lambda.size());
      vn_last_.clear();
      for (std::size_t k = 0; k < p_.eq.contacts.size(); ++k) vn_last_.push_back(p_.rate_v(p_.o_cont[k].first));
    }
    p_.eval_aux(t, y.data());
    // (a surface that only pushes, resting: its N to a part in 10⁹ of the largest N it has had, as
    // for a release below, so that a state defined by N = 0 is reached first)
    surface_scale_.resize(p_.eq.contacts.size(), 0.0);
    for (std::size_t k = 0; k < p_.eq.contacts.size(); ++k) {
      if (p_.cmode[k] == ContactMode::Open) {
        ev.push_back(p_.cgone[k] ? 1.0 : p_.aux[p_.a_gap + k]);
        continue;
      }
      const double N = p_.push(k, lam.data() + p_.contact_row(k));
      if (!p_.eq.contacts[k].surface) {
        ev.push_back(p_.eq.contacts[k].lodged ? 1.0 : N);  // (a lodged body never lets go)
        continue;
      }
      surface_scale_[k] = std::max(surface_scale_[k], std::fabs(N));
      ev.push_back(N + 1e-9 * surface_scale_[k]);
    }
    for (std::size_t k = 0; k < p_.eq.friction.size(); ++k) {
      if (p_.fmode[k] == FrictionMode::Slide) {
        auto [vx, vy] = p_.slip(k);
        ev.push_back(vx * p_.fdir[k][0] + vy * p_.fdir[k][1]);
      } else {
        auto F = stick_force(k, lam);
        ev.push_back(p_.flimit[k] - std::hypot(F[0], F[1]));
      }
    }
    // a rolling contact with μ_s: μ_s |N| − |F|, positive while it holds
    for (std::size_t k = 0; k < p_.limits.size(); ++k) ev.push_back(p_.limit_margin(k));
    // a surface that can only push: N, positive while it pushes, to a part in 10⁹ of the largest
    // N seen (so that a state defined by N = 0, where the run is to stop, is reached first)
    released_scale_.resize(p_.releases.size(), 0.0);
    for (std::size_t k = 0; k < p_.releases.size(); ++k) ev.push_back(p_.release_N(k) + 1e-9 * released_scale_[k]);
    // a rolling contact on a freed surface: sticking, μ_s N − |F| (F = λ_t |f|); sliding, its slip
    // ċ along the way it slides
    for (std::size_t k = 0; k < p_.eq.contacts.size(); ++k) {
      if (p_.cmode[k] != ContactMode::Rest || p_.eq.contacts[k].rolling < 0) {
        ev.push_back(1.0);
        continue;
      }
      const std::size_t row = p_.contact_row(k);
      if (p_.cslide[k] == 0) ev.push_back(p_.cmu_s[k] * lam[row] - std::fabs(lam[row + 1]) * p_.out[p_.o_cfp[k]]);
      else ev.push_back(p_.cslide[k] * p_.rate_v(p_.o_cont[k].second));
    }
    // a stop condition that is zero at the start (a turning point sought from rest) takes the
    // sign it has as the motion begins: the run ends at its next zero
    if (p_.has_stop && stop_sign_ == 0 && t > t_ && p_.aux[p_.a_stop] != 0) stop_sign_ = p_.aux[p_.a_stop] > 0 ? 1 : -1;
    ev.push_back(p_.has_stop && stop_sign_ != 0 ? stop_sign_ * p_.aux[p_.a_stop] : 1.0);
    return ev;
  }

  // Rolling contact k switches: sticking, it slips where μ_s N no longer holds it (it slides
  // against μ_k N, the way the slip starts: against the friction it needed); sliding, its slip
  // has stopped: it sticks again if μ_s N holds it, else slides back.
  void rolling_switch(std::size_t k) {
    std::vector<double> dydt(y_.size());
    const std::string name = p_.m.effects[static_cast<std::size_t>(p_.eq.contacts[k].rolling)].name;
    // (sticking, the event has found μ_s N − |F| reach zero, or the start found it below: it slips
    // even where, at the located instant, the two agree to rounding)
    const bool was_sliding = p_.cslide[k] != 0;
    if (was_sliding) {
      p_.cslide[k] = 0;
      project_velocity();  // the slip held at zero exactly
    }
    p_.rhs(y_.data(), t_, dydt.data());
    const std::size_t row = p_.contact_row(k);
    const double N = p_.lambda(static_cast<Eigen::Index>(row)), lt = p_.lambda(static_cast<Eigen::Index>(row + 1)), F = std::fabs(lt) * p_.out[p_.o_cfp[k]];
    if (was_sliding && F <= p_.cmu_s[k] * N) {
      note("'" + name + "' rolls: its slip has stopped, and " + numerics::g_text(F, 6) + " N <= mu_s N = " + numerics::g_text(p_.cmu_s[k] * N, 6) + " N holds it", name, "sticks");
      return;
    }
    if (p_.cmu_k[k] < 0)
      throw SlipError("'" + name + "' slips at t = " + numerics::g_text(t_, 6) + " s, " + place() + ": rolling takes a friction force of " + numerics::g_text(F, 6) + " N, " +
                          numerics::g_text(F / N, 6) + " times the normal force of '" + contact_name(k) + "' (" + numerics::g_text(N, 6) + " N), and mu_s = " +
                          numerics::g_text(p_.cmu_s[k], 6) + " allows no more",
                      "give '" + name + "' its kinetic friction, 'mu_k: 0.25', and the simulation goes on with the body sliding",
                      p_.m.effects[static_cast<std::size_t>(p_.eq.contacts[k].rolling)].pos);
    // the slip starts against the friction the rolling needed: ċ of the sign opposite to λ_t's force
    p_.cslide[k] = lt > 0 ? -1 : 1;
    note("'" + name + "' " +
             (was_sliding ? "stops slipping and slips back at " + place() + ": rolling would take a friction force of " + numerics::g_text(F, 6) +
                                " N, more than mu_s N = " + numerics::g_text(p_.cmu_s[k] * N, 6) + " N"
                          : "slips at " + place() + ": the friction force rolling takes, " + numerics::g_text(F, 6) + " N, has reached mu_s N = " +
                                numerics::g_text(p_.cmu_s[k] * N, 6) + " N") +
             "; it slides against mu_k N",
         name, "slips");
  }

  std::array<double, 2> stick_force(std::size_t k, const std::vector<double>& lam) const {
    // the friction force F = Σ λ_r c_r over the held directions c_r
    const std::size_t row = p_.friction_row(k);
    std::array<double, 2> F{0, 0};
    for (int r = 0; r < p_.frows[k]; ++r) {
      F[0] += lam[row + static_cast<std::size_t>(r)] * p_.fbasis[k](r, 0);
      F[1] += lam[row + static_cast<std::size_t>(r)] * p_.fbasis[k](r, 1);
    }
    return F;
  }

  /// @returns false when the run ends here (the stop condition).
  bool handle(std::size_t i) {
    const std::size_t nct = p_.eq.contacts.size(), nf = p_.eq.friction.size(), nl = p_.limits.size(), nr = p_.releases.size();
    p_.eval_aux(t_, y_.data());
    if (p_.o.record) record();
    if (i == nct + nf + nl + nr + nct) {
      run_.stopped = true;
      return false;
    }
    if (i >= nct + nf + nl + nr) {
      rolling_switch(i - nct - nf - nl - nr);
      return true;
    }
    if (i >= nct + nf + nl) leaves(i - nct - nf - nl);
    if (i >= nct + nf) slips(i - nct - nf);
    if (i < nct) {
      if (p_.cmode[i] == ContactMode::Open) {
        // every open contact touching and approaching now strikes together
        std::vector<double> dydt(y_.size());
        p_.rhs(y_.data(), t_, dydt.data());
        std::vector<std::size_t> strike;
        for (std::size_t k = 0; k < nct; ++k) {
          if (p_.cmode[k] != ContactMode::Open) continue;
          double gap = p_.aux[p_.a_gap + k], vn = p_.rate_v(p_.o_cont[k].first);
          if ((k == i || gap <= gap_tol()) && vn < 0) strike.push_back(k);
        }
        if (!strike.empty()) impact(strike);
        settle_contacts();
      } else {
        p_.cmode[i] = ContactMode::Open;
        if (p_.eq.contacts[i].surface) leaves_surface(i);
        else lets_go(i);
      }
      return true;
    }
    const std::size_t k = i - nct;
    if (p_.fmode[k] == FrictionMode::Slide) {
      // the slip has stopped: stick if μN can hold it, else slide back
      stick_or_slip(k, true);
    } else {
      std::vector<double> dydt(y_.size());
      p_.rhs(y_.data(), t_, dydt.data());
      auto F = stick_force(k, std::vector<double>(p_.lambda.data(), p_.lambda.data() + p_.lambda.size()));
      double mag = std::hypot(F[0], F[1]);
      p_.fmode[k] = FrictionMode::Slide;
      p_.fdir[k] = {-F[0] / mag, -F[1] / mag};
      note("friction '" + friction_name(k) + "' slips (the load exceeds " + numerics::g_text(p_.flimit[k], 6) + ")", friction_name(k), "slips");
    }
    return true;
  }

  // Stick: hold the slip velocity at zero along the directions the point can slip in (one
  // or two; none when it cannot move), if the force that takes is within μN; else slide the
  // way the load pushes.
  void stick_or_slip(std::size_t k, bool stopped) {
    const std::size_t n = p_.n;
    std::vector<double> dydt(y_.size());
    p_.rhs(y_.data(), t_, dydt.data());
    p_.fill_M();
    auto [rx, ry] = p_.o_fric[k];
    const bool rot = p_.eq.friction[k].rotary;
    Mat J(rot ? 1 : 2, static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
      J(0, static_cast<Eigen::Index>(i)) = p_.rate_J(rx)[i];
      if (!rot) J(1, static_cast<Eigen::Index>(i)) = p_.rate_J(ry)[i];
    }
    p_.ldlt.compute(p_.M);
    Mat G = J * p_.ldlt.solve(J.transpose());  // J M⁻¹ Jᵀ: how freely the point slips each way
    p_.fbasis[k].setZero();
    if (rot) {
      p_.frows[k] = G(0, 0) > 0 ? 1 : 0;
      p_.fbasis[k](0, 0) = 1;
    } else {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(G.topLeftCorner<2, 2>());
      auto ev = es.eigenvalues();
      if (ev(1) <= 0) {
        p_.frows[k] = 0;
      } else if (ev(0) <= 1e-10 * ev(1)) {
        p_.frows[k] = 1;  // the point can slip along one line only
        p_.fbasis[k].row(0) = es.eigenvectors().col(1).transpose();
      } else {
        p_.frows[k] = 2;
        p_.fbasis[k] = Eigen::Matrix2d::Identity();
      }
    }
    p_.fmode[k] = FrictionMode::Stick;
    // the velocity held at zero exactly
    if (p_.frows[k] > 0) project_velocity();
    p_.rhs(y_.data(), t_, dydt.data());
    auto F = stick_force(k, std::vector<double>(p_.lambda.data(), p_.lambda.data() + p_.lambda.size()));
    double mag = std::hypot(F[0], F[1]);
    if (mag <= p_.flimit[k]) {
      if (stopped)
        note("friction '" + friction_name(k) + "' sticks: the slip has stopped and " + numerics::g_text(mag, 6) + " <= " + numerics::g_text(p_.flimit[k], 6) + " holds it",
             friction_name(k), "sticks");
      return;
    }
    p_.fmode[k] = FrictionMode::Slide;
    p_.fdir[k] = {-F[0] / mag, -F[1] / mag};
    if (stopped)
      note("friction '" + friction_name(k) + "' reverses: the slip stopped, but holding it takes " + numerics::g_text(mag, 6) + " > " + numerics::g_text(p_.flimit[k], 6),
           friction_name(k), "slips");
  }

  // ---------------------------------------------------------------- impacts
  // A jump of the rates: M (q̇⁺ − q̇⁻) = P + Gᵀ Λ with rows G q̇⁺ = w: the constraints
  // (unchanged), resting contacts (held), and the striking contacts (v_n⁺ = −e v_n⁻; rough
  // ones also v_t⁺ = 0). Returns Λ for the rows of `strike` (normal, then tangent when rough).
  Vec jump(const Vec& P, const std::vector<std::size_t>& strike, const std::vector<double>& e) {
    const std::size_t n = p_.n;
    std::vector<double> dydt(y_.size());
    p_.rhs(y_.data(), t_, dydt.data());
    p_.fill_M();
    p_.eval_aux(t_, y_.data());
    p_.constraint_rows();  // holonomic, sticking friction, resting contacts
    // friction forces are finite: they do not hold against an impulse
    Mat Bh = p_.B;
    std::vector<Eigen::Index> keep;
    for (std::size_t c = 0; c < p_.nc; ++c) keep.push_back(static_cast<Eigen::Index>(c));
    for (std::size_t k = 0; k < p_.eq.contacts.size(); ++k)
      for (std::size_t r = 0; r < p_.contact_rows(k); ++r) keep.push_back(static_cast<Eigen::Index>(p_.contact_row(k) + r));
    std::size_t rows = keep.size();
    for (std::size_t k : strike) rows += p_.eq.contacts[k].stick ? 2 : 1;
    Mat G(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(n));
    Vec w(static_cast<Eigen::Index>(rows));
    Eigen::Index r = 0;
    for (std::size_t c = 0; c < keep.size(); ++c, ++r) {
      G.row(r) = Bh.row(keep[c]);
      w(r) = c < p_.nc ? -p_.aux[p_.a_gt + c] : 0.0;
    }
    for (std::size_t j = 0; j < strike.size(); ++j) {
      auto [rn, rt] = p_.o_cont[strike[j]];
      for (std::size_t i = 0; i < n; ++i) G(r, static_cast<Eigen::Index>(i)) = p_.rate_J(rn)[i];
      // Newton's law of restitution: v_n⁺ = −e v_n⁻ (v_n = J q̇ + b; b = v_n − J q̇)
      double vn = p_.rate_v(rn), Jq = G.row(r).dot(Eigen::Map<const Vec>(y_.data() + n, static_cast<Eigen::Index>(n)));
      w(r++) = -e[j] * vn - (vn - Jq);
      if (p_.eq.contacts[strike[j]].stick) {
        for (std::size_t i = 0; i < n; ++i) G(r, static_cast<Eigen::Index>(i)) = p_.rate_J(rt)[i];
        double vt = p_.rate_v(rt), Jt = G.row(r).dot(Eigen::Map<const Vec>(y_.data() + n, static_cast<Eigen::Index>(n)));
        w(r++) = -(vt - Jt);
      }
    }
    Eigen::Map<Vec> qd(y_.data() + n, static_cast<Eigen::Index>(n));
    Vec rhs = p_.M * qd + P;
    Vec out, lam;
    p_.solve_kkt(rhs, G, w, out, lam, t_);
    qd = out;
    return lam.tail(static_cast<Eigen::Index>(rows - keep.size()));
  }

  void impact(std::vector<std::size_t> strike) {
    const std::size_t n = p_.n;
    for (int attempt = 0; attempt < 8 && !strike.empty(); ++attempt) {
      state_type before = y_;
      std::vector<double> dydt(y_.size());
      p_.rhs(y_.data(), t_, dydt.data());
      p_.eval_aux(t_, y_.data());
      Impact im;
      im.t = t_;
      im.T_before = p_.T();
      std::vector<double> e, vt_before;
      for (std::size_t k : strike) {
        if (p_.ce[k] < 0)
          throw SimulationError((words(k).verb == "leaves" ? surface_body(k) + " strikes '" + contact_name(k) + "' again"
                                                           : "cord '" + contact_name(k) + "' snaps taut") +
                                    " at t = " + numerics::g_text(t_, 6) + " s, " + place() + ", and the track does not say how it rebounds",
                                "give the track its coefficient of restitution, 'e: 0' (it lands and stays) to 'e: 1'",
                                p_.m.effects[p_.eq.contacts[k].effect].pos);
        e.push_back(p_.ce[k]);
        im.contacts.push_back(contact_name(k));
        im.vn_before.push_back(p_.rate_v(p_.o_cont[k].first));
        vt_before.push_back(p_.rate_v(p_.o_cont[k].second));
      }
      Vec lam = jump(Vec::Zero(static_cast<Eigen::Index>(n)), strike, e);
      // a contact can only push: one whose impulse comes out pulling is not in the impact
      std::vector<std::size_t> keep;
      Eigen::Index r = 0;
      double Pmax = lam.cwiseAbs().maxCoeff();
      bool pulls = false;
      for (std::size_t k : strike) {
        if (lam(r) < -1e-12 * Pmax) pulls = true;
        else keep.push_back(k);
        r += p_.eq.contacts[k].stick ? 2 : 1;
      }
      if (pulls) {
        y_ = before;
        strike = keep;
        continue;
      }
      p_.rhs(y_.data(), t_, dydt.data());
      p_.eval_aux(t_, y_.data());
      im.T_after = p_.T();
      // energy lost: −½ Σ P (v⁻ + v⁺) over the contact rows (the work of the impulses)
      r = 0;
      for (std::size_t j = 0; j < strike.size(); ++j) {
        auto [rn, rt] = p_.o_cont[strike[j]];
        double vn_after = p_.rate_v(rn);
        im.vn_after.push_back(vn_after);
        im.impulse.push_back(lam(r));
        im.loss += -0.5 * lam(r) * (im.vn_before[j] + vn_after);
        ++r;
        if (p_.eq.contacts[strike[j]].stick) {
          im.loss += -0.5 * lam(r) * (vt_before[j] + p_.rate_v(rt));
          ++r;
        }
      }
      run_.impact_loss += im.loss;
      run_.impacts.push_back(im);
      for (std::size_t k : strike)
        if (p_.eq.contacts[k].surface)
          note(words(k).verb == "leaves" ? surface_body(k) + " strikes '" + contact_name(k) + "' at " + place() + " (e = " + numerics::g_text(p_.ce[k], 6) + ")"
                                         : "cord '" + contact_name(k) + "' snaps taut at " + place() + " (e = " + numerics::g_text(p_.ce[k], 6) + ")",
               contact_name(k), words(k).verb == "leaves" ? "strikes" : "taut");
      // what follows: rest (e = 0, or a bounce too short to resolve), or a flight
      for (std::size_t j = 0; j < strike.size(); ++j) {
        std::size_t k = strike[j];
        double vn = im.vn_after[j];
        if (p_.ce[k] == 0 || vn <= 0) {
          p_.rest(k);
          continue;
        }
        // the normal acceleration in free flight: the next touch after about 2 v_n / |a_n|
        p_.cmode[k] = ContactMode::Open;
        p_.rhs(y_.data(), t_, dydt.data());
        auto [rn, rt] = p_.o_cont[k];
        double an = p_.rate_a0(rn);
        for (std::size_t i = 0; i < n; ++i) an += p_.rate_J(rn)[i] * dydt[n + i];
        if (an < 0) {
          double flight = 2 * vn / -an, apex = vn * vn / (2 * -an);
          next_dt_ = std::min(next_dt_, flight / 8);
          if (flight < p_.rest_time || apex < gap_tol()) {
            // the bounce would last less than the time resolution, or rise less than the
            // positions can resolve: end the bounces with a plastic impact now (its loss is
            // counted) and let the contact rest
            Vec l2 = jump(Vec::Zero(static_cast<Eigen::Index>(n)), {k}, {0.0});
            p_.rhs(y_.data(), t_, dydt.data());
            double after2 = p_.rate_v(rn);
            Impact rest;
            rest.t = t_;
            rest.contacts = {contact_name(k)};
            rest.vn_before = {vn};
            rest.vn_after = {after2};
            rest.impulse = {l2(0)};
            rest.loss = -0.5 * l2(0) * (vn + after2);
            rest.comes_to_rest = true;
            run_.impact_loss += rest.loss;
            run_.impacts.push_back(rest);
            p_.rest(k);
            note("contact '" + contact_name(k) + "' comes to rest (the next bounce would last " + numerics::g_text(flight, 6) + " s and rise " +
                 numerics::g_text(apex, 6) + " m)");
          }
        }
      }
      return;
    }
  }

  // Contact k lets go (its push has fallen to zero). One whose surface turns with a body (a
  // wheel's rim about the corner it pivoted on) is not looked for again: its gap is measured at
  // the material point that struck, which says where the surface is only while they touch.
  void lets_go(std::size_t k) {
    if (!p_.eq.contacts[k].turn.is_zero()) {
      p_.cgone[k] = 1;
      const model::Effect& e = p_.m.effects[p_.eq.contacts[k].effect];
      const auto r = e.reaction(p_.m);
      const std::string body = r && r->turns >= 0 ? p_.m.bodies[static_cast<std::size_t>(r->turns)].name : "its body";
      note(body + " lets go of '" + contact_name(k) + "' at " + place() + " (its normal force reached zero); a strike on it again is not looked for (" +
               body + "'s surface there has turned away from the point that struck)",
           contact_name(k), "lets go");
      return;
    }
    note("contact '" + contact_name(k) + "' lets go (its normal force reached zero)", contact_name(k), "lets go");
  }

  // resting contacts that pull let go; the others stay (their normal force is ≥ 0)
  void settle_contacts() {
    for (int pass = 0; pass < 4; ++pass) {
      std::vector<double> dydt(y_.size());
      p_.rhs(y_.data(), t_, dydt.data());
      // (the rows as solved: the modes change only after every contact has been looked at)
      std::vector<std::size_t> row(p_.eq.contacts.size());
      for (std::size_t k = 0; k < row.size(); ++k) row[k] = p_.contact_row(k);
      bool changed = false;
      for (std::size_t k = 0; k < p_.eq.contacts.size(); ++k) {
        if (p_.cmode[k] != ContactMode::Rest || p_.eq.contacts[k].lodged) continue;
        if (p_.push(k, p_.lambda.data() + row[k]) < 0) {
          p_.cmode[k] = ContactMode::Open;
          changed = true;
          if (p_.eq.contacts[k].surface) leaves_surface(k);
          else lets_go(k);
        }
      }
      if (!changed) return;
    }
  }

  // ---------------------------------------------------------------- projection
  // Back onto the constraints after a step: positions by Newton steps on g(q) = 0 (and the
  // gaps of resting contacts), rates so that A q̇ + ∂g/∂t = 0, each the M-orthogonal (least
  // kinetic energy) correction  δ = −M⁻¹ Jᵀ (J M⁻¹ Jᵀ)⁻¹ r.
  bool project() {
    if (!p_.rows_active()) return false;
    const std::size_t n = p_.n;
    for (int it = 0; it < 3; ++it) {
      std::vector<double> dydt(y_.size());
      p_.rhs(y_.data(), t_, dydt.data());
      p_.eval_aux(t_, y_.data());
      std::vector<Vec> rows;
      std::vector<double> res;
      for (std::size_t c = 0; c < p_.nc; ++c) {
        Vec a(static_cast<Eigen::Index>(n));
        for (std::size_t i = 0; i < n; ++i) a(static_cast<Eigen::Index>(i)) = p_.out[p_.o_A + c * n + i];
        rows.push_back(a);
        res.push_back(p_.aux[p_.a_g + c]);
      }
      for (std::size_t k = 0; k < p_.eq.contacts.size(); ++k) {
        if (p_.cmode[k] != ContactMode::Rest) continue;
        Vec a(static_cast<Eigen::Index>(n));
        for (std::size_t i = 0; i < n; ++i) a(static_cast<Eigen::Index>(i)) = p_.rate_J(p_.o_cont[k].first)[i];
        rows.push_back(a);
        res.push_back(p_.aux[p_.a_gap + k]);
      }
      if (rows.empty()) break;
      double worst = 0;
      for (double v : res) worst = std::max(worst, std::fabs(v));
      if (worst <= 1e-15 * std::max(1.0, scale_q())) break;
      correct(rows, res, 0);
    }
    project_velocity();
    return true;
  }

  double scale_q() const {
    double s = 0;
    for (std::size_t i = 0; i < p_.n; ++i) s = std::max(s, std::fabs(y_[i]));
    return s;
  }

  void project_velocity() {
    const std::size_t n = p_.n;
    std::vector<double> dydt(y_.size());
    p_.rhs(y_.data(), t_, dydt.data());
    p_.eval_aux(t_, y_.data());
    p_.constraint_rows();
    if (p_.B.rows() == 0) return;
    // residual B q̇ + b₀ with b₀ the velocity offsets (∂g/∂t of the holonomic rows)
    std::vector<Vec> rows;
    std::vector<double> res;
    Eigen::Map<const Vec> qd(y_.data() + n, static_cast<Eigen::Index>(n));
    for (Eigen::Index r = 0; r < p_.B.rows(); ++r) {
      rows.push_back(p_.B.row(r).transpose());
      double off = static_cast<std::size_t>(r) < p_.nc ? p_.aux[p_.a_gt + static_cast<std::size_t>(r)] : 0.0;
      // a row of a sticking point or a resting contact: its velocity v = J q̇ + b
      res.push_back(p_.B.row(r).dot(qd) + off);
    }
    // the rows of velocities with an explicit offset b (moving supports): use v itself
    std::size_t row = p_.nc;
    for (std::size_t k = 0; k < p_.eq.friction.size(); ++k) {
      if (p_.fmode[k] != FrictionMode::Stick) continue;
      auto [vx, vy] = p_.slip(k);
      for (int s = 0; s < p_.frows[k]; ++s, ++row) res[row] = p_.fbasis[k](s, 0) * vx + p_.fbasis[k](s, 1) * vy;
    }
    for (std::size_t k = 0; k < p_.eq.contacts.size(); ++k) {
      if (p_.cmode[k] != ContactMode::Rest) continue;
      auto [rn, rt] = p_.o_cont[k];
      res[row++] = p_.rate_v(rn);
      if (p_.eq.contacts[k].stick && p_.cslide[k] == 0) res[row++] = p_.rate_v(rt);
    }
    correct(rows, res, n);
  }

  // y[off .. off+n) −= M⁻¹ Jᵀ (J M⁻¹ Jᵀ)⁺ r
  void correct(const std::vector<Vec>& rows, const std::vector<double>& res, std::size_t off) {
    const auto n = static_cast<Eigen::Index>(p_.n);
    Mat J(static_cast<Eigen::Index>(rows.size()), n);
    Vec r(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      J.row(static_cast<Eigen::Index>(i)) = rows[i].transpose();
      r(static_cast<Eigen::Index>(i)) = res[i];
    }
    p_.fill_M();
    Eigen::LDLT<Mat> l(p_.M);
    Mat X = l.solve(J.transpose());
    Mat S = J * X;
    Eigen::CompleteOrthogonalDecomposition<Mat> cod(S);
    Vec d = X * cod.solve(r);
    for (Eigen::Index i = 0; i < n; ++i) y_[off + static_cast<std::size_t>(i)] -= d(i);
  }

  // ---------------------------------------------------------------- records
  // the state now, with its energies
  Sample sample() { return sample_at(t_, y_); }
  Sample sample_at(double t, const state_type& y) {
    p_.eval_aux(t, y.data());
    const auto n = static_cast<long>(p_.n);
    return Sample{t, std::vector<double>(y.begin(), y.begin() + n), std::vector<double>(y.begin() + n, y.begin() + 2 * n),
                  p_.T(), p_.V()};
  }
  void record() { run_.samples.push_back(sample()); }

  void finish() {
    const std::size_t n = p_.n;
    run_.end = sample();
    if (run_.samples.empty() || run_.samples.back().t != t_) run_.samples.push_back(run_.end);
    run_.E1 = p_.T() + p_.V();
    max_T_ = std::max(max_T_, p_.T());
    double U = impulse_work_;
    if (stop_.impulses && !p_.eq.impulses.empty()) run_.work.emplace_back("given impulses", impulse_work_);
    for (auto& [name, k] : p_.work_names) {
      run_.work.emplace_back(name, y_[2 * n + k]);
      U += y_[2 * n + k];
    }
    run_.conservative = p_.work_names.empty() && run_.impacts.empty() && (p_.eq.impulses.empty() || !stop_.impulses);
    run_.energy_scale = std::max(std::fabs(run_.E0), max_T_);
    if (run_.energy_scale == 0) run_.energy_scale = 1;
    // E₁ = E₀ + Σ U − Σ impact losses, up to the integration error
    run_.drift = (run_.E1 - run_.E0 - U + run_.impact_loss) / run_.energy_scale;
    run_.rhs_calls = p_.rhs_calls;
  }
};

}  // namespace

Run Simulator::Impl::run(const State& s0, const Stop& stop) {
  // the auxiliary kernel is compiled again only when the stop condition changes
  if (!(aux_when.has_value() == stop.when.has_value() && (!stop.when || aux_when->is_equal(*stop.when)))) {
    build_aux(stop.when);
    aux_when = stop.when;
  }
  rhs_calls = 0;
  fmode.assign(eq.friction.size(), FrictionMode::Slide);
  cmode.assign(eq.contacts.size(), ContactMode::Open);
  cslide.assign(eq.contacts.size(), 0);
  Runner r(*this, stop);
  // a start in the scene's coordinates: every gap closed (the bodies on their surfaces)
  State s = s0;
  if (s.q.size() == scene_n && s.qd.size() == scene_n && n > scene_n) {
    s.q.resize(n, 0.0);
    s.qd.resize(n, 0.0);
  }
  Run run = r.go(s);
  run.model = freed_model;
  return run;
}

}  // namespace kinergy::simulate
