#!/usr/bin/env bash
# CTest `goldens.replay`: regenerates the replay goldens with this build's hstmon into a
# scratch directory and fails on any byte of difference from tests/goldens/*.jsonl.
# A deliberate model or output change: bash scripts/update_goldens.sh, and commit.
#   tests/goldens/check.sh HSTMON_CLI SCRATCH_DIR
set -euo pipefail
cli="$1"
scratch="$2"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rm -rf "$scratch"
bash "$here/generate.sh" "$cli" "$scratch"

status=0
for golden in "$here"/*.jsonl; do
  name=$(basename "$golden")
  if [ ! -f "$scratch/$name" ]; then
    echo "goldens: $name is committed but no longer generated"; status=1
  elif ! cmp -s "$golden" "$scratch/$name"; then
    echo "goldens: $name differs (- committed, + this build):"
    { diff -u "$golden" "$scratch/$name" || true; } | sed -n '3,40p' | cut -c1-300
    status=1
  fi
done
for fresh in "$scratch"/*.jsonl; do
  [ -f "$here/$(basename "$fresh")" ] || { echo "goldens: $(basename "$fresh") is new: not committed yet"; status=1; }
done
if [ "$status" = 0 ]; then
  echo "goldens: $(ls "$here"/*.jsonl | wc -l) replay outputs identical to the committed ones"
else
  echo "goldens: if the change is intended, run: bash scripts/update_goldens.sh (and commit tests/goldens)"
fi
exit "$status"
