#pragma once
/// @file circuit_table_header.hpp
/// A circuit's fault table (circuit_faults.hpp; with slopes and orders: host_sim/fdi
/// circuit_signature_table.hpp) as a constexpr C++ header for firmware
/// (`hstmon-fdi table --circuit FILE --out HEADER`): BasicFaultSignature<N> rows over the
/// circuit's N sensor channels, in namespace hstmon::generated::<name>, so a firmware
/// monitor of that circuit matches on the same table the host replay generates. A row's
/// remark (CircuitFaultTable::remarks) is a comment above it.

#include <string>

#include "hstmon_circuit/circuit_faults.hpp"

namespace hstmon::circuit_tools {

/// The header text. @param name  C++ identifier of the namespace; @param source  what the
/// header comment names as its source (file names, not absolute paths, so a committed
/// header compares byte for byte wherever it is regenerated)
std::string circuit_table_header(const LoadedCircuit& c, const CircuitFaultTable& t, const std::string& name,
                                 const std::string& source);

}  // namespace hstmon::circuit_tools
