/// @file thesis_reference.cpp
#include "hstmon_sim/thesis_reference.hpp"

#include <cmath>
#include <stdexcept>

#include "hstmon/thesis_model.hpp"
#include "hstmon/circuit/thesis_circuit_model.hpp"

namespace hstmon::sim {

namespace {

bool same_inputs(const ThesisInputs<double>& a, const ThesisInputs<double>& b) {
  return a.Psupl == b.Psupl && a.Ps == b.Ps && a.Pbp == b.Pbp && a.kp == b.kp;
}

}  // namespace

ThesisReference::ThesisReference(const Params& p, const State& x0, double t0, const ReferenceTolerances& tol)
    : SegmentedReference(tol), p_(p) {
  if (!ThesisCircuitModel<double>::params_valid(p)) {
    throw std::invalid_argument("ThesisReference: invalid parameters");
  }
  reset(x0, t0);
}

void ThesisReference::to_array(const State& x, double* out) noexcept { sim::to_array(x, out); }

ThesisReference::State ThesisReference::from_array(const double* v) noexcept { return thesis_state_from(v); }

void ThesisReference::begin_segment(const Inputs& u) {
  if (!ThesisCircuitModel<double>::inputs_valid(u)) {
    throw std::invalid_argument("ThesisReference: non-finite inputs or kp < 0");
  }
  if (segment_open() && same_inputs(u, u_)) return;
  u_ = u;
  const Params p = p_;
  restart(
      [p, u](const double* x, double* dxdt) {
        const State d = thesis_derivative(p, u, thesis_state_from(x));
        to_array(d, dxdt);
      },
      [p, u](const double* x, double(&j)[4][4]) { thesis_jacobian(p, u, thesis_state_from(x), j); });
}

}  // namespace hstmon::sim
