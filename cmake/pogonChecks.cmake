# Build-level CTest checks, registered from the top-level CMakeLists.txt.
#
#   no_float_in_library     disassembles the built library and fails on any
#                           floating-point instruction or soft-float helper call
#                           (x86-64 only: the patterns are x86 mnemonics).
#   consumer_find_package   installs the build into a temporary prefix and builds
#                           cmake/consumer-test against it three ways:
#                           find_package(pogon), pkg-config, add_subdirectory().

if(NOT CMAKE_CROSSCOMPILING AND NOT EMSCRIPTEN
   AND CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$"
   AND CMAKE_SIZEOF_VOID_P EQUAL 8)
  if(CMAKE_OBJDUMP)
    set(_pogon_objdump "${CMAKE_OBJDUMP}")
  else()
    find_program(_pogon_objdump objdump)
  endif()
  if(_pogon_objdump)
    add_test(NAME no_float_in_library
      COMMAND sh "${PROJECT_SOURCE_DIR}/scripts/check-no-float.sh"
              "$<TARGET_FILE:pogon>" "${_pogon_objdump}")
    set_tests_properties(no_float_in_library PROPERTIES LABELS "build" TIMEOUT 120)
  else()
    message(WARNING "objdump not found: the test no_float_in_library is not registered")
  endif()
endif()

if(POGON_INSTALL AND NOT CMAKE_CROSSCOMPILING AND NOT EMSCRIPTEN)
  # What the consumer must be built with to link the installed library
  # (sanitizer flags of a debug-asan build, for example).
  string(TOUPPER "${CMAKE_BUILD_TYPE}" _pogon_bt)
  add_test(NAME consumer_find_package
    COMMAND sh "${PROJECT_SOURCE_DIR}/scripts/check-consumer.sh"
            "${PROJECT_BINARY_DIR}" "${PROJECT_SOURCE_DIR}" "$<CONFIG>")
  set_tests_properties(consumer_find_package PROPERTIES
    LABELS "build"
    TIMEOUT 300
    ENVIRONMENT "CMAKE_COMMAND=${CMAKE_COMMAND};POGON_CC=${CMAKE_C_COMPILER};POGON_CFLAGS=${CMAKE_C_FLAGS} ${CMAKE_C_FLAGS_${_pogon_bt}};POGON_LDFLAGS=${CMAKE_EXE_LINKER_FLAGS};POGON_VERSION=${PROJECT_VERSION};POGON_TRIG_TABLE_BITS=${PG_TRIG_TABLE_BITS};POGON_SHARED=${BUILD_SHARED_LIBS}")
endif()
