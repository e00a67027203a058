// How far a shape reaches from its body's position, and how much space it fills.
#pragma once

#include "coupler/scene/scene.hpp"

namespace cosim::scene {

// Half widths of the tightest world-axis-aligned box around `shape` turned by the unit
// quaternion `q`. Zero for planes and containers (unbounded) and meshes (not read here): for those the
// scene only bounds the position.
Vec3 half_extent(const Shape& shape, const Quat& q);

// Radius of the smallest sphere about the body's position that holds the shape in any
// orientation. Zero for planes, containers and meshes, as above.
double bounding_radius(const Shape& shape);

// The shape's volume; zero for planes, containers and meshes.
double volume(const Shape& shape);

// Whether the scene knows how far the shape reaches: every shape but planes, containers and
// meshes.
inline bool bounded(const Shape& shape) {
  return shape.type != ShapeType::Plane && shape.type != ShapeType::Mesh && !shape.container;
}

}  // namespace cosim::scene
