// `hstmon fleet SUMMARY.jsonl...`: which machines drift, from the summary lines of
// `hstmon replay --summary` (one file, or the concatenated output of parallel or Slurm
// tasks). Per machine, its logs in path order (name them by date); per channel (the thesis
// rig's or a circuit's sensors, by the names in the lines) the ratio
// residual RMS / noise of each log; a channel drifts when the mean ratio of the machine's
// last B logs (after its first B) is above k times that of its first B logs (docs/fleet.md).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli_commands.hpp"
#include "cli_log_options.hpp"
#include "cli_validators.hpp"

namespace hstmon::cli {

namespace {

struct FleetArgs {
  std::vector<std::string> files;
  std::size_t baseline = 2;  // B: logs at each end
  double k = 2.0;            // drift factor
  bool json = false;
};

struct LogSummary {
  std::string path;
  bool ok = false;
  std::map<std::string, double> ratio;  // residual RMS / noise per measured channel, by name
};

// Reads every summary line; false (message printed) on a line that is not one.
bool read_summaries(const std::vector<std::string>& files, std::map<std::string, std::vector<LogSummary>>& out) {
  for (const auto& file : files) {
    std::ifstream in(file);
    if (!in) {
      fmt::print(stderr, "{}: error: cannot open\n", file);
      return false;
    }
    std::string text;
    for (std::size_t line = 1; std::getline(in, text); ++line) {
      if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
      const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
      if (j.is_discarded() || !j.is_object() || j.value("type", "") != "log" || !j.contains("machine") ||
          !j["machine"].is_string() || !j.contains("log") || !j["log"].is_string()) {
        fmt::print(stderr, "{}:{}:1: error: not a summary line of `hstmon replay --summary`: {}\n", file, line,
                   capped(text, 80));
        return false;
      }
      LogSummary s;
      s.path = j["log"].get<std::string>();
      s.ok = j.value("status", "") == "ok";
      if (s.ok && j.contains("residuals") && j["residuals"].is_object()) {
        // Whatever channels the replay had: the thesis rig's four or a circuit's sensors.
        for (const auto& [name, ch] : j["residuals"].items()) {
          if (!ch.is_object()) continue;
          const auto rms = ch.find("rms");
          const auto noise = ch.find("noise");
          if (rms == ch.end() || noise == ch.end() || !rms->is_number() || !noise->is_number()) continue;
          const double n = noise->get<double>();
          if (n > 0.0) s.ratio[name] = rms->get<double>() / n;
        }
      }
      out[j["machine"].get<std::string>()].push_back(s);
    }
  }
  return true;
}

// Mean of the finite ratios of channel c over logs [b, e); NaN when there is none.
double mean_ratio(const std::vector<const LogSummary*>& logs, std::size_t b, std::size_t e, const std::string& c) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = b; i < e; ++i) {
    const auto it = logs[i]->ratio.find(c);
    if (it != logs[i]->ratio.end() && std::isfinite(it->second)) {
      sum += it->second;
      ++n;
    }
  }
  return n ? sum / static_cast<double>(n) : std::numeric_limits<double>::quiet_NaN();
}

int run_fleet(const FleetArgs& a) {
  std::map<std::string, std::vector<LogSummary>> machines;
  if (!read_summaries(a.files, machines)) return kExitBadInput;
  std::size_t total = 0;
  std::size_t failed_total = 0;
  std::size_t drifting = 0;
  std::vector<std::string> rows;
  for (auto& [machine, logs] : machines) {
    std::sort(logs.begin(), logs.end(), [](const LogSummary& x, const LogSummary& y) { return x.path < y.path; });
    std::vector<const LogSummary*> ok;
    for (const auto& l : logs) {
      if (l.ok) ok.push_back(&l);
    }
    const std::size_t failed = logs.size() - ok.size();
    total += logs.size();
    failed_total += failed;
    // First B logs against the last min(B, n − B) after them (n ok logs; none when n ≤ B).
    const std::size_t b = std::min(a.baseline, ok.size());
    const std::size_t m = std::min(a.baseline, ok.size() - b);
    nlohmann::json channels = nlohmann::json::object();
    std::string verdict = ok.size() > a.baseline ? "steady" : "too_few_logs";
    // The channels any of its logs measured, in name order.
    std::set<std::string> names;
    for (const LogSummary* l : ok) {
      for (const auto& kv : l->ratio) names.insert(kv.first);
    }
    std::string worst;
    double worst_growth = 0.0, worst_first = NAN, worst_last = NAN;
    for (const std::string& c : names) {
      const double first = mean_ratio(ok, 0, b, c);
      const double last = m ? mean_ratio(ok, ok.size() - m, ok.size(), c) : std::numeric_limits<double>::quiet_NaN();
      if (!std::isfinite(first) || !std::isfinite(last)) continue;
      const bool drifts = ok.size() > a.baseline && last > a.k * first;
      channels[c] = {{"first", first}, {"last", last}, {"drifts", drifts}};
      if (drifts) verdict = "drifting";
      if (last / first > worst_growth) {
        worst_growth = last / first;
        worst = c;
        worst_first = first;
        worst_last = last;
      }
    }
    if (verdict == "drifting") ++drifting;
    if (a.json) {
      rows.push_back(nlohmann::json{{"type", "machine"},
                                    {"machine", machine},
                                    {"logs", logs.size()},
                                    {"failed", failed},
                                    {"first_log", logs.front().path},
                                    {"last_log", logs.back().path},
                                    {"channels", channels},
                                    {"verdict", verdict}}
                         .dump());
    } else {
      const bool any = !worst.empty();
      rows.push_back(fmt::format("  {:<16} {:>5} {:>6}  {:<8} {:>9} {:>9}  {}", machine, logs.size(), failed,
                                 any ? worst : "-", any ? fmt::format("{:.3g}", worst_first) : "-",
                                 any ? fmt::format("{:.3g}", worst_last) : "-",
                                 verdict == "drifting" ? "DRIFTING" : verdict == "steady" ? "steady" : "too few logs"));
    }
  }
  if (a.json) {
    for (const auto& r : rows) fmt::print("{}\n", r);
    fmt::print("{}\n", nlohmann::json{{"type", "fleet"},
                                      {"machines", machines.size()},
                                      {"logs", total},
                                      {"failed", failed_total},
                                      {"drifting", drifting},
                                      {"baseline_logs", a.baseline},
                                      {"k", a.k}}
                           .dump());
    return kExitOk;
  }
  fmt::print("hstmon fleet: {} machines, {} logs ({} failed), {} drifting\n", machines.size(), total, failed_total,
             drifting);
  fmt::print("  drift: residual RMS / noise, mean of a machine's last {} logs above {:g}× that of its first {} (logs "
             "in path order; the last ones after the first)\n\n",
             a.baseline, a.k, a.baseline);
  fmt::print("  {:<16} {:>5} {:>6}  {:<8} {:>9} {:>9}  {}\n", "machine", "logs", "failed", "channel", "first", "last",
             "verdict");
  for (const auto& r : rows) fmt::print("{}\n", r);
  return kExitOk;
}

}  // namespace

void add_fleet_command(CLI::App& app, int& exit_code) {
  const auto [cmd, args] = add_command<FleetArgs>(
      app, exit_code, "fleet",
      "Which machines drift: per machine, residual RMS/noise of its last logs against its first (docs/fleet.md)",
      [](const FleetArgs& a, const CLI::App&) { return run_fleet(a); });
  cmd->add_option("SUMMARY", args->files, "Summary lines of `hstmon replay --summary` (JSON lines), one or more files")
      ->required();
  cmd->add_option("--baseline", args->baseline, "Logs at each end of a machine's history compared (default 2)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--k", args->k, "Drift factor: last logs' RMS/noise above k times the first logs' (default 2)")
      ->check(positive_number());
  cmd->add_flag("--json", args->json, "One JSON line per machine, then a fleet line");
}

}  // namespace hstmon::cli
