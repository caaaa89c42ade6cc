#pragma once
// CLI11 checks whose messages are one short line: CLI11's own PositiveNumber and
// NonNegativeNumber print the largest double in full (310 digits) when they refuse.
#include <CLI/CLI.hpp>

#include <cmath>
#include <exception>
#include <string>

namespace hstmon::cli {

/// A number that is finite and above `min` (or at least `min` when `inclusive`).
inline CLI::Validator number_from(double min, bool inclusive, const char* what) {
  return CLI::Validator(
      [min, inclusive, what](const std::string& text) -> std::string {
        double v = 0.0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        const bool ok = used != 0 && used == text.size() && std::isfinite(v) && (inclusive ? v >= min : v > min);
        if (ok) return {};
        return std::string("must be ") + what + ", got '" + text.substr(0, 40) + (text.size() > 40 ? "...'" : "'");
      },
      inclusive ? "NONNEGATIVE" : "POSITIVE");
}

/// A finite number above 0.
inline CLI::Validator positive_number() { return number_from(0.0, false, "a number above 0"); }

/// A finite number of 0 or more.
inline CLI::Validator non_negative_number() { return number_from(0.0, true, "a number of 0 or more"); }

}  // namespace hstmon::cli
