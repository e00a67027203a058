// Internal: the contact points a pair function finds, before they go into a Manifold.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "rigidbody/contact/contact.hpp"

namespace cosim::rigidbody::narrowphase::detail {

using Vec3 = Eigen::Vector3d;

struct Candidates {
  double margin = 0.0;
  std::vector<contact::ContactPoint> points;
  // Set by a pair function that kept its points per surface itself (a container's walls);
  // otherwise collide() keeps a spread of Manifold::kMaxPoints.
  bool reduced = false;

  // `on_a` is on a's surface, `normal` the unit normal from a to b and `distance` the
  // signed gap along it; the point is stored midway between the surfaces. Points farther
  // than the margin are dropped here so that pair functions need not test.
  void add(const Vec3& on_a, const Vec3& normal, double distance, std::uint32_t feature) {
    if (distance <= margin) points.push_back({on_a + 0.5 * distance * normal, normal, distance, feature});
  }
};

// Keep the `count` deepest points (vertex sets against a plane: resting faces).
void keep_deepest(std::vector<contact::ContactPoint>& points, std::size_t count);
// Keep at most 4: the deepest, the farthest from it, then the points adding the largest
// area (as Bullet's btPersistentManifold::sortCachedPoints and ODE's cullPoints aim for).
void keep_spread(std::vector<contact::ContactPoint>& points);

}  // namespace cosim::rigidbody::narrowphase::detail
