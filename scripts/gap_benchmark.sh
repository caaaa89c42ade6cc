#!/usr/bin/env bash
# Benchmark of `hstmon gap` (issues 6, 13): a full run — nominal run, where (channels and
# balance equations), envelope, effect fits, pairs, verdict and discovery — on two 15 s
# logs at 1 kHz that start at rest (Coulomb friction, in the library, and a leakage at the
# loading pump, outside it: every stage runs), one core, Release build. Prints the wall time (reading
# the logs included) and the time per stage; the target is 15 s in all.
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
"$build/bin/hstmon-gap-synth" --profile A --duration 15 --rate 1000 --seed 1 --start rest --effect coulomb_friction=1.0 --load-pump-leak 2e-13 --out "$tmp/a.csv"
"$build/bin/hstmon-gap-synth" --profile B --duration 15 --rate 1000 --seed 2 --start rest --effect coulomb_friction=1.0 --load-pump-leak 2e-13 --out "$tmp/b.csv"
start=$(date +%s.%N)
taskset -c 0 "$build/bin/hstmon" gap --fit "$tmp/a.csv" --check "$tmp/b.csv" --json > "$tmp/out.json"
end=$(date +%s.%N)
python3 - "$tmp/out.json" "$start" "$end" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
wall = float(sys.argv[3]) - float(sys.argv[2])
top = j["ranking"][0] if j["ranking"] else {}
disc = j.get("discovered") or []
print(f"gap benchmark: 2 x 15 s at 1 kHz from rest, one core: {wall:.1f} s wall "
      f"({j['simulations']} simulations); verdict {j['verdict']}, top {top.get('effect')} "
      f"shrink_check {top.get('shrink_check', 0):.3f}; discovered "
      + (", ".join(d['equation'] + ': ' + ' + '.join(t['form'] for t in d['terms']) for d in disc) or "none"))
stages = j.get("stage_seconds", [])
print("  stages: " + ", ".join(f"{s['stage']} {s['seconds']:.2f} s" for s in stages)
      + f"; reading the logs and output {wall - j['seconds']:.2f} s")
print("PASS (<= 15 s)" if wall <= 15 else "SLOW (> 15 s)")
PY
