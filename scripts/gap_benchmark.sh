#!/usr/bin/env bash
# Benchmark of `hstmon gap` (issue 6): a full run on two 15 s logs at 1 kHz, one core,
# Release build. Prints the wall time; the target is under a minute.
#   bash scripts/gap_benchmark.sh [BUILD_DIR]     (default build/h-gap-rel)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/h-gap-rel}
if [[ ! -x $build/bin/hstmon || ! -x $build/bin/hstmon-gap-synth ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHSTMON_BUILD_BENCH=OFF >/dev/null
  cmake --build "$build" -j2 --target hstmon hstmon-gap-synth >/dev/null
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/bin/hstmon-gap-synth" --profile A --duration 15 --rate 1000 --seed 1 --effect coulomb_friction=1.5 --out "$tmp/a.csv"
"$build/bin/hstmon-gap-synth" --profile B --duration 15 --rate 1000 --seed 2 --effect coulomb_friction=1.5 --out "$tmp/b.csv"
start=$(date +%s.%N)
taskset -c 0 "$build/bin/hstmon" gap --fit "$tmp/a.csv" --check "$tmp/b.csv" --json > "$tmp/out.json"
end=$(date +%s.%N)
python3 - "$tmp/out.json" "$start" "$end" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
wall = float(sys.argv[3]) - float(sys.argv[2])
top = j["ranking"][0] if j["ranking"] else {}
print(f"gap benchmark: 2 x 15 s at 1 kHz, one core: {wall:.1f} s wall "
      f"({j['simulations']} simulations); verdict {j['verdict']}, top {top.get('effect')} "
      f"shrink_check {top.get('shrink_check', 0):.3f}")
print("PASS (< 60 s)" if wall < 60 else "SLOW (>= 60 s)")
PY
