#!/usr/bin/env bash
# The whole host suite under AddressSanitizer + UndefinedBehaviorSanitizer (preset
# host-sanitizers: RelWithDebInfo, -fsanitize=address,undefined -fno-sanitize-recover=all,
# no benchmarks; warnings not errors here, see below) in build/host-sanitizers. Tests that probe the heap
# with their own allocator traps skip themselves under ASan by design.
# Usage: scripts/sanitizers.sh [extra ctest arguments, e.g. -R robust]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
jobs=$(( $(nproc) < 2 ? $(nproc) : 2 ))
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# The preset has HSTMON_WERROR=OFF: GCC 12's -fsanitize=shift instrumentation makes
# -Wsign-conversion fire falsely on `(uint8 >> i) & 1u` (lib/include/hstmon/fault_matcher.hpp),
# so with -Werror it would not build with GCC. Warnings are judged by host-debug; this
# build is for the runtime checks, all of which stay on. (docs/hardening.md)
cmake --preset host-sanitizers >/dev/null
cmake --build --preset host-sanitizers -j"$jobs"
# firmware.footprint measures the Cortex-M4 image (arm-none-eabi, not sanitized) against
# its budgets; scripts/footprint.sh and the host-debug suite run it, so it is left out here.
ctest --preset host-sanitizers -j"$jobs" -E '^firmware\.footprint$' "$@"
