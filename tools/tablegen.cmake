# tablegen.cmake — run pogon-tablegen and compare or install its output.
#
#   cmake -DGENERATOR=<pogon-tablegen> -DTARGET_FILE=<src/core/trig_table.inc>
#         -DOUTPUT=<scratch file> -DMODE=compare|write -P tablegen.cmake
#
# MODE=compare (the CTest test tablegen_matches): fails unless the generator's output is
#   byte for byte the committed TARGET_FILE.
# MODE=write (the target regenerate-tables): replaces TARGET_FILE with the output, only
#   after the generator succeeded, so a failing run never leaves a truncated table.
foreach(var GENERATOR TARGET_FILE OUTPUT MODE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "tablegen.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND "${GENERATOR}" OUTPUT_FILE "${OUTPUT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tablegen.cmake: ${GENERATOR} failed (${rc})")
endif()

if(MODE STREQUAL "compare")
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUTPUT}" "${TARGET_FILE}"
                  RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR
      "tablegen.cmake: ${TARGET_FILE} differs from the generator's output ${OUTPUT}.\n"
      "Regenerate with `cmake --build <build> --target regenerate-tables` and review the diff; "
      "if you did not change tools/tablegen.c, this machine's libm disagrees with the one "
      "that made the committed tables.")
  endif()
  message(STATUS "tablegen.cmake: ${TARGET_FILE} matches the generator bit for bit")
elseif(MODE STREQUAL "write")
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUTPUT}" "${TARGET_FILE}"
                  RESULT_VARIABLE same OUTPUT_QUIET ERROR_QUIET)
  if(same EQUAL 0)
    message(STATUS "tablegen.cmake: ${TARGET_FILE} is up to date")
    return()
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" -E copy "${OUTPUT}" "${TARGET_FILE}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "tablegen.cmake: could not write ${TARGET_FILE}")
  endif()
  message(STATUS "tablegen.cmake: wrote ${TARGET_FILE}; review and commit the diff")
else()
  message(FATAL_ERROR "tablegen.cmake: MODE must be compare or write, not '${MODE}'")
endif()
