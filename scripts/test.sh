#!/usr/bin/env bash
# Installs dependencies, then runs every test:
#   1. aarch64 cross build of the core's unit tests, run under qemu user mode;
#   2. the firmware footprint and cost report on Cortex-M4F under qemu: a build or run
#      failure fails this script; a budget overrun is printed (OVER) and, while the
#      README lists it as open, does not;
#   3. the host debug build (warnings are errors) and the whole host suite with CTest,
#      which includes the firmware image under qemu-system-arm compared with the host.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
jobs=$(nproc)
bash scripts/install-deps.sh

echo "== aarch64: core unit tests under qemu-aarch64"
cmake -S . -B build/aarch64 --toolchain toolchains/aarch64-linux-gnu.cmake -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/aarch64 -j"$jobs" >/dev/null
ctest --test-dir build/aarch64 -j"$jobs" --output-on-failure | tail -n 3

echo "== Cortex-M4F: footprint and cost budgets"
budget_rc=0
bash scripts/footprint.sh || budget_rc=$?
if [ "$budget_rc" -ge 2 ]; then
  echo "footprint: build or run failure" >&2
  exit "$budget_rc"
fi
[ "$budget_rc" -eq 0 ] || echo "footprint: a budget is exceeded (see the table above and the README)"

echo "== host: build and full suite"
cmake --preset host-debug >/dev/null
cmake --build --preset host-debug -j"$jobs"
ctest --preset host-debug -j"$jobs" -LE budget
