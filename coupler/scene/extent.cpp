#include "coupler/scene/extent.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosim::scene {

Vec3 half_extent(const Shape& shape, const Quat& q) {
  const Eigen::Matrix3d R = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
  const Eigen::Vector3d axis = R.col(2);  // cylinder and capsule axis in the world
  const Eigen::Vector3d half_axis = 0.5 * shape.height * axis.cwiseAbs();
  Eigen::Vector3d h = Eigen::Vector3d::Zero();
  if (shape.container) return {0, 0, 0};
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

double bounding_radius(const Shape& shape) {
  if (shape.container) return 0.0;
  switch (shape.type) {
    case ShapeType::Sphere:
      return shape.radius;
    case ShapeType::Ellipsoid:
      return std::max({shape.radii[0], shape.radii[1], shape.radii[2]});
    case ShapeType::Box:
      return std::hypot(shape.half_extents[0], shape.half_extents[1], shape.half_extents[2]);
    case ShapeType::Cylinder:  // a rim point: radius out, half the height up
      return std::hypot(shape.radius, 0.5 * shape.height);
    case ShapeType::Capsule:
      return shape.radius + 0.5 * shape.height;
    case ShapeType::Plane:
    case ShapeType::Mesh:
      break;
  }
  return 0.0;
}

double volume(const Shape& shape) {
  using std::numbers::pi;
  const double ball = 4.0 / 3.0 * pi * shape.radius * shape.radius * shape.radius;
  if (shape.container) return 0.0;
  switch (shape.type) {
    case ShapeType::Sphere:
      return ball;
    case ShapeType::Ellipsoid:
      return 4.0 / 3.0 * pi * shape.radii[0] * shape.radii[1] * shape.radii[2];
    case ShapeType::Box:
      return 8.0 * shape.half_extents[0] * shape.half_extents[1] * shape.half_extents[2];
    case ShapeType::Cylinder:
      return pi * shape.radius * shape.radius * shape.height;
    case ShapeType::Capsule:
      return pi * shape.radius * shape.radius * shape.height + ball;
    case ShapeType::Plane:
    case ShapeType::Mesh:
      break;
  }
  return 0.0;
}

}  // namespace cosim::scene
