# pogonCheckedTest.cmake — CTest tests that check a program's exit status AND its output.
#
# With PASS_REGULAR_EXPRESSION set, CTest decides on the output alone and ignores the exit
# status: a program that prints the expected line and then exits 3 (or crashes, or reports
# a leak at exit) passes. A test added with pogon_add_checked_test() instead runs this
# file as a script, which runs the program, requires its exact exit status, matches its
# output against every expression and checks the files it must write; any mismatch fails
# the script. The test has no PASS_REGULAR_EXPRESSION, so CTest goes by the script's exit
# status. This one file is both the CMake function and the script the tests run.
#
# In a CMakeLists.txt, after include(<this file>):
#   pogon_add_checked_test(NAME <name> [EXIT <code>] [OUTPUT <regex>...]
#                          [FRESH_DIR <dir>] [FILES <path>...]
#                          COMMAND <executable target or program> [<arg>...])
#     EXIT       the exact exit status required (default 0); e.g. 1 for a refused input
#     OUTPUT     CMake regular expressions that stdout and stderr together must each match
#     FRESH_DIR  a directory removed and re-created before the program runs, so that
#                FILES are known to come from this run
#     FILES      files that must exist after the run
#   An executable target runs from its build location, under its CROSSCOMPILING_EMULATOR
#   if it has one (as add_test(COMMAND <target>) would). Set LABELS, TIMEOUT etc. with
#   set_tests_properties() as usual, but never PASS_REGULAR_EXPRESSION: that would make
#   CTest ignore the exit status again (FAIL_REGULAR_EXPRESSION is fine, it does not).
#
# As a script (the command line the tests run; the first -- ends CMake's own options, the
# second one this script's):
#   cmake -P pogonCheckedTest.cmake -- [--exit N] [--output REGEX]... [--fresh-dir DIR]
#         [--file PATH]... -- PROGRAM [ARG...]
# CMake before 3.26 still takes a few of its own options after -- (-L, -N, -P followed by
# another option): the programs run this way must not be given those as arguments.

if(NOT CMAKE_SCRIPT_MODE_FILE)
  set_property(GLOBAL PROPERTY POGON_CHECKED_TEST_SCRIPT "${CMAKE_CURRENT_LIST_FILE}")

  function(pogon_add_checked_test)
    cmake_parse_arguments(PARSE_ARGV 0 ARG "" "NAME;EXIT;FRESH_DIR" "OUTPUT;FILES;COMMAND")
    if(ARG_UNPARSED_ARGUMENTS OR "${ARG_NAME}" STREQUAL "" OR "${ARG_COMMAND}" STREQUAL "")
      message(FATAL_ERROR "pogon_add_checked_test(NAME <name> ... COMMAND <program> ...): "
                          "bad arguments ${ARGV}")
    endif()
    if(NOT DEFINED ARG_EXIT)
      set(ARG_EXIT 0)
    endif()
    if(NOT ARG_EXIT MATCHES "^[0-9]+$")
      message(FATAL_ERROR "pogon_add_checked_test(${ARG_NAME}): EXIT must be a number, not '${ARG_EXIT}'")
    endif()
    set(checks --exit ${ARG_EXIT})
    foreach(regex IN LISTS ARG_OUTPUT)
      list(APPEND checks --output "${regex}")
    endforeach()
    if(NOT "${ARG_FRESH_DIR}" STREQUAL "")
      list(APPEND checks --fresh-dir "${ARG_FRESH_DIR}")
    endif()
    foreach(file IN LISTS ARG_FILES)
      list(APPEND checks --file "${file}")
    endforeach()
    list(POP_FRONT ARG_COMMAND program)
    if(TARGET ${program})
      get_target_property(emulator ${program} CROSSCOMPILING_EMULATOR)
      if(NOT emulator)
        set(emulator "")
      endif()
      set(program ${emulator} "$<TARGET_FILE:${program}>")
    endif()
    get_property(script GLOBAL PROPERTY POGON_CHECKED_TEST_SCRIPT)
    add_test(NAME ${ARG_NAME}
      COMMAND ${CMAKE_COMMAND} -P "${script}" -- ${checks} -- ${program} ${ARG_COMMAND})
  endfunction()
  return()
endif()

# ---- script mode ------------------------------------------------------------------------
cmake_minimum_required(VERSION 3.16)
set(expect_exit 0)
set(regexes "")
set(files "")
set(fresh_dir "")
set(command "")
# Arguments are kept in lists with their ; escaped, so that one argument stays one
# (sh -c 'a; b', a regex with a ;).
set(state cmake)   # cmake: CMake's own arguments; options: ours; command: the program's
math(EXPR last "${CMAKE_ARGC} - 1")
set(i 0)
while(i LESS_EQUAL last)
  set(arg "${CMAKE_ARGV${i}}")
  math(EXPR next "${i} + 1")
  if(state STREQUAL "cmake")
    if(arg STREQUAL "--")
      set(state options)
    endif()
  elseif(state STREQUAL "options")
    if(arg STREQUAL "--")
      set(state command)
    elseif(arg MATCHES "^--(exit|output|fresh-dir|file)$" AND next LESS_EQUAL last)
      string(REPLACE ";" "\\;" value "${CMAKE_ARGV${next}}")
      if(arg STREQUAL "--exit")
        set(expect_exit "${value}")
      elseif(arg STREQUAL "--output")
        list(APPEND regexes "${value}")
      elseif(arg STREQUAL "--fresh-dir")
        set(fresh_dir "${value}")
      else()
        list(APPEND files "${value}")
      endif()
      set(i ${next})
    else()
      message(FATAL_ERROR "pogonCheckedTest.cmake: unknown or incomplete option '${arg}'")
    endif()
  else()
    string(REPLACE ";" "\\;" arg "${arg}")
    list(APPEND command "${arg}")
  endif()
  math(EXPR i "${i} + 1")
endwhile()
if("${command}" STREQUAL "")   # not if(NOT command): the program may be called false
  message(FATAL_ERROR "pogonCheckedTest.cmake: no program given (... -- [options] -- PROGRAM [ARG...])")
endif()

if(NOT "${fresh_dir}" STREQUAL "")
  file(REMOVE_RECURSE "${fresh_dir}")
  file(MAKE_DIRECTORY "${fresh_dir}")
endif()
list(JOIN command " " command_text)
# The same variable for both streams: they are merged in the order they are produced.
execute_process(COMMAND ${command} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)

set(problems "")
if(NOT "${rc}" STREQUAL "${expect_exit}")
  string(APPEND problems "  exit status ${rc}, expected ${expect_exit}\n")
endif()
foreach(regex IN LISTS regexes)
  if(NOT out MATCHES "${regex}")
    string(APPEND problems "  the output does not match: ${regex}\n")
  endif()
endforeach()
foreach(file IN LISTS files)
  if(NOT EXISTS "${file}")
    string(APPEND problems "  not written: ${file}\n")
  endif()
endforeach()
if(NOT "${problems}" STREQUAL "")
  message(FATAL_ERROR "FAILED: ${command_text}\n${problems}---- its output:\n${out}")
endif()
message("${out}")
message("OK: ${command_text}: exit status ${rc}, output and files as expected")
