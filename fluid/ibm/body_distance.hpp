#pragma once
// The signed distance to a body as a grid of its dimension sees it: the shape's own on a
// three-dimensional grid; on a two-dimensional one (one axis a single periodic cell) the
// distance within the plane to the body's section by the layer's midplane. The shape's own
// distance is wrong there wherever its nearest surface lies off the plane, as the end caps
// of a cylinder as thick as the layer do for every point deeper inside than half the layer;
// so it is measured to dense points on the section's boundary (geometry::section_boundary,
// a sixth of a cell apart) along the normal of the nearest, and signed by the shape's
// inside test. Bodies on a two-dimensional grid turn about its flat axis only. There the
// distance is exact within kReach cells of the section and kReach cells (with its sign)
// further away: all the level-set fractions need, whose cut sub-boxes lie within a cell of
// the surface, and it keeps the search local (a search out to the middle of a body
// twenty cells across made the fractions cost more than the rest of the step).
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "fluid/bodies/rigid_body.hpp"
#include "fluid/grid/grid.hpp"

namespace cosim::fluid::ibm {

class BodyDistance {
 public:
  // `body` where it is first placed: a section's points are kept in its frame.
  BodyDistance(const grid::Axes& axes, const bodies::RigidBody& body);
  BodyDistance(const grid::Grid& grid, const bodies::RigidBody& body) : BodyDistance(grid.axes(), body) {}
  // out[i]: the signed distance of points[i] (world) to `body`, the same body now.
  void operator()(const bodies::RigidBody& body, std::span<const Eigen::Vector3d> points, std::span<double> out) const;
  double at(const bodies::RigidBody& body, const Eigen::Vector3d& point) const;

 private:
  std::int64_t key(const Eigen::Vector3d& body_point) const;

  static constexpr int kReach = 2;  // cells
  int flat_axis_ = -1;
  double cell_ = 0;                                // of the hash grid over the section's points
  std::vector<Eigen::Vector3d> points_, normals_;  // body frame
  std::unordered_map<std::int64_t, std::vector<int>> near_;
};

}  // namespace cosim::fluid::ibm
