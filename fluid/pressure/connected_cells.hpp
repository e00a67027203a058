#pragma once
// The pressure cells a projection can correct, in regions joined through open faces
// (neither imposed by a body nor a wall): a region joined to an outflow, which fixes its
// level, and each region around cells that no body touches (the bulk fluid, and fluid that
// bodies close off from it), whose level is free: one vector of the null space each. Cells
// inside bodies, and slivers that bodies close against each other or a wall (spheres
// landing on a floor, touching beads) where every cell has an imposed face, are in none:
// the operator's row would be zero or, at best, a block without a right-hand side to
// balance, and the solve would diverge. Their correction is fixed at zero instead.
#include <type_traits>
#include <vector>

#include <petscsys.h>

#include "fluid/bodies/imposed_faces.hpp"
#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"

namespace cosim::fluid::pressure {

class ConnectedCells {
 public:
  // Labels are global cell numbers, which a double holds exactly.
  static_assert(std::is_same_v<PetscScalar, double>);
  static constexpr double kOutflowRegion = 1;

  // Collective. Each region takes the smallest label of its seeds: kOutflowRegion on an
  // outflow face, the cell's own number on a cell with no face imposed; labels spread by
  // sweeps over open faces, exchanging ghosts until nothing changes.
  void update(const grid::Grid& grid, const grid::BoundaryConditions& bc, const bodies::ImposedFaces& imposed);
  double region(const grid::Index& cell) const;  // an owned cell's label; 0: in none
  // Every rank's labels (not 0), ascending: the same list on every rank.
  const std::vector<double>& regions() const { return regions_; }

 private:
  grid::Box owned_{};
  std::vector<double> labels_;
  std::vector<double> regions_;
};

}  // namespace cosim::fluid::pressure
