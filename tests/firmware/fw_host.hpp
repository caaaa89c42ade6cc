#pragma once
/// @file fw_host.hpp
/// What the host builds of the firmware's replays share: the log embedded in the program
/// (hstmon_fw_log_data.hpp) as the firmware reads it, and standard output as the sink.

#include <cstdio>

#include "fw_replay.hpp"
#include "hstmon_fw_log_data.hpp"

namespace hstmon_fw_host {

inline hstmon::fw::LogView embedded_log() {
  namespace d = hstmon::fw::log_data;
  return hstmon::fw::LogView{d::kName, d::kRows, d::kCols, d::kSignal, d::kScale, &d::kData[0][0]};
}

inline void print(const char* s) { std::fputs(s, stdout); }

}  // namespace hstmon_fw_host
