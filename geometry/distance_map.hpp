#pragma once

#include <span>
#include <vector>

#include "geometry/grid.hpp"
#include "geometry/shape.hpp"

namespace cosim::geometry {

// Signed distances and outward normals of a shape sampled on a regular grid in its body
// frame, read back by trilinear interpolation: constant cost per lookup whatever the shape.
//
// Accuracy (tested): node values are exact. Between nodes, |lookup - exact| <= (sqrt(3)/2) h
// for every shape, because the signed distance is 1-Lipschitz and the interpolation weights
// are a convex combination. Where the distance is smooth (away from edges, corners and the
// medial axis) the error is second order, about h^2 / 8 times the largest surface curvature.
// Normals are the exact closest-point normals at the nodes, interpolated and normalised.
// Outside the grid the lookup is the value at the nearest grid point plus the distance to
// it (an upper bound of the exact distance plus the interpolation error).
class DistanceMap {
 public:
  // The grid covers the shape's bounding box plus `margin` on every side, with nodes
  // `spacing` apart (the caller's resolution). Throws std::invalid_argument for a
  // half-space, a non-positive spacing, a negative margin, or more than 2^31 nodes.
  DistanceMap(const Shape& shape, double spacing, double margin);

  const GridSpec& grid() const { return grid_; }
  double shape_volume() const { return shape_volume_; }       // exact, of the shape sampled
  std::span<const double> values() const { return values_; }  // exact, at grid.index(i, j, k)
  double error_bound() const;                                 // (sqrt(3)/2) h, see above

  double signed_distance(const Eigen::Vector3d& p) const;
  SurfacePoint closest(const Eigen::Vector3d& p) const;  // point = p - distance * normal

 private:
  struct Cell {
    std::size_t base;  // index of the lower corner node
    Eigen::Array3d t;  // position inside the cell, in [0, 1]^3
    double outside;    // distance from p to the grid box
  };
  Cell locate(const Eigen::Vector3d& p) const;
  template <class T>
  T interpolate(const std::vector<T>& field, const Cell& cell) const;

  GridSpec grid_;
  double shape_volume_;
  std::vector<double> values_;
  std::vector<Eigen::Vector3f> normals_;  // single precision: they are interpolated anyway
};

}  // namespace cosim::geometry
