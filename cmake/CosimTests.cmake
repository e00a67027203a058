# cosim_discover_tests: gtest_discover_tests, with the stability suite split off.
#
#   cosim_discover_tests(<target> [TEST_PREFIX <prefix>]
#                        [STABILITY <gtest pattern>...]
#                        [ENVIRONMENT <VAR=value>...]
#                        [PROPERTIES <name> <value>...])
#
# Every GoogleTest executable under tests/ registers its cases with this (one ctest entry
# per case, as gtest_discover_tests does). The cases matching a STABILITY pattern are the
# hard cases: they get the ctest label `stability`, so `ctest -L stability`
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
# ENVIRONMENT takes a list of VAR=value: gtest_discover_tests (CMake 3.25) flattens a list
# given among its PROPERTIES, so only the first variable would reach the tests, and every
# name/value pair after it would shift. The variables are set instead by a ctest include
# file that runs after discovery, on the tests discovery listed.
function(cosim_discover_tests target)
  cmake_parse_arguments(arg "" "TEST_PREFIX" "STABILITY;ENVIRONMENT;PROPERTIES" ${ARGN})
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "cosim_discover_tests(${target}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  set(prefix)
  if(DEFINED arg_TEST_PREFIX)
    set(prefix TEST_PREFIX "${arg_TEST_PREFIX}")
  endif()
  set(lists ${target}_TESTS)
  if(NOT arg_STABILITY)
    gtest_discover_tests(${target} ${prefix} TEST_LIST ${target}_TESTS PROPERTIES ${arg_PROPERTIES})
  else()
    list(JOIN arg_STABILITY ":" patterns)
    gtest_discover_tests(${target} ${prefix} TEST_FILTER "-${patterns}" TEST_LIST ${target}_TESTS
                         PROPERTIES ${arg_PROPERTIES})
    gtest_discover_tests(${target} ${prefix} TEST_FILTER "${patterns}" TEST_LIST ${target}_STABILITY_TESTS
                         PROPERTIES LABELS stability ${arg_PROPERTIES})
    list(APPEND lists ${target}_STABILITY_TESTS)
  endif()
  if(arg_ENVIRONMENT)
    set(script "")
    foreach(list IN LISTS lists)
      string(APPEND script "if(${list})\n  set_tests_properties(\${${list}} PROPERTIES ENVIRONMENT \"${arg_ENVIRONMENT}\")\nendif()\n")
    endforeach()
    set(file ${CMAKE_CURRENT_BINARY_DIR}/${target}_environment.cmake)
    file(WRITE ${file} "${script}")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${file})
  endif()
endfunction()
