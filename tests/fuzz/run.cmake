# One fuzz test: runs FUZZER over CORPUS (read-only) with a fresh SCRATCH folder for what
# the run adds, so that the corpus in the repository stays as checked in: for SECONDS, or,
# with SECONDS 0, each corpus input once. A fixed seed makes a run repeat what it tried, as
# far as a fixed time allows. A crash input lands in SCRATCH (crash-<sha1>) and the test
# fails.
file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${SCRATCH}/new")
if(SECONDS EQUAL 0)
  set(duration -runs=0)
else()
  set(duration -max_total_time=${SECONDS})
endif()
execute_process(
  COMMAND "${FUZZER}" ${duration} -seed=1 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
          -artifact_prefix=${SCRATCH}/ "${SCRATCH}/new" "${CORPUS}"
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${FUZZER} found a failure (exit ${result}); its input is in ${SCRATCH}")
endif()
