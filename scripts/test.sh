#!/usr/bin/env bash
# Installs dependencies, then runs every test:
#   0. the style check (scripts/style.sh): clang-format on the files the last commit
#      changed, clang-tidy on the translation units reaching lib/ and ports/;
#   1. aarch64 cross build of the core's unit tests, run under qemu user mode;
#   2. the firmware footprint and cost budgets on Cortex-M4F under qemu (fails on a
#      budget overrun as on a build or run failure), and the host observer tick's
#      instructions against Boost.Odeint's (callgrind; fails above 0.8x the naive one);
#   3. the host check build (preset host-check: assertions on, -O1, warnings are errors)
#      and the whole host suite with CTest, which includes the firmware image under
#      qemu-system-arm compared with the host, the replay goldens (tests/goldens), the
#      independent validation sets (tests/data) and the consumer projects (tests/consumers:
#      find_package after cmake --install, add_subdirectory, pkg-config, Cortex-M4F);
#   4. a short libFuzzer run under AddressSanitizer + UndefinedBehaviorSanitizer of each
#      fuzz target from the committed corpora (scripts/fuzz.sh, HSTMON_FUZZ_SECONDS per
#      target, default 30): the log and parameter readers, the circuit loader and engine,
#      and both C APIs with the monitor behind them. Test suites under the sanitizers are
#      scripts/sanitizers.sh (whole host suite) and scripts/sanitizers.sh --lib (the
#      core's): instrumented builds cost twice a plain one, too much for every
#      submission (docs/hardening.md).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
jobs=$(nproc)
bash scripts/install-deps.sh

echo "== style: clang-format on the last commit's files, clang-tidy on lib/ and ports/"
bash scripts/style.sh

echo "== aarch64: core unit tests under qemu-aarch64"
cmake --preset aarch64 >/dev/null
cmake --build --preset aarch64 -j"$jobs" >/dev/null
ctest --preset aarch64 -j"$jobs" | tail -n 3

echo "== Cortex-M4F: footprint and cost budgets"
bash scripts/footprint.sh

echo "== host: observer tick instructions vs Boost.Odeint (callgrind)"
bash scripts/count_instructions.sh --strict -n 2000

echo "== host: build and full suite"
cmake --preset host-check >/dev/null
cmake --build --preset host-check -j"$jobs"
ctest --preset host-check -j"$jobs" -LE budget

echo "== fuzzing: ${HSTMON_FUZZ_SECONDS:-30} s per target"
HSTMON_FUZZ_SEED=${HSTMON_FUZZ_SEED:-1} bash scripts/fuzz.sh "${HSTMON_FUZZ_SECONDS:-30}"
