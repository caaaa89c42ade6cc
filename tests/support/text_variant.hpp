#pragma once
/// @file text_variant.hpp
/// Files with one mistake each, made from a good file by one replacement.

#include <gtest/gtest.h>

#include <string>

namespace hstmon_test {

/// `text` with its first `from` replaced by `to`. A `from` not in the text fails the test
/// (the variant would be the good file) and gives the text unchanged.
inline std::string replace_first(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

}  // namespace hstmon_test
