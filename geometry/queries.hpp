#pragma once

#include <cstdint>
#include <span>

#include "geometry/grid.hpp"
#include "geometry/shape.hpp"

// Point queries on any shape: signed distance (negative inside), closest surface point with
// outward normal, and inside test (surface points count as inside: contains(p) is
// signed_distance(p) <= 0 up to rounding on the surface itself). All are exact; see README.
namespace cosim::geometry {

// Body frame.
double signed_distance(const Shape& shape, const Eigen::Vector3d& p);
SurfacePoint closest_point(const Shape& shape, const Eigen::Vector3d& p);
bool contains(const Shape& shape, const Eigen::Vector3d& p);

// World frame: p, and the returned point and normal, are world coordinates.
double signed_distance(const Shape& shape, const Pose& pose, const Eigen::Vector3d& p);
SurfacePoint closest_point(const Shape& shape, const Pose& pose, const Eigen::Vector3d& p);
bool contains(const Shape& shape, const Pose& pose, const Eigen::Vector3d& p);

// Batches in the world frame: out[i] answers points[i]; out must have points.size()
// entries. The shape is dispatched once per batch, and mesh searches start from the
// previous point's triangle, so ordering the points coherently (grid order) is faster.
void signed_distances(const Shape& shape, const Pose& pose, std::span<const Eigen::Vector3d> points,
                      std::span<double> out);
void closest_points(const Shape& shape, const Pose& pose, std::span<const Eigen::Vector3d> points,
                    std::span<SurfacePoint> out);
void contains(const Shape& shape, const Pose& pose, std::span<const Eigen::Vector3d> points,
              std::span<std::uint8_t> out);

// The same on every node of a grid (out[grid.index(i, j, k)]), without materialising the
// node coordinates: the FBM indicator of a body on the fluid grid.
void signed_distances(const Shape& shape, const Pose& pose, const GridSpec& grid, std::span<double> out);
void closest_points(const Shape& shape, const Pose& pose, const GridSpec& grid, std::span<SurfacePoint> out);

}  // namespace cosim::geometry
