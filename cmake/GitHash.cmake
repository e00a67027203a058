# The run file records which source produced it.
execute_process(
  COMMAND git -C ${CMAKE_SOURCE_DIR} describe --always --dirty --abbrev=12
  OUTPUT_VARIABLE COSIM_GIT_HASH OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT COSIM_GIT_HASH)
  set(COSIM_GIT_HASH "unknown")
endif()
