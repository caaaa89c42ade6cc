# 64-bit Arm Linux (Debian: g++-aarch64-linux-gnu), tests run under qemu user mode
# (Debian: qemu-user). Names the system, the compilers and how to run a target binary;
# nothing else. With it the top-level CMakeLists builds lib/ and the lib-only unit tests
# (GoogleTest compiled from /usr/src/googletest for the target), and `ctest` runs them
# through qemu-aarch64.
#   cmake -S . -B build/aarch64 --toolchain toolchains/aarch64-linux-gnu.cmake
#   cmake --build build/aarch64 -j2 && ctest --test-dir build/aarch64
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

# -L: the target's sysroot, where qemu finds ld-linux-aarch64.so.1 and libstdc++.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64;-L;/usr/aarch64-linux-gnu)
