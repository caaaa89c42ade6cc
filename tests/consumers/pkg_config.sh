#!/usr/bin/env bash
# A C11 program (tests/consumers/c_pkgconfig) compiled and linked against the installed C
# API through pkg-config alone — no CMake on the consumer's side.
source "$(dirname "$0")/common.sh"
command -v pkg-config >/dev/null || { echo "skipped: pkg-config not installed"; exit 77; }
export PKG_CONFIG_PATH="$HSTMON_PREFIX/lib/pkgconfig"
# The same program against both C API libraries (the engine's only in host builds).
for pc in hstmon-c hstmon-c-engine; do
  echo "pkg-config: $pc $(pkg-config --modversion $pc): $(pkg-config --cflags --libs $pc)"
  # shellcheck disable=SC2046  # pkg-config output is a list of flags
  "${CC:-cc}" -std=c11 -Wall -Wextra -Wpedantic -Werror "$HSTMON_SRC/tests/consumers/c_pkgconfig/main.c" \
    $(pkg-config --cflags --libs $pc) ${LDFLAGS:-} -o "$work/consumer_$pc"
  "$work/consumer_$pc"
done
