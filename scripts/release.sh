#!/usr/bin/env bash
# Builds the release packages and checks the Debian package from a clean prefix:
#   1. configure and build (Release) in BUILD_DIR (default build/release) unless --no-build;
#   2. cpack: hstmon-<version>-Linux.deb and hstmon-<version>-Source.tar.gz into BUILD_DIR;
#   3. unpack the .deb into an empty directory (dpkg-deb -x: the files the package
#      installs, without root) and run the demo from there: the installed hstmon replays
#      the installed examples/prv_blockage.csv and must isolate kp-; the installed
#      hstmon-c.pc must name the unpacked headers; Debian's python3 must import the
#      unpacked Python module (from its dist-packages, PYTHONPATH set to it) and replay
#      the installed demo through it (isolating kp- again).
#   scripts/release.sh [--build-dir DIR] [--no-build]
# Exit status: 0 packages built and checked; 1 a check failed; 2 a build or packaging error.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build/release"
do_build=1
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift 2 ;;
    --no-build) do_build=0; shift ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "release.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ "$do_build" -eq 1 ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHSTMON_BUILD_TESTS=OFF -DHSTMON_BUILD_BENCH=OFF >/dev/null || exit 2
  targets=$(cmake --build "$build" --target help)  # whole, not piped into grep -q (pipefail)
  py_target=()
  grep -qw hstmon_python <<<"$targets" && py_target=(hstmon_python)  # the Python module, when pybind11 is found
  cmake --build "$build" -j"$(nproc)" --target hstmon hstmon-sim hstmon-fdi hstmon-gap-synth hstmon_c "${py_target[@]}" \
    >/dev/null || exit 2
fi
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
( cd "$build" && cpack -G DEB && cpack --config CPackSourceConfig.cmake ) >"$build/release.log" 2>&1 || {
  cat "$build/release.log" >&2; echo "release.sh: cpack failed" >&2; exit 2; }
deb="$build/hstmon_${version}_$(dpkg --print-architecture).deb"
src="$build/hstmon-${version}-Source.tar.gz"
for f in "$deb" "$src"; do [ -s "$f" ] || { echo "release.sh: $f missing" >&2; exit 2; }; done

prefix=$(mktemp -d "${TMPDIR:-/tmp}/hstmon_release.XXXXXX")
trap 'rm -rf "$prefix"' EXIT
dpkg-deb -x "$deb" "$prefix"
out=$("$prefix/usr/bin/hstmon" replay "$prefix/usr/share/hstmon/examples/prv_blockage.csv" --no-progress) || {
  echo "release.sh: the installed hstmon failed" >&2; exit 1; }
grep -q "isolated: kp-" <<<"$out" || { echo "release.sh: the installed demo did not isolate kp-:" >&2; echo "$out" >&2; exit 1; }
pc=$(find "$prefix/usr/lib" -name hstmon-c.pc | head -1)
inc=""
[ -n "$pc" ] && inc=$(PKG_CONFIG_PATH="$(dirname "$pc")" pkg-config --cflags-only-I hstmon-c | sed 's/^-I//; s/ *$//')
[ -n "$inc" ] && [ -f "$inc/hstmon_c.h" ] || {
  echo "release.sh: the package's hstmon-c.pc does not name its headers (${inc:-none})" >&2; exit 1; }
# The Python module, where the build has it: imported by Debian's python3 from the unpacked tree.
if [ -n "$(find "$build/python" -name '_core*.so' 2>/dev/null)" ]; then
  site=$(find "$prefix/usr/lib" -path '*dist-packages/hstmon/__init__.py' | head -1)
  [ -n "$site" ] || { echo "release.sh: the package lacks the Python module" >&2; exit 1; }
  pyout=$(cd "$prefix" && PYTHONPATH="$(dirname "$(dirname "$site")")" /usr/bin/python3 -c "import hstmon; \
r = hstmon.replay('$prefix/usr/share/hstmon/examples/prv_blockage.csv'); \
print(r.events[r.events.event == 'isolated'].iloc[0].faults[0])") || {
    echo "release.sh: python3 -c 'import hstmon' failed on the unpacked package" >&2; exit 1; }
  [ "$pyout" = "kp-" ] || { echo "release.sh: the installed Python module did not isolate kp-: $pyout" >&2; exit 1; }
  py_note="; python3 imports hstmon from it"
fi
listing=$(tar -tzf "$src")  # whole, not piped into grep -q (pipefail and SIGPIPE)
grep -q "^hstmon-${version}-Source/lib/include/hstmon/model_monitor.hpp$" <<<"$listing" || {
  echo "release.sh: the source archive lacks lib/" >&2; exit 1; }
if grep -qE '/build/|/\.git/' <<<"$listing"; then echo "release.sh: build or .git in the source archive" >&2; exit 1; fi
echo "release.sh: $(basename "$deb") ($(du -k "$deb" | cut -f1) kB) and $(basename "$src") ($(du -k "$src" | cut -f1) kB); the installed demo isolates kp-${py_note:-}"
