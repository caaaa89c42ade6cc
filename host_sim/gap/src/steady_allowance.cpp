/// @file steady_allowance.cpp
/// The thesis rig's steady gap against its parameter uncertainty (steady_allowance.hpp).
#include "steady_allowance.hpp"

#include <cmath>
#include <limits>

#include "hstmon/residual_bounds.hpp"
#include "hstmon/thesis_reduced.hpp"

namespace hstmon::gap::detail {

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kParamNames[hstmon::detail::kBoundParams] = {"Dm", "Dp", "Rlkg", "Ripl", "Rf", "Rbl", "kf"};

bool steady_y(const ThesisParams<double>& p, const ThesisInputs<double>& u, double (&y)[kChannels]) {
  using M = ThesisReducedModel<double>;
  double v[M::kOutputs];
  if (!M::params_valid(p) || !M::steady_outputs(p, u, v)) return false;
  for (int c = 0; c < kChannels; ++c) y[c] = v[c];
  return true;
}

ThesisInputs<double> inputs_at(const InputSeries& u, std::size_t k) {
  ThesisInputs<double> in;
  in.Psupl = u.Psupl[k];
  in.Ps = u.Ps[k];
  in.Pbp = u.Pbp[k];
  in.kp = u.kp[k];
  return in;
}

}  // namespace

std::vector<Setting> settings_of(const InputSeries& u, const std::vector<char>& transient) {
  std::vector<Setting> out;
  const std::size_t n = u.size();
  std::size_t first = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    if (k < n && !input_step(u, k)) continue;
    Setting s;
    s.first = first;
    s.end = k;
    // The log's first rows are a start-up as much as any step's (a log may start at rest).
    s.steady_from = first == 0 ? 1 : first;
    while (s.steady_from < k && (transient[s.steady_from] || (first == 0 && u.t[s.steady_from] - u.t[0] < 0.3))) {
      ++s.steady_from;
    }
    out.push_back(s);
    first = k;
  }
  return out;
}

ThesisParams<double> moved_params(const ThesisParams<double>& p, const std::vector<std::pair<std::string, double>>& moves) {
  ThesisParams<double> q = p;
  using I = hstmon::detail::BoundItems<double>;
  for (const auto& [name, v] : moves) {
    for (int k = 0; k < hstmon::detail::kBoundParams; ++k) {
      if (name == kParamNames[k]) q.*(I::kParam[k]) *= 1.0 + v;
    }
  }
  return q;
}

SteadyAllowance thesis_allowance(const ThesisParams<double>& p, const InputSeries& u,
                                 const std::vector<std::array<double, kChannels>>& y,
                                 const std::vector<std::array<double, kChannels>>& model,
                                 const std::array<bool, kChannels>& present, const std::array<double, kChannels>& noise,
                                 const std::vector<char>& transient) {
  SteadyAllowance out;
  const ThesisUncertainty<double> eps{};
  using I = hstmon::detail::BoundItems<double>;
  std::vector<double> r;
  std::vector<std::vector<double>> J(hstmon::detail::kBoundParams);
  std::vector<std::pair<const Setting*, std::size_t>> rows_of;  // setting, channel per entry of r
  const auto sets = settings_of(u, transient);
  for (const Setting& s : sets) {
    if (s.steady() == 0) continue;
    const ThesisInputs<double> in = inputs_at(u, s.end - 1);
    double y0[kChannels], yk[kChannels][hstmon::detail::kBoundParams];
    if (!steady_y(p, in, y0)) continue;
    bool ok = true;
    for (int k = 0; k < hstmon::detail::kBoundParams && ok; ++k) {
      ThesisParams<double> q = p;
      q.*(I::kParam[k]) *= 1.0 + eps.*(I::kEps[k]);
      double v[kChannels];
      ok = steady_y(q, in, v);
      for (int c = 0; c < kChannels; ++c) yk[c][k] = v[c];
    }
    if (!ok) continue;
    for (std::size_t c = 0; c < kChannels; ++c) {
      if (!present[c]) continue;
      double m = 0;
      for (std::size_t i = s.steady_from; i < s.end; ++i) m += y[i][c] - model[i][c];
      r.push_back(m / static_cast<double>(s.steady()) / noise[c]);
      // data − model: a model moved up lowers the residual.
      for (int k = 0; k < hstmon::detail::kBoundParams; ++k) J[static_cast<std::size_t>(k)].push_back(-(yk[c][k] - y0[c]) / noise[c]);
      rows_of.emplace_back(&s, c);
    }
  }
  out.a = parameter_allowance(r, J);
  for (std::size_t k = 0; k < out.a.delta.size(); ++k) {
    out.moves.emplace_back(kParamNames[k], out.a.delta[k] * eps.*(I::kEps[k]));
  }
  // Every row of a setting carries its setting's move; the rest of the log keeps its residual.
  std::vector<std::array<double, kChannels>> shift(y.size(), std::array<double, kChannels>{});
  for (std::size_t i = 0; i < rows_of.size(); ++i) {
    const auto& [s, c] = rows_of[i];
    const double d = out.a.after[i] - r[i];
    for (std::size_t k = s->first; k < s->end; ++k) shift[k][c] = d;
  }
  for (std::size_t c = 0; c < kChannels; ++c) {
    if (!present[c]) {
      out.rms_w_within[c] = kNan;
      continue;
    }
    double ss = 0;
    for (std::size_t k = 0; k < y.size(); ++k) ss += std::pow((y[k][c] - model[k][c]) / noise[c] + shift[k][c], 2);
    out.rms_w_within[c] = y.empty() ? 0.0 : std::sqrt(ss / static_cast<double>(y.size()));
  }
  return out;
}

}  // namespace hstmon::gap::detail
