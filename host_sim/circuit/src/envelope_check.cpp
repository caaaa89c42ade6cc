#include "hstmon_circuit/envelope_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon/fault_estimator.hpp"
#include "hstmon_host/circuit_units.hpp"

namespace hstmon::circuit_tools {

namespace {

// The fault estimator's settle and input tolerance: the stretch judged is the one its
// first window would be.
const FaultEstimator<host::HostCircuitModel>::Config kWindows{};

}  // namespace

EnvelopeCheck::EnvelopeCheck(const LoadedCircuit& c, const Model& model, const std::vector<double>& sigma, double window)
    : c_(c), model_(model), sigma_(sigma), window_(window) {
  const std::size_t n = c.file.sensors.size();
  sigma_.resize(n, 0.0);
  sum_.assign(n, 0.0);
  bound_.assign(n, 0.0);
  n_.assign(n, 0);
  half_sum_.assign(n, 0.0);
  half_n_.assign(n, 0);
  res_.text = "not checked: no stretch of held inputs long enough to settle and judge (" +
              fmt::format("{:g}", window_) + " s after 3 time constants)";
}

void EnvelopeCheck::detected(double t) {
  if (res_.checked || abandoned_ || t_detected_ >= 0.0) return;
  t_detected_ = t;
  if (!holding_ || t < t_from_) abandon();
}

void EnvelopeCheck::abandon() {
  abandoned_ = true;
  res_.text = fmt::format(
      "not checked: a fault was detected (t = {:.4g} s) before the machine held steady, so no stretch shows the "
      "machine as it was",
      t_detected_);
}

void EnvelopeCheck::begin_hold(double t, const Model::Inputs& u) {
  // A window that starts again after a detection would judge the fault, not the machine.
  if (t_detected_ >= 0.0) {
    abandon();
    return;
  }
  holding_ = true;
  u_hold_ = u;
  t_from_ = t + settle_time(model_, u, kWindows.settle_taus, kWindows.settle_min, kWindows.settle_max);
  std::fill(sum_.begin(), sum_.end(), 0.0);
  std::fill(n_.begin(), n_.end(), 0);
  std::fill(half_sum_.begin(), half_sum_.end(), 0.0);
  std::fill(half_n_.begin(), half_n_.end(), 0);
}

void EnvelopeCheck::add(double t, const Model::Inputs& u, const double* r, unsigned valid, const double* bound) {
  if (res_.checked || abandoned_) return;
  if (!holding_ || !inputs_within(u_hold_, u, kWindows.input_tolerance)) begin_hold(t, u);
  if (abandoned_ || t < t_from_) return;
  for (std::size_t ch = 0; ch < sum_.size(); ++ch) {
    if (((valid >> ch) & 1u) == 0 || !std::isfinite(r[ch])) continue;
    sum_[ch] += r[ch];
    n_[ch] += 1;
    if (t - t_from_ < 0.5 * window_) {
      half_sum_[ch] += r[ch];
      half_n_[ch] += 1;
    }
    bound_[ch] = bound != nullptr ? std::fabs(bound[ch]) : 0.0;
  }
  t_last_ = t;
  if (t - t_from_ < window_) return;
  // The machine may still be settling where the model has (a start from rest runs up at
  // the machine's own pace): a window whose halves differ by more than 5 % of the
  // tolerance (and their noise) is not steady, and the next one is tried.
  if (!steady()) {
    if (t_detected_ >= 0.0) {
      abandon();
      return;
    }
    t_from_ = t;
    std::fill(sum_.begin(), sum_.end(), 0.0);
    std::fill(n_.begin(), n_.end(), 0);
    std::fill(half_sum_.begin(), half_sum_.end(), 0.0);
    std::fill(half_n_.begin(), half_n_.end(), 0);
    return;
  }
  finish();
}

bool EnvelopeCheck::steady() const {
  for (std::size_t ch = 0; ch < sum_.size(); ++ch) {
    const std::size_t n2 = n_[ch] - half_n_[ch];
    if (half_n_[ch] == 0 || n2 == 0) continue;
    const double first = half_sum_[ch] / static_cast<double>(half_n_[ch]);
    const double second = (sum_[ch] - half_sum_[ch]) / static_cast<double>(n2);
    const double noise = 4.0 * sigma_[ch] * std::sqrt(1.0 / static_cast<double>(half_n_[ch]) + 1.0 / static_cast<double>(n2));
    if (std::fabs(second - first) > 0.05 * 2.0 * (bound_[ch] + 2.0 * sigma_[ch]) + noise) return false;
  }
  return true;
}

void EnvelopeCheck::finish() {
  if (res_.checked || abandoned_ || !holding_ || t_last_ - t_from_ < window_ || !steady()) return;
  res_.checked = true;
  res_.t0 = t_from_;
  res_.t1 = t_last_;
  std::string beyond, worst_text;
  double worst = 0.0;
  for (std::size_t ch = 0; ch < sum_.size(); ++ch) {
    if (n_[ch] == 0) continue;
    const double mean = sum_[ch] / static_cast<double>(n_[ch]);
    const double tolerance = 2.0 * (bound_[ch] + 2.0 * sigma_[ch]);
    if (!(tolerance > 0.0)) continue;
    const double ratio = std::fabs(mean) / tolerance;
    const host::CircuitSensor& s = c_.file.sensors[ch];
    const host::UnitResult unit = host::parse_circuit_unit(s.quantity, s.unit);
    const double k = unit.ok() ? 1.0 / unit.conversion.factor : 1.0;
    const std::string name = s.unit.empty() ? host::circuit_si_unit(s.quantity) : s.unit;
    if (ratio > 1.0) {
      res_.out = true;
      beyond += fmt::format("{}{} {:+.3g} {} from the model (it may be {:.3g} {})", beyond.empty() ? "" : ", ", s.name,
                            mean * k, name, tolerance * 0.5 * k, name);
    }
    if (ratio > worst) {
      worst = ratio;
      worst_text = s.name;
    }
  }
  if (res_.out) {
    res_.text = fmt::format(
        "the model does not describe this machine: at its first steady stretch (t = {:.3g} … {:.3g} s) {}; no fault "
        "is named. Run `hstmon identify --circuit` on healthy steady data, or `hstmon gap --circuit`",
        res_.t0, res_.t1, beyond);
  } else {
    res_.text = fmt::format("within the model's envelope at its first steady stretch (t = {:.3g} … {:.3g} s)", res_.t0,
                            res_.t1);
  }
}

}  // namespace hstmon::circuit_tools
