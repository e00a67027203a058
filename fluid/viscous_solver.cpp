#include "fluid/viscous_solver.hpp"

#include <string>
#include <vector>

#include "fluid/petsc_check.hpp"
#include "fluid/viscous_stencil.hpp"

namespace cosim::fluid {
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

ViscousSolver::ViscousSolver(const Grid& grid, const BoundaryConditions& bc) : grid_(grid), bc_(bc) {
  // A bad -viscous_* option fails here.
  create_or_release([this] { create(); }, [this] { release(); });
}

void ViscousSolver::create() {
  const Grid& grid = grid_;
  for (int c = 0; c < 3; ++c) {
    matrix_[c] = star_matrix(grid.velocity_dm(c));
    // Imposed rows are zeroed and later refilled: keep their preallocated entries.
    COSIM_PETSC(MatSetOption(matrix_[c], MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));
    COSIM_PETSC(KSPCreate(grid.comm(), &ksp_[c]));
    COSIM_PETSC(KSPSetOptionsPrefix(ksp_[c], "viscous_"));
    COSIM_PETSC(KSPSetType(ksp_[c], KSPGMRES));
    // SOR needs no storage beyond the matrix, where ILU(0), PETSc's default, keeps a copy:
    // 0.26 KB per cell less at the same speed and iterations (fluid/README.md, Throughput).
    PC pc;
    COSIM_PETSC(KSPGetPC(ksp_[c], &pc));
    COSIM_PETSC(PCSetType(pc, PCSOR));
    COSIM_PETSC(KSPSetTolerances(ksp_[c], 1e-10, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
    // The previous step's velocity is a good first guess.
    COSIM_PETSC(KSPSetInitialGuessNonzero(ksp_[c], PETSC_TRUE));
    COSIM_PETSC(KSPSetFromOptions(ksp_[c]));
  }
}

ViscousSolver::~ViscousSolver() { release(); }

void ViscousSolver::release() {
  for (int c = 0; c < 3; ++c) {
    KSPDestroy(&ksp_[c]);
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
  const int generation = imposed ? imposed->generation() : -1;
  if (s != assembled_for_[c] || !nu.uniform() || generation != assembled_generation_[c]) assemble(c, s, nu, imposed);
  return solve_or_throw(ksp_[c], rhs, x, "viscous solve for velocity component " + std::to_string(c));
}

}  // namespace cosim::fluid
