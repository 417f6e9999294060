# cortex-m4.cmake — CMake toolchain file: Cortex-M4 with the hard-float ABI (its FPU is never used: -mgeneral-regs-only).
# qemu board: mps2-an386. See arm-none-eabi.cmake and docs/embedded.md.
set(POGON_CORTEX_M_FLAGS -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16)
set(POGON_CORTEX_M_BOARD mps2-an386)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
