#include "geometry/distance_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/detail/checks.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

constexpr double max_nodes = 2147483648.0;

GridSpec grid_around(const Shape& shape, double spacing, double margin) {
  if (!is_bounded(shape)) throw std::invalid_argument("distance map: a half-space is unbounded");
  detail::require_positive(spacing, "distance map", "spacing");
  if (!(margin >= 0.0)) throw std::invalid_argument("distance map: margin must not be negative");
  const Aabb box = world_aabb(shape, Pose());
  const Eigen::Vector3d extent = box.max - box.min + Eigen::Vector3d::Constant(2.0 * margin);
  GridSpec grid;
  grid.spacing = spacing;
  double nodes = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double n = std::ceil(extent[a] / spacing) + 1.0;
    nodes *= n;
    if (nodes > max_nodes) throw std::invalid_argument("distance map: more than 2^31 nodes; use a coarser spacing");
    grid.count[a] = static_cast<int>(n);
  }
  // Centred on the box, so that the margin is the same on both sides.
  const Eigen::Vector3d span = spacing * Eigen::Vector3d(grid.count[0] - 1, grid.count[1] - 1, grid.count[2] - 1);
  grid.origin = 0.5 * (box.min + box.max - span);
  return grid;
}

}  // namespace

DistanceMap::DistanceMap(const Shape& shape, double spacing, double margin)
    : grid_(grid_around(shape, spacing, margin)), shape_volume_(volume(shape)) {
  std::vector<SurfacePoint> nodes(grid_.size());
  closest_points(shape, Pose(), grid_, nodes);
  values_.reserve(nodes.size());
  normals_.reserve(nodes.size());
  for (const auto& s : nodes) {
    values_.push_back(s.distance);
    normals_.push_back(s.normal.cast<float>());
  }
}

double DistanceMap::error_bound() const { return 0.5 * std::sqrt(3.0) * grid_.spacing; }

DistanceMap::Cell DistanceMap::locate(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d u = (p - grid_.origin) / grid_.spacing;
  Eigen::Vector3d clamped;
  std::array<int, 3> i{};
  Eigen::Array3d t;
  for (int a = 0; a < 3; ++a) {
    // Written so that NaN lands on 0 (and gives a NaN distance) instead of an index.
    clamped[a] = u[a] > 0.0 ? std::min(u[a], static_cast<double>(grid_.count[a] - 1)) : 0.0;
    i[a] = std::min(static_cast<int>(clamped[a]), grid_.count[a] - 2);
    t[a] = clamped[a] - i[a];
  }
  return {grid_.index(i[0], i[1], i[2]), t, grid_.spacing * (u - clamped).norm()};
}

template <class T>
T DistanceMap::interpolate(const std::vector<T>& field, const Cell& cell) const {
  const std::size_t dy = static_cast<std::size_t>(grid_.count[0]);
  const std::size_t dz = dy * static_cast<std::size_t>(grid_.count[1]);
  const auto lerp = [](const T& a, const T& b, double t) -> T { return a + (b - a) * t; };
  const auto along_x = [&](std::size_t n) { return lerp(field[n], field[n + 1], cell.t[0]); };
  const std::size_t b = cell.base;
  return lerp(lerp(along_x(b), along_x(b + dy), cell.t[1]), lerp(along_x(b + dz), along_x(b + dz + dy), cell.t[1]),
              cell.t[2]);
}

double DistanceMap::signed_distance(const Eigen::Vector3d& p) const {
  const Cell cell = locate(p);
  return interpolate(values_, cell) + cell.outside;
}

SurfacePoint DistanceMap::closest(const Eigen::Vector3d& p) const {
  const Cell cell = locate(p);
  const double d = interpolate(values_, cell) + cell.outside;
  const Eigen::Vector3d n = detail::unit_or(interpolate(normals_, cell).cast<double>(), Eigen::Vector3d::UnitZ());
  return {d, p - d * n, n};
}

}  // namespace cosim::geometry
