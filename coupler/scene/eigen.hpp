// Scene vectors as Eigen vectors, for the programs that compute with them.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "coupler/scene/scene.hpp"

namespace cosim::scene {

inline Eigen::Vector3d to_eigen(const Vec3& v) { return {v[0], v[1], v[2]}; }
inline Eigen::Quaterniond to_eigen(const Quat& q) { return {q[0], q[1], q[2], q[3]}; }

}  // namespace cosim::scene
