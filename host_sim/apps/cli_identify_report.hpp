#pragma once
// What the parts of `hstmon identify` share: its command line and what the paper sections
// add to its report (text, tables, and panels of the circuit report's figure).
#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cli_log_options.hpp"
#include "hstmon_ident/plots.hpp"
#include "hstmon_plot/circuit_report.hpp"

namespace hstmon::cli::identify {

namespace id = hstmon::ident;

/// The command line of `hstmon identify`.
struct IdentifyArgs {
  std::vector<std::string> logs;
  std::string out;
  std::string header;
  bool json = false;
  std::string report;
  LogOptionArgs io;  // --map, --separator, --lenient, --rate, --params (alias --prior)
  double min_duration = 0.2;
  std::size_t min_samples = 1;
  bool assume_steady = false;
  bool setting_per_window = false;
  std::size_t min_settings = 0;
  double noise_pressure = 0.0;
  double noise_speed = 0.0;
  std::string paper;
  double cd = 0.61;
  double rho = 870.0;
  bool studies = false;
  bool cd_given = false, rho_given = false;  // --cd, --rho on the command line (else a circuit's own)
  std::vector<std::string> window_inputs;    // --window-input: inputs fitted per steady window
  std::string circuit;                       // --circuit ("" = the built-in thesis.json)
  std::vector<std::string> fit;              // --fit ("" = the circuit's losses and openings)
};

/// v as JSON, null where it is not finite.
inline nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// Collects the paper sections' text (echoed to stdout unless quiet), the report's tables,
// and its plots as panels of the command report's one figure: one report folder, one page.
struct Report {
  bool quiet = false;
  std::string text;
  std::vector<sim::ReportPanel>* panels = nullptr;  // the plots (nullptr: no report, no plots)
  std::vector<sim::ReportTable> tables;             // the report's tables
  template <typename... A>
  void operator()(fmt::format_string<A...> f, A&&... a) {
    const std::string s = fmt::format(f, std::forward<A>(a)...);
    text += s;
    if (!quiet) fmt::print("{}", s);
  }
  bool plots() const { return panels != nullptr; }
  void plot(const std::string& title, const std::string& xlabel, const std::string& ylabel,
            const std::vector<id::PlotSeries>& series);
};

}  // namespace hstmon::cli::identify
