# The run file records which source produced it. The hash is read at every build (not only
# at configure time) and the header rewritten only when it changes, so nothing rebuilds
# needlessly.
set(COSIM_GIT_HASH_HEADER ${CMAKE_BINARY_DIR}/generated/cosim_git_hash.hpp)
add_custom_target(cosim_git_hash
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUTPUT=${COSIM_GIT_HASH_HEADER}
          -P ${CMAKE_SOURCE_DIR}/cmake/WriteGitHash.cmake
  BYPRODUCTS ${COSIM_GIT_HASH_HEADER}
  COMMENT "Reading the git hash")
