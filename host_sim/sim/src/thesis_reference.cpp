/// @file thesis_reference.cpp
#include "hstmon_sim/thesis_reference.hpp"

#include <cmath>
#include <stdexcept>

#include "hstmon/thesis_model.hpp"
#include "hstmon/circuit/thesis_circuit_model.hpp"

namespace hstmon::sim {

namespace {

std::vector<double> thesis_abs_tol(const ReferenceTolerances& tol) {
  return {tol.abs_pressure, tol.abs_pressure, tol.abs_pressure, tol.abs_speed};
}

bool same_inputs(const ThesisInputs<double>& a, const ThesisInputs<double>& b) {
  return a.Psupl == b.Psupl && a.Ps == b.Ps && a.Pbp == b.Pbp && a.kp == b.kp;
}

}  // namespace

ThesisReference::ThesisReference(const Params& p, const State& x0, double t0, const ReferenceTolerances& tol)
    : p_(p), integ_(thesis_abs_tol(tol), tol.rel, tol.initial_step, tol.max_step) {
  if (!ThesisCircuitModel<double>::params_valid(p)) {
    throw std::invalid_argument("ThesisReference: invalid parameters");
  }
  reset(x0, t0);
}

void ThesisReference::reset(const State& x, double t) {
  if (!(std::isfinite(x.Pmi) && std::isfinite(x.Pmo) && std::isfinite(x.Ppp) && std::isfinite(x.w_m) &&
        std::isfinite(t))) {
    throw std::invalid_argument("ThesisReference: non-finite state or time");
  }
  x_pending_ = x;
  t_pending_ = t;
  segment_open_ = false;
}

void ThesisReference::begin_segment(const Inputs& u) {
  if (!ThesisCircuitModel<double>::inputs_valid(u)) {
    throw std::invalid_argument("ThesisReference: non-finite inputs or kp < 0");
  }
  if (segment_open_ && same_inputs(u, u_)) return;
  const State x0 = segment_open_ ? state() : x_pending_;
  const double t0 = segment_open_ ? integ_.time() : t_pending_;
  u_ = u;
  const Params p = p_;
  double v[4];
  to_array(x0, v);
  integ_.restart(
      t0, v,
      [p, u](const double* x, double* dxdt) {
        const State d = thesis_derivative(p, u, thesis_state_from(x));
        to_array(d, dxdt);
      },
      [p, u](const double* x, double* jac) {
        double j[4][4];
        thesis_jacobian(p, u, thesis_state_from(x), j);
        for (int r = 0; r < 4; ++r) {
          for (int c = 0; c < 4; ++c) jac[r * 4 + c] = j[r][c];
        }
      });
  segment_open_ = true;
}

void ThesisReference::advance_to(double t_end, const Inputs& u) { advance_to(t_end, u, {}, {}); }

void ThesisReference::advance_to(double t_end, const Inputs& u, const std::vector<double>& sample_times,
                                 const Sampler& on_sample) {
  if (!(t_end >= time())) throw std::invalid_argument("ThesisReference::advance_to: t_end before current time");
  begin_segment(u);
  if (on_sample) {
    integ_.advance_to(t_end, sample_times,
                      [&on_sample](double t, const double* x) { on_sample(t, thesis_state_from(x)); });
  } else {
    integ_.advance_to(t_end);
  }
}

ThesisReference::State ThesisReference::state() const {
  return segment_open_ ? thesis_state_from(integ_.state().data()) : x_pending_;
}

double ThesisReference::time() const noexcept { return segment_open_ ? integ_.time() : t_pending_; }

}  // namespace hstmon::sim
