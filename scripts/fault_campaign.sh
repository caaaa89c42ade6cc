#!/usr/bin/env bash
# The fault campaign over rig conditions (issues 3 and 12, docs/fault_campaign.md): builds
# the release configuration and runs bench/fault_campaign.cpp — per condition (baseline rig,
# then transducer lag, sample rate, start-up, load shape, ADC, parameter error and Ppp range
# changed one at a time) the 50 % PRV blockage, every parameter fault of the thesis table,
# sensor loop break / stuck / bias, and nominal replay (10 h in all) with start-ups,
# stop/start and load changes. Not part of CI.
#
#   bash scripts/fault_campaign.sh [--quick] [--json] [--jobs N] [other campaign options]
#
# --quick: 0.5 h of nominal replay, fewer seeds (about 10 s). Options are passed through
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
