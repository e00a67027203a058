// A tally's numbers in one fixed order, for the state arrays (simulation_state.cpp) and the
// sums over the ranks (simulation.cpp).
#pragma once

#include <vector>

#include "tracker/tracking/obstacles.hpp"

namespace cosim::tracker::detail {

inline std::vector<long long*> counters(SurfaceTally& t) { return {&t.hits, &t.absorbed}; }
inline std::vector<double*> values(SurfaceTally& t) {
  return {&t.impulse[0], &t.impulse[1], &t.impulse[2], &t.energy};
}
inline std::vector<long long*> counters(ObstacleTally& t) {
  std::vector<long long*> out = counters(static_cast<SurfaceTally&>(t));
  out.insert(out.end(), {&t.entered, &t.left, &t.released, &t.overrun});
  return out;
}
inline std::vector<double*> values(ObstacleTally& t) {
  std::vector<double*> out = values(static_cast<SurfaceTally&>(t));
  out.insert(out.end(), {&t.angular_impulse[0], &t.angular_impulse[1], &t.angular_impulse[2]});
  return out;
}

}  // namespace cosim::tracker::detail
