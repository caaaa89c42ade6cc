#pragma once
/// @file bound_lead.hpp
/// What makes up each channel's model bound where the machine runs: the parameter whose
/// stated uncertainty moves the channel most on its own, and its share of the bound. It
/// answers "which value would I pin down (hstmon identify --circuit) to see smaller
/// faults on this channel?" (issue 30: a blanket 2 % on the pump curve hid an 8 % motor
/// displacement loss, and nothing said so).

#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::circuit_tools {

/// One channel's bound and what leads it.
struct ChannelBoundLead {
  double bound = 0.0;  ///< the model bound [SI]
  int param = -1;      ///< the leading parameter's index, −1 where no uncertain parameter moves the channel
  double share = 0.0;  ///< its own change over the bound, 0 … 1 [-]
};

/// Per sensor channel, at inputs u, with c's uncertainties (circuit_uncertainty). Empty
/// when the model has no steady state there.
/// @param model  the monitor's model (copied; its description must outlive the call)
std::vector<ChannelBoundLead> bound_leads(const LoadedCircuit& c, const host::HostCircuitModel& model,
                                          const host::HostCircuitModel::Inputs& u);

/// The leading parameter's name ("" where nothing leads).
std::string lead_name(const LoadedCircuit& c, const ChannelBoundLead& lead);

/// "Dp 64 %" for one channel ("" where nothing leads).
std::string lead_text(const LoadedCircuit& c, const ChannelBoundLead& lead);

}  // namespace hstmon::circuit_tools
