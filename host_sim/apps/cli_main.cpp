// hstmon: replay logged HST sensor streams through the monitor and report.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli_commands.hpp"
#include "cli_log_options.hpp"

int main(int argc, char** argv) {
  CLI::App app{"hstmon — hydrostatic transmission monitor (host tools)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hstmon " HSTMON_VERSION);  // project(VERSION) in CMakeLists.txt
  // Command-line errors in the style of every other hstmon error ("who: error: what").
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return fmt::format("hstmon: error: {}\nRun with --help for more information.\n", hstmon::cli::capped(e.what()));
  });
  int exit_code = hstmon::cli::kExitOk;
  hstmon::cli::add_replay_command(app, exit_code);
  hstmon::cli::add_identify_command(app, exit_code);
  hstmon::cli::add_gap_command(app, exit_code);
  hstmon::cli::add_fleet_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : hstmon::cli::kExitUsage;
  }
  return exit_code;
}
