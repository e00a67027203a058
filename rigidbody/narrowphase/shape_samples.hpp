// Internal: points (or balls) that stand for a bounded shape where it meets a surface known
// only by its distance: a mesh's distance map, a container's wall.
#pragma once

#include <vector>

#include "geometry/shape.hpp"
#include "rigidbody/narrowphase/candidates.hpp"

namespace cosim::rigidbody::narrowphase::detail {

struct Sample {
  Vec3 point;     // body frame of the sampled shape
  double radius;  // of the ball around it that belongs to the shape
};

// Sphere centre (its radius), balls along a capsule's axis at most a radius apart, box
// corners, 32 cylinder rim points, hull and mesh vertices, 26 support points of an
// ellipsoid. Not for a half-space or a container.
std::vector<Sample> samples(const geometry::Shape& shape);

}  // namespace cosim::rigidbody::narrowphase::detail
