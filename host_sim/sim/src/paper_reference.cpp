/// @file paper_reference.cpp
#include "hstmon_sim/paper_reference.hpp"

#include <stdexcept>

#include "hstmon_sim/paper_jacobian.hpp"

namespace hstmon::sim {

PaperReference::PaperReference(const Params& p, const State& x0, double t0, const ReferenceTolerances& tol)
    : SegmentedReference(tol) {
  if (!model_.set_params(p)) throw std::invalid_argument("PaperReference: invalid parameters");
  reset(x0, t0);
}

void PaperReference::begin_segment(const Inputs& u) {
  if (!Model::inputs_valid(u)) throw std::invalid_argument("PaperReference: invalid inputs");
  const Inputs& cur = model_.inputs();
  if (segment_open() && cur.A_dcv == u.A_dcv && cur.A_prv == u.A_prv) return;
  model_.set_inputs(u);
  const Model m = model_;
  restart(
      [m](const double* x, double* dxdt) {
        const State d = m.derivative(Eigen::Map<const State>(x));
        for (int i = 0; i < 4; ++i) dxdt[i] = d[i];
      },
      [m](const double* x, double(&j)[4][4]) { paper_jacobian(m, Eigen::Map<const State>(x), j); });
}

}  // namespace hstmon::sim
