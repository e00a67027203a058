// Shared helpers of the narrow-phase tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "rigidbody/narrowphase/narrowphase.hpp"

namespace cosim::rigidbody::narrowphase::testing {

using Vec3 = Eigen::Vector3d;
using geometry::Pose;
using geometry::Shape;

inline Pose at(const Vec3& position = Vec3::Zero(), const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  return Pose(position, q);
}
inline Eigen::Quaterniond about(const Vec3& axis, double angle) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

inline contact::Manifold contacts(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, double margin = 0.1) {
  contact::Manifold m;
  collide(a, pa, b, pb, margin, m);
  for (int i = 0; i < m.count; ++i) {
    const auto& p = m.points[i];
    EXPECT_TRUE(p.position.allFinite() && p.normal.allFinite() && std::isfinite(p.distance));
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-9);
  }
  return m;
}

inline double min_distance(const contact::Manifold& m) {
  double d = INFINITY;
  for (int i = 0; i < m.count; ++i) d = std::min(d, m.points[i].distance);
  return d;
}

// Whether some point of m is at `position` (within tol).
inline bool has_point(const contact::Manifold& m, const Vec3& position, double tol = 1e-9) {
  for (int i = 0; i < m.count; ++i)
    if ((m.points[i].position - position).norm() <= tol) return true;
  return false;
}

}  // namespace cosim::rigidbody::narrowphase::testing
