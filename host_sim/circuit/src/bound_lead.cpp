#include "hstmon_circuit/bound_lead.hpp"

#include <cmath>
#include <cstdio>

#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon_circuit/circuit_faults.hpp"

namespace hstmon::circuit_tools {

std::vector<ChannelBoundLead> bound_leads(const LoadedCircuit& c, const host::HostCircuitModel& model,
                                          const host::HostCircuitModel::Inputs& u) {
  using Model = host::HostCircuitModel;
  using Bound = ModelBound<Model>;
  Model m = model;
  m.set_inputs(u);
  double b[circuit::kExtent<Model::kOutputs>] = {};
  circuit::BoundLead<double, Model::kOutputs> lead;
  if (Bound::compute(m, circuit_uncertainty(c), b, nullptr, &lead) != Status::kOk) return {};
  std::vector<ChannelBoundLead> out(c.file.sensors.size());
  for (std::size_t ch = 0; ch < out.size() && ch < static_cast<std::size_t>(Model::kOutputs); ++ch) {
    out[ch].bound = b[ch];
    out[ch].param = lead.param[ch];
    out[ch].share = b[ch] > 0.0 ? std::fmin(1.0, lead.change[ch] / b[ch]) : 0.0;
  }
  return out;
}

std::string lead_name(const LoadedCircuit& c, const ChannelBoundLead& lead) {
  if (lead.param < 0 || static_cast<std::size_t>(lead.param) >= c.file.params.size()) return "";
  return c.file.params[static_cast<std::size_t>(lead.param)].name;
}

std::string lead_text(const LoadedCircuit& c, const ChannelBoundLead& lead) {
  const std::string name = lead_name(c, lead);
  if (name.empty()) return name;
  char b[64];
  std::snprintf(b, sizeof b, " %.0f %%", 100.0 * lead.share);
  return name + b;
}

}  // namespace hstmon::circuit_tools
