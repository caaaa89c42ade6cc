#pragma once
/// @file fault_runs.hpp
/// The noiseless runs of single faults that check a circuit table's slopes
/// (circuit_signature_table.hpp: a kept slope must survive the fault's simulated transient),
/// simulated for the table's own circuit, or once for a circuit with more channels and read
/// by the tables of that circuit with some of them (sensor placement: the channels a circuit
/// measures do not change how it moves, and each reading is the engine's output for its own
/// channel alone).

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::fdi {

/// One fault run from a steady start, sensor noise off.
struct FaultRun {
  bool steady = true;                        ///< false: the faulted circuit has no steady state (nothing simulated)
  bool failed = false;                       ///< the simulation threw
  std::vector<std::vector<double>> sensors;  ///< per channel, each sample's reading [SI]
};

/// c with the input or parameter `base` scaled by `factor` after a few samples of its steady
/// start, sampled at 1 kHz for `duration` [s] more.
FaultRun simulate_fault(const circuit_tools::LoadedCircuit& c, const std::string& base, double factor, double duration);

/// Where a table's fault runs come from: (base, factor, duration) → the run, as simulate_fault.
using FaultRuns = std::function<FaultRun(const std::string& base, double factor, double duration)>;

/// The runs of one circuit, each simulated once, read by channel.
class SharedFaultRuns {
 public:
  /// `all`: the circuit simulated, with every channel some reader wants.
  explicit SharedFaultRuns(circuit_tools::LoadedCircuit all);

  /// The run of `all` as simulate_fault, with `channels` (indices into all's channels) as its channels.
  FaultRun run(const std::string& base, double factor, double duration, const std::vector<std::size_t>& channels);

 private:
  circuit_tools::LoadedCircuit all_;
  std::map<std::tuple<std::string, double, double>, FaultRun> done_;
};

}  // namespace hstmon::fdi
