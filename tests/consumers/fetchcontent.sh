#!/usr/bin/env bash
# The same C++ consumer with FetchContent_MakeAvailable(hstmon) (SOURCE_DIR = this
# checkout, where a real consumer names its git mirror): the add_subdirectory path through
# FetchContent, so the same targets and no tests or tools.
source "$(dirname "$0")/common.sh"
cmake -S "$HSTMON_SRC/tests/consumers/cpp" -B "$work/build" -DHSTMON_FROM=fetch -DHSTMON_SOURCE_DIR="$HSTMON_SRC" \
  -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j"$jobs" --target consumer
"$work/build/consumer"
