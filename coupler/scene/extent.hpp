// How far a shape reaches from its body's position along each world axis.
#pragma once

#include "coupler/scene/scene.hpp"

namespace cosim::scene {

// Half widths of the tightest world-axis-aligned box around `shape` turned by the unit
// quaternion `q`. Zero for planes (unbounded) and meshes (not read here): for those the
// scene only bounds the position.
Vec3 half_extent(const Shape& shape, const Quat& q);

}  // namespace cosim::scene
