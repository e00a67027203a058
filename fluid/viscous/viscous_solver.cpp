#include "fluid/viscous/viscous_solver.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "fluid/petsc_check.hpp"
#include "fluid/transforms/solver_choice.hpp"
#include "fluid/viscous/viscous_stencil.hpp"

namespace cosim::fluid::viscous {

using bodies::ImposedFace;
using bodies::ImposedFaces;
using grid::BoundaryConditions;
using grid::BoundaryKind;
using grid::Box;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::shifted;
using grid::Side;
using transforms::use_transforms;

namespace {

// The implicit operator is a 7-point star, but the velocity DMDAs have a box stencil
// (convection reads diagonal neighbours), and DMCreateMatrix preallocates and fills all 27
// points of the box, which the ILU factor then copies. A star twin of the DMDA (same sizes
// and partition) gives the matrix, and with it the factor, the star's pattern: about a
// third of the storage. The matrix keeps its own reference to the twin.
Mat star_matrix(DM box) {
  PetscInt dim, size[3], ranks[3], dof, width;
  DMBoundaryType boundary[3];
  DMDAStencilType stencil;
  COSIM_PETSC(DMDAGetInfo(box, &dim, &size[0], &size[1], &size[2], &ranks[0], &ranks[1], &ranks[2], &dof, &width,
                          &boundary[0], &boundary[1], &boundary[2], &stencil));
  const PetscInt *own_x, *own_y, *own_z;
  COSIM_PETSC(DMDAGetOwnershipRanges(box, &own_x, &own_y, &own_z));
  MPI_Comm comm;
  COSIM_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(box), &comm));
  DM star = nullptr;
  COSIM_PETSC(DMDACreate3d(comm, boundary[0], boundary[1], boundary[2], DMDA_STENCIL_STAR, size[0], size[1], size[2],
                           ranks[0], ranks[1], ranks[2], dof, width, own_x, own_y, own_z, &star));
  COSIM_PETSC(DMSetUp(star));
  Mat matrix = nullptr;
  COSIM_PETSC(DMCreateMatrix(star, &matrix));
  COSIM_PETSC(DMDestroy(&star));
  return matrix;
}

}  // namespace

ViscousSolver::ViscousSolver(const Grid& grid, const BoundaryConditions& bc, const UniformViscousWeights* weights)
    : grid_(grid), bc_(bc), weights_(weights) {
  // A misspelt -viscous_* option fails here; a preconditioner the stencil operator cannot
  // serve, at the first solve.
  create_or_release(
      [this] {
        std::string obstacle;
        if (!weights_)
          obstacle = "needs a uniform (Newtonian) viscosity";
        else if (!FastViscous::applies(grid_))
          obstacle = "needs uniform x and y axes; this grid stretches one";
        if (use_transforms("viscous", obstacle)) fast_ = std::make_unique<FastViscous>(grid_, bc_, *weights_);
        // The Krylov path too: for solves with imposed faces, and so a bad -viscous_*
        // option fails here either way.
        create();
      },
      [this] { release(); });
}

void ViscousSolver::create() {
  const Grid& grid = grid_;
  for (int c = 0; c < 3; ++c) {
    DM dm = grid.velocity_dm(c);
    PetscInt local = 0;
    if (weights_) {
      Operator& op = operators_[static_cast<std::size_t>(c)];
      op = {this, c, 0, nullptr, nullptr};
      COSIM_PETSC(DMCreateLocalVector(dm, &op.local));
      Vec global;
      COSIM_PETSC(DMGetGlobalVector(dm, &global));
      COSIM_PETSC(VecGetLocalSize(global, &local));
      COSIM_PETSC(DMRestoreGlobalVector(dm, &global));
      COSIM_PETSC(MatCreateShell(grid.comm(), local, local, PETSC_DETERMINE, PETSC_DETERMINE, &op, &matrix_[c]));
      COSIM_PETSC(MatShellSetOperation(matrix_[c], MATOP_MULT, reinterpret_cast<void (*)(void)>(multiply)));
      COSIM_PETSC(MatShellSetOperation(matrix_[c], MATOP_GET_DIAGONAL, reinterpret_cast<void (*)(void)>(diagonal)));
    } else {
      matrix_[c] = star_matrix(dm);
      // Imposed rows are zeroed and later refilled: keep their preallocated entries.
      COSIM_PETSC(MatSetOption(matrix_[c], MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));
    }
    COSIM_PETSC(KSPCreate(grid.comm(), &ksp_[c]));
    COSIM_PETSC(KSPSetOptionsPrefix(ksp_[c], "viscous_"));
    // SOR needs no storage beyond the matrix, where ILU(0), PETSc's default, keeps a copy:
    // 0.26 KB per cell less at the same speed and iterations (bench/fluid_throughput/README.md).
    // Without a matrix, Jacobi, which needs more iterations; GMRES restarted after 4 keeps 6
    // vectors where 30 keeps up to 32, and was as fast on the cavity and on Hasimoto's
    // array at nu dt / h^2 = 1 (bench/fluid_throughput/README.md). BiCGStab, with fewer still,
    // broke down on the staircase's identity rows.
    COSIM_PETSC(KSPSetType(ksp_[c], KSPGMRES));
    if (weights_) COSIM_PETSC(KSPGMRESSetRestart(ksp_[c], 4));
    PC pc;
    COSIM_PETSC(KSPGetPC(ksp_[c], &pc));
    COSIM_PETSC(PCSetType(pc, weights_ ? PCJACOBI : PCSOR));
    COSIM_PETSC(KSPSetTolerances(ksp_[c], 1e-10, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
    // The previous step's velocity is a good first guess.
    COSIM_PETSC(KSPSetInitialGuessNonzero(ksp_[c], PETSC_TRUE));
    COSIM_PETSC(KSPSetFromOptions(ksp_[c]));
  }
}

ViscousSolver::~ViscousSolver() { release(); }

void ViscousSolver::release() {
  fast_.reset();
  for (int c = 0; c < 3; ++c) {
    KSPDestroy(&ksp_[c]);
    VecDestroy(&operators_[static_cast<std::size_t>(c)].local);
    MatDestroy(&matrix_[c]);
  }
}

void ViscousSolver::assemble(int c, double s, const ViscosityField& nu, const ImposedFaces* imposed) {
  Mat A = matrix_[c];
  COSIM_PETSC(MatZeroEntries(A));
  for_each_index(grid_.owned(grid_.velocity_dm(c)), [&](const Index& p) {
    MatStencil row{p[2], p[1], p[0], 0};
    MatStencil cols[13];
    PetscScalar vals[13];
    int n = 0;
    if (grid_.on_boundary(c, p)) {
      const bool lower = p[c] == 0;
      cols[n] = row;
      vals[n++] = 1;
      if (bc_.at(c, lower ? Side::lower : Side::upper).kind == BoundaryKind::outflow) {
        const Index inside = shifted(p, c, lower ? 1 : -1);
        cols[n] = {inside[2], inside[1], inside[0], 0};
        vals[n++] = -1;
      }
    } else {
      const Stencil st = viscous_stencil(grid_, bc_, nu, c, p, 0.0);
      for (int e = 0; e < st.size; ++e) {
        const Index& at = st.entries[static_cast<std::size_t>(e)].at;
        cols[n] = {at[2], at[1], at[0], 0};
        vals[n++] = -s * st.entries[static_cast<std::size_t>(e)].weight;
      }
      cols[n] = row;
      vals[n++] = 1;
    }
    COSIM_PETSC(MatSetValuesStencil(A, 1, &row, n, cols, vals, ADD_VALUES));
  });
  COSIM_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  COSIM_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  std::vector<MatStencil> rows;
  if (imposed)
    for (const ImposedFace& f : imposed->owned(c)) rows.push_back({f.at[2], f.at[1], f.at[0], 0});
  COSIM_PETSC(MatZeroRowsStencil(A, static_cast<PetscInt>(rows.size()), rows.data(), 1.0, nullptr, nullptr));
  COSIM_PETSC(KSPSetOperators(ksp_[c], A, A));
  assembled_for_[c] = s;
  assembled_generation_[c] = imposed ? imposed->generation() : -1;
}

int ViscousSolver::solve(int c, double s, const ViscosityField& nu, const ImposedFaces* imposed, Vec rhs, Vec x) {
  if (fast_ && !imposed) {
    fast_->solve(c, s, rhs, x);
    return 0;
  }
  const int generation = imposed ? imposed->generation() : -1;
  const bool changed = s != assembled_for_[c] || generation != assembled_generation_[c];
  if (weights_ && changed) {
    Operator& op = operators_[static_cast<std::size_t>(c)];
    op.s = s;
    op.imposed = imposed;
    // A new operator for the KSP: its preconditioner's diagonal is taken again.
    COSIM_PETSC(MatAssemblyBegin(matrix_[c], MAT_FINAL_ASSEMBLY));
    COSIM_PETSC(MatAssemblyEnd(matrix_[c], MAT_FINAL_ASSEMBLY));
    COSIM_PETSC(KSPSetOperators(ksp_[c], matrix_[c], matrix_[c]));
    assembled_for_[c] = s;
    assembled_generation_[c] = generation;
  } else if (!weights_ && (changed || !nu.uniform())) {
    assemble(c, s, nu, imposed);
  }
  return solve_or_throw(ksp_[c], rhs, x, "viscous solve for velocity component " + std::to_string(c));
}

// y = (I - s L) x row by row as assemble() would build the rows from the same weights:
// boundary faces hold their value (an outflow's equals the face inside), imposed faces too.
// The weights across x are listed per face, those across y and z are constant along a
// row: the inner loop reads seven neighbours and streams.
PetscErrorCode ViscousSolver::multiply(Mat A, Vec x, Vec y) {
  PetscFunctionBeginUser;
  Operator* op = nullptr;
  PetscCall(MatShellGetContext(A, &op));
  const ViscousSolver& self = *op->solver;
  const Grid& grid = self.grid_;
  const UniformViscousWeights& weights = *self.weights_;
  const int c = op->c;
  DM dm = grid.velocity_dm(c);
  PetscCall(DMGlobalToLocalBegin(dm, x, INSERT_VALUES, op->local));
  PetscCall(DMGlobalToLocalEnd(dm, x, INSERT_VALUES, op->local));
  const PetscScalar*** u = nullptr;
  PetscScalar*** out = nullptr;
  PetscCall(DMDAVecGetArrayRead(dm, op->local, &u));
  PetscCall(DMDAVecGetArray(dm, y, &out));
  const auto boundary_row = [&](const Index& p) {
    const bool lower = p[c] == 0;
    double value = u[p[2]][p[1]][p[0]];
    if (self.bc_.at(c, lower ? Side::lower : Side::upper).kind == BoundaryKind::outflow) {
      const Index inside = shifted(p, c, lower ? 1 : -1);
      value -= u[inside[2]][inside[1]][inside[0]];
    }
    out[p[2]][p[1]][p[0]] = value;
  };
  const double s = op->s;
  const Box box = grid.owned(dm);
  const ViscousWeights* across_x = &weights.at(c, 0, 0);
  // On its own bounded axis a component's first and last faces are boundary rows.
  Index first = box.lo, last = box.hi;
  if (!grid.axis(c).periodic()) {
    first[c] = std::max<PetscInt>(first[c], 1);
    last[c] = std::min<PetscInt>(last[c], grid.axis(c).cells());
  }
  for (PetscInt k = box.lo[2]; k < box.hi[2]; ++k)
    for (PetscInt j = box.lo[1]; j < box.hi[1]; ++j) {
      if (k < first[2] || k >= last[2] || j < first[1] || j >= last[1]) {
        for (PetscInt i = box.lo[0]; i < box.hi[0]; ++i) boundary_row({i, j, k});
        continue;
      }
      const ViscousWeights& wy = weights.at(c, 1, j);
      const ViscousWeights& wz = weights.at(c, 2, k);
      const PetscScalar* row = u[k][j];
      const PetscScalar *south = u[k][j - 1], *north = u[k][j + 1], *down = u[k - 1][j], *up = u[k + 1][j];
      PetscScalar* result = out[k][j];
      for (PetscInt i = first[0]; i < last[0]; ++i) {
        const SevenPoints points{row[i], {row[i - 1], south[i], down[i]}, {row[i + 1], north[i], up[i]}};
        result[i] = row[i] - s * weighted_sum(across_x[i], wy, wz, points);
      }
      for (PetscInt i = box.lo[0]; i < first[0]; ++i) boundary_row({i, j, k});
      for (PetscInt i = last[0]; i < box.hi[0]; ++i) boundary_row({i, j, k});
    }
  if (op->imposed)
    for (const ImposedFace& f : op->imposed->owned(c)) out[f.at[2]][f.at[1]][f.at[0]] = u[f.at[2]][f.at[1]][f.at[0]];
  PetscCall(DMDAVecRestoreArray(dm, y, &out));
  PetscCall(DMDAVecRestoreArrayRead(dm, op->local, &u));
  PetscFunctionReturn(0);
}

PetscErrorCode ViscousSolver::diagonal(Mat A, Vec d) {
  PetscFunctionBeginUser;
  Operator* op = nullptr;
  PetscCall(MatShellGetContext(A, &op));
  const ViscousSolver& self = *op->solver;
  const Grid& grid = self.grid_;
  const int c = op->c;
  DM dm = grid.velocity_dm(c);
  PetscScalar*** out = nullptr;
  PetscCall(DMDAVecGetArray(dm, d, &out));
  for_each_index(grid.owned(dm), [&](const Index& p) {
    double value = 1;
    if (!grid.on_boundary(c, p))
      for (int axis = 0; axis < 3; ++axis)
        if (!grid.axis(axis).degenerate()) value -= op->s * self.weights_->at(c, axis, p[axis]).centre;
    out[p[2]][p[1]][p[0]] = value;
  });
  if (op->imposed)
    for (const ImposedFace& f : op->imposed->owned(c)) out[f.at[2]][f.at[1]][f.at[0]] = 1;
  PetscCall(DMDAVecRestoreArray(dm, d, &out));
  PetscFunctionReturn(0);
}

}  // namespace cosim::fluid::viscous
