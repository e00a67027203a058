// Scene shapes as geometry shapes, for every program that places the scene's bodies
// (cosim-rigidbody, cosim-fluid), so that a body has the same shape and centre in all. A
// library of its own beside the scene loader, so that neither the loader nor the geometry
// library knows of the other.
#pragma once

#include <Eigen/Core>

#include "geometry/shape.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::scene {

geometry::Shape shape_of(const Shape& s);

// Meshes and hulls are moved on construction so their centre of mass is the body origin:
// a scene body at (x, q) has its centre of mass at x + q * com_shift.
Eigen::Vector3d com_shift(const geometry::Shape& shape);

}  // namespace cosim::scene
