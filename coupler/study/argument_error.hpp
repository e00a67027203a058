// A `cosim study` argument that cannot be used: the message names the argument and its
// value, and the command exits with status 2, as for an invalid scene.
#pragma once

#include <stdexcept>

namespace cosim::study {

struct ArgumentError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace cosim::study
