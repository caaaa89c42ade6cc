#pragma once
// What the parts of `hstmon identify` share: its command line and the report it writes
// (text echoed to stdout, figures for report.html, or with --circuit panels and tables of
// the circuit report).
#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cli_identify_html.hpp"
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
  double min_duration = 1.0;
  std::size_t min_samples = 3;
  bool assume_steady = false;
  bool setting_per_window = false;
  std::size_t min_settings = 3;
  double noise_pressure = 0.0;
  double noise_speed = 0.0;
  std::string paper;
  double cd = 0.61;
  double rho = 870.0;
  bool studies = false;
  bool cd_given = false, rho_given = false;  // --cd, --rho on the command line (else a circuit's own)
  std::vector<std::string> window_inputs;    // --window-input: inputs fitted per steady window (--circuit)
  std::string circuit;                       // --circuit: run_circuit_identify instead (cli_circuit_identify.hpp)
  std::vector<std::string> fit;
};

/// v as JSON, null where it is not finite.
inline nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// Appends to the report text and echoes it to stdout unless JSON is on; collects the plots
// for report.html. With --circuit (`panels` set) the plots become panels of the circuit
// report's one figure and the tables join its tables: one report folder, one page.
struct Report {
  bool quiet = false;
  std::string text;
  std::vector<ReportFigure> figures;
  std::string dir;                                  // the report folder ("" = no plots)
  std::vector<sim::ReportPanel>* panels = nullptr;  // --circuit: plots go here, not to SVG files
  std::vector<sim::ReportTable> tables;             // --circuit: the report's tables
  template <typename... A>
  void operator()(fmt::format_string<A...> f, A&&... a) {
    const std::string s = fmt::format(f, std::forward<A>(a)...);
    text += s;
    if (!quiet) fmt::print("{}", s);
  }
  bool plots() const { return !dir.empty(); }
  void plot(const std::string& stem, const std::string& title, const std::string& xlabel, const std::string& ylabel,
            const std::vector<id::PlotSeries>& series);
};

/// Adds `file` to the report's figures, or warns on stderr with the plot's error `err`.
void plot_or_warn(Report& rep, const std::string& file, const std::string& caption, const std::string& err);

}  // namespace hstmon::cli::identify
