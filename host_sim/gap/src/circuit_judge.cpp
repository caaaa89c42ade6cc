/// @file circuit_judge.cpp
/// Noise, parameter uncertainty and evidence for `gap --circuit` (circuit_judge.hpp).
#include "circuit_judge.hpp"

#include <algorithm>
#include <cmath>

#include "evidence.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "noise_floor.hpp"

namespace hstmon::gap::detail {

namespace {

// A point's means over the second half of its rows: a slow tail the settle time (five of
// the model's slowest time constants) leaves in a real machine stays out of the steady mean.
void second_half_means(const circuit_tools::CircuitLog& log, std::size_t a, std::size_t b,
                       ident::CircuitOperatingPoint& pt) {
  const std::size_t from = a + (b - a) / 2;
  for (std::size_t ch = 0; ch < pt.mean.size(); ++ch) {
    if (!std::isfinite(pt.mean[ch]) || ch >= log.sensors.size() || log.sensors[ch].size() != log.rows()) continue;
    double sum = 0;
    for (std::size_t k = from; k < b; ++k) sum += log.sensors[ch][k];
    pt.mean[ch] = sum / static_cast<double>(b - from);
  }
  pt.t0 = log.t[from];
  pt.n = b - from;
}

}  // namespace

PointSet circuit_point_set(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log) {
  PointSet s;
  s.points = ident::circuit_operating_points(c, {log}, 0.2);
  std::vector<std::pair<std::size_t, std::size_t>> stretches;
  for (auto& pt : s.points) {
    const auto a = static_cast<std::size_t>(std::lower_bound(log.t.begin(), log.t.end(), pt.t0) - log.t.begin());
    const auto b = static_cast<std::size_t>(std::upper_bound(log.t.begin(), log.t.end(), pt.t1) - log.t.begin());
    if (b <= a + 1) continue;
    stretches.emplace_back(a, b);
    second_half_means(log, a, b, pt);
  }
  std::vector<double> dts;
  for (std::size_t k = 1; k < log.rows(); ++k) dts.push_back(log.t[k] - log.t[k - 1]);
  const double dt = median_of(dts);
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    double sigma = circuit_tools::sensor_sigma(c.file.sensors[ch]);
    if (ch < log.sensors.size() && log.sensors[ch].size() == log.rows() && !stretches.empty()) {
      sigma = std::max(sigma, estimate_noise(log.sensors[ch], stretches, dt).noise());
    }
    s.sigma.push_back(sigma);
  }
  return s;
}

bool point_residuals(const circuit_tools::LoadedCircuit& c, const host::HostCircuitModel::Params& p, const PointSet& s,
                     std::vector<double>& res) {
  if (!ident::circuit_point_residuals(c, p, s.points, res)) return false;
  // circuit_point_residuals weighs by the stated σ; rescale to the log's.
  std::size_t k = 0;
  for (const auto& pt : s.points) {
    for (std::size_t ch = 0; ch < pt.mean.size(); ++ch) {
      if (!std::isfinite(pt.mean[ch])) continue;
      res[k++] *= circuit_tools::sensor_sigma(c.file.sensors[ch]) / s.sigma[ch];
    }
  }
  return true;
}

std::vector<std::pair<int, double>> uncertain_params(const circuit_tools::LoadedCircuit& c) {
  const auto eps = circuit_tools::circuit_uncertainty(c);
  std::vector<std::pair<int, double>> out;
  for (std::size_t k = 0; k < c.file.params.size(); ++k) {
    if (eps.rel[k] > 0.0) out.emplace_back(static_cast<int>(k), eps.rel[k]);
  }
  return out;
}

std::vector<std::vector<double>> allowance_columns(const circuit_tools::LoadedCircuit& c, const PointSet& s,
                                                   const std::vector<double>& r) {
  std::vector<std::vector<double>> J;
  for (const auto& [k, e] : uncertain_params(c)) {
    auto p = c.values.params;
    p.v[k] *= 1.0 + e;
    std::vector<double> rk;
    // A parameter that takes some point past any steady state moves nothing it can show.
    if (!point_residuals(c, p, s, rk) || rk.size() != r.size()) {
      J.emplace_back(r.size(), 0.0);
      continue;
    }
    for (std::size_t i = 0; i < r.size(); ++i) rk[i] -= r[i];
    J.push_back(std::move(rk));
  }
  return J;
}

Allowance circuit_allowance(const circuit_tools::LoadedCircuit& c, const PointSet& s, const std::vector<double>& r) {
  return parameter_allowance(r, allowance_columns(c, s, r));
}

host::HostCircuitModel::Params moved_params(const circuit_tools::LoadedCircuit& c, const std::vector<double>& delta) {
  host::HostCircuitModel::Params p = c.values.params;
  std::size_t j = 0;
  for (const auto& [k, e] : uncertain_params(c)) {
    if (j < delta.size()) p.v[k] *= 1.0 + e * delta[j];
    ++j;
  }
  return p;
}

std::string circuit_evidence(const std::string& which, const PointSet& s) {
  std::vector<SettingEvidence> ev;
  for (const auto& pt : s.points) ev.push_back({pt.n, pt.inputs});
  return missing_evidence(which, ev);
}

}  // namespace hstmon::gap::detail
