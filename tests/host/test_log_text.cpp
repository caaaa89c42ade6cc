// load_log_text: a plain file mapped, a gzip file decompressed, and every other file read
// as read_log_text reads it, with its errors; the text the same whichever way.
#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "hstmon_host/log_text.hpp"
#include "hstmon_host/text_source.hpp"

namespace {

namespace fs = std::filesystem;
using hstmon::host::load_log_text;
using hstmon::host::LogText;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "hstmon_log_text";
  fs::create_directories(dir);
  return dir / name;
}

std::string write_plain(const std::string& name, const std::string& text) {
  const fs::path p = scratch(name);
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string write_gz(const std::string& name, const std::string& text) {
  const std::string p = scratch(name).string();
  gzFile f = gzopen(p.c_str(), "wb");
  EXPECT_NE(f, nullptr);
  EXPECT_EQ(gzwrite(f, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
  gzclose(f);
  return p;
}

const std::string kLog = "t[s],p_mi[bar]\n0,1.5\n0.001,1.6\n";

TEST(LogText, PlainFileIsMappedWithItsText) {
  LogText text;
  ASSERT_FALSE(load_log_text(write_plain("plain.csv", kLog), text).has_value());
  EXPECT_TRUE(text.mapped());
  EXPECT_EQ(text.view(), kLog);
}

TEST(LogText, GzipFileIsDecompressedNotMapped) {
  LogText text;
  ASSERT_FALSE(load_log_text(write_gz("log.csv.gz", kLog), text).has_value());
  EXPECT_FALSE(text.mapped());
  EXPECT_EQ(text.view(), kLog);
}

TEST(LogText, ReloadingReplacesTheText) {
  LogText text;
  ASSERT_FALSE(load_log_text(write_plain("first.csv", kLog), text).has_value());
  ASSERT_FALSE(load_log_text(write_gz("second.csv.gz", "t\n1\n"), text).has_value());
  EXPECT_EQ(text.view(), "t\n1\n");
  ASSERT_FALSE(load_log_text(write_plain("third.csv", "t\n2\n"), text).has_value());
  EXPECT_EQ(text.view(), "t\n2\n");
}

TEST(LogText, EmptyFileIsEmptyText) {
  LogText text;
  ASSERT_FALSE(load_log_text(write_plain("empty.csv", ""), text).has_value());
  EXPECT_TRUE(text.view().empty());
}

TEST(LogText, ErrorsAreTheReadersErrors) {
  // A missing file, a folder, a damaged gzip stream: the same message as read_log_text's.
  std::string big;
  for (int i = 0; i < 2000; ++i) big += kLog;
  const std::string whole = write_gz("whole.csv.gz", big);
  std::string bytes;
  {
    std::ifstream in(whole, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bytes.size(), 40u);
  const std::string damaged = write_plain("damaged.csv.gz", bytes.substr(0, bytes.size() / 2));  // cut short
  for (const std::string& path : {scratch("missing.csv").string(), scratch("").string(), damaged}) {
    LogText text;
    std::string read;
    const auto mapped_error = load_log_text(path, text);
    const auto read_error = hstmon::host::read_log_text(path, read);
    ASSERT_TRUE(mapped_error.has_value()) << path;
    ASSERT_TRUE(read_error.has_value()) << path;
    EXPECT_EQ(mapped_error->to_string(), read_error->to_string()) << path;
  }
}

}  // namespace
