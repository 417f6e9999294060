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
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR s390x)

set(POGON_CROSS_TRIPLE s390x-linux-gnu)
find_program(POGON_CROSS_CC ${POGON_CROSS_TRIPLE}-gcc)
if(NOT POGON_CROSS_CC)
  message(FATAL_ERROR "${POGON_CROSS_TRIPLE}-gcc not found: scripts/setup-deps.sh cross installs it")
endif()
set(CMAKE_C_COMPILER ${POGON_CROSS_CC})
find_program(POGON_CROSS_CXX ${POGON_CROSS_TRIPLE}-g++)
if(POGON_CROSS_CXX)
  set(CMAKE_CXX_COMPILER ${POGON_CROSS_CXX})
endif()

# Static: the binaries run under qemu-user without the target's shared libraries.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
# find_library() must then find static archives (libm.a), not libm.so: the suffixes are
# set by CMake's platform files after this file, so through a rules override.
set(CMAKE_USER_MAKE_RULES_OVERRIDE ${CMAKE_CURRENT_LIST_DIR}/static-libraries.cmake)

find_program(POGON_CROSS_EMULATOR qemu-s390x)
if(POGON_CROSS_EMULATOR)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${POGON_CROSS_EMULATOR})
else()
  message(WARNING "qemu-s390x not found (Debian: qemu-user): programs build but ctest cannot run them")
endif()

# Look for libraries and headers only in the target's tree (not the host's /usr/lib).
set(CMAKE_FIND_ROOT_PATH /usr/${POGON_CROSS_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
