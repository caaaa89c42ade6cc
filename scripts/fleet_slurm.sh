#!/usr/bin/env bash
# One log of a fleet per Slurm array task (docs/fleet.md): task N replays line N+1 of
# LIST with `hstmon replay --summary` into OUTDIR/N.jsonl (N zero-padded to 6 digits, so
# `cat OUTDIR/*.jsonl` is in LIST's order). Each task is independent and idempotent: the
# same log gives the same bytes, so a failed or repeated task is simply run again.
#   ls logs/*/*.csv | LC_ALL=C sort > logs.txt; mkdir -p out
#   sbatch --array=0-$(($(wc -l < logs.txt) - 1)) scripts/fleet_slurm.sh logs.txt out
#   cat out/*.jsonl > fleet.jsonl; hstmon fleet fleet.jsonl
# Without Slurm (a test): SLURM_ARRAY_TASK_ID=0 bash scripts/fleet_slurm.sh logs.txt out
# HSTMON names the hstmon binary (default: hstmon on PATH); extra arguments after OUTDIR
# go to `hstmon replay` (e.g. --params rig.json --machine-from stem).
#SBATCH --job-name=hstmon-fleet
#SBATCH --cpus-per-task=1
#SBATCH --mem=256M
#SBATCH --output=hstmon-fleet-%A_%a.out
set -euo pipefail
list=${1:?usage: fleet_slurm.sh LIST OUTDIR [hstmon replay options]}
out=${2:?usage: fleet_slurm.sh LIST OUTDIR [hstmon replay options]}
shift 2
task=${SLURM_ARRAY_TASK_ID:?SLURM_ARRAY_TASK_ID is not set (run under sbatch --array, or set it)}
log=$(sed -n "$((task + 1))p" "$list")
if [[ -z $log ]]; then
  echo "fleet_slurm.sh: error: $list has no line $((task + 1)) (task $task)" >&2
  exit 1
fi
# Written under a temporary name and renamed: a task killed half-way leaves no partial line.
dest=$(printf '%s/%06d.jsonl' "$out" "$task")
rc=0
"${HSTMON:-hstmon}" replay --summary "$@" "$log" > "$dest.tmp" || rc=$?
mv "$dest.tmp" "$dest"
exit "$rc"   # 2 when the log failed: its line says why
