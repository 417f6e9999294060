# cmake -DDOXYGEN=... -DDOXYFILE=... -DLOG=... -P pogonDoxygenCheck.cmake
# Runs Doxygen over the public headers (no HTML) and fails when it warns: an undocumented
# public function, type, field or enumerator, or a broken documentation comment.
file(REMOVE "${LOG}")
execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "doxygen failed (exit ${rc}):\n${out}${err}")
endif()
set(warnings "")
if(EXISTS "${LOG}")
  file(READ "${LOG}" warnings)
endif()
string(STRIP "${warnings}" warnings)
if(NOT warnings STREQUAL "")
  string(REGEX MATCHALL "warning:" _n "${warnings}")
  list(LENGTH _n count)
  message(FATAL_ERROR "${warnings}\n\ndocs_api_complete: ${count} Doxygen warnings in the public headers: document "
    "each item with a /** ... */ comment before it (/**< ... */ after a field or enumerator).")
endif()
message(STATUS "docs_api_complete: every public item of include/pogon is documented")
