#include "fluid/pressure/pressure_solver.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/grid/mac_operators.hpp"
#include "fluid/petsc_check.hpp"
#include "fluid/pressure/cell_faces.hpp"
#include "fluid/transforms/solver_choice.hpp"

namespace cosim::fluid::pressure {

using bodies::ImposedFaces;
using grid::BoundaryConditions;
using grid::BoundaryKind;
using grid::Box;
using grid::divergence;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::LocalVelocity;
using transforms::use_transforms;

PressureSolver::PressureSolver(const Grid& grid, const BoundaryConditions& bc) : grid_(grid), bc_(bc) {
  create_or_release(
      [this] {
        update_null_space();
        COSIM_PETSC(DMCreateGlobalVector(grid_.pressure_dm(), &rhs_));
        transforms_ = use_transforms(
            "pressure", FastPoisson::applies(grid_) ? "" : "needs uniform x and y axes; this grid stretches one");
        if (!transforms_) create_krylov();  // a bad -pressure_* option fails here
      },
      [this] { release(); });
}

void PressureSolver::create_krylov() {
  const Grid& grid = grid_;
  COSIM_PETSC(KSPCreate(grid.comm(), &ksp_));
  COSIM_PETSC(KSPSetOptionsPrefix(ksp_, "pressure_"));
  COSIM_PETSC(KSPSetDM(ksp_, grid.pressure_dm()));
  COSIM_PETSC(KSPSetComputeOperators(ksp_, compute_operator, this));
  COSIM_PETSC(KSPSetType(ksp_, KSPCG));
  PC pc;
  COSIM_PETSC(KSPGetPC(ksp_, &pc));
  COSIM_PETSC(PCSetType(pc, PCGAMG));
  // Moving bodies change the operator: an aggregation built for the old one can make the
  // preconditioner indefinite (seen as DIVERGED_INDEFINITE_PC), so rebuild it.
  COSIM_PETSC(PCGAMGSetReuseInterpolation(pc, PETSC_FALSE));
  COSIM_PETSC(KSPSetTolerances(ksp_, 1e-10, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
  COSIM_PETSC(KSPSetFromOptions(ksp_));
}

PressureSolver::~PressureSolver() { release(); }

void PressureSolver::release() {
  fast_.reset();
  VecDestroy(&rhs_);
  KSPDestroy(&ksp_);
  MatNullSpaceDestroy(&constants_);
}

// Rows are the divergence of the face gradients times minus the cell volume, which makes
// the matrix symmetric positive (semi-)definite on stretched grids too.
PetscErrorCode PressureSolver::compute_operator(KSP ksp, Mat, Mat P, void* self) {
  PetscFunctionBeginUser;
  auto& s = *static_cast<PressureSolver*>(self);
  ++s.assemblies_;
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
  const ImposedFaces* imposed = s.imposed_;
  // Called again whenever the imposed faces change: start from zero, as values are added.
  PetscCall(MatZeroEntries(P));
  for_each_index(owned, [&](const Index& m) {
    if (status) return;
    MatStencil row{m[2], m[1], m[0], 0};
    MatStencil cols[7];
    PetscScalar vals[7];
    int n = 0;
    double diagonal = 0;
    // A closed cell keeps phi = 0 (identity row, scaled like its neighbours).
    const bool enclosed = s.closed(m);
    for_each_cell_face(grid, m, [&](const CellFace& f) {
      if (f.boundary) {
        if (s.bc_.at(f.axis, f.side).kind == BoundaryKind::outflow) diagonal += f.area / f.distance;
        return;
      }
      const double coupling = f.area / f.distance;
      if (enclosed) {
        diagonal += coupling;
        return;
      }
      // An imposed face is a wall for the projection: no flux through it is corrected.
      if (imposed && imposed->contains(f.axis, f.face)) return;
      diagonal += coupling;
      cols[n] = {f.neighbour[2], f.neighbour[1], f.neighbour[0], 0};
      vals[n++] = -coupling;
    });
    cols[n] = row;
    vals[n++] = diagonal;
    // ADD: on a periodic axis of two cells both neighbours are the same cell.
    status = MatSetValuesStencil(P, 1, &row, n, cols, vals, ADD_VALUES);
  });
  PetscCall(status);
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetNullSpace(P, s.constants_));  // null: none, also in place of an earlier one
  PetscFunctionReturn(0);
}

// Cells inside bodies and slivers closed by them (ConnectedCells) keep phi = 0.
bool PressureSolver::closed(const Index& m) const { return imposed_ && connected_.region(m) == 0; }

// phi is fixed up to a constant on each region no outflow pins: without bodies the whole
// domain when it has no outflow, with them each region of ConnectedCells but the outflow's.
void PressureSolver::update_null_space() {
  COSIM_PETSC(MatNullSpaceDestroy(&constants_));
  if (!imposed_) {
    if (!bc_.has_outflow()) COSIM_PETSC(MatNullSpaceCreate(grid_.comm(), PETSC_TRUE, 0, nullptr, &constants_));
    return;
  }
  region_means_.update(grid_, connected_);
  // Every cell closed, or every region joined to an outflow: no null space.
  if (!region_means_.empty()) constants_ = region_means_.null_space(grid_.comm());
}

int PressureSolver::solve(const LocalVelocity& u_star, double dt, const ImposedFaces* imposed, Vec phi) {
  prepare(imposed);
  DM dm = grid_.pressure_dm();
  PetscScalar*** r = nullptr;
  COSIM_PETSC(DMDAVecGetArray(dm, rhs_, &r));
  for_each_index(grid_.owned(dm), [&](const Index& m) {
    r[m[2]][m[1]][m[0]] = closed(m) ? 0 : -grid_.cell_volume(m) * divergence(grid_, u_star, m) / dt;
  });
  COSIM_PETSC(DMDAVecRestoreArray(dm, rhs_, &r));
  return solve_assembled(phi);
}

int PressureSolver::solve(Vec divergence, Vec phi) {
  prepare(nullptr);
  DM dm = grid_.pressure_dm();
  PetscScalar*** r = nullptr;
  const PetscScalar*** d = nullptr;
  COSIM_PETSC(DMDAVecGetArray(dm, rhs_, &r));
  COSIM_PETSC(DMDAVecGetArrayRead(dm, divergence, &d));
  for_each_index(grid_.owned(dm),
                 [&](const Index& m) { r[m[2]][m[1]][m[0]] = -grid_.cell_volume(m) * d[m[2]][m[1]][m[0]]; });
  COSIM_PETSC(DMDAVecRestoreArrayRead(dm, divergence, &d));
  COSIM_PETSC(DMDAVecRestoreArray(dm, rhs_, &r));
  return solve_assembled(phi);
}

// Each solver is set up when first needed: the staircase's imposed faces on a grid the
// transforms could serve take the Krylov solver from their first step.
void PressureSolver::prepare(const ImposedFaces* imposed) {
  transforms_now_ = transforms_ && !imposed;
  if (transforms_now_ && !fast_) {
    fast_ = std::make_unique<FastPoisson>(grid_, bc_);
    ++assemblies_;
  }
  if (!transforms_now_ && !ksp_) create_or_release([this] { create_krylov(); }, [this] { KSPDestroy(&ksp_); });
  const int generation = imposed ? imposed->generation() : -1;
  if (imposed != imposed_ || generation != assembled_generation_) {
    imposed_ = imposed;
    assembled_generation_ = generation;
    if (imposed_) connected_.update(grid_, bc_, *imposed_);
    update_null_space();
    // Asks the KSP to call compute_operator again before the next solve.
    if (!transforms_now_) COSIM_PETSC(KSPSetComputeOperators(ksp_, compute_operator, this));
  }
}

int PressureSolver::solve_assembled(Vec phi) {
  // Closed or periodic domains: the discrete compatibility condition holds only up to
  // round-off, which the solver must not try to fit.
  if (constants_) COSIM_PETSC(MatNullSpaceRemove(constants_, rhs_));
  if (!transforms_now_) return solve_or_throw(ksp_, rhs_, phi, "pressure solve");
  fast_->solve(rhs_, phi);
  // The transforms leave phi's constant free: the Krylov solver's zero mean.
  if (constants_) COSIM_PETSC(MatNullSpaceRemove(constants_, phi));
  return 0;
}

}  // namespace cosim::fluid::pressure
