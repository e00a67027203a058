#include "fluid/bodies/control_volumes.hpp"

#include <algorithm>

namespace cosim::fluid::bodies {

using grid::Axis;
using grid::Box;
using grid::Grid;
using grid::Index;

namespace {

// First index in [lo, hi) for which pred is false; pred must be true then false.
template <typename Pred>
PetscInt partition_point(PetscInt lo, PetscInt hi, Pred pred) {
  while (lo < hi) {
    const PetscInt mid = lo + (hi - lo) / 2;
    if (pred(mid))
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

}  // namespace

double IndicatorPatch::operator()(const Index& p) const {
  std::size_t at = 0, stride = 1;
  for (int d = 0; d < 3; ++d) {
    if (p[d] < range_.lo[d] || p[d] >= range_.hi[d]) return 0;
    at += static_cast<std::size_t>(p[d] - range_.lo[d]) * stride;
    stride *= static_cast<std::size_t>(range_.hi[d] - range_.lo[d]);
  }
  return values_[at];
}

Box control_volumes_meeting(const Grid& grid, int location, const geometry::Aabb& box, const Box& within) {
  Box range = within;
  for (int d = 0; d < 3; ++d) {
    const Axis& axis = grid.axis(d);
    const bool face_axis = d == location;
    range.lo[d] = partition_point(within.lo[d], within.hi[d],
                                  [&](PetscInt i) { return control_interval(axis, face_axis, i).hi <= box.min[d]; });
    range.hi[d] = std::max(range.lo[d], partition_point(range.lo[d], within.hi[d], [&](PetscInt i) {
                             return control_interval(axis, face_axis, i).lo < box.max[d];
                           }));
  }
  return range;
}

}  // namespace cosim::fluid::bodies
