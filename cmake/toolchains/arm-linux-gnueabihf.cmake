# arm-linux-gnueabihf.cmake — cross-compile pogon for 32-bit ARM (armv7-a, hard float: Debian armhf) with
# Debian's cross gcc, and run the programs under qemu-user (ctest uses the emulator).
#
#   scripts/setup-deps.sh cross      # gcc-arm-linux-gnueabihf libc6-dev-armhf-cross qemu-user
#   cmake -S . -B build/arm -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/arm-linux-gnueabihf.cmake \
#         -DCMAKE_BUILD_TYPE=Release -DPOGON_BUILD_TESTS=OFF
#   cmake --build build/arm && ctest --test-dir build/arm
#
# Programs are linked statically, so qemu-arm needs no target root file system.
# POGON_BUILD_TESTS=OFF because CMocka is not installed for the target; the example
# smoke tests still run (ctest runs them through CMAKE_CROSSCOMPILING_EMULATOR).
set(CMAKE_SYSTEM_PROCESSOR arm)
set(POGON_CROSS_TRIPLE arm-linux-gnueabihf)
set(POGON_CROSS_QEMU qemu-arm)
include(${CMAKE_CURRENT_LIST_DIR}/linux-qemu-common.cmake)
