#pragma once
// Ghosted copies of the three velocity components, with the ghost layer outside bounded
// faces filled from the boundary conditions, so that interpolation and convection
// stencils read the same way next to a boundary as in the interior.
#include <petscdmda.h>

#include <array>

#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"

namespace cosim::fluid::grid {

class LocalVelocity {
 public:
  explicit LocalVelocity(const Grid& grid);
  ~LocalVelocity();
  LocalVelocity(const LocalVelocity&) = delete;
  LocalVelocity& operator=(const LocalVelocity&) = delete;

  // Scatters the global components (with neighbours' values) and fills boundary ghosts for time t.
  void update(const std::array<Vec, 3>& global, const BoundaryConditions& bc, double t);
  double operator()(int c, const Index& p) const { return array_[static_cast<std::size_t>(c)][p[2]][p[1]][p[0]]; }

 private:
  void fill_boundary_ghosts(int c, PetscScalar*** u, const BoundaryConditions& bc, double t) const;
  void release();

  const Grid& grid_;
  std::array<Vec, 3> local_{};
  std::array<const PetscScalar***, 3> array_{};
};

}  // namespace cosim::fluid::grid
