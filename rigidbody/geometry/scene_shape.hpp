// Scene shapes as geometry shapes, for every program that places the scene's bodies
// (cosim-rigidbody, cosim-fluid), so that a body has the same shape and centre in all.
#pragma once

#include <Eigen/Core>

#include "rigidbody/geometry/shape.hpp"
#include "scene/scene.hpp"

namespace cosim::geometry {

Shape shape_of(const scene::Shape& s);

// Meshes and hulls are moved on construction so their centre of mass is the body origin:
// a scene body at (x, q) has its centre of mass at x + q * com_shift.
Eigen::Vector3d com_shift(const Shape& shape);

}  // namespace cosim::geometry
