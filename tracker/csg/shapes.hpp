#pragma once

#include <Eigen/Geometry>

#include "tracker/csg/expression.hpp"

namespace cosim::tracker::csg {

// Builders for the primitives in the object frame. Throw std::invalid_argument on
// non-positive sizes or zero directions.

// The solid n . (x - point) <= 0; `outward` need not be unit.
Expression half_space(const Eigen::Vector3d& point, const Eigen::Vector3d& outward);
Expression ball(const Eigen::Vector3d& centre, double radius);
// Infinite along `axis` through `point`.
Expression cylinder(const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double radius);
// The finite cylinder between the disc centres `base` and `top`: the infinite cylinder cut
// by two half-spaces (three state bits). Its rims are edges where the two normals meet.
Expression capped_cylinder(const Eigen::Vector3d& base, const Eigen::Vector3d& top, double radius);
// A native box (one state bit): centre, half extents along its axes, orientation.
Expression box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents,
               const Eigen::Quaterniond& orientation = Eigen::Quaterniond::Identity());

}  // namespace cosim::tracker::csg
