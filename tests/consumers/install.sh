#!/usr/bin/env bash
# Fixture of the consumer tests: `cmake --install` of this build tree's development
# component (headers, libhstmon_c.a and libhstmon_c_engine.a, the CMake package,
# hstmon-c.pc and hstmon-c-engine.pc) into HSTMON_PREFIX;
# then checks the tree holds every manifest with the project's one version.
#   install.sh BUILD_DIR VERSION
set -euo pipefail
build="$1"
version="$2"
rm -rf "$HSTMON_PREFIX"
mkdir -p "$(dirname "$HSTMON_PREFIX")"
cmake --install "$build" --prefix "$HSTMON_PREFIX" --component development >"$HSTMON_PREFIX.log" 2>&1 ||
  { cat "$HSTMON_PREFIX.log"; exit 1; }
cd "$HSTMON_PREFIX"
for f in include/hstmon/hstmon.hpp include/hstmon_c.h include/hstmon_c_types.h include/hstmon_circuit_c.h lib/libhstmon_c.a lib/libhstmon_c_engine.a \
         lib/cmake/hstmon/hstmonConfig.cmake lib/cmake/hstmon/hstmonConfigVersion.cmake \
         lib/cmake/hstmon/hstmonTargets.cmake lib/cmake/hstmon/HstmonCircuitCApi.cmake \
         share/hstmon/c_api/hstmon_circuit_c.cpp lib/pkgconfig/hstmon-c.pc lib/pkgconfig/hstmon-c-engine.pc; do
  [ -f "$f" ] || { echo "install: $f missing"; exit 1; }
done
grep -q "^Version: $version\$" lib/pkgconfig/hstmon-c.pc || { echo "install: hstmon-c.pc is not version $version"; exit 1; }
grep -q "set(PACKAGE_VERSION \"$version\")" lib/cmake/hstmon/hstmonConfigVersion.cmake ||
  { echo "install: hstmonConfigVersion.cmake is not version $version"; exit 1; }
echo "install: hstmon $version development files in $HSTMON_PREFIX"
