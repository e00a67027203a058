// Wall time since `start`, for the stats a participant reports with its outputs.
#pragma once

#include <chrono>

namespace cosim::participant {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace cosim::participant
