#!/usr/bin/env bash
# The same C++ consumer with add_subdirectory(hstmon source tree): gets hstmon::core and
# hstmon::c_api, and none of hstmon's tests or tools (the consumer's CMakeLists checks);
# builds everything it got (`all`, so the C API too) and runs.
source "$(dirname "$0")/common.sh"
cmake -S "$HSTMON_SRC/tests/consumers/cpp" -B "$work/build" -DHSTMON_FROM=source -DHSTMON_SOURCE_DIR="$HSTMON_SRC" \
  -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j"$jobs"
[ -f "$work/build/hstmon/ports/c_api/libhstmon_c.a" ] || { echo "add_subdirectory: the C API was not built"; exit 1; }
"$work/build/consumer"
