#pragma once
// The control volume of a grid point, by kind of point: the cell for cell centres and for
// the faces of other components; for a face of component d, along d the span between the
// two cell centres it separates. Both body treatments measure a body's share of them.
#include "fluid/grid.hpp"
#include "geometry/aabb.hpp"

namespace cosim::fluid {

struct Interval {
  double lo, hi;
};

inline Interval control_interval(const Axis& axis, bool face_axis, PetscInt i) {
  const int n = static_cast<int>(i);
  return face_axis ? Interval{axis.centre(n - 1), axis.centre(n)} : Interval{axis.face(n), axis.face(n + 1)};
}

// The points of `location` (a velocity component or kCellCentre) within `within` whose
// control volumes meet `box`, found by binary search on each axis.
Box control_volumes_meeting(const Grid& grid, int location, const geometry::Aabb& box, const Box& within);

}  // namespace cosim::fluid
