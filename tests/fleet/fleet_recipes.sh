#!/usr/bin/env bash
# The fleet recipes of docs/fleet.md, run small: six short logs of two machines (one of
# them with a PRV blockage in its last log) and one bad log.
#  - `hstmon replay --summary DIR` on 1 and on 2 threads: the same bytes;
#  - GNU parallel, one hstmon per log: its concatenated output equals the in-process one;
#  - the Slurm array script, every task run with SLURM_ARRAY_TASK_ID set: the same again;
#  - a repeated run gives byte-identical lines (idempotent);
#  - the bad log has an error line and exit code 2, the others are all there;
#  - `hstmon fleet` flags the blocked machine and only it;
#  - --machine-from stem and regex:, and the options that take one log;
#  - with --circuit (the paper's HST): the summary lines name the circuit's sensors,
#    1 and 2 threads agree, a bad log has its error line, and `hstmon fleet` flags the
#    machine whose last logs carry the Dm fault and only it.
#   bash fleet_recipes.sh HSTMON HSTMON_SIM SOURCE_DIR WORK_DIR
set -euo pipefail
hstmon=$1 sim=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work/logs/m01" "$work/logs/m02"
cd "$work"
for day in 1 2 3; do
  "$sim" --scenario rig --load steps --duration 3 --rate 500 --seed "$day" --out "logs/m01/2026-11-0$day.csv"
done
"$sim" --scenario rig --load steps --duration 3 --rate 500 --seed 4 --out logs/m02/2026-11-01.csv
"$sim" --scenario rig --load steps --duration 3 --rate 500 --seed 5 --out logs/m02/2026-11-02.csv
"$sim" --scenario rig --load steps --duration 3 --rate 500 --seed 6 --blockage 0.5 --out logs/m02/2026-11-03.csv
printf 't[s],p_mi[bar]\n0,1\n0.1,x\n' > logs/m02/2026-11-04.csv  # bad number: an error line

fail() { echo "fleet_recipes: FAIL: $*" >&2; exit 1; }
expect_rc() { local want=$1; shift; local rc=0; "$@" || rc=$?; [[ $rc == "$want" ]] || fail "exit $rc, want $want: $*"; }

expect_rc 2 "$hstmon" replay logs --jobs 2 > inproc2.jsonl
expect_rc 2 "$hstmon" replay logs --jobs 1 > inproc1.jsonl
cmp inproc1.jsonl inproc2.jsonl || fail "1 and 2 threads differ"
[[ $(wc -l < inproc2.jsonl) == 7 ]] || fail "want 7 lines"
grep -q '"log":"logs/m02/2026-11-04.csv","machine":"m02","status":"error"' inproc2.jsonl || fail "no error line"
grep -q 'logs/m02/2026-11-04.csv:3:' inproc2.jsonl || fail "error line names no file:line"
[[ $(grep -c '"status":"ok"' inproc2.jsonl) == 6 ]] || fail "want 6 ok lines"

# GNU parallel (docs/fleet.md): one process per log, output kept in input order.
find logs -name '*.csv' | LC_ALL=C sort > logs.txt
rc=0
parallel --will-cite -k -j 2 "$hstmon" replay --summary {} < logs.txt > parallel.jsonl || rc=$?
[[ $rc == 1 ]] || fail "parallel exit $rc, want 1 (one job failed)"
cmp inproc2.jsonl parallel.jsonl || fail "parallel output differs from the in-process one"

# Slurm array (docs/fleet.md), without Slurm: every task in turn.
mkdir -p slurm
for ((task = 0; task < $(wc -l < logs.txt); ++task)); do
  rc=0
  SLURM_ARRAY_TASK_ID=$task HSTMON=$hstmon bash "$src/scripts/fleet_slurm.sh" logs.txt slurm || rc=$?
  [[ $rc == 0 || ($rc == 2 && $task == 6) ]] || fail "slurm task $task exit $rc"
done
cat slurm/*.jsonl > slurm.jsonl
cmp inproc2.jsonl slurm.jsonl || fail "Slurm array output differs from the in-process one"

expect_rc 2 "$hstmon" replay logs > again.jsonl
cmp inproc2.jsonl again.jsonl || fail "a repeated run differs"

"$hstmon" fleet --json --baseline 2 inproc2.jsonl > fleet.jsonl
grep -q '"machine":"m01".*"verdict":"steady"' fleet.jsonl || fail "m01 should be steady"
grep -q '"machine":"m02".*"verdict":"drifting"' fleet.jsonl || fail "m02 should drift"
grep -q '"drifting":1,"failed":1' fleet.jsonl || fail "fleet line"
"$hstmon" fleet inproc2.jsonl > fleet.txt
grep -q 'm02 .*DRIFTING' fleet.txt || fail "human table"
# The machine rules, and options that take one log.
expect_rc 2 "$hstmon" replay logs/ --machine-from stem > stem.jsonl
grep -q '"log":"logs/m01/2026-11-01.csv","machine":"2026-11-01"' stem.jsonl ||
  fail "--machine-from stem (or logs/ read differently from logs)"
expect_rc 2 "$hstmon" replay logs --machine-from 'regex:/(m0[12])/' > regex.jsonl
grep -q '"log":"logs/m02/2026-11-03.csv","machine":"m02"' regex.jsonl || fail "--machine-from regex:"
expect_rc 1 "$hstmon" replay logs --machine-from 'regex:m01' 2> err.txt
grep -q "needs a capture group" err.txt || fail "regex without a group"
expect_rc 1 "$hstmon" replay logs --residuals r.csv 2> err.txt
grep -q -- "--residuals takes one log" err.txt || fail "--residuals with a folder"
mkdir -p empty
expect_rc 2 "$hstmon" replay empty 2> err.txt
grep -q "no logs" err.txt || fail "empty folder"
# A circuit's logs: c01 four nominal days, c02 two nominal then two with Dm × 0.9.
mkdir -p clogs/c01 clogs/c02
for day in 1 2 3 4; do cp "$src/examples/circuits/paper.csv" "clogs/c01/2026-11-0$day.csv"; done
cp "$src/examples/circuits/paper.csv" clogs/c02/2026-11-01.csv
cp "$src/examples/circuits/paper.csv" clogs/c02/2026-11-02.csv
cp "$src/examples/circuits/paper_dm_fault.csv" clogs/c02/2026-11-03.csv
cp "$src/examples/circuits/paper_dm_fault.csv" clogs/c02/2026-11-04.csv
printf 't[s],p_mi[bar]\n0,1\n0.005,x\n' > clogs/c02/2026-11-05.csv
circuit=(--circuit "$src/examples/circuits/paper.json")
expect_rc 2 "$hstmon" replay "${circuit[@]}" clogs --jobs 2 > circuit2.jsonl
expect_rc 2 "$hstmon" replay "${circuit[@]}" clogs --jobs 1 > circuit1.jsonl
cmp circuit1.jsonl circuit2.jsonl || fail "--circuit: 1 and 2 threads differ"
[[ $(grep -c '"circuit":"paper"' circuit2.jsonl) == 9 ]] || fail "--circuit: want 9 lines naming the circuit"
grep -q '"log":"clogs/c02/2026-11-05.csv","machine":"c02","status":"error"' circuit2.jsonl ||
  fail "--circuit: no error line for the bad log"
grep -q '"first_diagnosis":{"event":"isolated","fault":"Dm-"' circuit2.jsonl || fail "--circuit: Dm- not isolated"
grep -q '"residuals":{"p_mi":' circuit2.jsonl || fail "--circuit: residuals not by the circuit's sensor names"
"$hstmon" fleet --json --baseline 2 circuit2.jsonl > cfleet.jsonl
grep -q '"machine":"c01".*"verdict":"steady"' cfleet.jsonl || fail "--circuit: c01 should be steady"
grep -q '"machine":"c02".*"verdict":"drifting"' cfleet.jsonl || fail "--circuit: c02 should drift"
grep -q '"drifting":1,"failed":1' cfleet.jsonl || fail "--circuit: fleet line"
echo "fleet_recipes: ok"
