// Scene shapes as geometry shapes, for every program that places the scene's bodies
// (cosim-rigidbody, cosim-fluid), so that a body has the same shape and centre in all. Here,
// with the programs that read scenes, so that the geometry library knows nothing of them.
#pragma once

#include <Eigen/Core>

#include "rigidbody/geometry/shape.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::program {

geometry::Shape shape_of(const scene::Shape& s);

// Meshes and hulls are moved on construction so their centre of mass is the body origin:
// a scene body at (x, q) has its centre of mass at x + q * com_shift.
Eigen::Vector3d com_shift(const geometry::Shape& shape);

}  // namespace cosim::program
