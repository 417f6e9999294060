# Build-level CTest checks, registered from the top-level CMakeLists.txt.
#
#   no_float_in_library     disassembles the built library and fails on any
#                           floating-point instruction or soft-float helper call
#                           (x86-64 only: the patterns are x86 mnemonics).
#   consumer_find_package   installs the build into a temporary prefix and builds
#                           cmake/consumer-test against it three ways:
#                           find_package(pogon), pkg-config, add_subdirectory().
#   cortex_m_size_and_no_float  (below) the Cortex-M flash limits and no-float check.
#   static_clang_tidy, static_cppcheck  (below) src/ has no findings
#                           (scripts/static-analysis.sh); the clang preset turns them on.

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
  set(_pogon_consumer_ldflags "${CMAKE_EXE_LINKER_FLAGS}")
  if(POGON_COVERAGE)
    string(APPEND _pogon_consumer_ldflags " -fprofile-instr-generate") # the library's profile runtime
  endif()
  add_test(NAME consumer_find_package
    COMMAND sh "${PROJECT_SOURCE_DIR}/scripts/check-consumer.sh"
            "${PROJECT_BINARY_DIR}" "${PROJECT_SOURCE_DIR}" "$<CONFIG>")
  set_tests_properties(consumer_find_package PROPERTIES
    LABELS "build"
    TIMEOUT 300
    ENVIRONMENT "CMAKE_COMMAND=${CMAKE_COMMAND};POGON_CC=${CMAKE_C_COMPILER};POGON_CFLAGS=${CMAKE_C_FLAGS} ${CMAKE_C_FLAGS_${_pogon_bt}};POGON_LDFLAGS=${_pogon_consumer_ldflags};POGON_VERSION=${PROJECT_VERSION};POGON_TRIG_TABLE_BITS=${PG_TRIG_TABLE_BITS};POGON_SHARED=${BUILD_SHARED_LIBS}")
endif()

# cortex_m_size_and_no_float: tools/size/size_table.py --check builds the library for
# Cortex-M4 (hard-float ABI) and M0+ with arm-none-eabi-gcc -Os, fails when a flash
# configuration grew past tools/size/flash_limits.txt (+2 %) or when check-no-float.sh
# finds floating point in it; skipped (77) without the toolchain. Registered once, in
# the preset that runs the Cortex-M tests (POGON_CORTEX_M_TESTS, tests/targets).
find_program(_pogon_python3 python3)
if(POGON_CORTEX_M_TESTS AND _pogon_python3)
  add_test(NAME cortex_m_size_and_no_float
    COMMAND ${_pogon_python3} "${PROJECT_SOURCE_DIR}/tools/size/size_table.py" --check
            --build "${PROJECT_BINARY_DIR}/cortex-m-size")
  set_tests_properties(cortex_m_size_and_no_float PROPERTIES
    LABELS "build;cortex-m" TIMEOUT 600 SKIP_RETURN_CODE 77 COST 100) # long: started first
endif()

# static_clang_tidy, static_cppcheck: clang-tidy (.clang-tidy's checks) and cppcheck find
# nothing in src/ (scripts/static-analysis.sh, with this build's compile commands);
# skipped (77) without the tools. One preset runs them (the clang preset), as their
# findings do not depend on the build.
option(POGON_STATIC_ANALYSIS "Register the static analysis tests (clang-tidy, cppcheck) on src/" OFF)
if(POGON_STATIC_ANALYSIS)
  foreach(_pogon_tool clang-tidy cppcheck)
    string(REPLACE "-" "_" _pogon_name "static_${_pogon_tool}")
    add_test(NAME ${_pogon_name}
      COMMAND sh "${PROJECT_SOURCE_DIR}/scripts/static-analysis.sh" ${_pogon_tool} "${PROJECT_BINARY_DIR}")
    # COST: clang-tidy is the clang preset's longest test; started first, it runs beside
    # the others instead of alone at the end (a fresh build has no timing history)
    set_tests_properties(${_pogon_name} PROPERTIES LABELS "static" TIMEOUT 1200 SKIP_RETURN_CODE 77 COST 1000)
  endforeach()
endif()
