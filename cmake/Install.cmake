# `cmake --install`: the participant SDK and the programs. A participant of its own builds
# against the prefix with find_package(cosim) and cosim::participant, and runs under the
# installed `cosim`, which finds the built-in programs next to itself (examples/participant).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# cosim::participant and what it links, with the headers of their HEADERS file sets. The
# libraries are static, so the run-file library comes too: the scene reads a run file's last
# poses for `generate: file` (coupler/scene/pose_file.cpp).
set(sdk_targets cosim_participant cosim_protocol cosim_field cosim_scene cosim_output)
foreach(target IN LISTS sdk_targets)
  string(REPLACE "cosim_" "" name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  # The headers are C++20, in a user's build too.
  target_compile_features(${target} PUBLIC cxx_std_20)
  # A sanitizer build's libraries need the sanitizers' runtime in whatever links them.
  if(COSIM_SANITIZE)
    target_link_options(${target} INTERFACE -fsanitize=address,undefined)
  endif()
endforeach()
install(TARGETS ${sdk_targets} EXPORT cosimTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        FILE_SET HEADERS DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/cosim)
install(EXPORT cosimTargets NAMESPACE cosim:: DESTINATION ${config_dir})
configure_package_config_file(cmake/cosimConfig.cmake.in ${CMAKE_BINARY_DIR}/cosimConfig.cmake
                              INSTALL_DESTINATION ${config_dir})
# 0.x: no promise across minor versions.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cosimConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cosimConfig.cmake ${CMAKE_BINARY_DIR}/cosimConfigVersion.cmake
        DESTINATION ${config_dir})

install(TARGETS cosim cosim-rigidbody cosim-fluid cosim-tracker RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
