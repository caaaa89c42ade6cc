#pragma once
/// @file circuit_faults.hpp
/// The fault table and the parameter uncertainty of any circuit, from its file and the
/// engine — what the monitor of `hstmon replay --circuit` runs on.
///
/// Rows: `<parameter>+` and `<parameter>−` for every named parameter that moves a steady
/// state (displacements, resistances, orifice coefficients and areas, frictions,
/// torques, flows, pressures, fractions, speeds; not capacitances, volumes, inertias or
/// the density, which Cd covers), then `<input>+` and `<input>−` for every logged input
/// with a non-zero nominal value (the machine's true value is not the logged one: the
/// thesis's kp− is a PRV blockage under an unchanged setting), then `sensor_<channel>` for
/// every channel. A parameter
/// row's signature is numeric, from steady-state solves of the engine at the nominal
/// inputs: the magnitude on a channel is the sign of the change for a ±10 % and a ±30 %
/// fault when both agree and the 30 % change is at least one noise σ, kQualZero when
/// neither reaches one σ, else kQualAny; the direction is the noise-scaled 10 % change.
/// Slopes are kQualAny and orders 0 here: the transient part of a signature comes from the
/// circuit's temporal causal graph, derived in host_sim/fdi (fdi::circuit_signature_table,
/// which starts from this table; circuit_tools cannot depend on fdi). A fault
/// that moves no channel by one σ even at ±30 % has no row (it is listed as
/// undetectable at this operating point).

#include <string>
#include <vector>

#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon/fault_signature.hpp"
#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::circuit_tools {

/// A circuit's fault table. Row names point into `names`, so the table moves but does
/// not copy.
struct CircuitFaultTable {
  using Row = BasicFaultSignature<host::CircuitCap::kChannels>;
  std::vector<std::string> names;         ///< one per row, in row order
  std::vector<Row> rows;
  std::vector<std::string> undetectable;  ///< faults without a row (see the file comment)
  std::vector<std::string> notes;         ///< what was assumed (no steady state for a 30 % fault, …)
  std::vector<std::string> remarks;       ///< per row, in row order (or empty): why a slope or the orders were left open
  /// Per row, in row order (or empty): the length of the noise-scaled steady residual of a
  /// 10 % fault, the scale its unit `direction` was divided by [σ]; 0 for sensor rows
  std::vector<double> gains;

  CircuitFaultTable() = default;
  CircuitFaultTable(CircuitFaultTable&&) = default;
  CircuitFaultTable& operator=(CircuitFaultTable&&) = default;
  CircuitFaultTable(const CircuitFaultTable&) = delete;
  CircuitFaultTable& operator=(const CircuitFaultTable&) = delete;
};

/// Applies a fault on parameter k of circuit c to p, relative to nominal, as every
/// circuit tool applies one (the fault table, its simulations, the monitor's fits, the
/// campaign's machines): the parameter × factor, and a setting's companions moved by the
/// same pressure (hstmon/circuit/setting_shift.hpp: a relief valve's full-open pressure
/// with its cracking pressure, a compensated pump's knee and dead-head with its cut-in).
void apply_param_fault(const host::CircuitFile& c, host::HostCircuitModel::Params& p,
                       const host::HostCircuitModel::Params& nominal, std::size_t k, double factor);

/// The noise σ the circuit tools judge sensor s by [SI]: its `noise`, or, without one, 1 %
/// of its range (of 100 SI units without a range) — the fault table's directions, the
/// monitor's thresholds and the fits' weights need a scale; a sign does not.
double sensor_sigma(const host::CircuitSensor& s);

/// The relative uncertainty the monitor's model bound assumes: 2 % on every named
/// parameter that moves a steady state (as for Table 2.2's regressed parameters), 0 on
/// the rest and on literals.
circuit::CircuitUncertainty<double, host::CircuitCap> default_uncertainty(const host::CircuitFile& f);

/// The relative uncertainty the monitor's model bound takes for c: what its parameter
/// file's "uncertainty" section states, and default_uncertainty's for the rest.
circuit::CircuitUncertainty<double, host::CircuitCap> circuit_uncertainty(const LoadedCircuit& c);

/// True when parameter p can be a fault row / is uncertain (see the file comment).
bool moves_steady_state(const host::CircuitParam& p);

/// Builds the table for c at its nominal inputs (the parameter file's).
/// @throws std::runtime_error when the circuit has no steady state at the nominal inputs
CircuitFaultTable circuit_fault_table(const LoadedCircuit& c);

/// The rows of circuit_fault_table(c) for the named faults ("R_ip-", with their sign) and
/// every sensor row, bit for bit and in the table's order, solving only for those: the named
/// faults without a row are in `undetectable`, the notes are those on them; a name that is
/// no fault of c is left out (fault_table_builders.hpp, FaultRowsBuilder).
/// @throws std::runtime_error as circuit_fault_table
CircuitFaultTable circuit_fault_rows(const LoadedCircuit& c, const std::vector<std::string>& faults);

}  // namespace hstmon::circuit_tools
