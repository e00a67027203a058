#pragma once

#include <Eigen/Core>

#include "geometry/shape.hpp"

namespace cosim::geometry {

// Of a shape with uniform density, in its body frame. The centre of mass is the body origin
// for every shape (meshes and hulls are shifted on construction, see com_shift()), so the
// inertia tensor is about the origin. Closed forms for the analytic shapes, exact
// polyhedral integrals for hulls and meshes.
struct MassProperties {
  double volume = 0.0;
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

// Throws std::invalid_argument for a half-space or a density that is not positive.
MassProperties mass_properties(const Shape& shape, double density);

}  // namespace cosim::geometry
