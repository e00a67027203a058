// Window records with a known value in every slot, shared by the tests and the plot helper.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "coupler/output/run_file.hpp"

namespace cosim::output::test {

// Window k ends at time (k + 1) * dt; every pose/force slot holds a value that names its
// window, body and column, so a misplaced row or column shows up as a wrong number.
inline double slot(std::uint64_t k, std::size_t body, std::size_t column) {
  return 1000.0 * static_cast<double>(k) + 100.0 * static_cast<double>(body) + static_cast<double>(column) + 0.25;
}

inline WindowRecord sample_window(std::uint64_t k, double dt, std::size_t bodies,
                                  const std::vector<std::string>& participants) {
  WindowRecord w;
  w.window = k;
  w.time = static_cast<double>(k + 1) * dt;
  w.iterations = static_cast<int>(k % 7) + 1;
  w.residual = 1e-3 / static_cast<double>(k + 1);
  w.wall_seconds = 0.5 + 0.01 * static_cast<double>(k);
  for (std::size_t b = 0; b < bodies; ++b) {
    for (std::size_t c = 0; c < 13; ++c) w.poses.push_back(slot(k, b, c));
    for (std::size_t c = 0; c < 6; ++c) w.forces.push_back(slot(k, b, 13 + c));
  }
  for (std::size_t p = 0; p < participants.size(); ++p) {
    w.participant_wall_seconds[participants[p]] = 0.1 * static_cast<double>(p + 1);
    w.participant_substeps[participants[p]] = static_cast<double>(p + 2);
  }
  return w;
}

}  // namespace cosim::output::test
