#!/usr/bin/env bash
# A circuit's C API from the installed package (tests/consumers/circuit_c): the user's
# circuit file (here the shipped test stand) through hstmon-circuit-header and
# hstmon-fdi table, then find_package(hstmon) and hstmon_add_circuit_c_api() build the
# C API for it; the C program runs the monitor.
source "$(dirname "$0")/common.sh"
gen="$work/generated/hstmon/generated"
mkdir -p "$gen"
circuit="$HSTMON_SRC/examples/circuits/test_stand.json"
"$HSTMON_CIRCUIT_HEADER_TOOL" "$circuit" --tick 1e-3 --name stand_circuit --out "$gen/stand_circuit.hpp"
"$HSTMON_FDI_TOOL" table --circuit "$circuit" --name stand_signatures --out "$gen/stand_signatures.hpp"
cmake -S "$HSTMON_SRC/tests/consumers/circuit_c" -B "$work/build" -DCMAKE_PREFIX_PATH="$HSTMON_PREFIX" \
  -DGENERATED_DIR="$work/generated" -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j"$jobs" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/build/consumer"
