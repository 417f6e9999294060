# Run a libFuzzer target for a fixed number of inputs from a fixed seed, from a fresh
# working corpus (so repeated CTest runs do not accumulate inputs), over the seed corpus:
# the same inputs on every run of the same code, so a verdict does not depend on the
# machine's speed or luck. Used by the fuzz_*_smoke tests:
#   cmake -DFUZZER=<exe> -DCORPUS=<work dir> -DSEEDS=<seed dir> -DDICT=<dict> -DRUNS=1000
#         -DSEED=1 -DARTIFACTS=<dir> -P run_fuzzer.cmake
# A crash leaves its input in ARTIFACTS (crash-<sha1>) and fails the test. An input may
# take 60 s: under ASan on a loaded 2-core machine the replay corpus's pyramid took more
# than 10 s.
foreach(var FUZZER CORPUS SEEDS DICT RUNS SEED ARTIFACTS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzzer.cmake: ${var} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${CORPUS}")
file(MAKE_DIRECTORY "${CORPUS}" "${ARTIFACTS}")
execute_process(
  COMMAND "${FUZZER}" -runs=${RUNS} -seed=${SEED} -timeout=60 -rss_limit_mb=2048 -print_final_stats=1
          "-dict=${DICT}" "-artifact_prefix=${ARTIFACTS}/" "${CORPUS}" "${SEEDS}"
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER} failed (exit ${rc}); the input is in ${ARTIFACTS}/")
endif()
