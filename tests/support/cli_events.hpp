#pragma once
/// @file cli_events.hpp
/// Runs an hstmon command line through the shell and keeps what the validation tests judge:
/// its exit status and the `"type":"event"` objects of its JSON-lines standard output.

#include <sys/wait.h>

#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hstmon_test {

struct CliEvents {
  int status = -1;                      ///< exit status (-1: did not run or did not exit)
  std::vector<nlohmann::json> events;   ///< detected, isolated, ambiguous, unexplained, cleared, …
};

/// @param cmd a shell command whose standard output is `hstmon … --json`
inline CliEvents run_cli_events(const std::string& cmd) {
  CliEvents r;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return r;
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
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
