# Host build with Clang (Debian's clang-14 or newer): a second compiler for warnings,
# and the one libFuzzer needs. Names compilers only; flags belong to targets or presets.
#   cmake -S . -B build/clang --toolchain toolchains/host-clang.cmake
set(CMAKE_C_COMPILER clang)
set(CMAKE_CXX_COMPILER clang++)
