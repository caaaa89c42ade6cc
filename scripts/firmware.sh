#!/usr/bin/env bash
# Builds the Cortex-M4F firmware (toolchains/arm-none-eabi.cmake) and runs an image under
# QEMU's mps2-an386 with semihosting; the image's output goes to stdout, its exit status
# is this script's.
#
#   scripts/firmware.sh [IMAGE] [--build-dir DIR] [--no-build] [--log CSV] [--monitor-log CSV] [--timeout S]
#
# IMAGE: replay (default; the JSON lines of `hstmon replay --json` for the embedded log),
#        replay_trace (plus one %a line of residuals per row), footprint, footprint_empty
#        (run with -icount shift=0: 1 instruction = 1 ns of virtual time), heap_probe
#        (must FAIL to link: checks the no-heap rule; exit 0 when it does fail),
#        circuit_footprint, circuit_footprint_empty (the circuit engine on the generated
#        circuit header, -icount as footprint), circuit_replay_trace (the embedded log
#        through the engine: one %a residual line per row and a digest), circuit_monitor
#        (a circuit's whole monitor on its generated circuit header and fault table over
#        --monitor-log: the JSON lines of `hstmon replay --circuit --json` and one %a
#        residual line per row), circuit_c_api (the paper's monitor through the circuit
#        C API from a C main: cost, stack and a detected episode, -icount as footprint),
#        monitor_cost_paper, monitor_cost_closed_loop_hst (a circuit's whole monitor on its
#        compiled model at 1 ms: the usual tick and the ticks after an input change).
# Defaults: build dir build/firmware-arm, log examples/prv_blockage.csv, monitor log
# examples/circuits/paper_dm_fault.csv, timeout 300 s.
# Exit status: the image's; 124 on timeout; 2 on a bad command line or build failure.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
image=replay
build="$root/build/firmware-arm"
do_build=1
log=""
monitor_log=""
timeout_s=300
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift 2 ;;
    --no-build) do_build=0; shift ;;
    --log) log="$(realpath "$2")"; shift 2 ;;
    --monitor-log) monitor_log="$(realpath "$2")"; shift 2 ;;
    --timeout) timeout_s="$2"; shift 2 ;;
    replay|replay_trace|footprint|footprint_empty|heap_probe|circuit_footprint|circuit_footprint_empty|circuit_replay_trace|circuit_monitor|circuit_c_api|monitor_cost_paper|monitor_cost_closed_loop_hst) image="$1"; shift ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) echo "firmware.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
for tool in arm-none-eabi-g++ qemu-system-arm cmake; do
  command -v "$tool" >/dev/null || { echo "firmware.sh: '$tool' not found (bash scripts/install-deps.sh)" >&2; exit 2; }
done

if [ "$do_build" = 1 ]; then
  # Preset firmware-arm (CMakePresets.json): the arm-none-eabi toolchain, Release, warnings
  # are errors; -B overrides its build dir.
  cfg=(-S "$root" --preset firmware-arm -B "$build")
  [ -n "$log" ] && cfg+=("-DHSTMON_FW_LOG=$log")
  [ -n "$monitor_log" ] && cfg+=("-DHSTMON_FW_MONITOR_LOG=$monitor_log")
  cmake "${cfg[@]}" >"$build.configure.log" 2>&1 || { cat "$build.configure.log" >&2; exit 2; }
  if [ "$image" = heap_probe ]; then
    if cmake --build "$build" --target hstmon_fw_heap_probe -j2 >"$build.heap_probe.log" 2>&1; then
      echo "firmware.sh: heap_probe linked, but an image that calls malloc must not" >&2
      exit 1
    fi
    if grep -q "undefined reference to \`__wrap_malloc'" "$build.heap_probe.log"; then
      echo "heap_probe: link refused as intended (undefined reference to __wrap_malloc)"
      exit 0
    fi
    cat "$build.heap_probe.log" >&2
    exit 2
  fi
  cmake --build "$build" -j2 --target hstmon_fw_replay hstmon_fw_replay_trace hstmon_fw_footprint \
    hstmon_fw_footprint_empty hstmon_fw_circuit_footprint hstmon_fw_circuit_footprint_empty \
    hstmon_fw_circuit_replay_trace hstmon_fw_circuit_monitor hstmon_fw_circuit_c_api \
    hstmon_fw_monitor_cost_paper hstmon_fw_monitor_cost_closed_loop_hst >"$build.build.log" 2>&1 || { cat "$build.build.log" >&2; exit 2; }
fi

elf="$build/bin/hstmon_fw_$image.elf"
[ -f "$elf" ] || { echo "firmware.sh: $elf not built" >&2; exit 2; }
# Semihosting output goes to a file chardev (without one, QEMU 7 writes it to stderr,
# mixed with its own messages); the file is copied to stdout afterwards.
tmp="$(mktemp)"
trap 'rm -f "$tmp"' EXIT
qemu=(qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none
      -chardev "file,id=semihost,path=$tmp"
      -semihosting-config enable=on,target=native,chardev=semihost -kernel "$elf")
case "$image" in footprint*|circuit_footprint*|circuit_monitor|circuit_c_api|monitor_cost_*) qemu+=(-icount shift=0) ;; esac
rc=0
timeout "$timeout_s" "${qemu[@]}" </dev/null || rc=$?
cat "$tmp"
[ "$rc" = 124 ] && echo "firmware.sh: $image timed out after $timeout_s s" >&2
exit "$rc"
