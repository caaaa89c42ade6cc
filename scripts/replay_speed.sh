#!/usr/bin/env bash
# End-to-end replay speed from disk (issue 16, item 5): `hstmon replay --json --no-progress`
# of a 1 kHz log of 15 min and of 60 min (3.6 M rows, ~290 MB), written by hstmon-sim,
# single-threaded (one core), Release build. Prints wall, user and system time, peak
# memory (/usr/bin/time -v) and rows/s per wall second; best of RUNS (default 3). The
# target is ≥ 3.6 M rows/s wall for the one-hour log. The log is read whole (a plain file
# mapped, log_text.hpp), column by column (circuit_log.hpp), so peak memory grows with it.
# The first run of each size warms the page cache, so the figures are for a log the machine
# has just written or read. HSTMON_REPLAY_ARGS adds arguments to the replay (e.g.
# --interpret: the generic engine instead of the compiled thesis circuit).
#   bash scripts/replay_speed.sh [BUILD_DIR] [RUNS]     (default build/host-release, 3)
set -euo pipefail
source "$(dirname "$0")/speed_setup.sh" "$@"
for minutes in 15 60; do
  log=$tmp/rig_${minutes}min.csv
  "$build/bin/hstmon-sim" --scenario rig --load steps --duration $((minutes * 60)) --rate 1000 --seed 1 --out "$log"
  rows=$(($(wc -l < "$log") - 1))
  best=""
  for ((i = 0; i < runs; ++i)); do
    /usr/bin/time -v -o "$tmp/time.txt" "$build/bin/hstmon" replay --json --no-progress ${HSTMON_REPLAY_ARGS:-} "$log" > "$tmp/out.jsonl"
    read -r wall user sys rss < <(awk -F': ' '
      /Elapsed \(wall clock\)/ { n = split($2, p, ":"); w = 0; for (i = 1; i <= n; ++i) w = w * 60 + p[i] }
      /User time/ { u = $2 } /System time/ { s = $2 } /Maximum resident/ { r = $2 }
      END { print w, u, s, r }' "$tmp/time.txt")
    if [[ -z $best ]] || awk -v a="$wall" -v b="${best%% *}" 'BEGIN { exit !(a < b) }'; then
      best="$wall $user $sys $rss"
    fi
  done
  read -r wall user sys rss <<< "$best"
  awk -v m="$minutes" -v rows="$rows" -v bytes="$(stat -c %s "$log")" -v w="$wall" -v u="$user" -v s="$sys" -v r="$rss" 'BEGIN {
    printf "replay %2d min at 1 kHz (%d rows, %.0f MB): wall %.2f s (user %.2f s, system %.2f s), peak RSS %.1f MB: %.2f M rows/s\n",
           m, rows, bytes / 1e6, w, u, s, r / 1024, rows / w / 1e6 }'
done
