#pragma once
/// @file cli_run.hpp
/// Runs a command line through the shell (popen) and keeps its exit status and standard
/// output: the one way the tests run the hstmon tools.

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace hstmon_test {

struct CliRun {
  int exit_code = -1;  ///< exit status; 128 + the signal if one ended it; -1 if it did not start
  std::string out;     ///< standard output (with standard error where the command line says 2>&1)
};

/// @param cmd_line a shell command line, redirections and all
inline CliRun run_command(const std::string& cmd_line) {
  CliRun r;
  FILE* p = popen(cmd_line.c_str(), "r");
  if (p == nullptr) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

#ifdef HSTMON_CLI
/// `hstmon ARGS 2>&1`: the command-line tool's standard output and standard error together.
inline CliRun run_hstmon(const std::string& args) {
  return run_command(std::string("'") + HSTMON_CLI + "' " + args + " 2>&1");
}
#endif

}  // namespace hstmon_test
