# Bare-metal Arm (Cortex-M) with the GNU Arm Embedded toolchain (Debian: gcc-arm-none-eabi,
# libnewlib-arm-none-eabi, libstdc++-arm-none-eabi-newlib). Names the system and the
# compilers only: the CPU and FPU flags (-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard)
# belong to the INTERFACE target hstmon_cpu_cm4f (ports/cortex_m4_mps2), so one build tree
# could hold images for several cores and nothing leaks into host-side checks.
#   cmake -S . -B build/arm --toolchain toolchains/arm-none-eabi.cmake -DCMAKE_BUILD_TYPE=Release
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)

# Without a CPU there is no linker script or startup code yet: CMake's compiler checks
# build a static library instead of an executable.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
