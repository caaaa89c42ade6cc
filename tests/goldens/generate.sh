#!/usr/bin/env bash
# Writes `hstmon replay --json` of every shipped example log into OUT_DIR, one .jsonl per
# log. The one list of goldens: tests/goldens/check.sh (CTest) compares against it,
# scripts/update_goldens.sh rewrites the committed files with it.
#   tests/goldens/generate.sh HSTMON_CLI OUT_DIR
# Runs from the repository root with relative paths, so the "log" fields in the output do
# not depend on where the checkout is. Numbers are printed shortest-round-trip (nlohmann's
# dump), i.e. every bit of each double shows.
set -euo pipefail
cli=$(realpath "$1")
out=$(realpath -m "$2")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
mkdir -p "$out"

# The thesis rig's logs: no --circuit, so the built-in thesis.json with Table 2.2, diagnosis on.
for log in prv_blockage prv_blockage_das prv_staircase_das; do
  "$cli" replay --json --no-progress "examples/$log.csv" >"$out/$log.jsonl"
done

# Circuit logs: each through its circuit file and its parameter file.
for circuit in closed_loop_hst paper test_stand; do
  "$cli" replay --json --no-progress --circuit "examples/circuits/$circuit.json" \
    --params "examples/circuits/$circuit.params.json" "examples/circuits/$circuit.csv" >"$out/circuit_$circuit.jsonl"
done
