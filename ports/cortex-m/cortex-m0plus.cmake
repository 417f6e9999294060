# cortex-m0plus.cmake — CMake toolchain file: Cortex-M0+ (ARMv6-M; runs on the Cortex-M3 board too).
# qemu board: mps2-an385. See arm-none-eabi.cmake and docs/embedded.md.
set(POGON_CORTEX_M_FLAGS -mcpu=cortex-m0plus)
set(POGON_CORTEX_M_BOARD mps2-an385)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
