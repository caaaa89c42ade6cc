/// @file rig_run.cpp
#include "hstmon_sim/rig_run.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hstmon::sim {

ThesisScenario thesis_rig_run(const RigRun& r) {
  if (!(r.duration > 0.0 && r.supply_on >= 0.0 && r.run_time >= 0.0 && r.stop_time >= 0.0)) {
    throw std::invalid_argument("rig run: need duration > 0 and non-negative times");
  }
  if (!r.from_rest && r.supply_on > 0.0) throw std::invalid_argument("rig run: a steady start has the supply on");
  if (r.run_time > 0.0 && !(r.stop_time > 0.0)) throw std::invalid_argument("rig run: cycles need a stop time > 0");
  const std::vector<std::pair<double, double>> kp = load_setpoints(r.load, r.inputs.kp, r.duration);

  // Supply switching times, alternately on and off, from the first switch-on.
  std::vector<double> toggles;
  const double t_on = r.from_rest ? r.supply_on : 0.0;
  if (t_on > 0.0) toggles.push_back(t_on);
  if (r.run_time > 0.0) {
    for (double t = t_on + r.run_time; t < r.duration; t += r.run_time + r.stop_time) {
      toggles.push_back(t);
      if (t + r.stop_time < r.duration) toggles.push_back(t + r.stop_time);
    }
  }
  auto supply_at = [&](double t) {
    bool on = t_on <= 0.0;  // before the first toggle; each toggle flips it
    for (double s : toggles) {
      if (s > t) break;
      on = !on;
    }
    return on;
  };
  auto kp_at = [&](double t) {
    std::size_t k = 0;
    while (k + 1 < kp.size() && kp[k + 1].first <= t) ++k;
    return kp[k].second;
  };

  std::vector<double> times = {0.0};
  for (const auto& s : kp) times.push_back(s.first);
  times.insert(times.end(), toggles.begin(), toggles.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());

  ThesisScenario sc;
  sc.name = "rig";
  sc.description = "thesis rig as run: start from rest or steady, start/stop cycles, load " +
                   std::string(to_string(r.load.shape));
  sc.duration = r.duration;
  sc.initial = r.from_rest ? InitialCondition::kRest : InitialCondition::kSteady;
  for (double t : times) {
    if (t >= r.duration) break;
    ThesisInputs<double> u = r.inputs;
    u.kp = kp_at(t);
    if (!supply_at(t)) u.Psupl = u.Ps;
    if (!sc.schedule.empty()) {
      const ThesisInputs<double>& p = sc.schedule.back().u;
      if (p.Psupl == u.Psupl && p.kp == u.kp) continue;
    }
    sc.schedule.push_back({t, u});
  }
  validate(sc);
  return sc;
}

}  // namespace hstmon::sim
