# Runs one libFuzzer executable for a bounded time (the ctest entries of cmake/fuzz.cmake).
# -DFUZZER=exe -DCORPUS=seed dir (read only) -DWORK=scratch dir -DSECONDS=n [-DDICT=file]
# [-DREPLAY=1: run each seed once instead of fuzzing for SECONDS]
# The seeds are copied into WORK/corpus, which the fuzzer grows; crashes land in WORK/artifacts/.
# Fails when the fuzzer reports a finding (crash, leak, UB, timeout, out of memory).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
file(GLOB seeds ${CORPUS}/*)
file(COPY ${seeds} DESTINATION ${WORK}/corpus)
set(args -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1
         -artifact_prefix=${WORK}/artifacts/)
if(REPLAY)
  list(APPEND args -runs=0)
else()
  list(APPEND args -max_total_time=${SECONDS})
endif()
if(DICT)
  list(APPEND args -dict=${DICT})
endif()
execute_process(COMMAND ${FUZZER} ${args} ${WORK}/corpus RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER} found a problem (exit ${rc}); the input is in ${WORK}/artifacts/")
endif()
