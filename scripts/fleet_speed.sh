#!/usr/bin/env bash
# Fleet replay speed (issue 16, item 6): `hstmon replay --summary` over 200 logs (20
# machines × 10 days, each 60 s at 1 kHz = 60 001 rows; ten distinct logs written by
# hstmon-sim, hard-linked under the 200 names) with --jobs 1 and --jobs 2, Release build.
# Prints the wall time and rows/s of each, the speed-up, and checks that both outputs are
# byte-identical. Best of RUNS (default 3); on a shared machine the speed-up is bounded
# by what the other users leave free.
#   bash scripts/fleet_speed.sh [BUILD_DIR] [RUNS]     (default build/host-release, 3)
set -euo pipefail
source "$(dirname "$0")/speed_setup.sh" "$@"
for seed in 0 1 2 3 4 5 6 7 8 9; do
  "$build/bin/hstmon-sim" --scenario rig --load steps --duration 60 --rate 1000 --seed $((seed + 1)) --out "$tmp/src$seed.csv"
done
for m in $(seq -w 1 20); do
  mkdir -p "$tmp/fleet/m$m"
  for d in 0 1 2 3 4 5 6 7 8 9; do ln "$tmp/src$(((10#$m + d) % 10)).csv" "$tmp/fleet/m$m/2026-11-1$d.csv"; done
done
rows=$((200 * ($(wc -l < "$tmp/src0.csv") - 1)))
declare -A best
for jobs in 1 2; do
  for ((i = 0; i < runs; ++i)); do
    (cd "$tmp" && /usr/bin/time -f "%e %U %S" -o "time.txt" "$build/bin/hstmon" replay --jobs $jobs fleet > "out$jobs.jsonl")
    read -r wall user sys < "$tmp/time.txt"
    if [[ -z ${best[$jobs]:-} ]] || awk -v a="$wall" -v b="${best[$jobs]%% *}" 'BEGIN { exit !(a < b) }'; then
      best[$jobs]="$wall $user $sys"
    fi
  done
done
cmp "$tmp/out1.jsonl" "$tmp/out2.jsonl" || { echo "fleet_speed: outputs of --jobs 1 and 2 differ" >&2; exit 1; }
[[ $(grep -c '"status":"ok"' "$tmp/out1.jsonl") == 200 ]] || { echo "fleet_speed: not 200 ok lines" >&2; exit 1; }
read -r a au as <<< "${best[1]}"
read -r b bu bs <<< "${best[2]}"
awk -v r="$rows" -v a="$a" -v au="$au" -v as="$as" -v b="$b" -v bu="$bu" -v bs="$bs" -v load="$(cut -d' ' -f1 /proc/loadavg)" 'BEGIN {
  printf "fleet replay, 200 logs (%d rows), wall (user + system):\n", r
  printf "  --jobs 1: %.2f s (%.2f + %.2f s), %.2f M rows/s\n", a, au, as, r / a / 1e6
  printf "  --jobs 2: %.2f s (%.2f + %.2f s), %.2f M rows/s\n", b, bu, bs, r / b / 1e6
  printf "  speed-up %.2fx; outputs identical; load average %s when done\n", a / b, load }'
