// The log files people really have (issue 31), through both log readers — the thesis
// logs' (read_log, LogStream) and a circuit's (read_circuit_log, on thesis.json, whose
// columns are the thesis logs' names): gzip-compressed, a header in Windows-1250 or
// -1252, a trailing separator on every line, a --map that matches nothing. Both give the
// same rows, or the same error.
#include <gtest/gtest.h>
#include <zlib.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/loaded_circuit.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_host/log_layout.hpp"
#include "hstmon_host/log_options.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/log_stream.hpp"
#include "hstmon_host/text_encoding.hpp"

#include "../support/cli_run.hpp"

namespace {

namespace ct = hstmon::circuit_tools;
namespace hh = hstmon::host;
using hh::Signal;

const ct::LoadedCircuit& thesis_circuit() {
  static const ct::LoadedCircuit c = hstmon_test::load_example("thesis");
  return c;
}

/// A file in this run's scratch folder, removed with it at exit.
std::filesystem::path scratch(const std::string& name) {
  struct Dir {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("hstmon_log_shapes_" + std::to_string(::getpid()));
    Dir() { std::filesystem::create_directories(path); }
    ~Dir() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir dir;
  return dir.path / name;
}

std::string write_plain(const std::string& name, const std::string& text) {
  const auto p = scratch(name);
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string write_gz(const std::string& name, const std::string& text) {
  const auto p = scratch(name).string();
  gzFile f = gzopen(p.c_str(), "wb");
  EXPECT_NE(f, nullptr);
  EXPECT_EQ(gzwrite(f, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
  gzclose(f);
  return p;
}

/// A thesis-rig log: `rows` rows of the seven columns, separator `sep`, `tail` after each line.
std::string rig_log(std::size_t rows, char sep = ',', const std::string& tail = "") {
  std::string s = "t[s]" + std::string(1, sep) + "p_sup[bar]" + sep + "kp" + sep + "p_mi[bar]" + sep + "p_mo[bar]" +
                  sep + "p_pp[bar]" + sep + "w_m[rpm]" + tail + "\n";
  char row[200];
  for (std::size_t i = 0; i < rows; ++i) {
    std::snprintf(row, sizeof row, "%.4f%c35.000%c4.851e-08%c%.3f%c0.040%c%.3f%c%.2f", 1e-3 * static_cast<double>(i),
                  sep, sep, sep, 30.0 + 0.01 * static_cast<double>(i % 97), sep, sep,
                  10.0 + 0.02 * static_cast<double>(i % 13), sep, 500.0 + static_cast<double>(i % 31));
    s += row + tail + "\n";
  }
  return s;
}

/// What both readers read: time and p_mi [SI]; or the error.
struct Read {
  std::vector<double> t, p_mi;
  std::string error;
};

std::size_t sensor(const std::string& column) {
  const auto& sensors = thesis_circuit().file.sensors;
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    if (sensors[i].column == column) return i;
  }
  ADD_FAILURE() << "no sensor " << column;
  return 0;
}

Read thesis_read(const std::string& path, const hh::ReadOptions& o = {}) {
  const hh::LogData d = hh::read_log(path, o);
  if (!d.ok()) return {{}, {}, d.error->to_string()};
  return {d.t, d.column(Signal::kPMi), ""};
}

/// The same file through LogStream, chunk by chunk with a small buffer.
Read thesis_stream(const std::string& path, const hh::ReadOptions& o = {}) {
  hh::LogStream s;
  Read r;
  if (s.open(path, o, 7, 256)) {
    while (s.next()) {
      r.t.insert(r.t.end(), s.data().t.begin(), s.data().t.end());
      const auto& p = s.data().column(Signal::kPMi);
      r.p_mi.insert(r.p_mi.end(), p.begin(), p.end());
    }
  }
  if (!s.data().ok()) return {{}, {}, s.data().error->to_string()};
  return r;
}

Read circuit_read(const std::string& path, const hh::ReadOptions& o = {}) {
  const ct::CircuitLog log = ct::read_circuit_log(path, thesis_circuit().file, o);
  if (!log.ok()) return {{}, {}, log.error->to_string()};
  return {log.t, log.sensors[sensor("p_mi")], ""};
}

void expect_same(const Read& a, const Read& b, const char* what) {
  EXPECT_EQ(a.error, b.error) << what;
  EXPECT_EQ(a.t, b.t) << what;
  EXPECT_EQ(a.p_mi, b.p_mi) << what;
}

/// Both readers (and the streamed thesis read) give `want` for the file at `path`.
void expect_all(const std::string& path, const Read& want, const hh::ReadOptions& o = {}) {
  expect_same(thesis_read(path, o), want, "read_log");
  expect_same(thesis_stream(path, o), want, "LogStream");
  expect_same(circuit_read(path, o), want, "read_circuit_log");
}

#define EXPECT_READ_OK(r) EXPECT_EQ((r).error, "")

}  // namespace

TEST(LogShapes, GzipIsReadAsThePlainText) {
  const std::string text = rig_log(500);
  const Read plain = thesis_read(write_plain("plain.csv", text));
  EXPECT_READ_OK(plain);
  ASSERT_EQ(plain.t.size(), 500u);
  expect_all(write_gz("log.csv.gz", text), plain);
  // Known by the magic bytes, whatever the name.
  expect_all(write_gz("log.dat", text), plain);
}

TEST(LogShapes, DamagedGzipNamesTheLineOfTheText) {
  const std::string gz = write_gz("whole.csv.gz", rig_log(2000));
  std::ifstream in(gz, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  bytes.resize(bytes.size() / 2);
  const std::string cut = write_plain("cut.csv.gz", bytes);
  const Read r = thesis_read(cut);
  EXPECT_NE(r.error.find("cannot decompress (gzip)"), std::string::npos) << r.error;
  EXPECT_EQ(r.error.rfind(cut + ":", 0), 0u) << r.error;
  EXPECT_EQ(r.error.find(cut + ":0"), std::string::npos) << "a line of the text: " << r.error;
  expect_same(circuit_read(cut), r, "read_circuit_log");
  EXPECT_NE(thesis_stream(cut).error.find("cannot decompress (gzip)"), std::string::npos);
}

// 'ciśnienie' (pressure) as a Polish Excel writes it: Windows-1250, ś = 0x9C.
TEST(LogShapes, Windows1250HeaderIsReadAsUtf8) {
  const std::string utf8 = "t[s];ci\xC5\x9Bnienie[bar];p_mi[bar]\n0;1,5;2\n0,001;1,5;3\n";
  const std::string cp1250 = "t[s];ci\x9Cnienie[bar];p_mi[bar]\n0;1,5;2\n0,001;1,5;3\n";
  hh::ReadOptions o;
  ASSERT_EQ(hh::add_column_map(o, "ci\xC5\x9Bnienie=p_sup"), "");
  const Read want = thesis_read(write_plain("utf8.csv", utf8), o);
  EXPECT_READ_OK(want);
  EXPECT_EQ(want.p_mi, (std::vector<double>{2e5, 3e5}));
  expect_all(write_plain("cp1250.csv", cp1250), want, o);
  expect_all(write_gz("cp1250.csv.gz", cp1250), want, o);
  // Unmapped, the column is named in UTF-8 in the note.
  const hh::LogData d = hh::read_log(scratch("cp1250.csv").string());
  ASSERT_TRUE(d.ok());
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_NE(d.notes[0].find("'ci\xC5\x9Bnienie'"), std::string::npos) << d.notes[0];
  EXPECT_NE(d.notes[0].find(":1:6: note"), std::string::npos) << "character columns: " << d.notes[0];
}

TEST(LogShapes, EncodingDetectionAndOption) {
  using E = hh::TextEncoding;
  EXPECT_EQ(hh::detect_head_encoding("t;ci\x9Cnienie;pr\xEA" "dko\x9C\xE6\n"), E::kWindows1250);
  EXPECT_EQ(hh::detect_head_encoding("t;ot\xE1\xE8ky;t\xB3ok\n"), E::kWindows1250);  // Czech č, Polish ł
  EXPECT_EQ(hh::detect_head_encoding("t;F\xF6rderpumpe;Q[m\xB3/s];Temp[\xB0" "C]\n"), E::kWindows1252);
  EXPECT_EQ(hh::detect_head_encoding("t;press\xE3o\n"), E::kWindows1252);  // ã is no Polish or Czech letter
  EXPECT_EQ(hh::detect_head_encoding("t;p\xC2\xB0\xFF\n"), E::kUtf8) << "UTF-8 with junk: left for the reader";
  EXPECT_EQ(hh::detect_head_encoding(std::string("t;a\x01\xE8\n")), E::kUtf8) << "binary";
  // The option wins over detection: Latin-1 reads 0xB3 as ³ however it looks.
  const std::string text = "t[s],Vm\xB3,p_mi\n0,1,2\n";
  hh::ReadOptions o;
  EXPECT_EQ(hh::set_encoding(o, "latin-1"), "");
  EXPECT_NE(hh::set_encoding(o, "ebcdic"), "");
  const hh::LogData d = hh::read_log_from_memory(text, "mem.csv", o);
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_NE(d.notes[0].find("'Vm\xC2\xB3'"), std::string::npos) << d.notes[0];
  const ct::CircuitLog c = ct::parse_circuit_log(text, "mem.csv", thesis_circuit().file, o);
  ASSERT_TRUE(c.ok()) << c.error->to_string();
  ASSERT_EQ(c.notes.size(), 1u);
  EXPECT_NE(c.notes[0].find("'Vm\xC2\xB3'"), std::string::npos) << c.notes[0];
}

TEST(LogShapes, TrailingSeparatorsAreDropped) {
  const Read want = thesis_read(write_plain("clean.tsv", rig_log(50, '\t')));
  EXPECT_READ_OK(want);
  expect_all(write_plain("trailing.tsv", rig_log(50, '\t', "\t")), want);
  expect_all(write_plain("trailing.csv", rig_log(50, ',', ",")), want);
  // A value under the unnamed column is no column to drop: the same error in both.
  std::string text = rig_log(3, ',', ",");
  text.insert(text.size() - 1, "7");
  const std::string path = write_plain("value.csv", text);
  const Read r = thesis_read(path);
  EXPECT_EQ(r.error, path + ":4:52: error: " + hh::kUnnamedValueMessage);
  expect_all(path, r);
  // An empty name anywhere else is still an error.
  EXPECT_FALSE(thesis_read(write_plain("gap.csv", "t,,p_mi\n0,1,2\n")).error.empty());
  EXPECT_FALSE(circuit_read(scratch("gap.csv").string()).error.empty());
}

TEST(LogShapes, MapThatMatchesNoColumnIsAnErrorListingTheColumns) {
  const std::string path = write_plain("map.csv", rig_log(5));
  hh::ReadOptions o;
  ASSERT_EQ(hh::add_column_map(o, "Druck_A=p_mi"), "");
  const Read r = thesis_read(path, o);
  EXPECT_EQ(r.error, path + ":1:1: error: column map entry 'Druck_A' matches no column; the columns are 't', "
                            "'p_sup', 'kp', 'p_mi', 'p_mo', 'p_pp', 'w_m'");
  expect_all(path, r, o);
}

// The command line: exit 2 (bad input) with the columns listed, for both readers.
TEST(LogShapes, CliBadMapExitsTwo) {
  const std::string path = write_plain("cli.csv", rig_log(20));
  const std::string cli = HSTMON_CLI;
  const std::string circuit = std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/thesis.json";
  for (const std::string& extra : {std::string(), "--circuit " + circuit}) {
    const std::string cmd = cli + " replay " + extra + " --map nope=p_mi " + path + " 2>&1";
    const hstmon_test::CliRun r = hstmon_test::run_command(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.out;
    EXPECT_NE(r.out.find("column map entry 'nope' matches no column; the columns are 't', 'p_sup'"), std::string::npos)
        << r.out;
  }
}
