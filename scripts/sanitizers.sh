#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer runs (-fsanitize=address,undefined
# -fno-sanitize-recover=all; docs/hardening.md). Tests that probe the heap with their own
# allocator traps skip themselves under ASan by design (the plain builds run them).
#
# Usage: scripts/sanitizers.sh [--lib] [extra ctest arguments, e.g. -R robust]
#   (default)  the whole host suite: preset host-sanitizers (RelWithDebInfo, no benchmarks)
#              in build/host-sanitizers. A cold build is the most expensive thing the
#              project compiles (instrumented objects take about twice a plain -O0 -g build).
#   --lib      the embedded core's own suite only (lib/ and its C API: tests/core,
#              tests/matcher, ports/c_api's tests; the set the aarch64 cross run uses):
#              preset host-sanitizers-lib, in build/host-sanitizers-lib: about 6 min cold on
#              2 cores instead of over 30. scripts/test.sh runs neither; its fuzz run
#              (scripts/fuzz.sh) puts the readers, the circuit engine and both C APIs with
#              the monitor behind them under ASan + UBSan.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
jobs=$(( $(nproc) < 2 ? $(nproc) : 2 ))
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

if [[ ${1:-} == --lib ]]; then
  shift
  # Preset host-sanitizers-lib: host-sanitizers' flags with -DHSTMON_BUILD_HOST=OFF.
  cmake --preset host-sanitizers-lib >/dev/null
  cmake --build --preset host-sanitizers-lib -j"$jobs" >/dev/null
  ctest --preset host-sanitizers-lib -j"$jobs" "$@"
  exit
fi

# Both presets have HSTMON_WERROR=OFF: GCC 12's -fsanitize=shift instrumentation makes
# -Wsign-conversion fire falsely on `(uint8 >> i) & 1u` (lib/include/hstmon/fault_matcher.hpp),
# so with -Werror it would not build with GCC. Warnings are judged by the plain builds; this
# build is for the runtime checks, all of which stay on. (docs/hardening.md)
cmake --preset host-sanitizers >/dev/null
cmake --build --preset host-sanitizers -j"$jobs"
# firmware.footprint measures the Cortex-M4 image (arm-none-eabi, not sanitized) against
# its budgets; scripts/footprint.sh runs it, so it is left out here.
ctest --preset host-sanitizers -j"$jobs" -E '^firmware\.footprint$' "$@"
