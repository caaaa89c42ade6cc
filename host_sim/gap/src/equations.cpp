/// @file equations.cpp
/// Analytical redundancy relations on measured signals (see equations.hpp, docs/gap.md).
#include "hstmon_gap/equations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "hstmon/signed_root.hpp"
#include "load_bins.hpp"
#include "local_fit.hpp"

namespace hstmon::gap {

namespace {

constexpr double kLocateRatio = 3.0;  // an equation is out of balance beyond 3× its propagated noise
// Channel indices (ThesisChannel order) as array indices.
constexpr std::size_t kChPmi = 0, kChPmo = 1, kChPpp = 2, kChWm = 3;

}  // namespace

const std::array<const char*, kEquations>& equation_names() {
  static const std::array<const char*, kEquations> n = {"flow:p_mi", "flow:p_mo", "flow:p_pp", "torque:w_m"};
  return n;
}

const std::array<const char*, kEquations>& equation_units() {
  static const std::array<const char*, kEquations> u = {"m^3/s", "m^3/s", "m^3/s", "N*m"};
  return u;
}

ArrData evaluate_arrs(const ThesisParams<double>& p, const InputSeries& u,
                      const std::vector<std::array<double, kChannels>>& y, const std::array<bool, kChannels>& present,
                      const std::array<double, kChannels>& noise) {
  ArrData a;
  const std::size_t n = u.size();
  if (n < 3 || y.size() != n) return a;
  const int m = detail::smoothing_half_width(u.t);
  a.half_window = m;
  // Input setting id per row: a window must not straddle a change (the smoothing of a step
  // is no signal of the model's).
  std::vector<int> seg(n, 0);
  for (std::size_t k = 1; k < n; ++k) seg[k] = seg[k - 1] + (input_step(u, k) ? 1 : 0);
  const bool has_mi = present[kChPmi], has_mo = present[kChPmo], has_pp = present[kChPpp], has_w = present[kChWm];
  a.available = {has_mi && has_w, has_mo && has_w, has_pp && has_w, has_mi && has_mo && has_pp && has_w};
  const auto mu = static_cast<std::size_t>(m);
  const double gl = 1.0 / p.Rlkg, gi = 1.0 / p.Ripl, R = p.Rf + p.Rbl;
  for (std::size_t k = mu + 1; k + mu < n; ++k) {  // the window leaves out row 0 (the initial condition)
    if (seg[k - mu] != seg[k + mu]) continue;
    // Local linear fit: mean (the smoothed value at the centre) and slope.
    std::array<double, kChannels> mean{}, slope{};
    const detail::Window win = detail::window_at(u.t, k, mu);
    const double N = win.N, stt = win.stt;
    for (std::size_t c = 0; c < kChannels; ++c) {
      if (!present[c]) continue;
      detail::line_fit(
          u.t, win, [&](std::size_t i) { return y[i][c]; }, mean[c], slope[c]);
    }
    // Where the signal bends within the window (a transient faster than the smoothing) the
    // window mean and slope are biased: such rows are left out.
    bool bent = false;
    for (std::size_t c = 0; c < kChannels && !bent; ++c) {
      if (!present[c]) continue;
      bent = detail::bends(
          u.t, win, [&](std::size_t i) { return y[i][c]; }, mean[c], slope[c], noise[c]);
    }
    if (bent) continue;
    a.rows.push_back(k);
    a.y.push_back(mean);
    a.dPpp.push_back(slope[kChPpp]);
    a.dw.push_back(slope[kChWm]);
    a.Psupl.push_back(u.Psupl[k]);
    a.Ps.push_back(u.Ps[k]);
    a.Pbp.push_back(u.Pbp[k]);
    a.kp.push_back(u.kp[k]);
    a.t_since_start.push_back(u.t[k] - u.t[0]);
    // Noise of a window mean and of a window slope, per channel.
    std::array<double, kChannels> sm{}, sd{};
    for (std::size_t c = 0; c < kChannels; ++c) {
      sm[c] = noise[c] / std::sqrt(N);
      sd[c] = noise[c] / std::sqrt(stt);
    }
    const double Pmi = mean[kChPmi], Ppp = mean[kChPpp], w = mean[kChWm];
    const double Pmo = has_mo ? mean[kChPmo] : u.Ps[k];
    auto put = [&](int e, double r, double var) {
      a.r[static_cast<std::size_t>(e)].push_back(a.available[static_cast<std::size_t>(e)] ? r : 0.0);
      a.sigma[static_cast<std::size_t>(e)].push_back(std::sqrt(var));
    };
    {
      double s_in = 0;
      const double q_in = p.kf * signed_root(u.Psupl[k] - Pmi, p.dp_t_dcv, s_in);
      const double r = q_in - p.Dm * w - Pmi * gl - (Pmi - Pmo) * gi;
      const double d_mi = p.kf * s_in + gl + gi;
      put(kEqFlowMi, r,
          std::pow(d_mi * sm[kChPmi], 2) + (has_mo ? std::pow(gi * sm[kChPmo], 2) : 0.0) +
              std::pow(p.Dm * sm[kChWm], 2));
    }
    {
      double s_out = 0;
      const double q_out = p.kf * signed_root(Pmo - u.Ps[k], p.dp_t_dcv, s_out);
      const double r = p.Dm * w + (Pmi - Pmo) * gi - Pmo * gl - q_out;
      const double d_mo = p.kf * s_out + gl + gi;
      put(kEqFlowMo, r,
          std::pow(d_mo * sm[kChPmo], 2) + (has_mi ? std::pow(gi * sm[kChPmi], 2) : 0.0) +
              std::pow(p.Dm * sm[kChWm], 2));
    }
    {
      double s_prv = 0;
      const double q_prv = u.kp[k] * signed_root(Ppp - u.Pbp[k], p.dp_t_prv, s_prv);
      const double r = p.Dp * w - q_prv - slope[kChPpp] / p.K;
      put(kEqFlowPp, r,
          std::pow(u.kp[k] * s_prv * sm[kChPpp], 2) + std::pow(p.Dp * sm[kChWm], 2) +
              std::pow(sd[kChPpp] / p.K, 2));
    }
    {
      const double r = p.Dm * (Pmi - Pmo) - R * w - p.Dp * (Ppp - u.Pbp[k]) - p.J * slope[kChWm];
      put(kEqTorque, r,
          std::pow(p.Dm * sm[kChPmi], 2) + std::pow(p.Dm * sm[kChPmo], 2) + std::pow(p.Dp * sm[kChPpp], 2) +
              std::pow(R * sm[kChWm], 2) + std::pow(p.J * sd[kChWm], 2));
    }
  }
  return a;
}

void imbalance_stats(const std::vector<double>& r, const std::vector<double>& sigma, EquationStats& s) {
  const double n = static_cast<double>(r.size());
  double s1 = 0, s2 = 0, sw = 0, sn = 0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    s1 += r[k];
    s2 += r[k] * r[k];
    sw += std::pow(r[k] / sigma[k], 2);
    sn += sigma[k] * sigma[k];
  }
  s.mean = s1 / n;
  s.rms = std::sqrt(s2 / n);
  s.noise = std::sqrt(sn / n);
  s.rms_w = std::sqrt(sw / n);
}

std::vector<EquationStats> equation_stats(const ArrData& a) {
  std::vector<EquationStats> out;
  const auto bins = detail::load_bins(a.kp);
  for (std::size_t e = 0; e < kEquations; ++e) {
    EquationStats s;
    s.equation = equation_names()[e];
    s.unit = equation_units()[e];
    s.available = a.available[e] && !a.rows.empty();
    if (!s.available) {
      out.push_back(s);
      continue;
    }
    const auto& r = a.r[e];
    const auto& sg = a.sigma[e];
    imbalance_stats(r, sg, s);
    const EquationStats::Part* hi = nullptr;
    const EquationStats::Part* lo = nullptr;
    for (const auto& b : bins) {
      double m1 = 0, mw = 0;
      std::size_t cnt = 0;
      for (std::size_t k = 0; k < r.size(); ++k) {
        if (!b.mask[k]) continue;
        m1 += r[k];
        mw += std::pow(r[k] / sg[k], 2);
        ++cnt;
      }
      if (cnt == 0) continue;
      s.by_load.push_back({b.label, m1 / static_cast<double>(cnt), std::sqrt(mw / static_cast<double>(cnt))});
    }
    for (const auto& b : s.by_load) {
      if (hi == nullptr || std::fabs(b.mean) > std::fabs(hi->mean)) hi = &b;
      if (lo == nullptr || std::fabs(b.mean) < std::fabs(lo->mean)) lo = &b;
    }
    if (hi != nullptr && lo != nullptr) {
      char buf[256];
      if (std::fabs(hi->mean) - std::fabs(lo->mean) <= 0.25 * std::fabs(hi->mean)) {
        std::snprintf(buf, sizeof buf, "about the same in every load regime (mean %.3g to %.3g %s)", lo->mean,
                      hi->mean, s.unit.c_str());
      } else {
        std::snprintf(buf, sizeof buf, "depends on the load: mean %.3g %s at %s, %.3g at %s", hi->mean,
                      s.unit.c_str(), hi->label.c_str(), lo->mean, lo->label.c_str());
      }
      s.dependence = buf;
    }
    out.push_back(std::move(s));
  }
  return out;
}

int located_equation(const std::vector<EquationStats>& s) {
  int best = -1;
  for (std::size_t e = 0; e < s.size(); ++e) {
    if (!s[e].available || !(s[e].rms_w > kLocateRatio)) continue;
    if (best < 0 || s[e].rms_w > s[static_cast<std::size_t>(best)].rms_w) best = static_cast<int>(e);
  }
  return best;
}

}  // namespace hstmon::gap
