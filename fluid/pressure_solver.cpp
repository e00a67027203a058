#include "fluid/pressure_solver.hpp"

#include <cmath>

#include "fluid/mac_operators.hpp"
#include "fluid/petsc_check.hpp"

namespace cosim::fluid {

PressureSolver::PressureSolver(const Grid& grid, const BoundaryConditions& bc) : grid_(grid), bc_(bc) {
  // A bad -pressure_* option fails here.
  create_or_release([this] { create(); }, [this] { release(); });
}

void PressureSolver::create() {
  const Grid& grid = grid_;
  if (!bc_.has_outflow()) COSIM_PETSC(MatNullSpaceCreate(grid.comm(), PETSC_TRUE, 0, nullptr, &constants_));
  COSIM_PETSC(KSPCreate(grid.comm(), &ksp_));
  COSIM_PETSC(KSPSetOptionsPrefix(ksp_, "pressure_"));
  COSIM_PETSC(KSPSetDM(ksp_, grid.pressure_dm()));
  COSIM_PETSC(KSPSetComputeOperators(ksp_, compute_operator, this));
  COSIM_PETSC(KSPSetType(ksp_, KSPCG));
  PC pc;
  COSIM_PETSC(KSPGetPC(ksp_, &pc));
  COSIM_PETSC(PCSetType(pc, PCGAMG));
  COSIM_PETSC(KSPSetTolerances(ksp_, 1e-10, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
  COSIM_PETSC(KSPSetFromOptions(ksp_));
  COSIM_PETSC(DMCreateGlobalVector(grid.pressure_dm(), &rhs_));
}

PressureSolver::~PressureSolver() { release(); }

void PressureSolver::release() {
  VecDestroy(&rhs_);
  KSPDestroy(&ksp_);
  MatNullSpaceDestroy(&constants_);
}

// Rows are the divergence of the face gradients times minus the cell volume, which makes
// the matrix symmetric positive (semi-)definite on stretched grids too.
PetscErrorCode PressureSolver::compute_operator(KSP ksp, Mat, Mat P, void* self) {
  PetscFunctionBeginUser;
  auto& s = *static_cast<PressureSolver*>(self);
  const Grid& grid = s.grid_;
  DM dm;
  PetscCall(KSPGetDM(ksp, &dm));
  PetscCheck(dm == grid.pressure_dm(), grid.comm(), PETSC_ERR_SUP,
             "the pressure operator is assembled on the finest grid only: use Galerkin coarse operators "
             "(-pressure_pc_mg_galerkin pmat) with -pressure_pc_type mg");
  Box owned;
  PetscInt m_[3];
  PetscCall(DMDAGetCorners(dm, &owned.lo[0], &owned.lo[1], &owned.lo[2], &m_[0], &m_[1], &m_[2]));
  for (int d = 0; d < 3; ++d) owned.hi[d] = owned.lo[d] + m_[d];
  PetscErrorCode status = 0;
  for_each_index(owned, [&](const Index& m) {
    if (status) return;
    MatStencil row{m[2], m[1], m[0], 0};
    MatStencil cols[7];
    PetscScalar vals[7];
    int n = 0;
    double diagonal = 0;
    for (int d = 0; d < 3; ++d) {
      const Axis& a = grid.axis(d);
      if (a.degenerate()) continue;
      const int id = static_cast<int>(m[d]);
      const double area = grid.cell_volume(m) / a.width(id);
      for (Side side : {Side::lower, Side::upper}) {
        const bool at_boundary = !a.periodic() && (side == Side::lower ? id == 0 : id == a.cells() - 1);
        if (at_boundary) {
          if (s.bc_.at(d, side).kind == BoundaryKind::outflow)
            diagonal += area / (side == Side::lower ? a.centre(0) - a.lo() : a.hi() - a.centre(id));
          continue;
        }
        const int step = side == Side::lower ? -1 : 1;
        const double coupling = area / std::abs(a.centre(id + step) - a.centre(id));
        const Index nb = shifted(m, d, step);
        cols[n] = {nb[2], nb[1], nb[0], 0};
        vals[n++] = -coupling;
        diagonal += coupling;
      }
    }
    cols[n] = row;
    vals[n++] = diagonal;
    // ADD: on a periodic axis of two cells both neighbours are the same cell.
    status = MatSetValuesStencil(P, 1, &row, n, cols, vals, ADD_VALUES);
  });
  PetscCall(status);
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  if (s.constants_) PetscCall(MatSetNullSpace(P, s.constants_));
  PetscFunctionReturn(0);
}

int PressureSolver::solve(const LocalVelocity& u_star, double dt, Vec phi) {
  DM dm = grid_.pressure_dm();
  PetscScalar*** r = nullptr;
  COSIM_PETSC(DMDAVecGetArray(dm, rhs_, &r));
  for_each_index(grid_.owned(dm), [&](const Index& m) {
    r[m[2]][m[1]][m[0]] = -grid_.cell_volume(m) * divergence(grid_, u_star, m) / dt;
  });
  COSIM_PETSC(DMDAVecRestoreArray(dm, rhs_, &r));
  // Closed or periodic domains: the discrete compatibility condition holds only up to
  // round-off, which the solver must not try to fit.
  if (constants_) COSIM_PETSC(MatNullSpaceRemove(constants_, rhs_));
  return solve_or_throw(ksp_, rhs_, phi, "pressure solve");
}

}  // namespace cosim::fluid
