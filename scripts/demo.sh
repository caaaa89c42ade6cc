#!/usr/bin/env bash
# The main job on a fresh machine: install dependencies, build the release binaries, and
# replay the shipped PRV-blockage log (thesis §2.4: kp halved at t = 80 s) through the
# monitor. Extra arguments go to `hstmon replay` (e.g. --json, --plot out.svg).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
bash scripts/install-deps.sh
cmake --preset host-release >/dev/null
cmake --build --preset host-release -j"$(nproc)" --target hstmon >/dev/null
exec build/host-release/bin/hstmon replay examples/prv_blockage.csv "$@"
