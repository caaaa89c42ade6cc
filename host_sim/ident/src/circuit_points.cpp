// The operating points of a circuit's logs (circuit_fit.hpp): stretches where the logged
// inputs hold AND the outputs are steady. An event the log does not record (a bypass valve
// switching) steps the outputs while the inputs hold still; averaging across it gives a
// point the machine never sat at, so a held stretch is split where an output steps.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_host/number_text.hpp"
#include "hstmon_ident/circuit_fit.hpp"
#include "hstmon_ident/input_hold.hpp"

namespace hstmon::ident {

namespace {

using Model = host::HostCircuitModel;

// A change `si` of sensor `name` in its display unit ("-2.79 rpm"); SI if no sensor has that name.
std::string sensor_text(const circuit_tools::LoadedCircuit& c, const std::string& name, double si) {
  for (const host::CircuitSensor& s : c.file.sensors) {
    if (s.name == name) return host::display_unit(s.quantity, s.unit).text(si, 3, true);
  }
  return host::number_text(si, 3) + " (SI)";
}

constexpr double kStepZ = 8.0;            // an output step, in standard errors of the block means
constexpr double kBlock = 0.05;           // block length for the step search [s]
constexpr double kStepSigmas = 3.0;       // … and in the sensor's σ (a drift of noise is not an event)
constexpr double kTrendZ = 4.0;           // a trend, in standard errors of the line's rise over the stretch

struct Stretch {
  std::size_t a = 0, b = 0;  // rows [a, b)
};

// Where the outputs step inside rows [a, b): the block boundary with the largest
// two-sided change of block means on some channel, if beyond kStepZ standard errors and
// beyond 3 of the sensor's σ (a real change, not a drift of noise); rows.size() otherwise.
std::size_t find_step(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log, Stretch s,
                      std::string& channel, double& size) {
  const std::size_t none = log.rows();
  const double span = log.t[s.b - 1] - log.t[s.a];
  if (span < 4.0 * kBlock) return none;
  // Block edges.
  std::vector<std::size_t> edge{s.a};
  for (std::size_t k = s.a + 1; k < s.b; ++k) {
    if (log.t[k] - log.t[edge.back()] >= kBlock) edge.push_back(k);
  }
  if (edge.back() != s.b) edge.push_back(s.b);
  const std::size_t nb = edge.size() - 1;
  if (nb < 4) return none;
  std::size_t best_at = none;
  double best_z = kStepZ;
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    if (ch >= log.sensors.size() || log.sensors[ch].size() != log.rows()) continue;
    const std::vector<double>& y = log.sensors[ch];
    std::vector<double> m(nb);
    for (std::size_t j = 0; j < nb; ++j) {
      double sum = 0.0;
      for (std::size_t k = edge[j]; k < edge[j + 1]; ++k) sum += y[k];
      m[j] = sum / static_cast<double>(edge[j + 1] - edge[j]);
    }
    const double rows_per_block = static_cast<double>(s.b - s.a) / static_cast<double>(nb);
    const double sigma = circuit_tools::sensor_sigma(c.file.sensors[ch]);
    const double sb = std::max(column_noise(m), sigma / std::sqrt(rows_per_block));
    if (!(sb > 0.0)) continue;
    // Binary segmentation: the split between blocks with the largest |mean left − mean right|.
    double total = 0.0;
    for (double v : m) total += v;
    double left = 0.0;
    for (std::size_t j = 1; j < nb; ++j) {
      left += m[j - 1];
      const double nl = static_cast<double>(j), nr = static_cast<double>(nb - j);
      const double d = (total - left) / nr - left / nl;
      const double z = std::fabs(d) / (sb * std::sqrt(1.0 / nl + 1.0 / nr));
      if (z > best_z && std::fabs(d) > kStepSigmas * sigma) {
        best_z = z;
        best_at = edge[j];
        channel = c.file.sensors[ch].name;
        size = d;
      }
    }
  }
  return best_at;
}

// The channel whose least-squares line over rows [a, b) moves furthest, in sensor σ; the
// stretch is not steady when that exceeds kStepSigmas (a start still settling). A rise
// within kTrendZ of its own noise (white noise of σ about a line: the rise's standard error
// is duration/√Σ(t − t̄)² in σ, about 1 σ over 10 rows, 0.08 σ over 2 000) counts as none:
// noise alone draws a 3 σ rise on a few rows of a DAS log.
double trend_sigmas(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log, Stretch s,
                    std::string& channel) {
  double worst = 0.0;
  const double n = static_cast<double>(s.b - s.a);
  double tm = 0.0;
  for (std::size_t k = s.a; k < s.b; ++k) tm += log.t[k];
  tm /= n;
  double stt = 0.0;
  for (std::size_t k = s.a; k < s.b; ++k) stt += (log.t[k] - tm) * (log.t[k] - tm);
  if (!(stt > 0.0)) return 0.0;
  const double noise = (log.t[s.b - 1] - log.t[s.a]) / std::sqrt(stt);
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    if (ch >= log.sensors.size() || log.sensors[ch].size() != log.rows()) continue;
    const double sigma = circuit_tools::sensor_sigma(c.file.sensors[ch]);
    if (!(sigma > 0.0)) continue;
    double ym = 0.0;
    for (std::size_t k = s.a; k < s.b; ++k) ym += log.sensors[ch][k];
    ym /= n;
    double sty = 0.0;
    for (std::size_t k = s.a; k < s.b; ++k) sty += (log.t[k] - tm) * (log.sensors[ch][k] - ym);
    const double moved = std::fabs(sty / stt) * (log.t[s.b - 1] - log.t[s.a]) / sigma;
    if (moved > worst && moved > kTrendZ * noise) {
      worst = moved;
      channel = c.file.sensors[ch].name;
    }
  }
  return worst;
}

void add_point(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log, std::size_t index,
               Stretch s, const Model::Inputs& u, std::vector<CircuitOperatingPoint>& out) {
  CircuitOperatingPoint p;
  p.log = index;
  p.t0 = log.t[s.a];
  p.t1 = log.t[s.b - 1];
  p.n = s.b - s.a;
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) p.inputs.push_back(u.v[i]);
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    double mean = std::nan("");
    if (ch < log.sensors.size() && log.sensors[ch].size() == log.rows()) {
      double sum = 0.0;
      for (std::size_t k = s.a; k < s.b; ++k) sum += log.sensors[ch][k];
      mean = sum / static_cast<double>(p.n);
    }
    p.mean.push_back(mean);
  }
  out.push_back(std::move(p));
}

// The first row of [from, end) at or after time t.
std::size_t row_at(const circuit_tools::CircuitLog& log, std::size_t from, std::size_t end, double t) {
  while (from < end && log.t[from] < t) ++from;
  return from;
}

void find_points(const circuit_tools::LoadedCircuit& c, const host::HostCircuit& desc, const circuit_tools::CircuitLog& log,
                 std::size_t index, const CircuitPointRules& rules, std::vector<CircuitOperatingPoint>& out,
                 std::vector<std::string>& notes) {
  const double min_duration = rules.assume_steady ? 0.0 : rules.min_duration;
  const std::size_t min_samples = rules.assume_steady ? 1 : std::max<std::size_t>(1, rules.min_samples);
  const std::size_t rows = log.rows();
  const std::size_t n_in = c.file.inputs.size();
  auto logged = [&](std::size_t i) { return i < log.inputs.size() && log.inputs[i].size() == rows; };
  auto input_at = [&](std::size_t i, std::size_t row) { return logged(i) ? log.inputs[i][row] : c.values.inputs.v[i]; };
  std::vector<double> tolerance(n_in, 0.0);
  for (std::size_t i = 0; i < n_in; ++i) {
    if (logged(i)) tolerance[i] = kInputNoise * column_noise(log.inputs[i]);
  }
  std::size_t start = 0;
  double prev_rate = 0.0;  // the previous held stretch's slowest rate [1/s]; 0 before the first
  while (start < rows) {
    std::size_t end = start + 1;
    for (; end < rows; ++end) {
      bool held = true;
      for (std::size_t i = 0; i < n_in && held; ++i) {
        const double a = input_at(i, end), b = input_at(i, start);
        held = a == b || std::fabs(a - b) <= std::max(kInputRelative * std::fabs(b), tolerance[i]);
      }
      if (!held) break;
    }
    // The held inputs: their mean over the stretch (a measured input scatters).
    Model::Inputs u = c.values.inputs;
    for (std::size_t i = 0; i < n_in; ++i) {
      double sum = 0.0;
      for (std::size_t k = start; k < end; ++k) sum += input_at(i, k);
      u.v[i] = sum / static_cast<double>(end - start);
    }
    const Model m(desc, c.values.params, u);
    Model::State xs;
    const double rate = m.valid() && m.steady_state(xs) ? m.slowest_rate(xs) : 0.0;
    // The machine leaves the last point at that point's pace as much as it reaches this
    // one at its own (the monitor's settle, model_monitor.hpp): the slower of the two.
    const double pace = prev_rate > 0.0 && rate > 0.0 ? std::min(rate, prev_rate) : rate;
    prev_rate = rate;
    const double settle = rules.assume_steady ? 0.0 : pace > 0.0 ? 5.0 / pace : HUGE_VAL;
    // Steady pieces: after the settle, split where an output steps (then settle again).
    std::vector<Stretch> todo{{row_at(log, start, end, log.t[start] + settle), end}};
    while (!todo.empty()) {
      const Stretch s = todo.back();
      todo.pop_back();
      if (s.a >= s.b || s.b - s.a < min_samples || log.t[s.b - 1] - log.t[s.a] < min_duration) continue;
      std::string channel;
      double size = 0.0;
      const std::size_t at = find_step(c, log, s, channel, size);
      if (at >= rows) {
        const double moved = trend_sigmas(c, log, s, channel);
        if (moved <= kStepSigmas) {
          add_point(c, log, index, s, u, out);
          continue;
        }
        char text[200];
        std::snprintf(text, sizeof text,
                      "%s: t = %.4g … %.4g s left out: %s still moves by %.3g sigma over it while the inputs hold "
                      "(not steady)",
                      log.path.c_str(), log.t[s.a], log.t[s.b - 1], channel.c_str(), moved);
        notes.emplace_back(text);
        continue;
      }
      if (!rules.steps_are_settings) {
        char text[240];
        std::snprintf(text, sizeof text,
                      "%s: %s steps by %s at t = %.4g s while the inputs hold (an event the log does not "
                      "record, or a start still settling): the stretch is split there and each side judged alone",
                      log.path.c_str(), channel.c_str(), sensor_text(c, channel, size).c_str(), log.t[at]);
        notes.emplace_back(text);
      }
      todo.push_back({s.a, at});
      todo.push_back({row_at(log, at, s.b, log.t[at] + settle), s.b});
    }
    start = end;
  }
}

}  // namespace

std::vector<CircuitOperatingPoint> circuit_operating_points(const circuit_tools::LoadedCircuit& c,
                                                            const std::vector<circuit_tools::CircuitLog>& logs,
                                                            const CircuitPointRules& rules,
                                                            std::vector<std::string>* notes) {
  host::HostCircuit desc = c.file.circuit;
  desc.stiff_mask = 0;
  std::vector<CircuitOperatingPoint> out;
  std::vector<std::string> said;
  for (std::size_t l = 0; l < logs.size(); ++l) find_points(c, desc, logs[l], l, rules, out, said);
  std::sort(out.begin(), out.end(), [](const CircuitOperatingPoint& a, const CircuitOperatingPoint& b) {
    return a.log != b.log ? a.log < b.log : a.t0 < b.t0;
  });
  if (notes != nullptr) notes->insert(notes->end(), said.begin(), said.end());
  return out;
}

std::vector<CircuitOperatingPoint> circuit_operating_points(const circuit_tools::LoadedCircuit& c,
                                                            const std::vector<circuit_tools::CircuitLog>& logs,
                                                            double min_duration, std::vector<std::string>* notes) {
  CircuitPointRules rules;
  rules.min_duration = min_duration;
  return circuit_operating_points(c, logs, rules, notes);
}

std::size_t distinct_settings(const std::vector<CircuitOperatingPoint>& points) {
  std::vector<const std::vector<double>*> seen;
  for (const CircuitOperatingPoint& p : points) {
    const bool known = std::any_of(seen.begin(), seen.end(), [&](const std::vector<double>* q) {
      for (std::size_t i = 0; i < p.inputs.size() && i < q->size(); ++i) {
        if (std::fabs(p.inputs[i] - (*q)[i]) > kInputRelative * std::fabs((*q)[i]) + 1e-12) return false;
      }
      return true;
    });
    if (!known) seen.push_back(&p.inputs);
  }
  return seen.size();
}

double column_noise(const std::vector<double>& v) {
  if (v.size() < 3) return 0.0;
  std::vector<double> d;
  d.reserve(v.size() - 1);
  for (std::size_t k = 1; k < v.size(); ++k) d.push_back(std::fabs(v[k] - v[k - 1]));
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return 1.4826 * d[d.size() / 2] / std::sqrt(2.0);
}

}  // namespace hstmon::ident
