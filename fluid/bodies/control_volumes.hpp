#pragma once
// The control volume of a grid point, by kind of point: the cell for cell centres and for
// the faces of other components; for a face of component d, along d the span between the
// two cell centres it separates. Both body treatments measure a body's share of them.
#include <vector>

#include "fluid/grid/grid.hpp"
#include "geometry/aabb.hpp"

namespace cosim::fluid::bodies {

struct Interval {
  double lo, hi;
};

inline Interval control_interval(const grid::Axis& axis, bool face_axis, PetscInt i) {
  const int n = static_cast<int>(i);
  return face_axis ? Interval{axis.centre(n - 1), axis.centre(n)} : Interval{axis.face(n), axis.face(n + 1)};
}

// A body's share of the control volumes of one kind of grid point over a box of them
// (zero outside it): what both body treatments measure.
class IndicatorPatch {
 public:
  IndicatorPatch(grid::Box range, std::vector<double> values) : range_(range), values_(std::move(values)) {}
  const grid::Box& range() const { return range_; }
  // Number of grid points the body was tested against.
  std::size_t tested() const { return values_.size(); }
  double operator()(const grid::Index& p) const;

 private:
  grid::Box range_;
  std::vector<double> values_;  // over range_, i fastest
};

// The points of `location` (a velocity component or kCellCentre) within `within` whose
// control volumes meet `box`, found by binary search on each axis.
grid::Box control_volumes_meeting(const grid::Grid& grid, int location, const geometry::Aabb& box,
                                  const grid::Box& within);

}  // namespace cosim::fluid::bodies
