// Time integration of the equations of motion, with the switching parts of a scene as events.
#include "kinergy/simulate/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "impl.hpp"

namespace kinergy::simulate {


Method method_from_name(const std::string& s) {
  if (s == "dopri5") return Method::Dopri5;
  if (s == "rkf78") return Method::Rkf78;
  if (s == "bs" || s == "bulirsch_stoer") return Method::BulirschStoer;
  if (s == "symplectic") return Method::Symplectic;
  if (s == "rk4") return Method::Rk4;
  throw InputError("no integration method '" + s + "'", "choose dopri5, rkf78, bs (Bulirsch-Stoer), symplectic or rk4");
}

std::string method_name(Method m) {
  switch (m) {
    case Method::Dopri5: return "dopri5";
    case Method::Rkf78: return "rkf78";
    case Method::BulirschStoer: return "bs";
    case Method::Symplectic: return "symplectic";
    case Method::Rk4: return "rk4";
  }
  return "?";
}

Simulator::Simulator(const model::Model& m, const exmap& values, const Options& o)
    : p_(std::make_unique<Impl>(m, values, o)) {}
Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;
const Equations& Simulator::equations() const { return p_->eq; }
const model::Model& Simulator::model() const { return p_->m; }
std::size_t Simulator::size() const { return 2 * p_->n + p_->nw; }
void Simulator::rhs(const double* y, double t, double* dydt) { p_->rhs(y, t, dydt); }
void Simulator::modes_at(const double* y, double t) {
  Impl& p = *p_;
  std::vector<double> dy(size());
  p.rhs(y, t, dy.data());  // (the contacts' rates at y)
  p.eval_aux(t, y);
  double sq = 1, sv = 1e-300;
  for (std::size_t i = 0; i < p.n; ++i) sq = std::max(sq, std::fabs(y[i])), sv = std::max(sv, std::fabs(y[p.n + i]));
  for (std::size_t k = 0; k < p.eq.contacts.size(); ++k)
    if (std::fabs(p.aux[p.a_gap + k]) <= 1e-9 * sq && std::fabs(p.rate_v(p.o_cont[k].first)) <= 1e-9 * sv) p.rest(k);
  // a friction that slips at y: sliding, against that slip, F = −μN v̂ (its rates were laid out by
  // the rhs call above)
  std::vector<std::size_t> at_rest;
  for (std::size_t k = 0; k < p.eq.friction.size(); ++k) {
    const auto v = p.slip(k);
    const double sp = std::hypot(v[0], v[1]);
    if (!(sp > 0)) {
      at_rest.push_back(k);
      continue;
    }
    p.fmode[k] = FrictionMode::Slide;
    p.fdir[k] = {v[0] / sp, v[1] / sp};
  }
  // a friction at rest at y (a body just released against its bearing's couple): against the
  // slip that starts there, the way the other loads push it, a_slip = J q̈ + J̇ q̇ with this
  // friction left out. (Where it holds the body at rest, there is no kinetics to check: the
  // analysis refuses that state.)
  for (std::size_t k : at_rest) {
    const double keep = p.flimit[k];
    p.flimit[k] = 0;
    p.rhs(y, t, dy.data());
    p.flimit[k] = keep;
    const auto [rx, ry] = p.o_fric[k];
    const bool rot = p.eq.friction[k].rotary;
    double ax = p.rate_a0(rx), ay = rot ? 0.0 : p.rate_a0(ry);
    for (std::size_t i = 0; i < p.n; ++i) {
      ax += p.rate_J(rx)[i] * dy[p.n + i];
      if (!rot) ay += p.rate_J(ry)[i] * dy[p.n + i];
    }
    const double a = std::hypot(ax, ay);
    if (!(a > 0)) continue;
    p.fmode[k] = FrictionMode::Slide;
    p.fdir[k] = {ax / a, ay / a};
  }
}
Run Simulator::run(const State& s0, const Stop& stop) { return p_->run(s0, stop); }

}  // namespace kinergy::simulate
