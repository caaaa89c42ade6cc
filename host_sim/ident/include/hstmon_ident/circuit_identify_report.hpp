#pragma once
/// @file circuit_identify_report.hpp
/// What `identify --circuit` says, for the CLI and the Python module alike: its text
/// (the fitted parameters, their errors and the monitor's new bound, the residual RMS
/// before and after) and its report folder (the parameters in an engineer's units, the
/// operating points with each channel's residual before and after, and a figure of them).
#include <cstddef>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_ident/circuit_fit.hpp"
#include "hstmon_plot/circuit_report.hpp"

namespace hstmon::ident {

/// What a run of identify --circuit was given, as its text and report name it.
struct CircuitIdentifyRun {
  std::string circuit;            ///< the circuit file as given
  std::vector<std::string> logs;  ///< the logs as given (a DataFrame: a label)
  std::string out;                ///< the parameter file written ("" = none)
  std::string header;             ///< the C++ header written ("" = none)
};

/// A channel's agreement at the operating points after the fit, in the form of the
/// thesis's Table 2.3 but measured − model: the relative error (measured − model)/measured
/// averaged, and its RMS, over the points that log the channel.
struct ChannelAgreement {
  std::string channel;  ///< the sensor's name
  std::size_t points = 0;
  double mean = 0.0;  ///< average relative error [-]
  double rms = 0.0;   ///< RMS relative error [-]
};

/// Per sensor channel of c, from the points' fitted residuals (`after`, in σ); a channel
/// no point logs, or whose readings are all 0, is left out.
std::vector<ChannelAgreement> channel_agreement(const circuit_tools::LoadedCircuit& c, const CircuitFitResult& r);

/// The text `hstmon identify --circuit` prints.
std::string circuit_identify_text(const CircuitIdentifyRun& run, const circuit_tools::LoadedCircuit& c,
                                  const CircuitFitResult& r);

/// The report of one fit; `text` is the command's own text output.
sim::CircuitReport circuit_identify_report(const CircuitIdentifyRun& run, const circuit_tools::LoadedCircuit& c,
                                           const CircuitFitResult& r, const std::string& text);

}  // namespace hstmon::ident
