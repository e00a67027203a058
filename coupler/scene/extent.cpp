#include "coupler/scene/extent.hpp"

#include <Eigen/Geometry>

namespace cosim::scene {

Vec3 half_extent(const Shape& shape, const Quat& q) {
  const Eigen::Matrix3d R = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
  const Eigen::Vector3d axis = R.col(2);  // cylinder and capsule axis in the world
  const Eigen::Vector3d half_axis = 0.5 * shape.height * axis.cwiseAbs();
  Eigen::Vector3d h = Eigen::Vector3d::Zero();
  switch (shape.type) {
    case ShapeType::Sphere:
      h.setConstant(shape.radius);
      break;
    case ShapeType::Box:
      h = R.cwiseAbs() * Eigen::Vector3d(shape.half_extents.data());
      break;
    case ShapeType::Ellipsoid:  // support of an ellipsoid along e_i: |diag(a) R^T e_i|
      h = (R * Eigen::Vector3d(shape.radii.data()).asDiagonal()).rowwise().norm();
      break;
    case ShapeType::Capsule:
      h = half_axis.array() + shape.radius;
      break;
    case ShapeType::Cylinder:  // a disc of radius r with normal n reaches r sqrt(1 - n_i^2) along e_i
      h = half_axis.array() + shape.radius * (1.0 - axis.array().square()).max(0.0).sqrt();
      break;
    case ShapeType::Plane:
    case ShapeType::Mesh:
      break;
  }
  return {h.x(), h.y(), h.z()};
}

}  // namespace cosim::scene
