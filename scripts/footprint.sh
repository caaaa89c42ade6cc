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
with_json="$(fw footprint "${no_build[@]}")" || { echo "footprint.sh: footprint image failed" >&2; exit 2; }
fw footprint_empty --no-build >/dev/null || { echo "footprint.sh: empty image failed" >&2; exit 2; }
field() { echo "$with_json" | grep -o "\"$1\":[0-9]*" | head -1 | cut -d: -f2; }

read -r t1 d1 b1 _ < <(arm-none-eabi-size "$build/bin/hstmon_fw_footprint.elf" | awk 'NR==2{print $1,$2,$3}')
read -r t0 d0 b0 _ < <(arm-none-eabi-size "$build/bin/hstmon_fw_footprint_empty.elf" | awk 'NR==2{print $1,$2,$3}')
flash=$(( (t1 + d1) - (t0 + d0) ))
ram=$(( (d1 + b1) - (d0 + b0) ))
stack=$(field stack_bytes)
su="$(find "$build" -path '*hstmon_c.dir*' -name '*.su' | head -1)"
frame=$(awk -F'\t' '{ if ($2 > m) m = $2 } END { print m + 0 }' "$su")
instr=$(awk -v s="$(field counts_step_loop)" -v e="$(field counts_empty_loop)" -v ci="$(field calib_instructions)" \
  -v cc="$(field calib_counts)" -v n="$(field ticks)" 'BEGIN { printf "%.0f", (s - e) * ci / cc / n }')
to_instr() { awk -v c="$1" -v ci="$(field calib_instructions)" -v cc="$(field calib_counts)" 'BEGIN { printf "%.0f", c * ci / cc }'; }
heap_syms=$(arm-none-eabi-nm "$build/bin/hstmon_fw_footprint.elf" | grep -cwE 'malloc|_malloc_r|_sbrk|_Znwj' || true)
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
printf "  %-44s %8s %-6s\n" "first step after reset/input change (bound)" "$(to_instr "$(field counts_bound_step)")" "instr"
row "  its stack (painting)" "$(field stack_bound_bytes)" "B" "$max_stack"
printf "  %-44s %8s %-6s\n" "costliest tick of a fault episode (±40)" "$(to_instr "$(field counts_episode_max)")" "instr"
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
cfield() { echo "$circ_json" | grep -o "\"$1\":[0-9]*" | head -1 | cut -d: -f2; }
read -r t1 d1 b1 _ < <(arm-none-eabi-size "$build/bin/hstmon_fw_circuit_footprint.elf" | awk 'NR==2{print $1,$2,$3}')
read -r t0 d0 b0 _ < <(arm-none-eabi-size "$build/bin/hstmon_fw_circuit_footprint_empty.elf" | awk 'NR==2{print $1,$2,$3}')
c_flash=$(( (t1 + d1) - (t0 + d0) ))
c_ram=$(( (d1 + b1) - (d0 + b0) ))
c_instr=$(awk -v s="$(cfield counts_step_loop)" -v e="$(cfield counts_empty_loop)" -v ci="$(cfield calib_instructions)" \
  -v cc="$(cfield calib_counts)" -v n="$(cfield ticks)" 'BEGIN { printf "%.0f", (s - e) * ci / cc / n }')
c_heap=$(arm-none-eabi-nm "$build/bin/hstmon_fw_circuit_footprint.elf" | grep -cwE 'malloc|_malloc_r|_sbrk|_Znwj' || true)
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
mon_json="$(fw circuit_monitor --no-build | grep '"type":"circuit_monitor_footprint"')" ||
  { echo "footprint.sh: circuit monitor image failed" >&2; exit 2; }
mfield() { echo "$mon_json" | grep -o "\"$1\":[0-9]*" | head -1 | cut -d: -f2; }
melf="$build/bin/hstmon_fw_circuit_monitor.elf"
read -r t1 d1 b1 _ < <(arm-none-eabi-size "$melf" | awk 'NR==2{print $1,$2,$3}')
sym() { arm-none-eabi-nm "$melf" | awk -v n="$1" '$3==n{print $1}'; }
stack_reserve=$(( 16#$(sym __stack_top__) - 16#$(sym __stack_limit__) ))
m_flash=$(( (t1 + d1) - (t0 + d0) - $(mfield log_bytes) ))
m_ram=$(( d1 + b1 - stack_reserve ))
m_heap=$(arm-none-eabi-nm "$melf" | grep -cwE 'malloc|_malloc_r|_sbrk|_Znwj' || true)
echo "circuit monitor: CompiledCircuitMonitor<float> + generated fault table, replaying the embedded log, Cortex-M4F, -O2 (reported)"
printf "  %-44s %8s %-6s\n" "flash (image − empty − embedded log)" "$m_flash" "B"
printf "  %-44s %8s %-6s\n" "RAM (data+bss − stack reserve)" "$m_ram" "B"
printf "  %-44s %8s %-6s\n" "  of which the monitor object (static)" "$(mfield monitor_bytes)" "B"
printf "  %-44s %8s %-6s\n" "  and the setup's model scratch (static)" "$(mfield model_bytes)" "B"
printf "  %-44s %8s %-6s\n" "stack, whole replay (painting)" "$(mfield stack_bytes)" "B"
msu="$(find "$build" -path '*hstmon_fw_circuit_monitor.dir*' -name 'fw_circuit_monitor.cpp.su' | head -1)"
printf "  %-44s %8s %-6s\n" "  of which the replay loop's frame (.su)" \
  "$(awk -F'\t' '/circuit_monitor_replay/ { if ($2 > m) m = $2 } END { print m + 0 }' "$msu")" "B"
printf "  %-44s %8s %-6s\n" "instructions per tick, whole replay (bound)" \
  "$(awk -v s="$(mfield counts_replay)" -v ci="$(mfield calib_instructions)" -v cc="$(mfield calib_counts)" \
    -v n="$(mfield ticks)" 'BEGIN { printf "%.0f", s * ci / cc / n }')" "instr"
row "heap: malloc/_sbrk/new symbols in image" "$m_heap" "" 0

# A circuit's C API (ports/c_api hstmon_circuit_c.h; main_circuit_c_api.c): the paper's
# monitor from a C main, one monitor in the library's static pool. Reported, not gated
# (the circuit monitor's budgets are the engine's, above). Flash: the image minus the C API
# footprint image without a monitor (same C startup); RAM: data + bss minus the stack
# reserve (the pool and the image's own statics); instructions per 5 ms step
# at the steady state, stacks by painting; the image fails unless a fault episode is
# detected.
capi_json="$(fw circuit_c_api --no-build | grep '"type":"circuit_c_api"')" ||
  { echo "footprint.sh: circuit C API image failed" >&2; exit 2; }
afield() { echo "$capi_json" | grep -o "\"$1\":[0-9]*" | head -1 | cut -d: -f2; }
read -r t1 d1 b1 _ < <(arm-none-eabi-size "$build/bin/hstmon_fw_circuit_c_api.elf" | awk 'NR==2{print $1,$2,$3}')
read -r t0 d0 b0 _ < <(arm-none-eabi-size "$build/bin/hstmon_fw_footprint_empty.elf" | awk 'NR==2{print $1,$2,$3}')
a_heap=$(arm-none-eabi-nm "$build/bin/hstmon_fw_circuit_c_api.elf" | grep -cwE 'malloc|_malloc_r|_sbrk|_Znwj' || true)
echo "circuit C API: hstmon_circuit_c.h for paper.json ($(afield channels) channels, $(afield faults) rows) from C, Cortex-M4F, -O2 (reported)"
printf "  %-44s %8s %-6s\n" "flash (image − C API empty image)" "$(( (t1 + d1) - (t0 + d0) ))" "B"
aelf="$build/bin/hstmon_fw_circuit_c_api.elf"
asym() { arm-none-eabi-nm "$aelf" | awk -v n="$1" '$3==n{print $1}'; }
printf "  %-44s %8s %-6s\n" "RAM (data+bss − stack reserve)" "$(( d1 + b1 - (16#$(asym __stack_top__) - 16#$(asym __stack_limit__)) ))" "B"
printf "  %-44s %8s %-6s\n" "  of which the monitor's buffer (static)" "$(afield monitor_bytes)" "B"
printf "  %-44s %8s %-6s\n" "stack, create + reset_steady (painting)" "$(afield stack_setup_bytes)" "B"
printf "  %-44s %8s %-6s\n" "stack, step (painting)" "$(afield stack_step_bytes)" "B"
printf "  %-44s %8s %-6s\n" "instructions per 5 ms step (qemu icount)" \
  "$(awk -v s="$(afield counts_step_loop)" -v e="$(afield counts_empty_loop)" -v ci="$(afield calib_instructions)" \
    -v cc="$(afield calib_counts)" -v n="$(afield ticks)" 'BEGIN { printf "%.0f", (s - e) * ci / cc / n }')" "instr"
row "heap: malloc/_sbrk/new symbols in image" "$a_heap" "" 0
# A circuit's whole monitor on its compiled model at 1 ms (main_circuit_monitor_cost.cpp):
# the usual tick at the steady state, and the ticks after an input change (the first
# recomputes the model bound), for paper.json and closed_loop_hst.json. Flash: the image
# minus the circuit empty image; RAM: data + bss minus the stack reserve. Reported against
# the engine issue's budgets (2 000 instructions per usual tick, 32 KiB flash, 2 KiB RAM,
# 1 KiB stack), gated on the heap only.
for c in paper closed_loop_hst; do
  cost_json="$(fw "monitor_cost_$c" --no-build)" || { echo "footprint.sh: monitor cost image ($c) failed" >&2; exit 2; }
  kfield() { echo "$cost_json" | grep -o "\"$1\":[0-9]*" | head -1 | cut -d: -f2; }
  kelf="$build/bin/hstmon_fw_monitor_cost_$c.elf"
  read -r t1 d1 b1 _ < <(arm-none-eabi-size "$kelf" | awk 'NR==2{print $1,$2,$3}')
  read -r t0 d0 _ _ < <(arm-none-eabi-size "$build/bin/hstmon_fw_circuit_footprint_empty.elf" | awk 'NR==2{print $1,$2,$3}')
  ksym() { arm-none-eabi-nm "$kelf" | awk -v n="$1" '$3==n{print $1}'; }
  k_instr() {  # counts [per n ticks] → instructions
    awk -v c="$1" -v n="${2:-1}" -v ci="$(kfield calib_instructions)" -v cc="$(kfield calib_counts)" \
      'BEGIN { printf "%.0f", c * ci / cc / n }'
  }
  k_heap=$(arm-none-eabi-nm "$kelf" | grep -cwE 'malloc|_malloc_r|_sbrk|_Znwj' || true)
  echo "circuit monitor cost: $c.json at 1 ms, compiled model ($(kfield states) states, $(kfield channels) channels), Cortex-M4F, -O2 (reported)"
  printf "  %-44s %8s %-6s %8s\n" "flash (image − circuit empty image)" "$(( (t1 + d1) - (t0 + d0) ))" "B" "(32768)"
  printf "  %-44s %8s %-6s %8s\n" "RAM (data+bss − stack reserve)" \
    "$(( d1 + b1 - (16#$(ksym __stack_top__) - 16#$(ksym __stack_limit__)) ))" "B" "(2048)"
  printf "  %-44s %8s %-6s\n" "  of which the monitor object" "$(kfield monitor_bytes)" "B"
  printf "  %-44s %8s %-6s %8s\n" "stack, configure, reset, first ticks (painting)" "$(kfield stack_setup_bytes)" "B" "(1024)"
  printf "  %-44s %8s %-6s %8s\n" "stack, usual steps (painting)" "$(kfield stack_usual_bytes)" "B" "(1024)"
  printf "  %-44s %8s %-6s %8s\n" "stack, steps after an input change (painting)" "$(kfield stack_change_bytes)" "B" "(1024)"
  printf "  %-44s %8s %-6s %8s\n" "instructions per usual tick (qemu icount)" \
    "$(k_instr "$(( $(kfield counts_usual_loop) - $(kfield counts_empty_loop) ))" "$(kfield ticks)")" "instr" "(2000)"
  printf "  %-44s %8s %-6s\n" "  RK4 substeps of the usual ticks" "$(kfield max_substeps)" ""
  printf "  %-44s %8s %-6s\n" "first tick after an input change (bound)" "$(k_instr "$(kfield counts_change_first)")" "instr"
  printf "  %-44s %8s %-6s\n" "costliest tick after it (of $(kfield after_ticks))" "$(k_instr "$(kfield counts_change_worst)")" "instr"
  printf "  %-44s %8s %-6s\n" "mean tick after it, the bound's tick included" \
    "$(k_instr "$(kfield counts_change_total)" "$(kfield after_ticks)")" "instr"
  row "heap: malloc/_sbrk/new symbols in image" "$k_heap" "" 0
done
exit $fail
