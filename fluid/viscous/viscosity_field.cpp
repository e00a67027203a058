#include "fluid/viscous/viscosity_field.hpp"

#include <cmath>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::viscous {

using grid::Axis;
using grid::for_each_boundary_ghost;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::kCellCentre;
using grid::LocalVelocity;
using grid::shifted;

ViscosityField::ViscosityField(const Grid& grid, ViscosityModel model, double density)
    : grid_(grid), model_(model), density_(density), constant_(model(0.0) / density) {
  if (uniform()) return;
  COSIM_PETSC(DMCreateGlobalVector(grid.cell_dm(), &global_));
  COSIM_PETSC(DMCreateLocalVector(grid.cell_dm(), &local_));
}

ViscosityField::~ViscosityField() {
  if (array_) DMDAVecRestoreArrayRead(grid_.cell_dm(), local_, &array_);
  VecDestroy(&local_);
  VecDestroy(&global_);
}

void ViscosityField::update(const LocalVelocity& u) {
  if (uniform()) return;
  DM dm = grid_.cell_dm();
  if (array_) COSIM_PETSC(DMDAVecRestoreArrayRead(dm, local_, &array_));
  PetscScalar*** nu = nullptr;
  COSIM_PETSC(DMDAVecGetArray(dm, global_, &nu));
  for_each_index(grid_.owned(dm),
                 [&](const Index& m) { nu[m[2]][m[1]][m[0]] = model_(shear_rate(grid_, u, m)) / density_; });
  COSIM_PETSC(DMDAVecRestoreArray(dm, global_, &nu));
  COSIM_PETSC(DMGlobalToLocalBegin(dm, global_, INSERT_VALUES, local_));
  COSIM_PETSC(DMGlobalToLocalEnd(dm, global_, INSERT_VALUES, local_));
  // Beyond a bounded face the viscosity continues unchanged, so a wall edge takes the
  // viscosity of the cells beside it.
  COSIM_PETSC(DMDAVecGetArray(dm, local_, &nu));
  for_each_boundary_ghost(grid_, dm, kCellCentre, [&](const Index& g, const Index& in, int, bool) {
    nu[g[2]][g[1]][g[0]] = nu[in[2]][in[1]][in[0]];
  });
  COSIM_PETSC(DMDAVecRestoreArray(dm, local_, &nu));
  COSIM_PETSC(DMDAVecGetArrayRead(dm, local_, &array_));
}

double ViscosityField::at_cell(const Index& cell) const {
  return uniform() ? constant_ : array_[cell[2]][cell[1]][cell[0]];
}

double ViscosityField::at_edge(int c, int d, const Index& p, PetscInt j) const {
  if (uniform()) return constant_;
  Index cell = p;
  cell[d] = j;
  const Index below_c = shifted(cell, c, -1);
  return 0.25 * (at_cell(cell) + at_cell(below_c) + at_cell(shifted(cell, d, -1)) + at_cell(shifted(below_c, d, -1)));
}

double shear_rate(const Grid& grid, const LocalVelocity& u, const Index& cell) {
  double sum = 0;  // D:D
  for (int c = 0; c < 3; ++c) {
    const Axis& ac = grid.axis(c);
    if (!ac.degenerate()) {
      const double normal = (u(c, shifted(cell, c, 1)) - u(c, cell)) / ac.width(static_cast<int>(cell[c]));
      sum += normal * normal;
    }
    for (int d = c + 1; d < 3; ++d) {
      const Axis& ad = grid.axis(d);
      double shear = 0;
      for (PetscInt a = cell[c]; a <= cell[c] + 1; ++a)
        for (PetscInt b = cell[d]; b <= cell[d] + 1; ++b) {
          Index q = cell;
          q[c] = a;
          q[d] = b;
          const int ia = static_cast<int>(a), ib = static_cast<int>(b);
          if (!ad.degenerate()) shear += (u(c, q) - u(c, shifted(q, d, -1))) / (ad.centre(ib) - ad.centre(ib - 1));
          if (!ac.degenerate()) shear += (u(d, q) - u(d, shifted(q, c, -1))) / (ac.centre(ia) - ac.centre(ia - 1));
        }
      shear *= 0.125;  // mean over four edges of (du_c/dx_d + du_d/dx_c) / 2
      sum += 2 * shear * shear;
    }
  }
  return std::sqrt(2 * sum);
}

}  // namespace cosim::fluid::viscous
