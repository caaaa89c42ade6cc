/// @file campaign_runs.cpp
#include "campaign_runs.hpp"

#include <cmath>
#include <random>

#include "hstmon/generated/thesis_signatures.hpp"
#include "hstmon/residual_bounds.hpp"

namespace hstmon_campaign {

using hstmon::MatchEventKind;
using hstmon::sim::SensorFaultKind;

namespace {

FaultCase param_case(const char* row, double Params::*field, double sign, double mag) {
  FaultCase f;
  f.row = row;
  f.target = Target::kParam;
  f.param = field;
  f.factor = 1.0 + sign * mag;
  f.magnitude = mag;
  return f;
}

FaultCase input_case(const char* row, double Inputs::*field, double sign, double mag) {
  FaultCase f = param_case(row, nullptr, sign, mag);
  f.target = Target::kInput;
  f.input = field;
  return f;
}

std::string percent(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g%%", v * 100.0);
  return b;
}

}  // namespace

std::vector<FaultCase> parameter_faults() {
  struct Spec {
    const char* name;  // without sign
    double Params::*param;
    double Inputs::*input;
    double mag[2];
    bool minus_only;
  };
  // Magnitudes: 10 % / 30 % by default; kp 30 / 50 % (the thesis's blockage is 50 %);
  // Pbp 30 / 60 % (Pbp moves Ppp alone, whose threshold is ≈ 5 bar; 10 % = 1 bar is far
  // below it); Rf 30 / 90 % (Rf is 3 % of the shaft's viscous friction Rbl + Rf); leakage
  // resistances −50 / −90 % (leak flows grow 2× and 10×). docs/fault_campaign.md.
  const Spec specs[] = {
      {"kp", nullptr, &Inputs::kp, {0.3, 0.5}, false},
      {"kf", &Params::kf, nullptr, {0.1, 0.3}, false},
      {"Psupl", nullptr, &Inputs::Psupl, {0.1, 0.3}, false},
      {"Pbp", nullptr, &Inputs::Pbp, {0.3, 0.6}, false},
      {"Rbl", &Params::Rbl, nullptr, {0.1, 0.3}, false},
      {"Rf", &Params::Rf, nullptr, {0.3, 0.9}, false},
      {"Dp", &Params::Dp, nullptr, {0.1, 0.3}, false},
      {"Dm", &Params::Dm, nullptr, {0.1, 0.3}, false},
      {"Rlkg", &Params::Rlkg, nullptr, {0.5, 0.9}, true},
      {"Ripl", &Params::Ripl, nullptr, {0.5, 0.9}, true},
      {"J", &Params::J, nullptr, {0.1, 0.3}, false},
      {"K", &Params::K, nullptr, {0.1, 0.3}, false},
  };
  std::vector<FaultCase> out;
  for (const Spec& s : specs) {
    for (int sg = 0; sg < (s.minus_only ? 1 : 2); ++sg) {
      const double sign = sg == 0 ? -1.0 : 1.0;
      const std::string row = std::string(s.name) + (sg == 0 ? "-" : "+");
      for (double m : s.mag) {
        FaultCase f = s.param ? param_case(row.c_str(), s.param, sign, m) : input_case(row.c_str(), s.input, sign, m);
        f.label = row + " " + percent(m);
        out.push_back(f);
      }
    }
  }
  return out;
}

std::vector<FaultCase> sensor_faults(const hstmon::sim::SensorConfig& sensors) {
  static const char* rows[] = {"sensor_p_mi", "sensor_p_mo", "sensor_p_pp", "sensor_w_m"};
  static const char* chans[] = {"p_mi", "p_mo", "p_pp", "w_m"};
  struct Kind {
    SensorFaultKind kind;
    double fs;  // bias [fraction of full scale] or drift [fraction of full scale per s]
    const char* label;
  };
  const Kind kinds[] = {{SensorFaultKind::kBias, 0.02, "bias +2%FS"},  {SensorFaultKind::kBias, -0.02, "bias -2%FS"},
                        {SensorFaultKind::kBias, 0.05, "bias +5%FS"},  {SensorFaultKind::kBias, -0.05, "bias -5%FS"},
                        {SensorFaultKind::kDrift, 0.02, "drift +2%FS/s"}, {SensorFaultKind::kDrift, -0.02, "drift -2%FS/s"},
                        {SensorFaultKind::kStuck, 0.0, "stuck"}};
  std::vector<FaultCase> out;
  for (int ch = 0; ch < 4; ++ch) {
    const auto& spec = sensors.channels.at(static_cast<std::size_t>(ch));
    const double fs = spec.range_hi - spec.range_lo;
    for (const Kind& k : kinds) {
      FaultCase f;
      f.row = rows[ch];
      f.label = std::string(chans[ch]) + " " + k.label;
      f.target = Target::kSensor;
      f.sensor.channel = ch;
      f.sensor.kind = k.kind;
      f.sensor.value = k.fs * fs;
      f.sensor_value_fs = k.fs * 100.0;
      out.push_back(f);
    }
  }
  return out;
}

Params perturbed_machine(std::uint64_t seed, double spread) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(-spread, spread);
  Params p;
  double* fields[] = {&p.Dm, &p.Dp, &p.Rlkg, &p.Ripl, &p.Rf, &p.Rbl, &p.kf, &p.J, &p.K};
  for (double* f : fields) *f *= 1.0 + uni(rng);
  return p;
}

Mon::Config monitor_config(const hstmon::sim::SensorConfig& sensors) {
  Mon::Config c;
  c.observer.tick = sensors.sample_period;
  for (int i = 0; i < 4; ++i) {
    const auto& ch = sensors.channels.at(static_cast<std::size_t>(i));
    c.evaluator.noise_sigma[i] = ch.noise_std;
    c.sensors.range_lo[i] = ch.range_lo;
    c.sensors.range_hi[i] = ch.range_hi;
  }
  return c;
}

namespace {

Mon make_monitor(const hstmon::sim::ThesisMeasurements& log, const Mon::Config& cfg) {
  Mon mon;
  if (mon.configure(Params{}, cfg, hstmon::kThesisSignatures, hstmon::kThesisSignatureCount) != hstmon::Status::kOk ||
      mon.reset_steady(log.front().u) != hstmon::Status::kOk) {
    std::fprintf(stderr, "fault_campaign: monitor configuration failed\n");
    std::exit(3);
  }
  return mon;
}

bool is_decision(MatchEventKind k) {
  return k == MatchEventKind::kIsolated || k == MatchEventKind::kAmbiguous || k == MatchEventKind::kUnexplained;
}

}  // namespace

RunResult monitor_log(const hstmon::sim::ThesisMeasurements& log, const Mon::Config& cfg, double fault_time) {
  Mon mon = make_monitor(log, cfg);
  RunResult r;
  Mon::Measurement m;
  m.valid = 0xF;
  Mon::Event e;
  for (const auto& s : log) {
    for (int i = 0; i < 4; ++i) m.y[i] = s.y[static_cast<std::size_t>(i)];
    mon.step(s.t, s.u, m);
    r.health |= mon.health();
    const bool before = s.t < fault_time - 1e-9;
    if (before && mon.evaluator().alarm() != 0) ++r.alarm_ticks_before;
    while (mon.pop_event(e)) {
      if (e.time < fault_time - 1e-9) {
        if (e.kind == MatchEventKind::kDetected) ++r.false_events;
        continue;
      }
      if (e.kind == MatchEventKind::kDetected && !r.detected) {
        r.detected = true;
        r.t_detect = e.time;
      }
      if (is_decision(e.kind)) {
        if (!r.decided) {
          r.t_decide = e.time;
          r.first_decision = e;
        }
        r.decided = true;
        r.last_decision = e;
        r.first_channels = mon.matcher().first_channels();
        for (int i = 0; i < 4; ++i) {
          r.magnitude[i] = mon.matcher().symbol(i).magnitude;
          r.slope[i] = mon.matcher().symbol(i).slope;
        }
      }
    }
  }
  r.final_status = mon.matcher().status();
  return r;
}

NominalStats monitor_nominal(const hstmon::sim::ThesisMeasurements& log, const Mon::Config& cfg) {
  Mon mon = make_monitor(log, cfg);
  NominalStats st;
  Mon::Measurement m;
  m.valid = 0xF;
  Mon::Event e;
  bool want_decision = false;
  for (const auto& s : log) {
    for (int i = 0; i < 4; ++i) m.y[i] = s.y[static_cast<std::size_t>(i)];
    mon.step(s.t, s.u, m);
    ++st.ticks;
    st.health |= mon.health();
    if (mon.evaluator().alarm() != 0) ++st.alarm_ticks;
    while (mon.pop_event(e)) {
      if (e.kind == MatchEventKind::kDetected) {
        ++st.detections;
        st.detection_times.push_back(e.time);
        st.alarm_channels.push_back(mon.evaluator().alarm());
        want_decision = true;
      } else if (want_decision && is_decision(e.kind)) {
        st.first_candidates.emplace_back(e.count ? e.candidate[0].name : "(none)");
        want_decision = false;
      }
    }
  }
  return st;
}

hstmon::sim::ThesisScenario nominal_segment(std::uint64_t seed, double duration, bool load_changes) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> kp_draw(0.65, 1.6);
  std::uniform_int_distribution<int> op_draw(0, 2);
  hstmon::sim::ThesisScenario sc;
  sc.name = load_changes ? "nominal_load_changes" : "nominal_constant";
  sc.duration = duration;
  sc.initial = hstmon::sim::InitialCondition::kSteady;
  Inputs u;
  if (!load_changes) {
    u.kp = hstmon::sim::kThesisKpNominal * kOperatingPoints[op_draw(rng)].kp_factor;
    sc.schedule = {{0.0, u}};
    return sc;
  }
  double f = kp_draw(rng);
  u.kp = hstmon::sim::kThesisKpNominal * f;
  sc.schedule = {{0.0, u}};
  constexpr double kEvery = 10.0, kRamp = 4.0, kStep = 0.1;
  for (double t0 = kEvery; t0 + kRamp < duration; t0 += kEvery) {
    const double target = kp_draw(rng);
    const int n = static_cast<int>(std::lround(kRamp / kStep));
    for (int k = 1; k <= n; ++k) {
      const double fk = f + (target - f) * static_cast<double>(k) / static_cast<double>(n);
      u.kp = hstmon::sim::kThesisKpNominal * fk;
      sc.schedule.push_back({t0 + static_cast<double>(k - 1) * kStep, u});
    }
    f = target;
  }
  return sc;
}

std::vector<std::vector<int>> isolable_classes(const hstmon::FaultSignature* table, int count, double tie_margin) {
  auto compatible = [](int a, int b) { return a == hstmon::kQualAny || b == hstmon::kQualAny || a == b; };
  auto same = [&](const hstmon::FaultSignature& a, const hstmon::FaultSignature& b) {
    if (a.sensor != b.sensor) return false;
    for (int i = 0; i < hstmon::kFdiChannels; ++i) {
      if (!compatible(a.channel[i].magnitude, b.channel[i].magnitude) ||
          !compatible(a.channel[i].slope, b.channel[i].slope) || a.channel[i].order != b.channel[i].order) {
        return false;
      }
    }
    double na = 0, nb = 0, dot = 0;
    for (int i = 0; i < hstmon::kFdiChannels; ++i) {
      na += static_cast<double>(a.direction[i]) * a.direction[i];
      nb += static_cast<double>(b.direction[i]) * b.direction[i];
      dot += static_cast<double>(a.direction[i]) * b.direction[i];
    }
    if (na == 0.0 || nb == 0.0) return na == nb;
    const double c = dot / std::sqrt(na * nb);
    return std::acos(std::fmin(1.0, std::fmax(-1.0, c))) < tie_margin;
  };
  std::vector<std::vector<int>> cls(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    for (int j = 0; j < count; ++j) {
      if (same(table[k], table[j])) cls[static_cast<std::size_t>(k)].push_back(j);
    }
  }
  return cls;
}

int row_index(const std::string& name) {
  for (int k = 0; k < hstmon::kThesisSignatureCount; ++k) {
    if (name == hstmon::kThesisSignatures[k].name) return k;
  }
  return -1;
}

double predicted_visibility(const FaultCase& f, const Inputs& u, const Mon::Config& cfg) {
  if (f.target == Target::kSensor) return -1.0;
  using Model = hstmon::ThesisReducedModel<double>;
  Model model{Params{}};
  model.set_inputs(u);
  double bound[hstmon::kFdiChannels];
  if (hstmon::thesis_model_bound(model, cfg.uncertainty, bound) != hstmon::Status::kOk) return -1.0;
  Params p;
  Inputs v = u;
  if (f.target == Target::kParam) p.*(f.param) *= f.factor;
  if (f.target == Target::kInput) v.*(f.input) *= f.factor;
  Model::Output y0, y1;
  if (!hstmon::steady_outputs(Params{}, u, y0) || !hstmon::steady_outputs(p, v, y1)) return -1.0;
  double r = 0.0;
  for (int i = 0; i < hstmon::kFdiChannels; ++i) {
    const double thr = bound[i] + cfg.evaluator.k_drift * cfg.evaluator.noise_sigma[i];
    r = std::fmax(r, std::fabs(y1[i] - y0[i]) / thr);
  }
  return r;
}

}  // namespace hstmon_campaign
