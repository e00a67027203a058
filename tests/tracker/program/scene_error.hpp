#pragma once
// The message of the scene error that reading something throws, or "no error".

#include <string>

#include "coupler/scene/error.hpp"

namespace cosim::tracker::program::testing {

template <typename Read>
std::string scene_error_of(const Read& read) {
  try {
    read();
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace cosim::tracker::program::testing
