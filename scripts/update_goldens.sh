#!/usr/bin/env bash
# Rewrites the replay goldens (tests/goldens/*.jsonl) on purpose, after a model, parameter
# or output change that is meant; review `git diff tests/goldens` and commit it with the
# change. The goldens test (CTest goldens.replay) fails on any other difference.
#   scripts/update_goldens.sh [--build-dir DIR]     (default build/host-debug)
# Builds the hstmon target in DIR first (configuring DIR with the host-debug preset when it
# is that preset's directory and not configured yet).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="$root/build/host-debug"
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build=$(realpath -m "$2"); shift 2 ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "update_goldens.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ ! -f "$build/CMakeCache.txt" ]; then
  [ "$build" = "$root/build/host-debug" ] || { echo "update_goldens.sh: $build is not a configured build" >&2; exit 2; }
  (cd "$root" && cmake --preset host-debug >/dev/null)
fi
cmake --build "$build" --target hstmon -j"$(( $(nproc) < 2 ? $(nproc) : 2 ))"
rm -f "$root"/tests/goldens/*.jsonl
bash "$root/tests/goldens/generate.sh" "$build/bin/hstmon" "$root/tests/goldens"
git -C "$root" status --short tests/goldens
