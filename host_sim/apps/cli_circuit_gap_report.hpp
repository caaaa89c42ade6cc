#pragma once
// `gap --circuit --report DIR`: the verdict, where the gap lies per channel, every
// candidate effect's size and how far it shrinks the check log's residual, and a figure.
#include <string>

#include "cli_circuit_gap.hpp"
#include "cli_circuit_report.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_gap/circuit_gap.hpp"

namespace hstmon::cli {

/// The report of one gap run; `verdict` in words, `text` the command's own text output.
CircuitReport circuit_gap_report(const CircuitGapArgs& a, const circuit_tools::LoadedCircuit& c,
                                 const gap::CircuitGapResult& r, const std::string& verdict, const std::string& text);

}  // namespace hstmon::cli
