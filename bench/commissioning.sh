#!/usr/bin/env bash
# Commissioning, through the CLI as a user runs it: the test stand's machine (1.5 % off
# the data sheet in displacement and throttle, 10 % in leakage) logged healthy, then
# `identify --circuit` writes a parameter file whose uncertainty follows the fit, then two
# faults that begin at an input change are replayed on the data sheet (blanket 2 % bound)
# and on the commissioned file: a 4 bar offset on the 400 bar p_line transmitter (1 % of
# range) and a leak of 5 % of the pump flow. Prints each replay's final verdict.
#   bash bench/commissioning.sh BUILD_DIR   (e.g. build/host-release)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin="$root/${1:-build/host-release}/bin"
circuit="$root/examples/circuits/test_stand.json"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$root/examples/circuits/test_stand.params.json" "$work/machine.params.json" <<'EOF'
import json, math, sys
p = json.load(open(sys.argv[1]))
p["params"]["D"] = 45e-6 / (2 * math.pi) * 1.015
p["params"]["k_throttle"] = 2.9e-7 * 0.985
p["params"]["R_leak"] = 1.5e12 * 0.9
json.dump(p, open(sys.argv[2], "w"))
EOF

run() {  # seed out [extra sim options]
  local seed=$1 out=$2
  shift 2
  "$bin/hstmon-sim" --circuit "$circuit" --params "$work/machine.params.json" --duration 24 --rate 200 \
    --seed "$seed" --step throttle=0.92@4 --step "n_drive=1200 rpm@8" --step throttle=0.8@12 \
    --step throttle=0.9@16 --step "n_drive=1300 rpm@20" "$@" --out "$out"
}
run 1 "$work/healthy.csv"
run 2 "$work/leak.csv" --fault R_leak=0.163@8
run 3 "$work/clean.csv"
# +4 bar on p_line from 8 s (the column is in bar).
awk -F, -v OFS=, '/^#/ || !seen++ {print; next} {if ($1 >= 8) $4 += 4; print}' "$work/clean.csv" >"$work/offset.csv"

echo "== identify --circuit on the healthy log"
"$bin/hstmon" identify --circuit "$circuit" --fit D,R_leak,k_throttle --out "$work/commissioned.params.json" \
  "$work/healthy.csv" | grep -v "note:"
for log in clean leak offset; do
  for params in "" "$work/commissioned.params.json"; do
    label=${params:+commissioned}
    echo "== $log, ${label:-data sheet (blanket 2 %)}"
    "$bin/hstmon" replay --circuit "$circuit" ${params:+--params "$params"} "$work/$log.csv" |
      grep -E "status at the end|no fault detected|t = .*(isolated|ambiguous)" | tail -2 | cut -c1-220
  done
done
