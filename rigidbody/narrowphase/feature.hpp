// Internal: the feature (face, segment or point) by which a convex shape touches another.
#pragma once

#include "geometry/shape.hpp"
#include "rigidbody/narrowphase/clip.hpp"

namespace cosim::rigidbody::narrowphase::detail {

// The feature of a bounded convex shape facing `direction` (world): a box's or hull's face
// whose normal is nearest the direction, a cylinder's cap (a regular octagon with a vertex
// at the rim's support point) or side segment, whichever the direction is nearer, a
// capsule's segment between its end spheres' support points, or the support point of a
// smooth shape. Points in the world frame; every feature holds the support point.
Feature supporting_feature(const geometry::Shape& shape, const geometry::Pose& pose, const Vec3& direction);

}  // namespace cosim::rigidbody::narrowphase::detail
