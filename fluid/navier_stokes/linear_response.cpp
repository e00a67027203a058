#include "fluid/navier_stokes/linear_response.hpp"

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::navier_stokes {

using grid::Grid;

LinearResponse::LinearResponse(const Grid& grid, Solve solve) : grid_(grid), solve_(std::move(solve)) {}

void LinearResponse::open() {
  if (open_) return;
  open_ = true;
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    COSIM_PETSC(DMGetGlobalVector(dm, &rhs_[c]));
    COSIM_PETSC(DMGetGlobalVector(dm, &change_[c]));
    COSIM_PETSC(VecZeroEntries(rhs_[c]));
    COSIM_PETSC(DMDAVecGetArray(dm, rhs_[c], &rhs_arrays_[c]));
  }
}

// PETSc reports a failure here itself; a destructor must not throw.
LinearResponse::~LinearResponse() {
  if (!open_) return;
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    if (change_arrays_[c]) DMDAVecRestoreArray(dm, change_[c], &change_arrays_[c]);
    DMDAVecRestoreArray(dm, rhs_[c], &rhs_arrays_[c]);
    DMRestoreGlobalVector(dm, &rhs_[c]);
    DMRestoreGlobalVector(dm, &change_[c]);
  }
}

void LinearResponse::close_change() {
  for (int c = 0; c < 3; ++c)
    if (change_arrays_[c]) COSIM_PETSC(DMDAVecRestoreArray(grid_.velocity_dm(c), change_[c], &change_arrays_[c]));
  change_arrays_ = {};
}

const std::array<PetscScalar***, 3>& LinearResponse::rhs() {
  open();
  return rhs_arrays_;
}

void LinearResponse::run(bool keep) {
  open();
  close_change();
  for (int c = 0; c < 3; ++c) COSIM_PETSC(DMDAVecRestoreArray(grid_.velocity_dm(c), rhs_[c], &rhs_arrays_[c]));
  solve_(rhs_, change_, keep);
  for (int c = 0; c < 3; ++c) {
    COSIM_PETSC(VecZeroEntries(rhs_[c]));
    COSIM_PETSC(DMDAVecGetArray(grid_.velocity_dm(c), rhs_[c], &rhs_arrays_[c]));
  }
}

const std::array<PetscScalar***, 3>& LinearResponse::change() {
  run(false);
  for (int c = 0; c < 3; ++c) COSIM_PETSC(DMDAVecGetArray(grid_.velocity_dm(c), change_[c], &change_arrays_[c]));
  return change_arrays_;
}

void LinearResponse::apply() { run(true); }

}  // namespace cosim::fluid::navier_stokes
