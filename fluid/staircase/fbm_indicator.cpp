#include "fluid/staircase/fbm_indicator.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "fluid/bodies/control_volumes.hpp"
#include "geometry/queries.hpp"

namespace cosim::fluid::staircase {

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

IndicatorPatch indicator(const Grid& grid, int location, const RigidBody& body, const IndicatorOptions& options,
                         const Box& within) {
  geometry::Aabb box = geometry::world_aabb(body.shape, body.pose);
  if (options.offset > 0) {
    double widest = 0;
    for (int d = 0; d < 3; ++d)
      if (!grid.axis(d).degenerate()) widest = std::max(widest, grid.axis(d).max_width());
    box.min.array() -= options.offset * widest;
    box.max.array() += options.offset * widest;
  }
  const Box range = control_volumes_meeting(grid, location, box, within);
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>((range.hi[0] - range.lo[0]) * (range.hi[1] - range.lo[1]) *
                                          (range.hi[2] - range.lo[2])));
  for_each_index(range, [&](const Index& p) {
    Eigen::Vector3d lo, hi;
    std::array<int, 3> n{};
    for (int d = 0; d < 3; ++d) {
      const Axis& axis = grid.axis(d);
      const Interval cv = control_interval(axis, d == location, p[d]);
      // A one-cell periodic axis carries no variation: sample its midplane only.
      n[d] = axis.degenerate() ? 1 : options.subsamples;
      lo[d] = axis.degenerate() ? 0.5 * (cv.lo + cv.hi) : cv.lo;
      hi[d] = axis.degenerate() ? lo[d] : cv.hi;
    }
    const Eigen::Vector3d mid = 0.5 * (lo + hi);
    // The surface moved out by `offset` of the control volume's mean width.
    double grow = 0;
    if (options.offset > 0) {
      int spanned = 0;
      for (int d = 0; d < 3; ++d)
        if (!grid.axis(d).degenerate()) {
          grow += hi[d] - lo[d];
          ++spanned;
        }
      if (spanned > 0) grow *= options.offset / spanned;
    }
    const auto inside = [&](const Eigen::Vector3d& x) {
      return grow == 0 ? geometry::contains(body.shape, body.pose, x)
                       : geometry::signed_distance(body.shape, body.pose, x) <= grow;
    };
    if (options.subsamples == 1) {
      values.push_back(inside(mid) ? 1.0 : 0.0);
      return;
    }
    const double distance = geometry::signed_distance(body.shape, body.pose, mid) - grow;
    const double reach = 0.5 * (hi - lo).norm();
    if (std::abs(distance) > reach) {
      values.push_back(distance < 0 ? 1.0 : 0.0);
      return;
    }
    int count = 0;
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          const Eigen::Vector3d s(i + 0.5, j + 0.5, k + 0.5);
          const Eigen::Vector3d x = lo + (hi - lo).cwiseProduct(s.cwiseQuotient(Eigen::Vector3d(n[0], n[1], n[2])));
          count += inside(x) ? 1 : 0;
        }
    values.push_back(static_cast<double>(count) / (n[0] * n[1] * n[2]));
  });
  return {range, std::move(values)};
}

}  // namespace cosim::fluid::staircase
