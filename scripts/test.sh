#!/usr/bin/env bash
# Installs dependencies, builds the host debug configuration (warnings are errors) and
# runs the whole test suite with CTest.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
bash scripts/install-deps.sh
cmake --preset host-debug >/dev/null
cmake --build --preset host-debug -j"$(nproc)"
ctest --preset host-debug -j"$(nproc)"
