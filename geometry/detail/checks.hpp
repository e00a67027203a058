#pragma once

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cosim::geometry::detail {

// Shape parameters come from scene files: reject what would give NaN or zero volume.
inline double require_positive(double value, const char* shape, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(shape) + ": " + what + " must be positive and finite, got " +
                                std::to_string(value));
  return value;
}

inline Eigen::Vector3d require_positive(const Eigen::Vector3d& v, const char* shape, const char* what) {
  for (int i = 0; i < 3; ++i) require_positive(v[i], shape, what);
  return v;
}

// A unit direction along d, or `fallback` when d is zero: every radial direction of a point
// on a symmetry axis is equally valid, but queries must still return a unit normal.
inline Eigen::Vector3d unit_or(const Eigen::Vector3d& d, const Eigen::Vector3d& fallback) {
  const double n = d.norm();
  return n > 0.0 ? Eigen::Vector3d(d / n) : fallback;
}

}  // namespace cosim::geometry::detail
