#include "hstmon_circuit/circuit_faults.hpp"

#include <cmath>
#include <cstddef>
#include <set>
#include <stdexcept>

#include "hstmon/circuit/monitor_setup.hpp"
#include "hstmon/circuit/setting_shift.hpp"
#include "hstmon_host/circuit_units.hpp"

namespace hstmon::circuit_tools {

namespace {

using Model = host::HostCircuitModel;
using host::CircuitQuantity;
constexpr int kN = host::CircuitCap::kChannels;

// Steady outputs divided by each channel's σ for the parameters p; false if none.
bool scaled_steady(const host::HostCircuit& desc, const Model::Params& p, const Model::Inputs& u,
                   const std::vector<double>& sigma, double (&z)[kN]) {
  const Model m(desc, p, u);
  Model::Output y;
  if (!m.valid() || !circuit::steady_outputs(m, y)) return false;
  for (int i = 0; i < kN; ++i) z[i] = i < static_cast<int>(sigma.size()) ? y[i] / sigma[static_cast<std::size_t>(i)] : 0.0;
  return true;
}

std::int8_t sign_of(double v) { return v > 0.0 ? std::int8_t{kQualPlus} : std::int8_t{kQualMinus}; }

}  // namespace

double sensor_sigma(const host::CircuitSensor& s) { return circuit::sensor_sigma(s.noise, s.lo, s.hi); }

bool moves_steady_state(const host::CircuitParam& p) {
  if (p.literal) return false;
  switch (p.quantity) {
    case CircuitQuantity::kStiffness:
    case CircuitQuantity::kVolume:
    case CircuitQuantity::kInertia:
    case CircuitQuantity::kDensity:
      return false;
    default:
      return true;
  }
}

circuit::CircuitUncertainty<double, host::CircuitCap> default_uncertainty(const host::CircuitFile& f) {
  circuit::CircuitUncertainty<double, host::CircuitCap> e;
  for (std::size_t k = 0; k < f.params.size(); ++k) e.rel[k] = moves_steady_state(f.params[k]) ? 0.02 : 0.0;
  return e;
}

circuit::CircuitUncertainty<double, host::CircuitCap> circuit_uncertainty(const LoadedCircuit& c) {
  circuit::CircuitUncertainty<double, host::CircuitCap> e = default_uncertainty(c.file);
  const auto& stated = c.values.uncertainty;
  for (std::size_t k = 0; k < stated.size() && k < c.file.params.size(); ++k) {
    if (stated[k]) e.rel[k] = *stated[k];
  }
  return e;
}

void apply_param_fault(const host::CircuitFile& c, Model::Params& p, const Model::Params& nominal, std::size_t k,
                       double factor) {
  const circuit::SettingCompanions with = circuit::setting_companions(c.circuit, static_cast<int>(k));
  hstmon::apply_param_fault(p, nominal, static_cast<int>(k), with.index, factor);
}

namespace {

// The table, or with `only` its rows of those faults (and every sensor row).
CircuitFaultTable fault_table(const LoadedCircuit& c, const std::set<std::string>* only) {
  CircuitFaultTable t;
  host::HostCircuit desc = c.file.circuit;
  desc.stiff_mask = 0;  // the full equations: steady states do not depend on it
  const std::size_t channels = c.file.sensors.size();
  std::vector<double> sigma(channels);
  for (std::size_t ch = 0; ch < channels; ++ch) sigma[ch] = sensor_sigma(c.file.sensors[ch]);
  const Model::Inputs& u = c.values.inputs;
  double z0[kN];
  if (!scaled_steady(desc, c.values.params, u, sigma, z0)) {
    throw std::runtime_error("circuit " + c.file.name + ": no steady state at the nominal inputs: no fault table");
  }
  struct Pending {
    std::string name;
    CircuitFaultTable::Row row;
    double gain = 0.0;
  };
  std::vector<Pending> pending;
  // One fault: `name`+ and `name`−, the quantity scaled by 1 ± 0.1 and 1 ± 0.3 by set().
  auto add_fault = [&](const std::string& base, const auto& set) {
    for (const int side : {+1, -1}) {
      const std::string name = base + (side > 0 ? "+" : "-");
      if (only != nullptr && only->count(name) == 0) continue;
      double z10[kN], z30[kN];
      Model::Params p = c.values.params;
      Model::Inputs v = u;
      set(p, v, 1.0 + side * 0.1);
      if (!scaled_steady(desc, p, v, sigma, z10)) {
        t.notes.push_back(name + ": no steady state for a 10 % fault at the nominal inputs: no row");
        continue;
      }
      p = c.values.params;
      v = u;
      set(p, v, 1.0 + side * 0.3);
      const bool big = scaled_steady(desc, p, v, sigma, z30);
      if (!big) t.notes.push_back(name + ": no steady state for a 30 % fault: signs from the 10 % fault alone");
      Pending r{name, {}, 0.0};
      r.row.sensor = false;
      double visible = 0.0, norm = 0.0;
      for (int i = 0; i < kN; ++i) {
        const double d10 = z10[i] - z0[i];
        const double d30 = big ? z30[i] - z0[i] : d10;
        visible = std::fmax(visible, std::fabs(d30));
        std::int8_t mag = kQualAny;
        if (std::fabs(d30) < 1.0 && std::fabs(d10) < 1.0) {
          mag = kQualZero;
        } else if (d10 != 0.0 && sign_of(d10) == sign_of(d30)) {
          mag = sign_of(d30);
        }
        r.row.channel[i] = ChannelSignature{mag, kQualAny, 0};
        norm += d10 * d10;
      }
      if (visible < 1.0) {
        t.undetectable.push_back(name);
        continue;
      }
      norm = std::sqrt(norm);
      r.gain = norm;
      for (int i = 0; i < kN; ++i) r.row.direction[i] = norm > 0.0 ? static_cast<float>((z10[i] - z0[i]) / norm) : 0.0f;
      pending.push_back(std::move(r));
    }
  };
  for (std::size_t k = 0; k < c.file.params.size(); ++k) {
    if (!moves_steady_state(c.file.params[k])) continue;
    add_fault(c.file.params[k].name, [&c, k](Model::Params& p, Model::Inputs&, double f) {
      apply_param_fault(c.file, p, c.values.params, k, f);
    });
  }
  // A logged input can be wrong too: the machine's true value differs from the log's
  // (the thesis's kp− is the PRV blockage under an unchanged logged setting).
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) {
    if (u.v[i] == 0.0) continue;  // a relative fault of 0 is none
    add_fault(c.file.inputs[i].name, [i](Model::Params&, Model::Inputs& v, double f) { v.v[i] *= f; });
  }
  for (std::size_t ch = 0; ch < channels; ++ch) {
    Pending r{"sensor_" + c.file.sensors[ch].name, {}, 0.0};
    r.row.sensor = true;
    for (int i = 0; i < kN; ++i) {
      const bool own = i == static_cast<int>(ch);
      r.row.channel[i] = own ? ChannelSignature{kQualAny, kQualAny, 0} : ChannelSignature{kQualZero, kQualZero, 0};
      r.row.direction[i] = 0.0f;
    }
    pending.push_back(std::move(r));
  }
  // Names first, then the rows pointing at them: the strings do not move once placed.
  t.names.reserve(pending.size());
  for (const Pending& r : pending) {
    t.names.push_back(r.name);
    t.gains.push_back(r.gain);
  }
  t.rows.reserve(pending.size());
  for (std::size_t j = 0; j < pending.size(); ++j) {
    t.rows.push_back(pending[j].row);
    t.rows.back().name = t.names[j].c_str();
  }
  return t;
}

}  // namespace

CircuitFaultTable circuit_fault_table(const LoadedCircuit& c) { return fault_table(c, nullptr); }

CircuitFaultTable circuit_fault_rows(const LoadedCircuit& c, const std::vector<std::string>& faults) {
  const std::set<std::string> only(faults.begin(), faults.end());
  return fault_table(c, &only);
}

}  // namespace hstmon::circuit_tools
