#include "tracker/csg/shapes.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cosim::tracker::csg {
namespace {

Eigen::Vector3d unit(const Eigen::Vector3d& d, const char* what) {
  const double n = d.norm();
  if (!(n > 0.0) || !std::isfinite(n))
    throw std::invalid_argument(std::string("csg ") + what + ": direction must be non-zero and finite");
  return d / n;
}

void require_positive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("csg ") + what + ": size must be positive and finite");
}

// A rotation taking the canonical z axis to `axis` (unit).
Eigen::Matrix3d z_to(const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
}

Eigen::Affine3d frame(const Eigen::Vector3d& origin, const Eigen::Matrix3d& linear) {
  Eigen::Affine3d a = Eigen::Affine3d::Identity();
  a.linear() = linear;
  a.translation() = origin;
  return a;
}

}  // namespace

Expression half_space(const Eigen::Vector3d& point, const Eigen::Vector3d& outward) {
  return Expression::primitive(PrimitiveKind::half_space, frame(point, z_to(unit(outward, "half-space"))));
}

Expression ball(const Eigen::Vector3d& centre, double radius) {
  require_positive(radius, "ball");
  return Expression::primitive(PrimitiveKind::ball, frame(centre, radius * Eigen::Matrix3d::Identity()));
}

Expression cylinder(const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double radius) {
  require_positive(radius, "cylinder");
  return Expression::primitive(PrimitiveKind::cylinder, frame(point, radius * z_to(unit(axis, "cylinder"))));
}

Expression capped_cylinder(const Eigen::Vector3d& base, const Eigen::Vector3d& top, double radius) {
  const Eigen::Vector3d axis = unit(top - base, "capped cylinder");
  return cylinder(base, axis, radius) & half_space(top, axis) & half_space(base, -axis);
}

Expression box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents,
               const Eigen::Quaterniond& orientation) {
  for (int i = 0; i < 3; ++i) require_positive(half_extents[i], "box");
  return Expression::primitive(PrimitiveKind::box,
                               frame(centre, orientation.normalized().toRotationMatrix() * half_extents.asDiagonal()));
}

}  // namespace cosim::tracker::csg
