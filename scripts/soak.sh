#!/usr/bin/env bash
# Soak: a simulated HOURS (default 24) at 1 kHz through Monitor<float> and Monitor<double>
# (tests/soak/soak.cpp: the stiff reference simulates a ±2 % mismatched machine in 30-min
# start/stop cycles — from rest with the logger running, supply on, PRV steps every 4 s or
# ramps/sinusoids, supply off and coast to rest — through rig_fast sensors; extra
# arguments go to hstmon_soak, e.g. --lag 10). Prints start-ups, load changes, ticks,
# alarms (must be 0), non-finite ticks (0), max substeps, generator and monitor time, and
# the mean residual per hour. Then, if valgrind is
# installed, callgrind instruction counts of an ordinary tick and of the first tick after a
# load change (model bound recomputed). Exits non-zero if an alarm or a NaN occurred.
# Usage: scripts/soak.sh [HOURS=24] [float|double|both] [hstmon_soak options]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
hours=${1:-24}
type=${2:-both}
shift $(( $# > 2 ? 2 : $# ))
build=build/h-soak
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHSTMON_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j2 --target hstmon_soak >/dev/null
status=0
"$build/bin/hstmon_soak" --hours "$hours" --type "$type" "$@" || status=$?
if command -v valgrind >/dev/null; then
  echo "== callgrind: instructions per tick (Release, this host's x86-64 code)"
  out=$(mktemp -d)
  valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file="$out/cg.%p" \
    "$build/bin/hstmon_soak" --slice --type "$type" >/dev/null 2>"$out/log" || true
  for f in "$out"/cg.*; do
    desc=$(grep -m1 '^desc: Trigger' "$f" | sed 's/^desc: Trigger: Client Request: //')
    total=$(grep -m1 '^totals:' "$f" | awk '{print $2}')
    [[ -n "$total" && "$total" != 0 ]] && echo "  $desc: $total instructions"
  done
  rm -rf "$out"
fi
exit $status
