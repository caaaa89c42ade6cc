/// @file operating_points.cpp
/// Steady windows → thesis operating points with PRV-setting labels.
#include "hstmon_ident/operating_points.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>

namespace hstmon::ident {

namespace {
using host::Signal;
constexpr Signal kChannels[4] = {Signal::kPMi, Signal::kPMo, Signal::kPPp, Signal::kWm};
}  // namespace

void append_operating_points(const host::LogData& log, const SteadyWindowResult& windows,
                             const OperatingPointOptions& options, std::vector<OperatingPoint>& points,
                             std::vector<std::string>& settings) {
  const bool by_kp = log.has(Signal::kKp) && !options.setting_per_window;
  std::map<double, std::size_t> kp_setting;
  for (const SteadyWindow& w : windows.windows) {
    OperatingPoint p;
    p.source = fmt::format("{} t={:g}…{:g} s", log.path, w.t0, w.t1);
    p.n = w.samples();
    p.assumed = w.assumed;
    p.u = options.defaults;
    const auto in = [&](Signal s, double fallback) {
      const double v = w.inputs[host::index(s)];
      return log.has(s) && std::isfinite(v) ? v : fallback;
    };
    p.u.Psupl = in(Signal::kPSup, options.defaults.Psupl);
    p.u.Ps = in(Signal::kPS, options.defaults.Ps);
    p.u.Pbp = in(Signal::kPBp, options.defaults.Pbp);
    p.u.kp = in(Signal::kKp, options.defaults.kp);
    for (int c = 0; c < 4; ++c) {
      const std::size_t k = host::index(kChannels[c]);
      const bool have = windows.measured[k];
      p.y[static_cast<std::size_t>(c)] = have ? w.stats[k].mean : std::numeric_limits<double>::quiet_NaN();
      p.ss[static_cast<std::size_t>(c)] = have ? w.stats[k].ss : 0.0;
    }
    if (by_kp) {
      auto it = kp_setting.find(p.u.kp);
      if (it == kp_setting.end()) {
        it = kp_setting.emplace(p.u.kp, settings.size()).first;
        settings.push_back(fmt::format("{} kp={:.6g}", log.path, p.u.kp));
      }
      p.setting = it->second;
    } else {
      p.setting = settings.size();
      settings.push_back(fmt::format("{} t={:g}…{:g} s", log.path, w.t0, w.t1));
    }
    points.push_back(p);
  }
}

}  // namespace hstmon::ident
