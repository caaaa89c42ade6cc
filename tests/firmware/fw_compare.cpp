// Compares two outputs of `hstmon replay --json` (or of the firmware replay): same
// header counts (rows, ticks, tick, start, health, unhealthy rows, max substeps), and per
// channel the same n and residual statistics within a tolerance:
//   |a − b| ≤ rel·max(|a|, |b|) + abs_c,  abs_c = --abs-pa [Pa], --abs-rad [rad/s] or
//   --abs-other [SI] for any other unit (a circuit's flow channels; default 1e-9),
// and the same time of the peak unless the two peaks' sizes are within that tolerance
// of the other build's (two near-equal peaks may swap).
// Matcher events ("type":"event" lines, in order) must agree exactly but for the scores:
// same count, kinds, times (the row time, compared as doubles with ==: same tick), number
// of consistent hypotheses, candidate names in the same order; scores within --score
// (absolute). The "diagnosis" lines must agree (status, events). A "firmware" line, if
// present, must report no events dropped and no event whose stored part differed from
// the printed ranking.
// The channels are those of the files (the thesis's four, or a circuit's), the same in both.
//   hstmon_fw_compare A.jsonl B.jsonl [--rel R] [--abs-pa P] [--abs-rad W] [--abs-other X] [--score S]
//                     [--min-events N]
// --min-events: fewer events than N is a failure too (the log must exercise the matcher).
// Exit status: 0 agree, 1 differ (each difference printed), 2 usage or unreadable input.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

using nlohmann::json;

namespace {

struct Parsed {
  json header;
  std::map<std::string, json> channels;
  std::vector<json> events;
  json diagnosis;
  json firmware;
};

bool load(const char* path, Parsed& p) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != '{') continue;  // qemu or trace noise
    const json j = json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.contains("type")) continue;
    if (j["type"] == "replay") p.header = j;
    if (j["type"] == "residual") p.channels[j["channel"].get<std::string>()] = j;
    if (j["type"] == "event") p.events.push_back(j);
    if (j["type"] == "diagnosis") p.diagnosis = j;
    if (j["type"] == "firmware") p.firmware = j;
  }
  return !p.header.is_null() && !p.channels.empty();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s A.jsonl B.jsonl [--rel R] [--abs-pa P] [--abs-rad W]\n", argv[0]);
    return 2;
  }
  double rel = 1e-4, abs_pa = 1.0, abs_rad = 1e-4, abs_other = 1e-9, score_tol = 1e-4;
  long min_events = 0;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string k = argv[i];
    const double v = std::atof(argv[i + 1]);
    if (k == "--rel") rel = v;
    else if (k == "--abs-pa") abs_pa = v;
    else if (k == "--abs-rad") abs_rad = v;
    else if (k == "--abs-other") abs_other = v;
    else if (k == "--score") score_tol = v;
    else if (k == "--min-events") min_events = std::atol(argv[i + 1]);
    else { std::fprintf(stderr, "unknown option %s\n", k.c_str()); return 2; }
  }
  Parsed a, b;
  if (!load(argv[1], a) || !load(argv[2], b)) {
    std::fprintf(stderr, "cannot read a replay header and residual lines from %s and %s\n", argv[1], argv[2]);
    return 2;
  }
  if (a.channels.size() != b.channels.size()) {
    std::printf("channels: %zu vs %zu\n", a.channels.size(), b.channels.size());
    return 1;
  }
  int bad = 0;
  for (const char* k : {"rows", "ticks", "start", "health", "unhealthy_rows", "max_substeps"}) {
    if (a.header[k] != b.header[k]) {
      std::printf("header %s: %s vs %s\n", k, a.header[k].dump().c_str(), b.header[k].dump().c_str());
      ++bad;
    }
  }
  for (const char* k : {"tick_s", "t_first", "t_last"}) {
    if (std::fabs(a.header[k].get<double>() - b.header[k].get<double>()) > 1e-9) {
      std::printf("header %s: %s vs %s\n", k, a.header[k].dump().c_str(), b.header[k].dump().c_str());
      ++bad;
    }
  }
  double worst = 0.0;
  for (auto& [name, ja] : a.channels) {
    if (b.channels.count(name) == 0) {
      std::printf("%s: only in %s\n", name.c_str(), argv[1]);
      ++bad;
      continue;
    }
    const json& jb = b.channels[name];
    if (ja["n"] != jb["n"] || ja["measured"] != jb["measured"]) {
      std::printf("%s: n/measured %s/%s vs %s/%s\n", name.c_str(), ja["n"].dump().c_str(), ja["measured"].dump().c_str(),
                  jb["n"].dump().c_str(), jb["measured"].dump().c_str());
      ++bad;
      continue;
    }
    if (!ja.contains("mean")) continue;
    const double abs_c = ja["unit"] == "Pa" ? abs_pa : (ja["unit"] == "rad/s" ? abs_rad : abs_other);
    for (const char* k : {"mean", "rms", "max_abs", "max", "noise"}) {
      const double x = ja[k].get<double>(), y = jb[k].get<double>();
      const double tol = rel * std::fmax(std::fabs(x), std::fabs(y)) + abs_c;
      worst = std::fmax(worst, std::fabs(x - y) / tol);
      if (!(std::fabs(x - y) <= tol)) {
        std::printf("%s %s: %.17g vs %.17g (|Δ| %.3g > tol %.3g)\n", name.c_str(), k, x, y, std::fabs(x - y), tol);
        ++bad;
      }
    }
    // Where the peak is: the same row, unless two rows' residuals tie within the stated
    // tolerance (float and double may then pick either; max_abs above already agrees).
    const double ta = ja["t_max"].get<double>(), tb = jb["t_max"].get<double>();
    if (std::fabs(ta - tb) > 1e-9) {
      const double xa = ja["max_abs"].get<double>(), xb = jb["max_abs"].get<double>();
      const double tol = rel * std::fmax(std::fabs(xa), std::fabs(xb)) + abs_c;
      if (std::fabs(xa - xb) <= tol) {
        std::printf("%s t_max: %.17g vs %.17g (peaks tie within tolerance: %.9g vs %.9g)\n", name.c_str(), ta, tb,
                    xa, xb);
      } else {
        std::printf("%s t_max: %.17g vs %.17g (peak at a different row)\n", name.c_str(), ta, tb);
        ++bad;
      }
    }
  }
  // Matcher events.
  double worst_score = 0.0;
  if (a.events.size() != b.events.size()) {
    std::printf("events: %zu vs %zu\n", a.events.size(), b.events.size());
    ++bad;
  }
  for (std::size_t i = 0; i < a.events.size() && i < b.events.size(); ++i) {
    const json& ea = a.events[i];
    const json& eb = b.events[i];
    const double ta = ea["t"].get<double>(), tb = eb["t"].get<double>();
    bool same = ea["event"] == eb["event"] && ta == tb && ea["consistent"] == eb["consistent"] &&
                ea["candidates"].size() == eb["candidates"].size();
    for (std::size_t j = 0; same && j < ea["candidates"].size(); ++j) {
      const json& ca = ea["candidates"][j];
      const json& cb = eb["candidates"][j];
      const double d = std::fabs(ca["score"].get<double>() - cb["score"].get<double>());
      worst_score = std::fmax(worst_score, d);
      same = ca["fault"] == cb["fault"] && d <= score_tol;
    }
    if (!same) {
      std::printf("event %zu:\n  %s\n  %s\n", i, ea.dump().c_str(), eb.dump().c_str());
      ++bad;
    }
  }
  if (a.diagnosis.is_null() != b.diagnosis.is_null() ||
      (!a.diagnosis.is_null() && (a.diagnosis["status"] != b.diagnosis["status"] || a.diagnosis["events"] != b.diagnosis["events"]))) {
    std::printf("diagnosis: %s vs %s\n", a.diagnosis.dump().c_str(), b.diagnosis.dump().c_str());
    ++bad;
  }
  for (const Parsed* p : {&a, &b}) {
    const json& f = p->firmware;
    if (f.is_null()) continue;
    for (const char* k : {"events_dropped", "event_mismatches"}) {
      if (f.contains(k) && f[k] != 0) {
        std::printf("firmware %s: %s\n", k, f[k].dump().c_str());
        ++bad;
      }
    }
  }
  if (static_cast<long>(a.events.size()) < min_events) {
    std::printf("events: %zu, fewer than --min-events %ld (the log must exercise the matcher)\n", a.events.size(),
                min_events);
    ++bad;
  }
  std::string summary;
  for (const json& e : a.events) {
    summary += (summary.empty() ? "" : "; ") + e["event"].get<std::string>() + " " + e["t"].dump() + " {";
    for (std::size_t j = 0; j < e["candidates"].size(); ++j) {
      summary += (j ? ", " : "") + e["candidates"][j]["fault"].get<std::string>();
    }
    summary += "}";
  }
  std::printf("%s: worst |Δ|/tol = %.3g (rel %.3g, abs %.3g Pa, %.3g rad/s); %zu events%s%s, worst score |Δ| = %.3g "
              "(tol %.3g)\n",
              bad ? "DIFFER" : "agree", worst, rel, abs_pa, abs_rad, a.events.size(), summary.empty() ? "" : ": ",
              summary.c_str(), worst_score, score_tol);
  return bad ? 1 : 0;
}
