#pragma once
// The numbers every tracker library speaks in: positions and velocities, and the 32-bit
// indices of cells and faces.

#include <Eigen/Core>

#include <cstdint>

namespace cosim::tracker {

using Vec3 = Eigen::Vector3d;
using Index = std::int32_t;

}  // namespace cosim::tracker
