#!/usr/bin/env bash
# Instructions per observer tick on stiff closed circuits, counted by callgrind
# (bench/count_stiff_ticks.cpp: Observer<HostCircuitModel>, the interpreter the host
# replay runs, 1 ms tick, all channels measured at the steady state).
#
#   scripts/count_stiff_ticks.sh [BUILD_DIR] [TICKS]
#
#   BUILD_DIR  a Release build tree (default <repo>/build/host-release); the target
#              hstmon_count_stiff_ticks is (re)built in it
#   TICKS      ticks counted per row (default 2000)
#
# Rows: examples/circuits/closed_loop_hst.json at its parameter file's inputs (the usual
# tick, linearly implicit), the same with RK4 substeps instead, and right after its load
# torque rises by half (the ticks after an input change); the same circuit with its stiff
# modes softened (bench/circuits/closed_loop_hst_soft: the same elements and laws, so the
# same work per evaluation, with check valves and charge volume that one RK4 substep
# covers; ticked with exactly one substep, since the observer's ρ bound, an upper bound,
# asks for more there); the validation set's closed circuit (tests/data/validation_circuits). The ratio
# closed_loop_hst / soft is the cost of the linearly implicit tick against the same
# circuit without its stiff modes (docs/circuits.md "Stiff ticks").
# Exit status: 0 counted, 2 tool or build error.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build/host-release}
ticks=${2:-2000}
command -v valgrind >/dev/null || { echo "valgrind not found" >&2; exit 2; }
cmake --build "$build" -j2 --target hstmon_count_stiff_ticks >/dev/null || exit 2
bin="$build/bin/hstmon_count_stiff_ticks"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# count NAME CIRCUIT PARAMS MODE: prints "NAME Ir/tick (driver's line)"; sets $per_tick.
count() {
  local name=$1 circuit=$2 params=$3 mode=$4
  local line
  line=$(valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file="$out/$name.out" \
    "$bin" "$circuit" "$params" "$mode" "$ticks" 2>/dev/null) || { echo "$name: driver failed" >&2; exit 2; }
  local ir
  ir=$(awk '/^totals:/ {print $2; exit}' "$out/$name.out")
  per_tick=$((ir / ticks))
  printf '%-34s %8d Ir/tick   (%s)\n' "$name" "$per_tick" "$line"
}

ex="$root/examples/circuits"
count closed_loop_hst "$ex/closed_loop_hst.json" "$ex/closed_loop_hst.params.json" steady
stiff=$per_tick
count closed_loop_hst_rk4_substeps "$ex/closed_loop_hst.json" "$ex/closed_loop_hst.params.json" rk4
count closed_loop_hst_after_load_step "$ex/closed_loop_hst.json" "$ex/closed_loop_hst.params.json" step
count closed_loop_hst_soft "$root/bench/circuits/closed_loop_hst_soft.json" \
  "$root/bench/circuits/closed_loop_hst_soft.params.json" rk4_one
plain=$per_tick
val="$root/tests/data/validation_circuits"
count validation_closed_circuit "$val/circuit.json" "$val/circuit.params.json" steady
awk -v a="$stiff" -v b="$plain" 'BEGIN { printf "closed_loop_hst / closed_loop_hst_soft: %.2fx\n", a / b }'
