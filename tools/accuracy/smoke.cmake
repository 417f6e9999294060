# accuracy_smoke: run `pogon-accuracy --quick` and check that it exits 0 and prints the
# presets table. The output is echoed only when both hold, so the test's
# PASS_REGULAR_EXPRESSION (which alone would ignore the exit code) sees the table only
# from a successful run.
#   cmake -DEXE=<pogon-accuracy> -DOUT=<dir> -P smoke.cmake
execute_process(COMMAND "${EXE}" --quick --out "${OUT}"
  RESULT_VARIABLE rv OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rv EQUAL 0)
  message(FATAL_ERROR "pogon-accuracy --quick exited with ${rv}\n${err}\n${out}")
endif()
if(NOT out MATCHES "\\| scene \\| unit \\| fast error \\|" OR NOT out MATCHES "\\| energy \\| relative \\|")
  message(FATAL_ERROR "pogon-accuracy --quick printed no presets table\n${out}")
endif()
foreach(f results.csv pareto.svg tables.md rain_divergence.csv)
  if(NOT EXISTS "${OUT}/${f}")
    message(FATAL_ERROR "pogon-accuracy --quick did not write ${OUT}/${f}")
  endif()
endforeach()
message("${out}")
