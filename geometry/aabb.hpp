#pragma once

#include <Eigen/Core>
#include <limits>

namespace cosim::geometry {

// Axis-aligned box [min, max]. Unbounded sides (half-spaces) are +-infinity.
struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  static Aabb around(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extent) {
    return {center - half_extent, center + half_extent};
  }

  bool is_bounded() const { return min.allFinite() && max.allFinite(); }

  void extend(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }

  bool contains(const Eigen::Vector3d& p, double tolerance = 0.0) const {
    return ((p - min).array() >= -tolerance).all() && ((max - p).array() >= -tolerance).all();
  }

  // Zero inside; the branch-and-bound searches prune with it.
  double squared_distance(const Eigen::Vector3d& p) const {
    return (min - p).cwiseMax(p - max).cwiseMax(0.0).squaredNorm();
  }
};

}  // namespace cosim::geometry
