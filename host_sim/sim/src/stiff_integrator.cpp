/// @file stiff_integrator.cpp
/// Boost.Odeint rosenbrock4 driver with hard stops and dense sampling (see header).

#include "hstmon_sim/stiff_integrator.hpp"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace hstmon::sim {

namespace odeint = boost::numeric::odeint;
namespace ublas = boost::numeric::ublas;

namespace {

using Stepper = odeint::rosenbrock4<double>;
using Controller = odeint::rosenbrock4_controller<Stepper>;
using UVector = Stepper::state_type;
using UMatrix = Stepper::matrix_type;

/// f in scaled coordinates z = x / s: dz/dt = f(s·z) / s.
struct ScaledRhs {
  const StiffIntegrator::Rhs* rhs;
  const std::vector<double>* scale;
  std::vector<double>* x;
  std::vector<double>* f;
  void operator()(const UVector& z, UVector& dzdt, double /*t*/) const {
    const std::size_t n = scale->size();
    for (std::size_t i = 0; i < n; ++i) (*x)[i] = z[i] * (*scale)[i];
    (*rhs)(x->data(), f->data());
    for (std::size_t i = 0; i < n; ++i) dzdt[i] = (*f)[i] / (*scale)[i];
  }
};

/// Jacobian in scaled coordinates: Jz_ij = J_ij·s_j / s_i; ∂f/∂t = 0 (autonomous segment).
struct ScaledJacobian {
  const StiffIntegrator::Jacobian* jac;
  const std::vector<double>* scale;
  std::vector<double>* x;
  std::vector<double>* j;
  void operator()(const UVector& z, UMatrix& jz, const double& /*t*/, UVector& dfdt) const {
    const std::size_t n = scale->size();
    for (std::size_t i = 0; i < n; ++i) (*x)[i] = z[i] * (*scale)[i];
    (*jac)(x->data(), j->data());
    for (std::size_t r = 0; r < n; ++r) {
      for (std::size_t c = 0; c < n; ++c) jz(r, c) = (*j)[r * n + c] * (*scale)[c] / (*scale)[r];
      dfdt[r] = 0.0;
    }
  }
};

bool all_finite(const UVector& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

}  // namespace

struct StiffIntegrator::Impl {
  std::vector<double> scale;  // per-state absolute tolerance = scaling of z
  double rel_tol;
  double initial_step;
  double max_step;

  Rhs rhs;
  Jacobian jac;
  std::optional<Controller> controller;  // not assignable: re-emplaced at each restart
  bool started = false;
  double t = 0.0;
  double dt = 0.0;  // next trial step
  UVector z, z_new, z_dense;
  std::vector<double> x_buf, f_buf, j_buf, x_out;
  mutable std::vector<double> x_state;
  IntegratorStats stats;

  void to_x(const UVector& zz, std::vector<double>& out) const {
    for (std::size_t i = 0; i < scale.size(); ++i) out[i] = zz[i] * scale[i];
  }
};

StiffIntegrator::StiffIntegrator(std::vector<double> abs_tol, double rel_tol, double initial_step,
                                 double max_step)
    : impl_(std::make_unique<Impl>()) {
  if (abs_tol.empty()) throw std::invalid_argument("StiffIntegrator: no states");
  for (double a : abs_tol) {
    if (!(std::isfinite(a) && a > 0.0)) throw std::invalid_argument("StiffIntegrator: abs_tol must be > 0");
  }
  if (!(std::isfinite(rel_tol) && rel_tol > 0.0)) throw std::invalid_argument("StiffIntegrator: rel_tol must be > 0");
  if (!(std::isfinite(initial_step) && initial_step > 0.0)) {
    throw std::invalid_argument("StiffIntegrator: initial_step must be > 0");
  }
  if (!(std::isfinite(max_step) && max_step >= 0.0)) throw std::invalid_argument("StiffIntegrator: max_step must be >= 0");
  Impl& m = *impl_;
  const std::size_t n = abs_tol.size();
  m.scale = std::move(abs_tol);
  m.rel_tol = rel_tol;
  m.initial_step = initial_step;
  m.max_step = max_step;
  m.z.resize(n);
  m.z_new.resize(n);
  m.z_dense.resize(n);
  m.x_buf.resize(n);
  m.f_buf.resize(n);
  m.j_buf.resize(n * n);
  m.x_out.resize(n);
  m.x_state.resize(n);
}

StiffIntegrator::~StiffIntegrator() = default;
StiffIntegrator::StiffIntegrator(StiffIntegrator&&) noexcept = default;
StiffIntegrator& StiffIntegrator::operator=(StiffIntegrator&&) noexcept = default;

std::size_t StiffIntegrator::size() const noexcept { return impl_->scale.size(); }

void StiffIntegrator::restart(double t, const double* x, Rhs rhs, Jacobian jac) {
  Impl& m = *impl_;
  if (!rhs || !jac) throw std::invalid_argument("StiffIntegrator::restart: empty rhs or Jacobian");
  if (!std::isfinite(t)) throw std::invalid_argument("StiffIntegrator::restart: non-finite time");
  for (std::size_t i = 0; i < m.scale.size(); ++i) {
    if (!std::isfinite(x[i])) throw std::invalid_argument("StiffIntegrator::restart: non-finite state");
    m.z[i] = x[i] / m.scale[i];
  }
  m.rhs = std::move(rhs);
  m.jac = std::move(jac);
  // A fresh controller forgets the error history of the previous segment.
  m.controller.emplace(1.0, m.rel_tol, m.max_step);
  m.t = t;
  m.dt = m.max_step > 0.0 ? std::min(m.initial_step, m.max_step) : m.initial_step;
  m.started = true;
  ++m.stats.restarts;
}

void StiffIntegrator::advance_to(double t_end, const std::vector<double>& sample_times,
                                 const Sampler& on_sample) {
  Impl& m = *impl_;
  if (!m.started) throw std::logic_error("StiffIntegrator::advance_to before restart");
  if (!(t_end >= m.t)) throw std::invalid_argument("StiffIntegrator::advance_to: t_end before current time");

  ScaledRhs f{&m.rhs, &m.scale, &m.x_buf, &m.f_buf};
  ScaledJacobian jf{&m.jac, &m.scale, &m.x_buf, &m.j_buf};
  auto system = std::make_pair(f, jf);

  // First sample strictly after the current time.
  auto next_sample = std::upper_bound(sample_times.begin(), sample_times.end(), m.t);
  const double eps = std::numeric_limits<double>::epsilon();

  while (m.t < t_end) {
    const double remaining = t_end - m.t;
    const bool clamped = m.dt >= remaining;
    double dt_try = clamped ? remaining : m.dt;
    double t_try = m.t;
    const odeint::controlled_step_result res = m.controller->try_step(system, m.z, t_try, m.z_new, dt_try);
    if (res == odeint::fail) {
      ++m.stats.rejected;
      m.dt = dt_try;
      if (!(m.dt > 8.0 * eps * std::max(1.0, std::fabs(m.t)))) {
        throw std::runtime_error("StiffIntegrator: step size underflow at t = " + std::to_string(m.t));
      }
      continue;
    }
    if (!all_finite(m.z_new)) {
      throw std::runtime_error("StiffIntegrator: non-finite state at t = " + std::to_string(m.t));
    }
    const double t_old = m.t;
    const double t_new = clamped ? t_end : t_try;  // a hard stop ends exactly at t_end
    const double h = t_new - t_old;
    ++m.stats.accepted;
    m.stats.min_step = (m.stats.accepted == 1) ? h : std::min(m.stats.min_step, h);
    m.stats.max_step = std::max(m.stats.max_step, h);

    if (on_sample && next_sample != sample_times.end() && *next_sample <= t_new) {
      m.controller->stepper().prepare_dense_output();
      for (; next_sample != sample_times.end() && *next_sample <= t_new; ++next_sample) {
        if (*next_sample == t_new) {
          m.to_x(m.z_new, m.x_out);
        } else {
          m.controller->stepper().calc_state(*next_sample, m.z_dense, m.z, t_old, m.z_new, t_new);
          m.to_x(m.z_dense, m.x_out);
        }
        on_sample(*next_sample, m.x_out.data());
      }
    }
    m.z.swap(m.z_new);
    m.t = t_new;
    // dt_try is the controller's suggestion after this step. A step shortened to hit t_end
    // says little about the step the solution allows, so keep the larger proposal.
    m.dt = clamped ? std::max(m.dt, dt_try) : dt_try;
  }
}

double StiffIntegrator::time() const noexcept { return impl_->t; }

double StiffIntegrator::next_step() const noexcept { return impl_->dt; }

void StiffIntegrator::restart(double t, const double* x, Rhs rhs, Jacobian jac, double first_step) {
  if (!(std::isfinite(first_step) && first_step > 0.0)) {
    throw std::invalid_argument("StiffIntegrator::restart: first_step must be > 0");
  }
  restart(t, x, std::move(rhs), std::move(jac));
  Impl& m = *impl_;
  m.dt = m.max_step > 0.0 ? std::min(first_step, m.max_step) : first_step;
}

const std::vector<double>& StiffIntegrator::state() const noexcept {
  impl_->to_x(impl_->z, impl_->x_state);
  return impl_->x_state;
}

const IntegratorStats& StiffIntegrator::stats() const noexcept { return impl_->stats; }

}  // namespace hstmon::sim
