#pragma once
/// @file circuit_gap_report.hpp
/// What `gap --circuit` says, for the CLI and the Python module alike: the verdict in
/// words, its text (where the gap lies, every candidate's size and how far it shrinks the
/// check log's residual) and its report folder (the same with a figure).
#include <string>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_gap/circuit_gap.hpp"
#include "hstmon_plot/circuit_report.hpp"

namespace hstmon::gap {

/// What a run of gap --circuit was given, as its text and report name it.
struct CircuitGapRun {
  std::string circuit;     ///< the circuit file as given
  std::string fit, check;  ///< the logs as given (a DataFrame: a label)
};

/// The verdict in one sentence.
std::string circuit_gap_verdict(const CircuitGapResult& r);

/// The text `hstmon gap --circuit` prints.
std::string circuit_gap_text(const CircuitGapRun& run, const circuit_tools::LoadedCircuit& c, const CircuitGapResult& r);

/// The report of one gap run; `text` is the command's own text output.
sim::CircuitReport circuit_gap_report(const CircuitGapRun& run, const circuit_tools::LoadedCircuit& c,
                                      const CircuitGapResult& r, const std::string& text);

}  // namespace hstmon::gap
