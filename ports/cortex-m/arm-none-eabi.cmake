# arm-none-eabi.cmake — CMake toolchain for bare-metal Cortex-M with arm-none-eabi-gcc and
# newlib (Debian: gcc-arm-none-eabi, libnewlib-arm-none-eabi). Included by
# cortex-m0plus.cmake, cortex-m3.cmake and cortex-m4.cmake, which set POGON_CORTEX_M_FLAGS
# (the -mcpu and float ABI) first.
#
# -mgeneral-regs-only: pogon has no floating point, and this keeps gcc from using FPU
# registers even for spills under the hard-float ABI. Programs link with mps2.ld (qemu's
# mps2 boards), startup.c and syscalls.c, and print through semihosting (librdimon).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_OBJDUMP arm-none-eabi-objdump CACHE FILEPATH "")
set(CMAKE_SIZE arm-none-eabi-size CACHE FILEPATH "")
# try_compile cannot link without a linker script: test the compiler with a library
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)

string(REPLACE ";" " " _pogon_cm_flags "${POGON_CORTEX_M_FLAGS}")
set(CMAKE_C_FLAGS_INIT "${_pogon_cm_flags} -mthumb -mgeneral-regs-only -ffunction-sections -fdata-sections")
# Full newlib, not newlib-nano: the example math_demo prints with %llu. pogon itself and
# the firmware need no 64-bit printf (the determinism_cortex_m* tests link them with
# --specs=nano.specs; tools/size measures with it).
set(CMAKE_EXE_LINKER_FLAGS_INIT
  "-T${CMAKE_CURRENT_LIST_DIR}/mps2.ld -nostartfiles --specs=rdimon.specs -Wl,--gc-sections")
# no 64-bit hardware divider on any Cortex-M (include/pogon/config.h)
set(PG_FAST_DIV64 OFF CACHE BOOL "" FORCE)
set(POGON_CORTEX_M ON)
# ctest runs the programs (the example smoke tests) on the board's emulator
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-system-arm -M ${POGON_CORTEX_M_BOARD} -nographic -semihosting -kernel)
