#include "fluid/grid/mac_operators.hpp"

#include <algorithm>
#include <cmath>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::grid {

double divergence(const Grid& grid, const LocalVelocity& u, const Index& cell) {
  double sum = 0;
  for (int d = 0; d < 3; ++d) {
    const Axis& a = grid.axis(d);
    if (a.degenerate()) continue;
    sum += (u(d, shifted(cell, d, 1)) - u(d, cell)) / a.width(static_cast<int>(cell[d]));
  }
  return sum;
}

const PetscScalar*** read_ghosted(DM pdm, Vec global, Vec local) {
  COSIM_PETSC(DMGlobalToLocalBegin(pdm, global, INSERT_VALUES, local));
  COSIM_PETSC(DMGlobalToLocalEnd(pdm, global, INSERT_VALUES, local));
  const PetscScalar*** array = nullptr;
  COSIM_PETSC(DMDAVecGetArrayRead(pdm, local, &array));
  return array;
}

double max_divergence(const Grid& grid, const LocalVelocity& u) {
  double local = 0;
  for_each_index(grid.owned(grid.pressure_dm()), [&](const Index& cell) {
    // Written so that a NaN wins: the callers check the result for a non-finite flow.
    const double d = std::abs(divergence(grid, u, cell));
    if (!(d <= local)) local = d;
  });
  double global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, grid.comm());
  return global;
}

double face_gradient(const Grid& grid, const BoundaryConditions& bc, const PetscScalar* const* const* q, int c,
                     const Index& p) {
  const Axis& a = grid.axis(c);
  if (a.degenerate()) return 0;
  const auto value = [q](const Index& cell) { return q[cell[2]][cell[1]][cell[0]]; };
  const int i = static_cast<int>(p[c]);
  if (grid.on_boundary(c, p)) {
    const Side side = i == 0 ? Side::lower : Side::upper;
    if (bc.at(c, side).kind != BoundaryKind::outflow) return 0;
    return side == Side::lower ? value(p) / (a.centre(0) - a.lo())
                               : -value(shifted(p, c, -1)) / (a.hi() - a.centre(i - 1));
  }
  return (value(p) - value(shifted(p, c, -1))) / (a.centre(i) - a.centre(i - 1));
}

}  // namespace cosim::fluid::grid
