# Sourced by the speed scripts (fleet_speed.sh, replay_speed.sh) with their arguments
# [BUILD_DIR] [RUNS]: sets root (the source tree), build (BUILD_DIR as an absolute path,
# default build/host-release; hstmon and hstmon-sim are built there if missing), runs
# (RUNS, default 3) and tmp (a fresh directory, removed when the script exits).
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build/host-release}
runs=${2:-3}
if [[ ! -x $build/bin/hstmon || ! -x $build/bin/hstmon-sim ]]; then
  cmake --preset host-release >/dev/null
  cmake --build "$build" -j2 --target hstmon hstmon-sim >/dev/null
fi
build=$(cd "$build" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
