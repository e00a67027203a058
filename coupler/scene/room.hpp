// How much room a container leaves a point: what placing the other bodies needs to know of
// it, from the scene's own shape (the loader does not link the geometry library).
#pragma once

#include <span>

#include "coupler/scene/scene.hpp"

namespace cosim::scene {

// The distance from `x` to the wall of `container` (a body whose shape is a container),
// positive inside its free space and negative beyond the wall. Exact for a sphere, a box
// and a capsule, and inside a cylinder; less than the distance (never more) inside an
// ellipsoid.
double room(const Body& container, const Vec3& x);

// The least room over the containers among `bodies` (+infinity without one).
double room(std::span<const Body> bodies, const Vec3& x);

}  // namespace cosim::scene
