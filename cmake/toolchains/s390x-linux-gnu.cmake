# s390x-linux-gnu.cmake — cross-compile pogon for IBM Z (s390x): 64-bit and big-endian with
# Debian's cross gcc, and run the programs under qemu-user (ctest uses the emulator).
#
#   scripts/setup-deps.sh cross      # gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user
#   cmake -S . -B build/s390x -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/s390x-linux-gnu.cmake \
#         -DCMAKE_BUILD_TYPE=Release -DPOGON_BUILD_TESTS=OFF
#   cmake --build build/s390x && ctest --test-dir build/s390x
#
# Programs are linked statically, so qemu-s390x needs no target root file system.
# POGON_BUILD_TESTS=OFF because CMocka is not installed for the target; the example
# smoke tests still run (ctest runs them through CMAKE_CROSSCOMPILING_EMULATOR).
set(CMAKE_SYSTEM_PROCESSOR s390x)
set(POGON_CROSS_TRIPLE s390x-linux-gnu)
set(POGON_CROSS_QEMU qemu-s390x)
include(${CMAKE_CURRENT_LIST_DIR}/linux-qemu-common.cmake)
