#include "cli_fleet_replay.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <system_error>
#include <thread>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "cli_commands.hpp"
#include "cli_events.hpp"
#include "cli_log_options.hpp"
#include "hstmon_circuit/circuit_log.hpp"

namespace hstmon::cli {

namespace fs = std::filesystem;

MachineRule parse_machine_rule(const std::string& text, std::string& error) {
  MachineRule rule;
  if (text == "parent") return rule;
  if (text == "stem") {
    rule.kind = MachineRule::Kind::kStem;
    return rule;
  }
  const std::string prefix = "regex:";
  if (text.compare(0, prefix.size(), prefix) == 0) {
    rule.kind = MachineRule::Kind::kRegex;
    rule.pattern = text.substr(prefix.size());
    try {
      const std::regex re(rule.pattern);
      if (re.mark_count() < 1) error = "'" + text + "' needs a capture group, e.g. regex:(m[0-9]+)_";
    } catch (const std::regex_error& e) {
      error = "'" + text + "': " + e.what();
    }
    return rule;
  }
  error = "'" + text + "' is not parent, stem or regex:PATTERN";
  return rule;
}

std::string machine_of(const std::string& path, const MachineRule& rule) {
  const fs::path p(path);
  switch (rule.kind) {
    case MachineRule::Kind::kParent:
      if (p.has_parent_path() && p.parent_path().filename() != "." && p.parent_path().filename() != "..") {
        return p.parent_path().filename().string();
      }
      return p.stem().string();
    case MachineRule::Kind::kStem: return p.stem().string();
    case MachineRule::Kind::kRegex: {
      std::smatch m;
      const std::regex re(rule.pattern);
      return std::regex_search(path, m, re) && m.size() > 1 ? m[1].str() : std::string();
    }
  }
  return {};
}

std::vector<std::string> expand_logs(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const auto& name : names) {
    std::error_code ec;
    if (!fs::is_directory(name, ec)) {
      out.push_back(name);
      continue;
    }
    for (fs::recursive_directory_iterator it(name, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string ext = it->path().extension().string();
      if ((ext == ".csv" || ext == ".tsv" || ext == ".txt") && it->is_regular_file(ec)) out.push_back(it->path().string());
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace {

// What a summary line says of one replay.
struct SummaryFacts {
  std::size_t rows = 0;
  double t_first = 0.0, t_last = 0.0;
  std::string final_status;
  const std::vector<host::ReplayEvent>* events = nullptr;
  std::uint32_t health = 0;
  std::vector<std::pair<std::string, const host::ChannelStats*>> measured;  ///< by channel name
  std::vector<std::string> notes;
};

void add_facts(nlohmann::json& j, SummaryFacts f) {
  j["rows"] = f.rows;
  j["t_first"] = f.t_first;
  j["t_last"] = f.t_last;
  j["final_status"] = f.final_status;
  j["events"] = f.events->size();
  nlohmann::json first = nullptr;  // the first detection or isolation: when and what
  for (const auto& e : *f.events) {
    if (e.event == "isolated" || e.event == "ambiguous" || e.event == "unexplained") {
      first = {{"t", e.t}, {"event", e.event}, {"fault", e.candidates.empty() ? "" : e.candidates.front().fault}};
      break;
    }
  }
  j["first_diagnosis"] = first;
  j["health"] = host::health_names(f.health);
  nlohmann::json res = nlohmann::json::object();
  for (const auto& [name, stats] : f.measured) {
    if (stats->n == 0) continue;
    nlohmann::json s = {{"n", stats->n}};
    add_residual_stats(s, *stats);
    res[name] = s;
  }
  j["residuals"] = res;
  if (f.notes.size() > kMaxNotes) f.notes.resize(kMaxNotes);
  for (auto& n : f.notes) n = capped(n);
  j["notes"] = f.notes;
}

std::string circuit_summary(nlohmann::json& j, const std::string& path, const FleetReplayArgs& args, bool& failed) {
  const circuit_tools::LoadedCircuit& c = *args.circuit;
  j["circuit"] = c.file.name;
  const circuit_tools::CircuitLog log = circuit_tools::read_circuit_log(path, c.file, args.read);
  // A strict read with an error has no valid rows; a lenient one replays those before it.
  failed = log.rows() == 0 || (log.error && !args.read.lenient);
  j["status"] = failed ? "error" : "ok";
  if (log.error) j["error"] = capped(log.error->to_string());
  if (failed) return j.dump();
  circuit_tools::CircuitReplayOptions o = args.circuit_replay;
  o.keep_trace = false;
  o.table = args.circuit_table.get();
  const circuit_tools::CircuitReplayResult r = circuit_tools::replay_circuit(c, log, o);
  const std::string status = r.table_rows > 0 ? r.final_status : std::string("not_run");
  SummaryFacts f{r.rows, r.t_first, r.t_last, status, &r.events, r.health, {}, log.notes};
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) {
    if (r.measured[ch]) f.measured.emplace_back(c.file.sensors[ch].name, &r.channels[ch]);
  }
  f.notes.insert(f.notes.end(), r.notes.begin(), r.notes.end());
  add_facts(j, std::move(f));
  return j.dump();
}

}  // namespace

std::string summary_line(const std::string& path, const FleetReplayArgs& args, bool* failed_out) {
  nlohmann::json j = {{"type", "log"}, {"log", path}, {"machine", machine_of(path, args.machine)}};
  bool failed = false;
  std::string line = circuit_summary(j, path, args, failed);
  if (failed_out != nullptr) *failed_out = failed;
  return line;
}

int run_fleet_replay(const std::vector<std::string>& logs, const FleetReplayArgs& args) {
#ifdef __GLIBC__
  // Each log takes a read buffer and a chunk of rows (~9 MB). glibc would map and unmap
  // them for every log, and the fresh pages' faults cost a third of the CPU time of 200
  // one-minute logs (0.7 s of 2.4 s); kept in the heap, the next log reuses them.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
  std::vector<std::string> lines(logs.size());
  std::vector<char> failed(logs.size(), 0);  // (not vector<bool>: threads write neighbours)
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < logs.size(); i = next++) {
      bool f = false;
      lines[i] = summary_line(logs[i], args, &f);
      failed[i] = f ? 1 : 0;
    }
  };
  unsigned jobs = args.jobs != 0 ? args.jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(1, logs.size())));
  std::vector<std::thread> pool;
  for (unsigned k = 1; k < jobs; ++k) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  for (const auto& line : lines) fmt::print("{}\n", line);
  return std::count(failed.begin(), failed.end(), 1) > 0 ? kExitBadInput : kExitOk;
}

}  // namespace hstmon::cli
