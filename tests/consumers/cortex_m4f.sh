#!/usr/bin/env bash
# Cortex-M4F consumer: installs hstmon from an arm-none-eabi build (toolchains/
# arm-none-eabi.cmake; only the C API is built), builds tests/consumers/cortex_m4f against
# that prefix with find_package, and runs the image under qemu-system-arm (mps2-an386)
# like the firmware tests. Skips (77) without the cross toolchain or qemu.
source "$(dirname "$0")/common.sh"
for tool in arm-none-eabi-gcc arm-none-eabi-g++ qemu-system-arm; do
  command -v "$tool" >/dev/null || { echo "skipped: $tool not installed"; exit 77; }
done
# The host build's compilers and flags (sanitizers) must not reach the cross builds.
unset CC CXX LDFLAGS CFLAGS CXXFLAGS
toolchain="$HSTMON_SRC/toolchains/arm-none-eabi.cmake"
run() { "$@" >"$work/step.log" 2>&1 || { cat "$work/step.log"; exit 1; }; }

run cmake -S "$HSTMON_SRC" -B "$work/hstmon" --toolchain "$toolchain" -DCMAKE_BUILD_TYPE=Release -DHSTMON_BUILD_TESTS=OFF
run cmake --build "$work/hstmon" --target hstmon_c -j"$jobs"
run cmake --install "$work/hstmon" --prefix "$work/prefix" --component development

run cmake -S "$HSTMON_SRC/tests/consumers/cortex_m4f" -B "$work/build" --toolchain "$toolchain" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" -DHSTMON_BSP_DIR="$HSTMON_SRC/ports/cortex_m4_mps2"
grep "hstmon .* from" "$work/step.log"
run cmake --build "$work/build" -j"$jobs"

# Semihosting output to a file chardev (as scripts/firmware.sh does); QEMU exits with main's status.
rc=0
timeout 120 qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
  -chardev "file,id=semihost,path=$work/semihost.txt" \
  -semihosting-config enable=on,target=native,chardev=semihost -kernel "$work/build/consumer_cm4f.elf" </dev/null || rc=$?
cat "$work/semihost.txt"
exit "$rc"
