#pragma once
// A body's volume fraction in the control volumes of one kind of grid point, from the signed
// distance phi at the corners of each of a control volume's 2 x 2 x 2 halves (Kempe &
// Froehlich, J. Comput. Phys. 231 (2012) 3663, eq. 30, on each half, averaged):
//   alpha = sum_m -phi_m H(-phi_m) / sum_m |phi_m|,
// exact for a plane parallel to a face of the box and otherwise close to the cut volume,
// and, unlike a count of sub-samples, continuous in the body's pose: the
// immersed boundary's inner-fluid momentum int alpha u dV, whose rate of change is part of
// the body's force, then changes smoothly as the body moves across the grid.
#include <span>
#include <vector>

#include "fluid/bodies/control_volumes.hpp"
#include "fluid/bodies/rigid_body.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/ibm/body_distance.hpp"

namespace cosim::fluid::ibm {

// From the corners' signed distances (negative inside); 1 when all are zero.
double level_set_fraction(std::span<const double> phi);

// alpha at the points of `location` (a velocity component or kCellCentre) in `within`
// whose control volumes meet the body's bounding box, with the body's distance as the
// grid sees it; zero elsewhere. On a one-cell periodic axis the control volume's midplane
// stands for it.
bodies::IndicatorPatch volume_fraction(const grid::Grid& grid, int location, const bodies::RigidBody& body,
                                       const BodyDistance& distance, const grid::Box& within);

// The shifts by whole periods along the periodic axes that make `box` meet `target`: none
// if no shift does; along the other axes zero, where the two must meet as they are, and
// zero everywhere for an unbounded box or target (a container meets everything).
std::vector<Eigen::Vector3d> periodic_shifts(const grid::Grid& grid, const geometry::Aabb& box,
                                             const geometry::Aabb& target);

// The fractions of the body and of its images whole periods away along the periodic axes
// (a fixed body may reach across a periodic face, and the part beyond it lies at the
// opposite face) at the points of `within` they reach: one patch per image, with the
// image's shift from the body.
struct FractionImage {
  bodies::IndicatorPatch patch;
  Eigen::Vector3d shift;
};
std::vector<FractionImage> volume_fractions(const grid::Grid& grid, int location, const bodies::RigidBody& body,
                                            const BodyDistance& distance, const grid::Box& within);

}  // namespace cosim::fluid::ibm
