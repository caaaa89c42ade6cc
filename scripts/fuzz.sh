#!/usr/bin/env bash
# libFuzzer run of the five fuzz targets (tests/fuzz; docs/hardening.md):
#   fuzz_log_reader  read_log_from_memory, options from the first byte
#   fuzz_params      parse_params_json (+ format/parse round trip)
#   fuzz_circuit     parse_circuit_json + parse_circuit_values_json, then the engine on
#                    what they accept; seeds also every shipped examples/circuits/*.json
#                    alone and with its .params.json
#   fuzz_c_api       the C API fed arbitrary sample streams (NaN, ±Inf, huge, denormal,
#                    dropouts, resets, time going backwards)
#   fuzz_c_api_engine  the same, on the engine's thesis model (hstmon_c_engine)
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET=60] [TARGET...]
# Builds with Clang + -fsanitize=fuzzer,address,undefined in build/h-fuzz and runs each
# target for that long, starting from the committed seeds (tests/fuzz/corpus/<target>);
# new inputs go to build/h-fuzz/corpus/<target> (not committed). Exits non-zero on a
# finding; the crashing input is left in build/h-fuzz/artifacts/.
# Reproduce one: build/h-fuzz/bin/fuzz_log_reader build/h-fuzz/artifacts/crash-…
# HSTMON_FUZZ_SEED=N fixes libFuzzer's random seed (CI uses 1, so a CI run explores the
# same first mutations every time; 0, the default, lets libFuzzer pick one).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
secs=${1:-60}
shift || true
targets=("$@")
[[ ${#targets[@]} -eq 0 ]] && targets=(fuzz_log_reader fuzz_params fuzz_circuit fuzz_c_api fuzz_c_api_engine)
declare -A seeds=([fuzz_log_reader]=log_reader [fuzz_params]=params [fuzz_circuit]=circuit [fuzz_c_api]=c_api
                  [fuzz_c_api_engine]=c_api)
declare -A maxlen=([fuzz_log_reader]=4096 [fuzz_params]=2048 [fuzz_circuit]=8192 [fuzz_c_api]=8192
                   [fuzz_c_api_engine]=8192)
build=build/h-fuzz
jobs=$(( $(nproc) < 2 ? $(nproc) : 2 ))

if ! command -v clang++ >/dev/null; then
  echo "fuzz.sh: clang++ not found (apt-get install -y clang)" >&2
  exit 2
fi
san="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g"
tc=(); [[ -f "$build/CMakeCache.txt" ]] || tc=(--toolchain toolchains/host-clang.cmake)
cmake -S . -B "$build" "${tc[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DHSTMON_FUZZ=ON -DHSTMON_BUILD_TESTS=OFF -DHSTMON_BUILD_BENCH=OFF -DHSTMON_WERROR=OFF \
  -DCMAKE_CXX_FLAGS="$san" -DCMAKE_C_FLAGS="$san" >/dev/null
cmake --build "$build" -j"$jobs" --target "${targets[@]}"

# The shipped circuits as seeds, written afresh each run so they follow the examples:
# "<circuit>\n@@params@@\n<params>" is fuzz_circuit's input with a parameter file.
shipped="$build/seeds/circuit"
rm -rf "$shipped" && mkdir -p "$shipped"
for c in examples/circuits/*.json; do
  [[ $c == *.params.json ]] && continue
  n=$(basename "$c" .json)
  cp "$c" "$shipped/$n.json"
  p="examples/circuits/$n.params.json"
  [[ -f $p ]] && { cat "$c"; printf '\n@@params@@\n'; cat "$p"; } >"$shipped/$n+params.json"
done
declare -A extra=([fuzz_circuit]="$shipped")

mkdir -p "$build/artifacts"
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
for t in "${targets[@]}"; do
  work="$build/corpus/$t"
  mkdir -p "$work"
  echo "== $t: ${secs} s"
  if ! "$build/bin/$t" "$work" "tests/fuzz/corpus/${seeds[$t]}" ${extra[$t]:-} \
      -max_total_time="$secs" -seed="${HSTMON_FUZZ_SEED:-0}" -max_len="${maxlen[$t]}" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$build/artifacts/$t-" -print_final_stats=1 >"$build/$t.log" 2>&1; then
    echo "!! $t: finding (log: $build/$t.log, input: $build/artifacts/$t-*)"
    grep -E "ERROR|invariant|runtime error|SUMMARY" "$build/$t.log" | head -n 5 || true
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::new_units_added" "$build/$t.log" | tr '\n' ' '
    echo
  fi
done
exit $status
