#pragma once
/// @file count_driver.hpp
/// What the callgrind drivers (count_ticks.cpp, count_engine_ticks.cpp) share: their
/// command line, `<variant> [ticks]`, and the check that a run stayed at the operating point.

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace hstmon_bench {

/// The tick count on the command line (default 10000), or 0 after printing what is wrong:
/// the usage (the variants are listed in `source`) or a tick count that is not positive.
inline long ticks_argument(int argc, char** argv, const char* source) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: %s <variant> [ticks]   (variants: see %s)\n", argv[0], source);
    return 0;
  }
  const long n = argc == 3 ? std::strtol(argv[2], nullptr, 10) : 10000;
  if (n <= 0) {
    std::fprintf(stderr, "ticks must be positive\n");
    return 0;
  }
  return n;
}

/// The motor speed w [rad/s] after the run is the operating point's (else the count would
/// be of the wrong work).
inline bool plausible(double w) { return std::isfinite(w) && w > 100.0 && w < 250.0; }

}  // namespace hstmon_bench
