/// @file param_fault.cpp
#include "hstmon_sim/param_fault.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "hstmon/circuit/thesis_circuit_model.hpp"
#include "fine_sampling.hpp"
#include "hstmon_sensors/sensor_chain.hpp"
#include "hstmon_sim/thesis_reference.hpp"

namespace hstmon::sim {

ThesisMeasurements measure_with_fault(const ThesisScenario& sc, const SensorConfig& cfg, std::uint64_t seed,
                                      const ThesisParams<double>& p, double fault_time,
                                      const ThesisParams<double>& faulty, const ReferenceTolerances& tol) {
  validate(sc);
  if (!ThesisCircuitModel<double>::params_valid(faulty)) {
    throw std::invalid_argument("measure_with_fault: invalid faulty parameters");
  }
  const detail::FineGrid grid(cfg, sc.duration, "measure_with_fault");

  // Segments: the schedule's, split at the fault time.
  struct Segment {
    double end;
    ThesisInputs<double> u;
    bool faulty;
  };
  std::vector<Segment> segs;
  for (std::size_t k = 0; k < sc.schedule.size(); ++k) {
    const double a = sc.schedule[k].t_start;
    const double b = segment_end(sc, k);
    if (fault_time > a && fault_time < b) {
      segs.push_back({fault_time, sc.schedule[k].u, false});
      segs.push_back({b, sc.schedule[k].u, true});
    } else {
      segs.push_back({b, sc.schedule[k].u, a >= fault_time});
    }
  }

  auto ref = std::make_unique<ThesisReference>(segs.front().faulty ? faulty : p,
                                               thesis_initial_state(sc, p), 0.0, tol);
  bool ref_faulty = segs.front().faulty;

  double x[4];
  to_array(ref->state(), x);
  detail::FineSampling<ThesisInputs<double>> sampling(cfg, seed, sc, grid, x);
  auto on_sample = [&sampling](double t, const ThesisState<double>& xs) {
    double v[4];
    to_array(xs, v);
    sampling.feed(t, v);
  };
  for (const Segment& s : segs) {
    if (s.faulty && !ref_faulty) {
      const ThesisState<double> x0 = ref->state();
      const double t0 = ref->time();
      ref = std::make_unique<ThesisReference>(faulty, x0, t0, tol);
      ref_faulty = true;
    }
    sampling.through(s.end, [&](double t_end, const std::vector<double>& points) {
      ref->advance_to(t_end, s.u, points, on_sample);
    });
  }
  return sampling.take();
}

ThesisScenario with_input_fault(const ThesisScenario& sc, double ThesisInputs<double>::*field, double factor,
                                double t_fault) {
  validate(sc);
  ThesisScenario out = sc;
  if (out.logged.empty()) out.logged = sc.schedule;
  out.schedule.clear();
  for (std::size_t k = 0; k < sc.schedule.size(); ++k) {
    const double a = sc.schedule[k].t_start;
    const double b = segment_end(sc, k);
    InputStep<ThesisInputs<double>> e = sc.schedule[k];
    if (a < t_fault && t_fault < b) {
      out.schedule.push_back(e);
      e.t_start = t_fault;
    }
    if (e.t_start >= t_fault) e.u.*field *= factor;
    out.schedule.push_back(e);
  }
  validate(out);
  return out;
}

void inject_sensor_fault(ThesisMeasurements& ms, const SensorConfig& cfg, const SensorFault& f) {
  if (f.channel < 0 || f.channel > 3) throw std::invalid_argument("inject_sensor_fault: channel must be 0..3");
  if (cfg.channels.size() != 4) throw std::invalid_argument("inject_sensor_fault: need 4 channels");
  const auto ch = static_cast<std::size_t>(f.channel);
  const ChannelSpec& spec = cfg.channels[ch];
  bool have_held = false;
  double held = 0.0;
  for (auto& r : ms) {
    if (r.t < f.t_start) {
      held = r.y[ch];
      have_held = true;
      continue;
    }
    switch (f.kind) {
      case SensorFaultKind::kBias: r.y[ch] = clip_and_quantise(r.y[ch] + f.value, spec); break;
      case SensorFaultKind::kDrift: r.y[ch] = clip_and_quantise(r.y[ch] + f.value * (r.t - f.t_start), spec); break;
      case SensorFaultKind::kLoopBreak: r.y[ch] = spec.range_lo - kNe43LoopBreak * (spec.range_hi - spec.range_lo); break;
      case SensorFaultKind::kStuck:
        if (!have_held) {
          held = r.y[ch];
          have_held = true;
        }
        r.y[ch] = held;
        break;
    }
  }
}

}  // namespace hstmon::sim
