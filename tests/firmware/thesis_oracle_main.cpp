// The reference of the thesis firmware image (ports/cortex_m4_mps2: the hand-written
// thesis monitor): the same monitor in double on the host (ports/host replay.hpp), with
// Table 2.2, printed as the JSON lines the image prints, for hstmon_fw_compare.
// `hstmon replay` runs the thesis rig through its circuit file instead (thesis.json), so
// the image's own equations are compared with this oracle, not with the product path.
//   hstmon_thesis_oracle LOG.csv
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "cli_events.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/replay.hpp"

int main(int argc, char** argv) {
  namespace hh = hstmon::host;
  if (argc != 2) {
    fmt::print(stderr, "usage: hstmon_thesis_oracle LOG.csv\n");
    return 2;
  }
  const std::string log_path = argv[1];
  const hh::LogData log = hh::read_log(log_path);
  if (!log.ok()) {
    fmt::print(stderr, "{}\n", log.error->to_string());
    return 2;
  }
  const hh::ReplayResult r = hh::replay(log, {}, {}, hh::ReplayOptions{});
  fmt::print("{}\n", hstmon::cli::replay_head_json(log_path, r).dump());
  const char* const names[4] = {"p_mi", "p_mo", "p_pp", "w_m"};
  for (std::size_t c = 0; c < 4; ++c) {
    nlohmann::json j = {{"type", "residual"},
                        {"channel", names[c]},
                        {"unit", c == 3 ? "rad/s" : "Pa"},
                        {"measured", r.measured[c]},
                        {"n", r.channels[c].n}};
    hstmon::cli::add_residual_stats(j, r.channels[c]);
    fmt::print("{}\n", j.dump());
  }
  hstmon::cli::print_json_diagnosis(r.envelope, r.events, r.final_status);
  return 0;
}
