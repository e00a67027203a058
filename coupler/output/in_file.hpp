#pragma once
// Runs f with HDF5's stack printing off and puts the file name on ObjectErrors, so every
// message names both the file and the object.

#include <filesystem>
#include <stdexcept>

#include "coupler/output/h5_handle.hpp"

namespace cosim::output {

template <class F>
auto in_file(const std::filesystem::path& path, F&& f) {
  QuietErrors quiet;
  try {
    return f();
  } catch (const ObjectError& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

}  // namespace cosim::output
