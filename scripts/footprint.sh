#!/usr/bin/env bash
# Footprint and cost of one monitor on Cortex-M4F (float, -O2), against the budgets of
# issue 4. One monitor = the C API's hstmon::Monitor<float, 26, 2, 1>: observer, sensor
# checks, residual evaluator, fault matcher. Builds the firmware (scripts/firmware.sh), then:
#  - flash / RAM: arm-none-eabi-size of the footprint image (one monitor through the C
#    API: create, reset, step, read) minus the same image without the monitor;
#  - stack: measured by stack painting in that image under qemu (deepest use below
#    main's frame), each against the same 512 B: create + reset_steady; 2000 nominal
#    steps; the first step after a reset or an input change (a tick plus the model bound:
#    ≈ 20 steady-state solves, the deepest path); a fault episode. The largest single
#    frame of the C API object from -fstack-usage (.su) is shown too (-Wstack-usage=512
#    also fails the build on a larger frame);
#  - instructions per 1 ms tick at the nominal point: qemu -icount shift=0 (1 instruction
#    = 1 ns), SysTick calibrated on a loop of known length, loop overhead subtracted;
#  - heap: no malloc/_sbrk symbol in the image, and an image that calls malloc must not link.
# Reported without a budget: the instructions of that first step and the costliest tick
# of a fault episode (neither is a per-tick cost at the nominal point).
# Then the circuit engine on the generated circuit header (issue 14; main_circuit_footprint.cpp):
# flash, RAM, setup and step stack, instructions per tick and heap, all gated.
# Then a circuit's whole monitor (issue 15; main_circuit_monitor.cpp): flash, RAM, stack reported, heap gated;
# and the same monitor through the circuit C API from C (main_circuit_c_api.c): reported, heap gated;
# and the whole monitor on the compiled paper.json and closed_loop_hst.json at 1 ms
# (main_circuit_monitor_cost.cpp): usual tick and the ticks after an input change, reported.
#   scripts/footprint.sh [--build-dir DIR] [--no-build]
# Exit status: 0 all budgets met; 1 a budget exceeded; 2 build or run failure.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build/firmware-arm"
no_build=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift 2 ;;
    --no-build) no_build=(--no-build); shift ;;
    -h|--help) sed -n '2,24p' "$0"; exit 0 ;;
    *) echo "footprint.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
# Budgets (issue 4; flash and RAM raised to issue 14's 24 KiB and 1.5 KiB when the monitor
# learned start-ups and transients, issue 12).
max_flash=24576 max_ram=1536 max_stack=512 max_instr=1000

fw() { "$root/scripts/firmware.sh" "$@" --build-dir "$build"; }
# What every image below is measured with.
json_field() { echo "$1" | grep -o "\"$2\":[0-9]*" | head -1 | cut -d: -f2; }  # JSON line, key
elf_size() { arm-none-eabi-size "$1" | awk 'NR==2{print $1,$2,$3}'; }          # text data bss
elf_symbol() { arm-none-eabi-nm "$1" | awk -v n="$2" '$3==n{print $1}'; }      # address (hex)
heap_symbols() { arm-none-eabi-nm "$1" | grep -cwE 'malloc|_malloc_r|_sbrk|_Znwj' || true; }
# Flash (text + data) and RAM (data + bss) of image $1 less those of image $2 [B].
size_less() {
  local t1 d1 b1 t0 d0 b0
  read -r t1 d1 b1 < <(elf_size "$1")
  read -r t0 d0 b0 < <(elf_size "$2")
  echo "$(( (t1 + d1) - (t0 + d0) )) $(( (d1 + b1) - (d0 + b0) ))"
}
# RAM of image $1 without its stack reserve: data + bss − (__stack_top__ − __stack_limit__) [B].
ram_less_stack() {
  local d b
  read -r _ d b < <(elf_size "$1")
  echo $(( d + b - (16#$(elf_symbol "$1" __stack_top__) - 16#$(elf_symbol "$1" __stack_limit__)) ))
}
# SysTick counts $2, less counts $4 (default 0), as instructions per tick over $3 ticks
# (default 1), by the calibration among the JSON fields function $1 reads.
instr_of() {
  awk -v c="$2" -v n="${3:-1}" -v e="${4:-0}" -v ci="$($1 calib_instructions)" -v cc="$($1 calib_counts)" \
    'BEGIN { printf "%.0f", (c - e) * ci / cc / n }'
}
# Instructions per tick of an image's step loop, its empty loop subtracted.
loop_instr() { instr_of "$1" "$($1 counts_step_loop)" "$($1 ticks)" "$($1 counts_empty_loop)"; }
# The JSON line of type $2 that image $1 prints; exits 2, naming it $3, when the image fails.
image_json() {
  fw "$1" --no-build | grep "\"type\":\"$2\"" || { echo "footprint.sh: $3 image failed" >&2; exit 2; }
}
# A reported (not gated) image's flash, image $1 less image $2 and $4 bytes (default 0), and
# its RAM without the stack reserve; $3 says what the flash is.
reported_sizes() {
  local flash
  read -r flash _ < <(size_less "$1" "$2")
  printf "  %-44s %8s %-6s\n" "$3" "$(( flash - ${4:-0} ))" "B"
  printf "  %-44s %8s %-6s\n" "RAM (data+bss − stack reserve)" "$(ram_less_stack "$1")" "B"
}

with_json="$(fw footprint "${no_build[@]}")" || { echo "footprint.sh: footprint image failed" >&2; exit 2; }
fw footprint_empty --no-build >/dev/null || { echo "footprint.sh: empty image failed" >&2; exit 2; }
field() { json_field "$with_json" "$1"; }

read -r flash ram < <(size_less "$build/bin/hstmon_fw_footprint.elf" "$build/bin/hstmon_fw_footprint_empty.elf")
stack=$(field stack_bytes)
su="$(find "$build" -path '*hstmon_c.dir*' -name '*.su' | head -1)"
frame=$(awk -F'\t' '{ if ($2 > m) m = $2 } END { print m + 0 }' "$su")
instr=$(loop_instr field)
heap_syms=$(heap_symbols "$build/bin/hstmon_fw_footprint.elf")
heap_probe="refused"
fw heap_probe >/dev/null 2>&1 || heap_probe="LINKED"

fail=0
row() {  # name value unit budget
  local ok="ok"
  case "$2" in
    ''|*[!0-9]*) ok="NOT MEASURED"; fail=1 ;;
    *) if [ "$2" -gt "$4" ]; then ok="OVER"; fail=1; fi ;;
  esac
  printf "  %-44s %8s %-6s %8s   %s\n" "$1" "$2" "$3" "≤ $4" "$ok"
}
echo "hstmon footprint: one monitor (C API: float observer + evaluator + matcher), Cortex-M4F, -O2, arm-none-eabi-gcc $(arm-none-eabi-gcc -dumpversion)"
printf "  %-44s %8s %-6s %8s\n" "what" "value" "unit" "budget"
row "flash (text+data, image with − without)" "$flash" "B" "$max_flash"
row "RAM (data+bss, image with − without)" "$ram" "B" "$max_ram"
printf "  %-44s %8s %-6s\n" "  of which the monitor object" "$(field monitor_bytes)" "B"
row "stack, create + reset_steady (painting)" "$stack" "B" "$max_stack"
row "stack, step (painting, incl. timing loop)" "$(field stack_step_bytes)" "B" "$max_stack"
printf "  %-44s %8s %-6s\n" "  largest single frame (.su, C API object)" "$frame" "B"
row "instructions per 1 ms tick (qemu icount)" "$instr" "instr" "$max_instr"
printf "  %-44s %8s %-6s\n" "  RK4 substeps of the measured ticks" "$(field max_substeps)" ""
printf "  %-44s %8s %-6s\n" "first step after reset/input change (bound)" "$(instr_of field "$(field counts_bound_step)")" "instr"
row "  its stack (painting)" "$(field stack_bound_bytes)" "B" "$max_stack"
printf "  %-44s %8s %-6s\n" "costliest tick of a fault episode (±40)" "$(instr_of field "$(field counts_episode_max)")" "instr"
row "  stack over the episode (painting)" "$(field stack_episode_bytes)" "B" "$max_stack"
row "heap: malloc/_sbrk/new symbols in image" "$heap_syms" "" 0
if [ "$heap_probe" != refused ]; then echo "  heap: an image calling malloc LINKED (must be refused)"; fail=1; fi
echo "  heap: an image that calls malloc: link $heap_probe"

# The circuit engine (issue 14): Observer<CompiledModel<float>> on the circuit's compiled
# model generated at build time (default thesis.json at 1 ms; HSTMON_FW_CIRCUIT_COMPILED=OFF
# runs the interpreting CircuitModel, which is far over the instruction budget), same
# methods and budgets as above.
circ_json="$(fw circuit_footprint --no-build)" || { echo "footprint.sh: circuit footprint image failed" >&2; exit 2; }
fw circuit_footprint_empty --no-build >/dev/null || { echo "footprint.sh: circuit empty image failed" >&2; exit 2; }
cfield() { json_field "$circ_json" "$1"; }
circuit_empty="$build/bin/hstmon_fw_circuit_footprint_empty.elf"
read -r c_flash c_ram < <(size_less "$build/bin/hstmon_fw_circuit_footprint.elf" "$circuit_empty")
c_instr=$(loop_instr cfield)
c_heap=$(heap_symbols "$build/bin/hstmon_fw_circuit_footprint.elf")
echo "circuit engine: Observer<CompiledModel<float>> on the generated circuit ($(cfield states) states, $(cfield stiff_nodes) stiff nodes), Cortex-M4F, -O2"
row "flash (text+data, image with − without)" "$c_flash" "B" "$max_flash"
row "RAM (data+bss, image with − without)" "$c_ram" "B" "$max_ram"
printf "  %-44s %8s %-6s\n" "  of which the observer object" "$(cfield observer_bytes)" "B"
printf "  %-44s %8s %-6s\n" "  of which the model object" "$(cfield model_bytes)" "B"
row "stack, configure + reset_steady (painting)" "$(cfield stack_setup_bytes)" "B" "$max_stack"
row "stack, step (painting, incl. timing loop)" "$(cfield stack_step_bytes)" "B" "$max_stack"
row "instructions per tick (qemu icount)" "$c_instr" "instr" "$max_instr"
printf "  %-44s %8s %-6s\n" "  RK4 substeps of the measured ticks" "$(cfield max_substeps)" ""
row "heap: malloc/_sbrk/new symbols in image" "$c_heap" "" 0

# A circuit's whole monitor (issue 15; main_circuit_monitor.cpp): CircuitMonitor<float> on
# the generated circuit header and fault table (default paper.json at 5 ms, 28 rows),
# replaying its embedded log. Reported, not gated: the image carries the replay's JSON
# output and statistics (double) besides the monitor. Flash: the image minus the circuit
# empty image minus the embedded log; RAM: data + bss minus the stack reserve; stack: the
# whole replay by painting, below main's frame; instructions: the whole replay (setup,
# monitor, statistics and output included, so a bound on the monitor's) per tick, qemu
# -icount as above.
mon_json="$(image_json circuit_monitor circuit_monitor_footprint "circuit monitor")"
mfield() { json_field "$mon_json" "$1"; }
melf="$build/bin/hstmon_fw_circuit_monitor.elf"
echo "circuit monitor: CompiledCircuitMonitor<float> + generated fault table, replaying the embedded log, Cortex-M4F, -O2 (reported)"
reported_sizes "$melf" "$circuit_empty" "flash (image − empty − embedded log)" "$(mfield log_bytes)"
printf "  %-44s %8s %-6s\n" "  of which the monitor object (static)" "$(mfield monitor_bytes)" "B"
printf "  %-44s %8s %-6s\n" "  and the setup's model scratch (static)" "$(mfield model_bytes)" "B"
printf "  %-44s %8s %-6s\n" "stack, whole replay (painting)" "$(mfield stack_bytes)" "B"
msu="$(find "$build" -path '*hstmon_fw_circuit_monitor.dir*' -name 'fw_circuit_monitor.cpp.su' | head -1)"
printf "  %-44s %8s %-6s\n" "  of which the replay loop's frame (.su)" \
  "$(awk -F'\t' '/circuit_monitor_replay/ { if ($2 > m) m = $2 } END { print m + 0 }' "$msu")" "B"
printf "  %-44s %8s %-6s\n" "instructions per tick, whole replay (bound)" \
  "$(instr_of mfield "$(mfield counts_replay)" "$(mfield ticks)")" "instr"
row "heap: malloc/_sbrk/new symbols in image" "$(heap_symbols "$melf")" "" 0

# A circuit's C API (ports/c_api hstmon_circuit_c.h; main_circuit_c_api.c): the paper's
# monitor from a C main, one monitor in the library's static pool. Reported, not gated
# (the circuit monitor's budgets are the engine's, above). Flash: the image minus the C API
# footprint image without a monitor (same C startup); RAM: data + bss minus the stack
# reserve (the pool and the image's own statics); instructions per 5 ms step
# at the steady state, stacks by painting; the image fails unless a fault episode is
# detected.
capi_json="$(image_json circuit_c_api circuit_c_api "circuit C API")"
afield() { json_field "$capi_json" "$1"; }
aelf="$build/bin/hstmon_fw_circuit_c_api.elf"
echo "circuit C API: hstmon_circuit_c.h for paper.json ($(afield channels) channels, $(afield faults) rows) from C, Cortex-M4F, -O2 (reported)"
reported_sizes "$aelf" "$build/bin/hstmon_fw_footprint_empty.elf" "flash (image − C API empty image)"
printf "  %-44s %8s %-6s\n" "  of which the monitor's buffer (static)" "$(afield monitor_bytes)" "B"
printf "  %-44s %8s %-6s\n" "stack, create + reset_steady (painting)" "$(afield stack_setup_bytes)" "B"
printf "  %-44s %8s %-6s\n" "stack, step (painting)" "$(afield stack_step_bytes)" "B"
printf "  %-44s %8s %-6s\n" "instructions per 5 ms step (qemu icount)" "$(loop_instr afield)" "instr"
row "heap: malloc/_sbrk/new symbols in image" "$(heap_symbols "$aelf")" "" 0
# A circuit's whole monitor on its compiled model at 1 ms (main_circuit_monitor_cost.cpp):
# the usual tick at the steady state, and the ticks after an input change (the first
# recomputes the model bound), for paper.json and closed_loop_hst.json. Flash: the image
# minus the circuit empty image; RAM: data + bss minus the stack reserve. Reported against
# the engine issue's budgets (2 000 instructions per usual tick, 32 KiB flash, 2 KiB RAM,
# 1 KiB stack), gated on the heap only.
for c in paper closed_loop_hst; do
  cost_json="$(fw "monitor_cost_$c" --no-build)" || { echo "footprint.sh: monitor cost image ($c) failed" >&2; exit 2; }
  kfield() { json_field "$cost_json" "$1"; }
  kelf="$build/bin/hstmon_fw_monitor_cost_$c.elf"
  read -r k_flash _ < <(size_less "$kelf" "$circuit_empty")
  k_heap=$(heap_symbols "$kelf")
  echo "circuit monitor cost: $c.json at 1 ms, compiled model ($(kfield states) states, $(kfield channels) channels), Cortex-M4F, -O2 (reported)"
  printf "  %-44s %8s %-6s %8s\n" "flash (image − circuit empty image)" "$k_flash" "B" "(32768)"
  printf "  %-44s %8s %-6s %8s\n" "RAM (data+bss − stack reserve)" "$(ram_less_stack "$kelf")" "B" "(2048)"
  printf "  %-44s %8s %-6s\n" "  of which the monitor object" "$(kfield monitor_bytes)" "B"
  printf "  %-44s %8s %-6s %8s\n" "stack, configure, reset, first ticks (painting)" "$(kfield stack_setup_bytes)" "B" "(1024)"
  printf "  %-44s %8s %-6s %8s\n" "stack, usual steps (painting)" "$(kfield stack_usual_bytes)" "B" "(1024)"
  printf "  %-44s %8s %-6s %8s\n" "stack, steps after an input change (painting)" "$(kfield stack_change_bytes)" "B" "(1024)"
  printf "  %-44s %8s %-6s %8s\n" "instructions per usual tick (qemu icount)" \
    "$(instr_of kfield "$(kfield counts_usual_loop)" "$(kfield ticks)" "$(kfield counts_empty_loop)")" "instr" "(2000)"
  printf "  %-44s %8s %-6s\n" "  RK4 substeps of the usual ticks" "$(kfield max_substeps)" ""
  printf "  %-44s %8s %-6s\n" "first tick after an input change (bound)" "$(instr_of kfield "$(kfield counts_change_first)")" "instr"
  printf "  %-44s %8s %-6s\n" "costliest tick after it (of $(kfield after_ticks))" "$(instr_of kfield "$(kfield counts_change_worst)")" "instr"
  printf "  %-44s %8s %-6s\n" "mean tick after it, the bound's tick included" \
    "$(instr_of kfield "$(kfield counts_change_total)" "$(kfield after_ticks)")" "instr"
  row "heap: malloc/_sbrk/new symbols in image" "$k_heap" "" 0
done
exit $fail
