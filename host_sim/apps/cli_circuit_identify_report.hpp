#pragma once
// `identify --circuit --report DIR`: the fitted parameters in an engineer's units, the
// operating points with each channel's residual before and after, and a figure of them.
#include <string>

#include "cli_circuit_identify.hpp"
#include "cli_circuit_report.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_ident/circuit_fit.hpp"

namespace hstmon::cli {

/// The report of one fit; `text` is the command's own text output.
CircuitReport circuit_identify_report(const CircuitIdentifyArgs& a, const circuit_tools::LoadedCircuit& c,
                                      const ident::CircuitFitResult& r, const std::string& text);

}  // namespace hstmon::cli
