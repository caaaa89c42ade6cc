/// @file steady_windows.cpp
/// Steady-state window detection (see steady_windows.hpp for the algorithm).
#include "hstmon_ident/steady_windows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hstmon::ident {

namespace {

using host::Signal;

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  double m = *mid;
  if (v.size() % 2 == 0) m = 0.5 * (m + *std::max_element(v.begin(), mid));
  return m;
}

// Least-squares line of y over t[first..last]: mean, slope, scatter about the line, Σ(y−ȳ)².
ChannelWindowStats line_stats(const std::vector<double>& t, const std::vector<double>& y, std::size_t first,
                              std::size_t last, double& stt) {
  const std::size_t n = last - first + 1;
  double tm = 0.0, ym = 0.0;
  for (std::size_t i = first; i <= last; ++i) {
    tm += t[i];
    ym += y[i];
  }
  tm /= static_cast<double>(n);
  ym /= static_cast<double>(n);
  double sty = 0.0, syy = 0.0;
  stt = 0.0;
  for (std::size_t i = first; i <= last; ++i) {
    const double dt = t[i] - tm, dy = y[i] - ym;
    stt += dt * dt;
    sty += dt * dy;
    syy += dy * dy;
  }
  ChannelWindowStats s;
  s.mean = ym;
  s.ss = syy;
  s.slope = stt > 0.0 ? sty / stt : 0.0;
  if (n >= 3) {
    const double sse = std::max(0.0, syy - s.slope * sty);
    s.scatter = std::sqrt(sse / static_cast<double>(n - 2));
  }
  return s;
}

bool is_input(Signal s) { return host::signal_info(s).input; }

}  // namespace

double noise_floor(Signal s) noexcept {
  return host::signal_info(s).quantity == host::Quantity::kSpeed ? 1e-4 : 1.0;
}

SteadyWindowResult find_steady_windows(const host::LogData& log, const SteadyWindowOptions& o) {
  SteadyWindowResult res;
  if (log.error) {
    res.error = log.error->to_string();
    return res;
  }
  const std::size_t n = log.rows();
  if (n == 0) {
    res.error = log.path + ": error: no data rows";
    return res;
  }
  std::vector<Signal> chans;
  for (std::size_t k = 1; k < host::kSignalCount; ++k) {
    const auto s = static_cast<Signal>(k);
    if (!is_input(s) && log.has(s)) chans.push_back(s);
  }
  if (chans.empty()) {
    res.error = log.path + ": error: no measured channel (p_mi, p_mo, p_pp, w_m, p_pump) in the log";
    return res;
  }
  for (std::size_t k = 0; k < host::kSignalCount; ++k) {
    const auto s = static_cast<Signal>(k);
    if (!log.has(s) || k == 0) continue;
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(log.column(s)[i])) {
        res.error = log.path + ": error: non-finite value in column " + std::string(host::signal_name(s)) +
                    " at row " + std::to_string(i + 1);
        return res;
      }
    }
  }
  for (Signal s : chans) {
    const std::size_t k = host::index(s);
    res.measured[k] = true;
    double sigma = o.noise[k];
    if (!(sigma > 0.0)) {
      // Successive differences: noise gives |Δ| ~ σ√2; level steps give a few large ones.
      // Cut-off 5× the larger of the MAD scale and the smallest non-zero |Δ| (the ADC step,
      // where quantisation makes most differences 0), then σ² = mean(Δ²)/2 below it.
      std::vector<double> d;
      const auto& y = log.column(s);
      double q = std::numeric_limits<double>::infinity();
      for (std::size_t i = 1; i < n; ++i) {
        d.push_back(std::fabs(y[i] - y[i - 1]));
        if (d.back() > 0.0) q = std::min(q, d.back());
      }
      sigma = 0.0;
      if (!d.empty()) {
        const double mad = median(d) / 0.6745;
        const double cut = 5.0 * std::max(mad, std::isfinite(q) ? q : 0.0);
        double s2 = 0.0;
        std::size_t cnt = 0;
        for (double v : d) {
          if (v <= cut) {
            s2 += v * v;
            ++cnt;
          }
        }
        sigma = cnt > 0 ? std::sqrt(s2 / (2.0 * static_cast<double>(cnt))) : 0.0;
      }
      res.noise_estimated[k] = true;
    }
    res.noise[k] = std::max(sigma, noise_floor(s));
  }

  const std::size_t min_samples = o.assume_steady ? 1 : std::max<std::size_t>(o.min_samples, 1);
  const double min_duration = o.assume_steady ? 0.0 : o.min_duration;
  const auto& t = log.t;

  // Acceptance test of [a, b]; on success fills w.
  auto accept = [&](std::size_t a, std::size_t b, SteadyWindow& w) {
    const std::size_t cnt = b - a + 1;
    if (cnt < min_samples || t[b] - t[a] < min_duration - 1e-12) return 0;  // too short
    w = SteadyWindow{};
    w.first = a;
    w.last = b;
    w.t0 = t[a];
    w.t1 = t[b];
    // Fewer than 3 samples cannot be tested for scatter or slope: steady by assumption.
    w.assumed = cnt < 3;
    for (Signal s : chans) {
      const std::size_t k = host::index(s);
      double stt = 0.0;
      const ChannelWindowStats st = line_stats(t, log.column(s), a, b, stt);
      w.stats[k] = st;
      const double sigma = res.noise[k];
      if (cnt >= 3 && st.scatter > o.scatter_k * sigma) return -1;
      if (cnt >= 3 && stt > 0.0 && std::fabs(st.slope) > o.slope_k * sigma / std::sqrt(stt) + o.slope_tol[k]) return -2;
    }
    return 1;
  };

  std::size_t i = 0;
  while (i < n) {
    // Grow [i, j] while each new sample agrees with the running mean on every channel.
    std::array<double, host::kSignalCount> sum{};
    for (Signal s : chans) sum[host::index(s)] = log.column(s)[i];
    std::size_t j = i;
    while (j + 1 < n) {
      const double cnt = static_cast<double>(j - i + 1);
      bool ok = true;
      for (Signal s : chans) {
        const std::size_t k = host::index(s);
        const double m = sum[k] / cnt;
        if (std::fabs(log.column(s)[j + 1] - m) > o.outlier_k * res.noise[k] * std::sqrt(1.0 + 1.0 / cnt)) {
          ok = false;
          break;
        }
      }
      if (!ok) break;
      ++j;
      for (Signal s : chans) sum[host::index(s)] += log.column(s)[j];
    }
    // Test, dropping the first quarter while the slope test fails.
    std::size_t a = i;
    SteadyWindow w;
    int verdict = accept(a, j, w);
    while (verdict == -2 && j - a + 1 >= 4) {
      a += (j - a + 1) / 4;
      verdict = accept(a, j, w);
    }
    if (verdict == 1) {
      for (std::size_t k = 0; k < host::kSignalCount; ++k) {
        const auto s = static_cast<Signal>(k);
        w.inputs[k] = std::numeric_limits<double>::quiet_NaN();
        if (k == 0 || !is_input(s) || !log.has(s)) continue;
        const auto& col = log.column(s);
        std::vector<double> v(col.begin() + static_cast<std::ptrdiff_t>(w.first),
                              col.begin() + static_cast<std::ptrdiff_t>(w.last) + 1);
        w.inputs[k] = median(v);
        const auto [mn, mx] = std::minmax_element(v.begin(), v.end());
        if (*mn != *mx) w.inputs_varied = true;
      }
      res.rejected_samples += a - i;
      res.windows.push_back(w);
    } else {
      res.rejected_samples += j - i + 1;
    }
    i = j + 1;
  }
  return res;
}

}  // namespace hstmon::ident
