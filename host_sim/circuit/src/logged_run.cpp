#include "hstmon_circuit/logged_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "hstmon_host/circuit_units.hpp"

namespace hstmon::circuit_tools {

namespace {

// A column's name with its unit as the circuit file gives it: "n_e[rpm]", "throttle".
std::string column_with_unit(const host::CircuitInput& in) {
  if (in.unit.empty() || in.unit == "-") return in.column;
  return in.column + "[" + in.unit + "]";
}

// An input's value in the unit the circuit file gives its column: "300 N*m", "0.7".
std::string value_with_unit(const host::CircuitInput& in, double si) {
  const host::UnitResult u = host::parse_circuit_unit(in.quantity, in.unit);
  if (!u.ok() || in.unit.empty() || in.unit == "-") return fmt::format("{:g}", si);
  return fmt::format("{:g} {}", u.conversion.from_si(si), in.unit);
}

double median_period(const std::vector<double>& t) {
  std::vector<double> d;
  d.reserve(t.size());
  for (std::size_t k = 1; k < t.size(); ++k) d.push_back(t[k] - t[k - 1]);
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

}  // namespace

std::optional<host::SourceError> logged_run(const CircuitLog& in, const LoadedCircuit& c, InputHold hold,
                                            double duration, double rate, CircuitSimOptions& o,
                                            std::vector<std::string>& notes) {
  const host::CircuitFile& f = c.file;
  const std::size_t line = in.header_line > 0 ? in.header_line : 1;
  InputProfile prof;
  prof.hold = hold;
  prof.t = in.t;
  prof.inputs.assign(f.inputs.size(), {});
  std::vector<std::string> absent;
  for (std::size_t i = 0; i < f.inputs.size(); ++i) {
    if (i < in.inputs.size() && in.rows() > 0 && in.inputs[i].size() == in.rows()) {
      prof.inputs[i] = in.inputs[i];
    } else {
      absent.push_back(f.inputs[i].name + " = " + value_with_unit(f.inputs[i], c.values.inputs.v[i]));
    }
  }
  if (!prof.any()) {
    std::string wanted;
    for (const auto& i : f.inputs) wanted += (wanted.empty() ? "" : ", ") + column_with_unit(i);
    return host::SourceError{in.path, line, 1,
                             "--inputs: no input column of circuit " + f.name +
                                 " in the header (its inputs' columns: " + wanted + "): nothing to drive the run with"};
  }
  if (in.rows() < 2) {
    return host::SourceError{in.path, line, 1,
                             "--inputs: the log has " + std::to_string(in.rows()) +
                                 " row; a logged run needs at least 2 (its span and row period)"};
  }
  if (!absent.empty()) {
    std::string list;
    for (const auto& a : absent) list += (list.empty() ? "" : ", ") + a;
    const char* const plural = absent.size() > 1 ? "s" : "";
    notes.push_back(in.path + ":" + std::to_string(line) + ":1: note: input" + plural + " not in the log, held at " +
                    (c.params_path.empty() ? "the circuit file's" : "the parameter file's") + " value" + plural + ": " +
                    list);
  }
  const double t0 = in.t.front();
  const double span = in.t.back() - t0;
  const double period = median_period(in.t);
  o.start_time = t0;
  o.duration = duration > 0.0 ? duration : span;
  o.rate = rate > 0.0 ? rate : 1.0 / period;
  const double end = t0 + o.duration;
  const double slack = 1e-9 * std::max(period, 1e-9);
  o.sample_times.clear();
  if (rate > 0.0) {
    const double count = std::floor(o.duration * rate + 1e-9) + 1.0;
    if (count > 1e7) {
      return host::SourceError{in.path, line, 1, "more than 10 million rows: lower --duration or --rate"};
    }
    for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
      o.sample_times.push_back(t0 + static_cast<double>(k) / rate);
    }
  } else {
    for (const double t : in.t) {
      if (t > end + slack) break;
      o.sample_times.push_back(t);
    }
    if (end > in.t.back() + slack) {
      const double more = std::floor((end - in.t.back()) / period + 1e-9);
      if (more + static_cast<double>(in.rows()) > 1e7) {
        return host::SourceError{in.path, line, 1, "more than 10 million rows: lower --duration"};
      }
      for (std::size_t j = 1; j <= static_cast<std::size_t>(more); ++j) {
        o.sample_times.push_back(in.t.back() + static_cast<double>(j) * period);
      }
    }
  }
  o.profile = std::move(prof);
  return std::nullopt;
}

}  // namespace hstmon::circuit_tools
