#!/usr/bin/env bash
# Issue 3's fault campaign (docs/fault_campaign.md): builds the release configuration and
# runs bench/fault_campaign.cpp — every fault of the thesis signature table at 2
# magnitudes × 3 operating points × 5 seeds, sensor bias/drift/stuck faults, and 10 h of
# nominal replay with ±2 % parameter error. Not part of CI.
#
#   bash scripts/fault_campaign.sh [--quick] [--json] [--jobs N] [other campaign options]
#
# --quick: 2 seeds and 0.5 h of nominal replay (about 5 s). Options are passed through
# (hstmon_fault_campaign --help lists them). Set BUILD_DIR to use another build tree.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
build=${BUILD_DIR:-build/host-release}
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  bash scripts/install-deps.sh
  if [[ "$build" == build/host-release ]]; then
    cmake --preset host-release >/dev/null
  else
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  fi
fi
cmake --build "$build" -j"${JOBS:-2}" --target hstmon_fault_campaign >/dev/null
exec "$build/bin/hstmon_fault_campaign" "$@"
