# linux-qemu-common.cmake — the part the Linux cross toolchain files share. Set
# CMAKE_SYSTEM_PROCESSOR, POGON_CROSS_TRIPLE and POGON_CROSS_QEMU, then include this.
set(CMAKE_SYSTEM_NAME Linux)
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

find_program(POGON_CROSS_EMULATOR ${POGON_CROSS_QEMU})
if(POGON_CROSS_EMULATOR)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${POGON_CROSS_EMULATOR})
else()
  message(WARNING "${POGON_CROSS_QEMU} not found (Debian: qemu-user): programs build but ctest cannot run them")
endif()

# Look for libraries and headers only in the target's tree (not the host's /usr/lib).
set(CMAKE_FIND_ROOT_PATH /usr/${POGON_CROSS_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
