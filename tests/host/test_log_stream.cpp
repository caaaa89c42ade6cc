// LogStream (chunked reads) against read_log (whole file): the same rows, bit for bit,
// the same notes and the same error, whatever the buffer and chunk sizes; and
// ChunkedReplay over the chunks against replay() of the whole log.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/log_stream.hpp"
#include "hstmon_host/replay.hpp"

namespace hh = hstmon::host;

namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A regular 1 kHz log with `rows` rows; every 37th line a comment, CRLF line ends on
// every 5th line, so the buffer boundaries fall on every kind of line.
std::string regular_log(int rows) {
  std::string s = "# exported by a test\nt[s],p_sup[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n";
  char line[160];
  for (int i = 0; i < rows; ++i) {
    if (i % 37 == 36) s += "# a comment\n\n";
    std::snprintf(line, sizeof line, "%.3f,35,4.41e-8,%.4f,1.88,%.3f,%d%s", i * 1e-3, 33.0 + (i % 17) * 0.01,
                  171.0 + (i % 5) * 0.1, 1677 + i % 3, i % 5 == 0 ? "\r\n" : "\n");
    s += line;
  }
  return s;
}

// All chunks of a stream appended, with the stream's notes and error.
hh::LogData read_streamed(const std::string& path, std::size_t chunk_rows, std::size_t buffer_bytes,
                          std::size_t* chunks = nullptr, bool whole = false) {
  hh::LogStream stream;
  hh::LogData all;
  std::size_t n = 0;
  if (stream.open(path, {}, chunk_rows, buffer_bytes)) {
    while (stream.next()) {
      ++n;
      const hh::LogData& c = stream.data();
      EXPECT_TRUE(whole || c.rows() <= chunk_rows) << c.rows();
      all.t.insert(all.t.end(), c.t.begin(), c.t.end());
      for (std::size_t s = 0; s < all.values.size(); ++s) {
        all.values[s].insert(all.values[s].end(), c.values[s].begin(), c.values[s].end());
      }
    }
    EXPECT_DOUBLE_EQ(stream.fraction(), stream.data().ok() ? 1.0 : stream.fraction());
  }
  all.present = stream.data().present;
  all.notes = stream.data().notes;
  all.error = stream.data().error;
  all.header_line = stream.data().header_line;
  if (chunks != nullptr) *chunks = n;
  return all;
}

void expect_same(const hh::LogData& whole, const hh::LogData& streamed) {
  EXPECT_EQ(whole.notes, streamed.notes);
  ASSERT_EQ(whole.error.has_value(), streamed.error.has_value());
  if (whole.error) {
    EXPECT_EQ(whole.error->to_string(), streamed.error->to_string());
    return;  // a strict read keeps no rows; the stream's rows are void
  }  // a strict read keeps no rows; the stream's rows are void
  EXPECT_EQ(whole.header_line, streamed.header_line);
  EXPECT_EQ(whole.present, streamed.present);
  EXPECT_EQ(whole.t, streamed.t);  // bit for bit
  for (std::size_t s = 0; s < whole.values.size(); ++s) EXPECT_EQ(whole.values[s], streamed.values[s]) << s;
}

}  // namespace

TEST(LogStream, SameRowsAsReadLogForAnyBufferAndChunk) {
  const std::string path = write_temp("stream_regular.csv", regular_log(3000));
  const hh::LogData whole = hh::read_log(path);
  ASSERT_TRUE(whole.ok());
  ASSERT_EQ(whole.rows(), 3000u);
  for (const std::size_t buffer : {std::size_t{200}, std::size_t{257}, std::size_t{4096}, hh::kStreamBufferBytes}) {
    for (const std::size_t chunk : {std::size_t{1}, std::size_t{7}, std::size_t{1000}, std::size_t{5000}}) {
      SCOPED_TRACE("buffer " + std::to_string(buffer) + ", chunk " + std::to_string(chunk));
      std::size_t chunks = 0;
      expect_same(whole, read_streamed(path, chunk, buffer, &chunks));
      EXPECT_EQ(chunks, (3000 + chunk - 1) / chunk);
    }
  }
}

TEST(LogStream, ErrorsAndNotesAsReadLog) {
  std::string bad_row = regular_log(2000);
  bad_row.insert(bad_row.rfind("1.500,"), "1.4995,35,x,1,1,1,1\n");  // bad number deep in the file
  std::string back_in_time = regular_log(2000);
  back_in_time += "1.000,35,4.41e-8,33,1.88,171,1677\n";  // the last row, after many chunks
  std::string ragged = regular_log(1500) + "1.6,35\n";
  std::string notes = "t[s],p_mi[bar],extra,w_m[rpm]\n" + std::string("0,1,2,3\n0.5,1,2,3\n");
  std::string bad_utf8 = regular_log(1200);
  bad_utf8.insert(bad_utf8.rfind("1.100,"), "# caf\xC3(\n");
  const std::string no_data = "t[s],p_mi[bar]\n# nothing\n";
  const std::string empty;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"bad_row", bad_row}, {"back_in_time", back_in_time}, {"ragged", ragged}, {"notes", notes},
      {"bad_utf8", bad_utf8}, {"no_data", no_data}, {"empty", empty}};
  for (const auto& [name, text] : cases) {
    SCOPED_TRACE(name);
    const std::string path = write_temp("stream_" + name + ".csv", text);
    const hh::LogData whole = hh::read_log(path);
    expect_same(whole, read_streamed(path, 64, 300));
    expect_same(whole, read_streamed(path, hh::kStreamChunkRows, hh::kStreamBufferBytes));
  }
  const hh::LogData missing = read_streamed(::testing::TempDir() + "no_such_log.csv", 64, 300);
  ASSERT_TRUE(missing.error.has_value());
  EXPECT_EQ(missing.error->to_string(), hh::read_log(::testing::TempDir() + "no_such_log.csv").error->to_string());
}

TEST(LogStream, HeaderBeyondTheFirstBufferReadsWhole) {
  // 40 comment lines above the header: more than the 256-byte buffer holds.
  std::string text;
  for (int i = 0; i < 40; ++i) text += "# a long preamble line of an export, number " + std::to_string(i) + "\n";
  text += regular_log(500);
  const std::string path = write_temp("stream_preamble.csv", text);
  std::size_t chunks = 0;
  expect_same(hh::read_log(path), read_streamed(path, 64, 256, &chunks, true));
  EXPECT_EQ(chunks, 1u);
}

TEST(LogStream, LineLongerThanTheBufferIsAnError) {
  std::string text = regular_log(100);
  text += "0.2000" + std::string(400, '0') + ",35,4.41e-8,33,1.88,171,1677\n";
  const std::string path = write_temp("stream_long_line.csv", text);
  const hh::LogData d = read_streamed(path, 64, 256);
  ASSERT_TRUE(d.error.has_value());
  EXPECT_NE(d.error->to_string().find(":107:1: error: line longer than"), std::string::npos) << d.error->to_string();
}

TEST(ChunkedReplay, SameResultAsReplayOfTheWholeLog) {
  const std::string path = write_temp("stream_replay.csv", regular_log(3000));
  const hh::LogData whole = hh::read_log(path);
  const hstmon::ThesisParams<double> params;
  const hstmon::ThesisInputs<double> inputs;
  hh::ReplayOptions opt;
  opt.keep_trace = true;
  const hh::ReplayResult a = hh::replay(whole, params, inputs, opt);

  hh::LogStream stream;
  ASSERT_TRUE(stream.open(path, {}, 1000, 4096));
  hh::ChunkedReplay chunked(params, inputs, opt);
  while (stream.next()) chunked.add(stream.data());
  const hh::ReplayResult b = chunked.finish();

  // The same accessor on both sides, so no field is compared with another by mistake.
  const auto summary = [](const hh::ReplayResult& r) {
    return std::make_tuple(r.rows, r.ticks, r.tick, r.t_first, r.t_last, r.notes, r.final_status, r.events.size(),
                           r.health);
  };
  EXPECT_EQ(summary(a), summary(b));
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_EQ(a.channels[c].n, b.channels[c].n);
    EXPECT_EQ(a.channels[c].sum, b.channels[c].sum);
    EXPECT_EQ(a.channels[c].sumsq_diff, b.channels[c].sumsq_diff);
    EXPECT_EQ(a.channels[c].row_max, b.channels[c].row_max);
  }
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (std::size_t i = 0; i < a.trace.size(); i += 97) EXPECT_EQ(a.trace[i].y_hat, b.trace[i].y_hat) << i;
}
