#pragma once
/// @file cli_events.hpp
/// Runs an hstmon command line through the shell and keeps what the validation tests judge:
/// its exit status and the `"type":"event"` objects of its JSON-lines standard output.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace hstmon_test {

struct CliEvents {
  int status = -1;                      ///< exit status (as CliRun::exit_code)
  std::vector<nlohmann::json> events;   ///< detected, isolated, ambiguous, unexplained, cleared, …
};

/// @param cmd a shell command whose standard output is `hstmon … --json`
inline CliEvents run_cli_events(const std::string& cmd) {
  const CliRun run = run_command(cmd);
  const std::string& out = run.out;
  CliEvents r;
  r.status = run.exit_code;
  std::size_t a = 0;
  while (a < out.size()) {
    std::size_t b = out.find('\n', a);
    if (b == std::string::npos) b = out.size();
    const nlohmann::json j = nlohmann::json::parse(out.substr(a, b - a), nullptr, false);
    a = b + 1;
    if (j.is_object() && j.value("type", "") == "event") r.events.push_back(j);
  }
  return r;
}

}  // namespace hstmon_test
