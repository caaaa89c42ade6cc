#pragma once
/// @file logged_run.hpp
/// A logged run set up for re-simulation (hstmon-sim --circuit F --inputs LOG, and
/// hstmon.simulate(circuit, inputs)): the log's input columns drive the circuit
/// (input_profile.hpp), on the log's own clock.
///  - The run starts at the log's first row time; the rows written are the log's own row
///    times (so the re-run lines up row by row with the measured log), or with a rate
///    t0 + k/rate; --step and --fault times are on the same clock.
///  - The run lasts the log's span (first to last row, both written) unless a duration is
///    given: a shorter one ends at the last row within it; a longer one holds the last
///    row's inputs and goes on at the log's median row period.
///  - Inputs not in the log keep their parameter-file values (a note names them).
/// Errors (a log with no input column of the circuit, fewer than 2 rows) are located at
/// the log's header line.

#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_sim.hpp"
#include "hstmon_circuit/input_profile.hpp"
#include "hstmon_host/source_error.hpp"

namespace hstmon::circuit_tools {

/// Sets o's profile, start time, rows written, duration and rate from the log `in` (read
/// for c, without error).
/// @param duration  [s]; 0 = the log's span
/// @param rate      [Hz]; 0 = the log's own rows
/// @param notes     receives "LOG:line:1: note: ..." lines (the inputs not in the log)
/// @return an error, or nothing with o set
std::optional<host::SourceError> logged_run(const CircuitLog& in, const LoadedCircuit& c, InputHold hold,
                                            double duration, double rate, CircuitSimOptions& o,
                                            std::vector<std::string>& notes);

}  // namespace hstmon::circuit_tools
