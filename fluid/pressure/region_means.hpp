#pragma once
// The null space of the pressure operator among bodies: phi is free up to a constant on
// each region of ConnectedCells that no outflow pins. As a MatNullSpace function, removing
// it means taking each region's mean out of a vector: one sweep and one Allreduce however
// many regions there are. A bed of beads can close many pockets, and one constant vector
// per region would cost a sweep each in every Krylov iteration.
#include <petscmat.h>

#include <vector>

#include "fluid/grid/grid.hpp"
#include "fluid/pressure/connected_cells.hpp"

namespace cosim::fluid::pressure {

class RegionMeans {
 public:
  // Collective: the regions of `connected` but the outflow's, on the pressure DM.
  void update(const grid::Grid& grid, const ConnectedCells& connected);
  bool empty() const { return cells_.empty(); }
  // Subtracts from x, a global vector of the pressure DM, its mean over each region: the
  // Euclidean projection onto the complement of the regions' constants. Collective.
  void remove(Vec x) const;
  // A MatNullSpace whose removal is remove(); this object must outlive it.
  MatNullSpace null_space(MPI_Comm comm) const;

 private:
  // Owned cells [begin, end) in DMDA order, all of one region: the sums run over
  // contiguous stretches, as fast as a dot product, instead of scattering cell by cell.
  struct Run {
    std::size_t begin, end, region;
  };
  MPI_Comm comm_ = MPI_COMM_NULL;
  std::vector<Run> runs_;
  std::vector<double> cells_;  // per region: its cells over all ranks
};

}  // namespace cosim::fluid::pressure
