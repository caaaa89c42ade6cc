#include "sim_compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "hstmon_host/circuit_units.hpp"

namespace hstmon::sim_app {

std::string compare_text(const host::CircuitFile& c, const circuit_tools::CircuitLog& measured,
                         const circuit_tools::CircuitLog& simulated) {
  // The rows at the same time in both (the re-run writes the log's own row times).
  std::size_t rows = 0;
  while (rows < measured.rows() && rows < simulated.rows() &&
         std::fabs(measured.t[rows] - simulated.t[rows]) <= 1e-9 * std::max(1.0, std::fabs(measured.t[rows]))) {
    ++rows;
  }
  std::string out = fmt::format("residual measured - simulated ({}, {} rows):\n", measured.path, rows);
  std::size_t width = 0;
  for (const auto& s : c.sensors) width = std::max(width, s.column.size() + (s.unit.empty() ? 0 : s.unit.size() + 2));
  for (std::size_t ch = 0; ch < c.sensors.size(); ++ch) {
    const host::CircuitSensor& s = c.sensors[ch];
    const bool si = s.unit.empty() || s.unit == "-";
    const std::string name = si ? s.column : s.column + "[" + s.unit + "]";
    const host::UnitResult u = host::parse_circuit_unit(s.quantity, s.unit);
    const host::UnitConversion conv = u.ok() ? u.conversion : host::UnitConversion{};
    const std::vector<double>* m = ch < measured.sensors.size() ? &measured.sensors[ch] : nullptr;
    if (m == nullptr || m->size() != measured.rows() || ch >= simulated.sensors.size() || rows == 0) {
      out += fmt::format("  {:<{}}  not in the log\n", name, width);
      continue;
    }
    double sum = 0.0, sum2 = 0.0, worst = 0.0, t_worst = measured.t[0];
    for (std::size_t k = 0; k < rows; ++k) {
      const double r = conv.from_si((*m)[k]) - conv.from_si(simulated.sensors[ch][k]);
      sum += r;
      sum2 += r * r;
      if (std::fabs(r) > std::fabs(worst)) {
        worst = r;
        t_worst = measured.t[k];
      }
    }
    const double n = static_cast<double>(rows);
    out += fmt::format("  {:<{}}  mean {:+.4g}  rms {:.4g}  max {:+.4g} at t = {} s\n", name, width, sum / n,
                       std::sqrt(sum2 / n), worst, t_worst);
  }
  return out;
}

}  // namespace hstmon::sim_app
