#include "fluid/navier_stokes/step_arrays.hpp"

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::navier_stokes {

using grid::Grid;

StepArrays::StepArrays(const Grid& grid, const std::array<Vec, 3>& rhs, bool with_estimate) : grid_(grid), rhs_(rhs) {
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    COSIM_PETSC(DMDAVecGetArray(dm, rhs_[c], &arrays_.rhs[c]));
    if (!with_estimate) continue;
    COSIM_PETSC(DMGetGlobalVector(dm, &estimate_[c]));
    COSIM_PETSC(DMDAVecGetArray(dm, estimate_[c], &arrays_.predicted[c]));
  }
}

// PETSc reports a failure here itself; a destructor must not throw.
StepArrays::~StepArrays() {
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    DMDAVecRestoreArray(dm, rhs_[c], &arrays_.rhs[c]);
    if (!estimate_[c]) continue;
    DMDAVecRestoreArray(dm, estimate_[c], &arrays_.predicted[c]);
    DMRestoreGlobalVector(dm, &estimate_[c]);
  }
}

}  // namespace cosim::fluid::navier_stokes
