#!/usr/bin/env bash
# The C++ consumer (tests/consumers/cpp) with find_package(hstmon CONFIG REQUIRED) from
# the installed prefix; also checks that SameMajorVersion refuses a request for 1.0.
source "$(dirname "$0")/common.sh"
src="$HSTMON_SRC/tests/consumers/cpp"
cmake -S "$src" -B "$work/build" -DHSTMON_FROM=package -DCMAKE_PREFIX_PATH="$HSTMON_PREFIX" \
  -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
grep "hstmon .* from" "$work/configure.log"
cmake --build "$work/build" -j"$jobs"
"$work/build/consumer"

# A consumer asking for another major version must not get this package.
mkdir -p "$work/major"
cat >"$work/major/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.21)
project(major_check LANGUAGES NONE)
find_package(hstmon 1.0 CONFIG QUIET)
if(hstmon_FOUND)
  message(FATAL_ERROR "hstmon ${hstmon_VERSION} accepted for a 1.0 request")
endif()
CMAKE
cmake -S "$work/major" -B "$work/major/build" -DCMAKE_PREFIX_PATH="$HSTMON_PREFIX" >/dev/null
echo "find_package: hstmon 1.0 request refused (SameMajorVersion)"
