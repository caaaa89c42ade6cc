#!/usr/bin/env bash
# One firmware test case (registered by CMakeLists.txt in this folder). Environment:
#   FW_SRC (repo root), FW_BUILD (cross build dir), FW_LOG (embedded log), FW_OUT (scratch
#   dir), FW_HOST (host float replay), FW_CIRCUIT_HOST (host float circuit-engine replay), FW_COMPARE (comparison tool),
#   FW_ORACLE (the thesis image's monitor in double on the host), HSTMON_CLI (optional),
#   FW_MIN_EVENTS (matcher events the log must give; 2 for the default prv_blockage.csv),
#   FW_MONITOR_HOST (host float circuit monitor), FW_MONITOR_LOG (its embedded log),
#   FW_MONITOR_CIRCUIT_FILE (the circuit file the CLI replays it with), FW_MONITOR_EXPECT
#   (the fault the default monitor log injects: an isolated event must name it first).
# Exit 77 = skipped (no cross toolchain / no qemu / no CLI in this build).
set -euo pipefail
case_name="$1"
mkdir -p "$FW_OUT"
out="$FW_OUT/$case_name"
# Float vs double tolerance (docs/firmware.md): relative 1e-5 of the statistic, plus
# 1 Pa (0.01 mbar) on pressures and 1e-4 rad/s (0.001 rpm) on speed; matcher events
# exact (kinds, row times, candidate names and order), scores within 1e-4.
tol=(--rel 1e-5 --abs-pa 1 --abs-rad 1e-4 --score 1e-4 --min-events "${FW_MIN_EVENTS:-0}")

need_cross() {
  for t in arm-none-eabi-g++ qemu-system-arm; do
    command -v "$t" >/dev/null || { echo "skipped: $t not installed"; exit 77; }
  done
}
# The thesis image runs the hand-written thesis monitor; its reference is that monitor in
# double (hstmon_thesis_oracle), as `hstmon replay` runs thesis.json through the engine.
need_oracle() {
  "$FW_ORACLE" "$FW_LOG" >"$out.oracle.jsonl"
}
fw() { "$FW_SRC/scripts/firmware.sh" "$@" --build-dir "$FW_BUILD" --log "$FW_LOG" --monitor-log "$FW_MONITOR_LOG"; }
# The circuit monitor's output must not be vacuous: a detection, and an isolation whose
# best candidate is the injected fault (when the log is the default one, which says which).
monitor_not_vacuous() {
  grep -q '"event":"detected"' "$1" || { echo "no detected event in $1"; exit 1; }
  if [ -n "${FW_MONITOR_EXPECT:-}" ]; then
    grep -q "^{\"candidates\":\[{\"fault\":\"$FW_MONITOR_EXPECT\".*\"event\":\"isolated\"" "$1" ||
      { echo "no isolated event naming $FW_MONITOR_EXPECT first in $1"; exit 1; }
  fi
}

case "$case_name" in
  host_float_vs_oracle)  # the portable loop in float (host) vs the same monitor in double
    need_oracle
    "$FW_HOST" >"$out.fw.jsonl"
    "$FW_COMPARE" "$out.oracle.jsonl" "$out.fw.jsonl" "${tol[@]}" ;;
  build)              # fixture: configure and build every image, run the smallest
    need_cross
    fw footprint_empty ;;
  heap_probe)         # an image that calls malloc must not link
    need_cross
    fw heap_probe ;;
  qemu_vs_oracle)     # Cortex-M4F under qemu vs the same monitor in double
    need_cross; need_oracle
    fw replay --no-build >"$out.fw.jsonl"
    "$FW_COMPARE" "$out.oracle.jsonl" "$out.fw.jsonl" "${tol[@]}" ;;
  qemu_bitexact)      # Cortex-M4F vs host float, every residual of every row in %a
    need_cross
    fw replay_trace --no-build >"$out.qemu.txt"
    "$FW_HOST" --trace >"$out.host.txt"
    if cmp -s "$out.qemu.txt" "$out.host.txt"; then
      echo "bit-exact: $(grep -c '^trace' "$out.host.txt") rows, $(grep residual_digest "$out.host.txt")"
    else
      echo "firmware and host float differ:"; diff "$out.qemu.txt" "$out.host.txt" | head -20; exit 1
    fi ;;
  circuit_bitexact)   # the circuit engine (generated header): Cortex-M4F vs host float, every row in %a
    need_cross
    fw circuit_replay_trace --no-build >"$out.qemu.txt"
    "$FW_CIRCUIT_HOST" >"$out.host.txt"
    rows=$(grep -c '^trace' "$out.host.txt" || true)
    [ "$rows" -gt 0 ] || { echo "circuit replay traced no row"; exit 1; }
    if cmp -s "$out.qemu.txt" "$out.host.txt"; then
      echo "bit-exact: $rows rows, $(grep residual_digest "$out.host.txt")"
    else
      echo "circuit engine: firmware and host float differ:"; diff "$out.qemu.txt" "$out.host.txt" | head -20; exit 1
    fi ;;
  circuit_monitor_bitexact)  # a circuit's whole monitor: Cortex-M4F vs host float, every line (events, %a residuals)
    need_cross
    fw circuit_monitor --no-build | grep -v '"type":"circuit_monitor_footprint"' >"$out.qemu.txt"
    "$FW_MONITOR_HOST" >"$out.host.txt"
    monitor_not_vacuous "$out.host.txt"
    if cmp -s "$out.qemu.txt" "$out.host.txt"; then
      echo "bit-exact: $(grep -c '^trace' "$out.host.txt") rows, $(grep -c '"type":"event"' "$out.host.txt") events," \
        "$(grep residual_digest "$out.host.txt")"
    else
      echo "circuit monitor: firmware and host float differ:"; diff "$out.qemu.txt" "$out.host.txt" | head -20; exit 1
    fi ;;
  circuit_monitor_vs_cli)    # the Cortex-M4F circuit monitor vs `hstmon replay --circuit --json --matcher-only` (double;
                             # the firmware runs the matcher, not the host's fit of the steady windows)
    need_cross
    [ -n "${HSTMON_CLI:-}" ] && [ -x "$HSTMON_CLI" ] || { echo "skipped: hstmon CLI not built"; exit 77; }
    "$HSTMON_CLI" replay --circuit "$FW_MONITOR_CIRCUIT_FILE" "$FW_MONITOR_LOG" --json --no-progress --matcher-only >"$out.cli.jsonl"
    fw circuit_monitor --no-build >"$out.fw.jsonl"
    monitor_not_vacuous "$out.fw.jsonl"
    "$FW_COMPARE" "$out.cli.jsonl" "$out.fw.jsonl" "${tol[@]}" --min-events 2 ;;
  footprint)          # budgets: flash, RAM, stack, instructions per tick, heap
    need_cross
    "$FW_SRC/scripts/footprint.sh" --build-dir "$FW_BUILD" --no-build ;;
  *) echo "fw_test.sh: unknown case $case_name" >&2; exit 2 ;;
esac
