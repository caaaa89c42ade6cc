// `hstmon fleet SUMMARY.jsonl...`: which machines drift, from the summary lines of
// `hstmon replay --summary` (one file, or the concatenated output of parallel or Slurm
// tasks). Per machine, its logs in path order (name them by date); per channel the ratio
// residual RMS / noise of each log; a channel drifts when the mean ratio of the machine's
// last B logs (after its first B) is above k times that of its first B logs (docs/fleet.md).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_commands.hpp"
#include "cli_log_options.hpp"
#include "cli_validators.hpp"

namespace hstmon::cli {

namespace {

const char* const kChannels[4] = {"p_mi", "p_mo", "p_pp", "w_m"};

struct FleetArgs {
  std::vector<std::string> files;
  std::size_t baseline = 2;  // B: logs at each end
  double k = 2.0;            // drift factor
  bool json = false;
};

struct LogSummary {
  std::string path;
  bool ok = false;
  double ratio[4] = {NAN, NAN, NAN, NAN};  // residual RMS / noise per channel (NaN: not measured)
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
        for (int c = 0; c < 4; ++c) {
          const auto it = j["residuals"].find(kChannels[c]);
          if (it == j["residuals"].end() || !it->is_object()) continue;
          const auto rms = it->find("rms");
          const auto noise = it->find("noise");
          if (rms == it->end() || noise == it->end() || !rms->is_number() || !noise->is_number()) continue;
          const double n = noise->get<double>();
          if (n > 0.0) s.ratio[c] = rms->get<double>() / n;
        }
      }
      out[j["machine"].get<std::string>()].push_back(s);
    }
  }
  return true;
}

// Mean of the finite ratios of channel c over logs [b, e); NaN when there is none.
double mean_ratio(const std::vector<const LogSummary*>& logs, std::size_t b, std::size_t e, int c) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = b; i < e; ++i) {
    if (std::isfinite(logs[i]->ratio[c])) {
      sum += logs[i]->ratio[c];
      ++n;
    }
  }
  return n ? sum / static_cast<double>(n) : NAN;
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
    int worst = -1;
    double worst_growth = 0.0;
    double first[4];
    double last[4];
    for (int c = 0; c < 4; ++c) {
      first[c] = mean_ratio(ok, 0, b, c);
      last[c] = m ? mean_ratio(ok, ok.size() - m, ok.size(), c) : NAN;
      if (!std::isfinite(first[c]) || !std::isfinite(last[c])) continue;
      const bool drifts = ok.size() > a.baseline && last[c] > a.k * first[c];
      channels[kChannels[c]] = {{"first", first[c]}, {"last", last[c]}, {"drifts", drifts}};
      if (drifts) verdict = "drifting";
      if (last[c] / first[c] > worst_growth) {
        worst_growth = last[c] / first[c];
        worst = c;
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
      const std::string ch = worst >= 0 ? kChannels[worst] : "-";
      rows.push_back(fmt::format("  {:<16} {:>5} {:>6}  {:<8} {:>9} {:>9}  {}", machine, logs.size(), failed, ch,
                                 worst >= 0 ? fmt::format("{:.3g}", first[worst]) : "-",
                                 worst >= 0 ? fmt::format("{:.3g}", last[worst]) : "-",
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
  auto args = std::make_shared<FleetArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fleet", "Which machines drift: per machine, residual RMS/noise of its last logs against its first (docs/fleet.md)");
  cmd->add_option("SUMMARY", args->files, "Summary lines of `hstmon replay --summary` (JSON lines), one or more files")
      ->required();
  cmd->add_option("--baseline", args->baseline, "Logs at each end of a machine's history compared (default 2)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--k", args->k, "Drift factor: last logs' RMS/noise above k times the first logs' (default 2)")
      ->check(positive_number());
  cmd->add_flag("--json", args->json, "One JSON line per machine, then a fleet line");
  cmd->callback([args, &exit_code]() { exit_code = run_fleet(*args); });
}

}  // namespace hstmon::cli
