// The candidate rule. The grid and the brute-force reference both decide every pair here,
// with the same floating-point operations, so their pair sets can be compared exactly.
#pragma once

#include "rigidbody/broadphase/object.hpp"

namespace cosim::rigidbody::broadphase {

inline Pair ordered_pair(Id a, Id b) { return a < b ? Pair{a, b} : Pair{b, a}; }

// Bounding spheres at most margin apart; touching spheres are candidates.
inline bool spheres_near(const Eigen::Vector3d& ca, double ra, const Eigen::Vector3d& cb, double rb, double margin) {
  const double reach = ra + rb + margin;
  return (ca - cb).squaredNorm() <= reach * reach;
}

// A sphere at most margin outside the half-space, or anywhere inside it. Comparing with the
// scaled reach avoids normalising the normal.
inline bool sphere_near_half_space(const HalfSpace& h, const Eigen::Vector3d& c, double r, double margin) {
  return h.normal.dot(c) - h.offset <= (r + margin) * h.normal.norm();
}

// A finite object and an infinite one.
inline bool near_wall(const Object& wall, const Eigen::Vector3d& c, double r, double margin) {
  return !wall.half_space || sphere_near_half_space(*wall.half_space, c, r, margin);
}

}  // namespace cosim::rigidbody::broadphase
