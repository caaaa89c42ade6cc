#pragma once
// The options every `hstmon <command> --circuit FILE` shares (gap, identify).
#include <string>

#include "hstmon_host/log_reader.hpp"

namespace hstmon::cli {

/// The options of a command that apply with --circuit, whatever the command.
struct CircuitCommonArgs {
  std::string circuit;     ///< circuit file (docs/circuits.md)
  std::string params;      ///< parameter file ("" = <stem>.params.json beside it)
  bool json = false;       ///< print one JSON object instead of the text
  std::string report;      ///< report folder ("" = none): report.md, report.html, figure.svg
  host::ReadOptions read;  ///< --map, --separator, --lenient, --rate (cli_log_options.hpp)
};

}  // namespace hstmon::cli
