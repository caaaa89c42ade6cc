#pragma once
/// @file params_errors.hpp
/// The parameter-file tests' shorthands: a text read as the file "p.json" (the name its
/// errors carry), and the check that such a text is refused as an ErrorCase says.

#include <gtest/gtest.h>

#include <string_view>

#include "error_cases.hpp"
#include "hstmon_host/params_file.hpp"

namespace hstmon_test {

/// `text` read as the parameter file "p.json".
inline hstmon::host::ParamsFileResult parse(std::string_view text) {
  return hstmon::host::parse_params_json(text, "p.json");
}

/// Checks that `c.text` is refused as `c` says and that no part of the file is kept.
inline void expect_params_refused(const ErrorCase& c) {
  const hstmon::host::ParamsFileResult r = parse(c.text);
  expect_error_at(r.error, "p.json", c);
  EXPECT_FALSE(r.params.has_value());
  EXPECT_FALSE(r.inputs.has_value());
  EXPECT_FALSE(r.sensors.has_value());
}

}  // namespace hstmon_test
