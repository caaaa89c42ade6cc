/// @file paper_reference.cpp
#include "hstmon_sim/paper_reference.hpp"

#include <stdexcept>

#include "hstmon_sim/paper_jacobian.hpp"

namespace hstmon::sim {

namespace {

std::vector<double> paper_abs_tol(const ReferenceTolerances& tol) {
  return {tol.abs_pressure, tol.abs_pressure, tol.abs_pressure, tol.abs_speed};
}

}  // namespace

PaperReference::PaperReference(const Params& p, const State& x0, double t0, const ReferenceTolerances& tol)
    : integ_(paper_abs_tol(tol), tol.rel, tol.initial_step, tol.max_step) {
  if (!model_.set_params(p)) throw std::invalid_argument("PaperReference: invalid parameters");
  reset(x0, t0);
}

void PaperReference::reset(const State& x, double t) {
  if (!x.allFinite() || !std::isfinite(t)) throw std::invalid_argument("PaperReference: non-finite state or time");
  x_pending_ = x;
  t_pending_ = t;
  segment_open_ = false;
}

void PaperReference::begin_segment(const Inputs& u) {
  if (!Model::inputs_valid(u)) throw std::invalid_argument("PaperReference: invalid inputs");
  const Inputs& cur = model_.inputs();
  if (segment_open_ && cur.A_dcv == u.A_dcv && cur.A_prv == u.A_prv) return;
  const State x0 = segment_open_ ? state() : x_pending_;
  const double t0 = segment_open_ ? integ_.time() : t_pending_;
  model_.set_inputs(u);
  const Model m = model_;
  integ_.restart(
      t0, x0.data(),
      [m](const double* x, double* dxdt) {
        const State d = m.derivative(Eigen::Map<const State>(x));
        for (int i = 0; i < 4; ++i) dxdt[i] = d[i];
      },
      [m](const double* x, double* jac) {
        double j[4][4];
        paper_jacobian(m, Eigen::Map<const State>(x), j);
        for (int r = 0; r < 4; ++r) {
          for (int c = 0; c < 4; ++c) jac[r * 4 + c] = j[r][c];
        }
      });
  segment_open_ = true;
}

void PaperReference::advance_to(double t_end, const Inputs& u) { advance_to(t_end, u, {}, {}); }

void PaperReference::advance_to(double t_end, const Inputs& u, const std::vector<double>& sample_times,
                                const Sampler& on_sample) {
  if (!(t_end >= time())) throw std::invalid_argument("PaperReference::advance_to: t_end before current time");
  begin_segment(u);
  if (on_sample) {
    integ_.advance_to(t_end, sample_times,
                      [&on_sample](double t, const double* x) { on_sample(t, Eigen::Map<const State>(x)); });
  } else {
    integ_.advance_to(t_end);
  }
}

PaperReference::State PaperReference::state() const {
  return segment_open_ ? State(Eigen::Map<const State>(integ_.state().data())) : x_pending_;
}

double PaperReference::time() const noexcept { return segment_open_ ? integ_.time() : t_pending_; }

}  // namespace hstmon::sim
