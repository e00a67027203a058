# cosim_discover_tests: gtest_discover_tests, with the stability suite split off.
#
#   cosim_discover_tests(<target> [TEST_PREFIX <prefix>]
#                        [STABILITY <gtest pattern>...]
#                        [PROPERTIES <name> <value>...])
#
# Every GoogleTest executable under tests/ registers its cases with this (one ctest entry
# per case, as gtest_discover_tests does). The cases matching a STABILITY pattern are the
# hard cases of issue 7: they get the ctest label `stability`, so `ctest -L stability`
# runs them all, across programs. Patterns are GoogleTest filter patterns on the gtest
# name, without TEST_PREFIX: `Suite.Case`, `Suite.*`, `*/Suite.Case/*` for
# value-parameterised cases.
#
# Each case is registered once: the executable is discovered twice, once with
# --gtest_filter=<patterns> (labelled) and once with --gtest_filter=-<patterns> (the rest),
# so the full `ctest` run holds every case exactly once and new cases land in the
# unlabelled half by default. To add a hard case, list its pattern under STABILITY of its
# executable and say at the test, in a comment starting "Guards against:", what it guards
# against. `ctest -N -L stability` lists what the label holds (a mistyped pattern matches
# nothing and only shows as a missing entry there).
#
# LABELS is put before the caller's PROPERTIES: gtest_discover_tests flattens a list value
# such as ENVIRONMENT "${COSIM_TEST_ENV}" into the property list, which shifts every
# name/value pair after it (CMake 3.25).
function(cosim_discover_tests target)
  cmake_parse_arguments(arg "" "TEST_PREFIX" "STABILITY;PROPERTIES" ${ARGN})
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "cosim_discover_tests(${target}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  set(prefix)
  if(DEFINED arg_TEST_PREFIX)
    set(prefix TEST_PREFIX "${arg_TEST_PREFIX}")
  endif()
  if(NOT arg_STABILITY)
    gtest_discover_tests(${target} ${prefix} PROPERTIES ${arg_PROPERTIES})
    return()
  endif()
  list(JOIN arg_STABILITY ":" patterns)
  gtest_discover_tests(${target} ${prefix} TEST_FILTER "-${patterns}" PROPERTIES ${arg_PROPERTIES})
  gtest_discover_tests(${target} ${prefix} TEST_FILTER "${patterns}" TEST_LIST ${target}_STABILITY_TESTS
                       PROPERTIES LABELS stability ${arg_PROPERTIES})
endfunction()
