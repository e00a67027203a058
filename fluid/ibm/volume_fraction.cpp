#include "fluid/ibm/volume_fraction.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fluid/bodies/control_volumes.hpp"
#include "geometry/aabb.hpp"

namespace cosim::fluid::ibm {

using bodies::control_interval;
using bodies::control_volumes_meeting;
using bodies::IndicatorPatch;
using bodies::Interval;
using bodies::RigidBody;
using grid::Axis;
using grid::Box;
using grid::for_each_index;
using grid::Grid;
using grid::Index;

double level_set_fraction(std::span<const double> phi) {
  double inside = 0, total = 0;
  for (double p : phi) {
    if (p < 0) inside -= p;
    total += std::abs(p);
  }
  return total > 0 ? inside / total : 1.0;
}

IndicatorPatch volume_fraction(const Grid& grid, int location, const RigidBody& body, const BodyDistance& distance,
                               const Box& within) {
  const Box range = control_volumes_meeting(grid, location, geometry::world_aabb(body.shape, body.pose), within);
  // The sub-boxes' corners form a lattice: along a component's own axis from cell centre to
  // cell centre, across it (and for cell centres) from face to face, each interval halved;
  // on a degenerate axis the midplane.
  constexpr int kSplit = 2;
  std::array<std::vector<double>, 3> corner;
  for (int d = 0; d < 3; ++d) {
    const Axis& axis = grid.axis(d);
    if (axis.degenerate()) {
      corner[d] = {axis.centre(0)};
      continue;
    }
    for (PetscInt i = range.lo[d]; i < range.hi[d]; ++i) {
      const Interval cv = control_interval(axis, d == location, i);
      for (int k = 0; k < kSplit; ++k) corner[d].push_back(cv.lo + (cv.hi - cv.lo) * k / kSplit);
    }
    if (range.hi[d] > range.lo[d]) corner[d].push_back(control_interval(axis, d == location, range.hi[d] - 1).hi);
  }
  const std::array<std::size_t, 3> n{corner[0].size(), corner[1].size(), corner[2].size()};
  std::array<int, 3> split{};
  for (int d = 0; d < 3; ++d) split[d] = n[d] == 1 ? 1 : kSplit;
  // The distances at one layer of control volumes' corner planes at a time (a container's
  // lattice spans the whole domain, eight nodes a cell); the layers come in order, and each
  // starts at the plane the one below ended at.
  const std::size_t plane = n[0] * n[1];
  std::vector<Eigen::Vector3d> nodes;
  std::vector<double> phi;
  std::size_t first_plane = 0;
  const auto fill_layer = [&](PetscInt k) {
    first_plane = n[2] == 1 ? 0 : static_cast<std::size_t>(kSplit * (k - range.lo[2]));
    const std::size_t planes = std::min(n[2], first_plane + kSplit + 1) - first_plane;
    const std::size_t known = phi.empty() ? 0 : 1;
    if (known) std::copy(phi.end() - static_cast<std::ptrdiff_t>(plane), phi.end(), phi.begin());
    nodes.clear();
    for (std::size_t z = first_plane + known; z < first_plane + planes; ++z)
      for (double y : corner[1])
        for (double x : corner[0]) nodes.emplace_back(x, y, corner[2][z]);
    phi.resize(planes * plane);
    distance(body, nodes, std::span<double>(phi).subspan(known * plane));
  };
  std::vector<double> values;
  PetscInt layer = range.lo[2] - 1;
  for_each_index(range, [&](const Index& p) {
    if (p[2] != layer) fill_layer(layer = p[2]);
    double sum = 0;
    for (int a = 0; a < split[0]; ++a)
      for (int b = 0; b < split[1]; ++b)
        for (int c = 0; c < split[2]; ++c) {
          const std::array<std::size_t, 3> first{
              n[0] == 1 ? 0 : static_cast<std::size_t>(kSplit * (p[0] - range.lo[0]) + a),
              n[1] == 1 ? 0 : static_cast<std::size_t>(kSplit * (p[1] - range.lo[1]) + b),
              n[2] == 1 ? 0 : static_cast<std::size_t>(kSplit * (p[2] - range.lo[2]) + c) - first_plane};
          std::array<double, 8> corners{};
          for (std::size_t m = 0; m < 8; ++m) {
            std::array<std::size_t, 3> at{};
            for (std::size_t d = 0; d < 3; ++d) at[d] = first[d] + (n[d] == 1 ? 0 : (m >> d) & 1);
            corners[m] = phi[at[0] + n[0] * (at[1] + n[1] * at[2])];
          }
          sum += level_set_fraction(corners);
        }
    values.push_back(sum / (split[0] * split[1] * split[2]));
  });
  return {range, std::move(values)};
}

std::vector<Eigen::Vector3d> periodic_shifts(const Grid& grid, const geometry::Aabb& box,
                                             const geometry::Aabb& target) {
  std::array<std::vector<double>, 3> along{std::vector<double>{0.0}, {0.0}, {0.0}};
  if (box.is_bounded() && target.is_bounded())
    for (int d = 0; d < 3; ++d) {
      const Axis& axis = grid.axis(d);
      if (axis.degenerate()) continue;
      along[d].clear();
      if (!axis.periodic()) {
        if (box.min[d] <= target.max[d] && box.max[d] >= target.min[d]) along[d].push_back(0.0);
        continue;
      }
      const double period = axis.hi() - axis.lo();
      const auto first = static_cast<long>(std::ceil((target.min[d] - box.max[d]) / period));
      const auto last = static_cast<long>(std::floor((target.max[d] - box.min[d]) / period));
      for (long k = first; k <= last; ++k) along[d].push_back(static_cast<double>(k) * period);
    }
  std::vector<Eigen::Vector3d> out;
  for (double x : along[0])
    for (double y : along[1])
      for (double z : along[2]) out.emplace_back(x, y, z);
  return out;
}

std::vector<FractionImage> volume_fractions(const Grid& grid, int location, const RigidBody& body,
                                            const BodyDistance& distance, const Box& within) {
  // A face's control volume reaches half a cell beyond the domain (face 0's below its
  // bottom), so images within a cell of it count.
  geometry::Aabb domain;
  for (int d = 0; d < 3; ++d) {
    const Axis& axis = grid.axis(d);
    domain.min[d] = axis.lo() - axis.max_width();
    domain.max[d] = axis.hi() + axis.max_width();
  }
  std::vector<FractionImage> out;
  for (const Eigen::Vector3d& shift : periodic_shifts(grid, geometry::world_aabb(body.shape, body.pose), domain)) {
    RigidBody image = body;
    image.pose.set_position(body.pose.position() + shift);
    IndicatorPatch patch = volume_fraction(grid, location, image, distance, within);
    if (patch.tested() > 0) out.push_back({std::move(patch), shift});
  }
  return out;
}

}  // namespace cosim::fluid::ibm
