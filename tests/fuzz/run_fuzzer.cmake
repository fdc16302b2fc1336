# One bounded fuzzing run, as the ctest test fuzz.<name> (tests/fuzz/CMakeLists.txt):
#   cmake -DFUZZER=exe -DSEEDS=dir -DWORK=dir [-DDICT=file] -DSECONDS=n -P run_fuzzer.cmake
# A fixed -seed keeps CI runs comparable (the time budget still varies).
# Copies the seed corpus to WORK/corpus (libFuzzer adds what it finds there,
# never to the source tree), fuzzes for SECONDS, and fails on any finding;
# the input that caused it is left in WORK/artifacts/.
foreach(var FUZZER SEEDS WORK SECONDS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzzer.cmake: ${var} is not set")
  endif()
endforeach()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
file(GLOB seeds ${SEEDS}/*)
if(NOT seeds)
  message(FATAL_ERROR "run_fuzzer.cmake: no seed corpus in ${SEEDS}")
endif()
file(COPY ${seeds} DESTINATION ${WORK}/corpus)

set(args -seed=1 -max_total_time=${SECONDS} -rss_limit_mb=1024 -malloc_limit_mb=512 -timeout=5
         -max_len=16384 -print_final_stats=1 -artifact_prefix=${WORK}/artifacts/)
if(DICT)
  list(APPEND args -dict=${DICT})
endif()
execute_process(COMMAND ${FUZZER} ${args} ${WORK}/corpus RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  file(GLOB found ${WORK}/artifacts/*)
  message(FATAL_ERROR "${FUZZER} failed (${rc}); the input is in: ${found}\n"
                      "Reproduce with: ${FUZZER} <input>; then add it as a test in tests/unit/legacy_io/.")
endif()
