#include "cli_log_replay.hpp"

#include <filesystem>
#include <system_error>

#include "hstmon_host/log_stream.hpp"

namespace hstmon::cli {

LogReplay replay_log_file(const std::string& path, const host::ReadOptions& read_options,
                          const ThesisParams<double>& params, const ThesisInputs<double>& inputs,
                          const host::ReplayOptions& options, const std::function<void(double)>& progress) {
  LogReplay out;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec) out.file_bytes = size;
  host::LogStream stream;
  host::ReplayOptions opt = options;
  opt.progress = nullptr;  // per chunk, from the bytes read, below
  host::ChunkedReplay replay(params, inputs, opt);
  if (stream.open(path, read_options)) {
    while (stream.next()) {
      replay.add(stream.data());
      if (progress) progress(stream.fraction());
    }
  }
  out.result = replay.finish();
  out.notes = stream.data().notes;
  out.error = stream.data().error;
  return out;
}

}  // namespace hstmon::cli
