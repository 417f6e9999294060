# cortex-m3.cmake — CMake toolchain file: Cortex-M3 (ARMv7-M).
# qemu board: mps2-an385. See arm-none-eabi.cmake and docs/embedded.md.
set(POGON_CORTEX_M_FLAGS -mcpu=cortex-m3)
set(POGON_CORTEX_M_BOARD mps2-an385)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
