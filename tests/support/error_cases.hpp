#pragma once
/// @file error_cases.hpp
/// Tables of inputs a reader must refuse, for parameterised tests: each case gives the
/// text, the line:column its error must point at and a part of the message.

#include <gtest/gtest.h>

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>

#include "hstmon_host/source_error.hpp"

namespace hstmon_test {

struct ErrorCase {
  const char* group;  ///< the kind of mistake; names the test ("BadNumbers_3")
  std::string text;
  std::size_t line, column;
  std::string part;  ///< a part of the message
};

/// A failing case shows its text with the escapes it was written with.
inline void PrintTo(const ErrorCase& c, std::ostream* os) { *os << c.group << ": " << testing::PrintToString(c.text); }

/// The test name of a case: its group and its place in the table.
inline std::string error_case_name(const testing::TestParamInfo<ErrorCase>& info) {
  return std::string(info.param.group) + "_" + std::to_string(info.index);
}

/// Checks that reading `c.text` as `file` gave the error `c` describes.
inline void expect_error_at(const std::optional<hstmon::host::SourceError>& error, const std::string& file,
                            const ErrorCase& c) {
  ASSERT_TRUE(error.has_value()) << "accepted: " << testing::PrintToString(c.text);
  EXPECT_EQ(error->file, file);
  EXPECT_EQ(error->line, c.line) << error->to_string();
  EXPECT_EQ(error->column, c.column) << error->to_string();
  EXPECT_NE(error->message.find(c.part), std::string::npos) << error->to_string();
}

}  // namespace hstmon_test
