#include "fluid/ibm/forcing_system.hpp"

#include <algorithm>
#include <exception>

#include "fluid/ibm/summed_rows.hpp"
#include "fluid/navier_stokes/step_stages.hpp"
#include "fluid/petsc_check.hpp"

namespace cosim::fluid::ibm {

using navier_stokes::forcing_iteration_event;

PetscInt roots_by_body(MPI_Comm comm, std::span<const std::size_t> first_marker) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const std::size_t markers = first_marker.empty() ? 0 : first_marker.back();
  // Rank r's first value: that of the first body starting at or after r / size of them.
  const auto start = [&](int r) -> std::size_t {
    if (r >= size || first_marker.empty()) return 3 * markers;
    const std::size_t even =
        (markers * static_cast<std::size_t>(r) + static_cast<std::size_t>(size) - 1) / static_cast<std::size_t>(size);
    return 3 * *std::lower_bound(first_marker.begin(), first_marker.end(), even);
  };
  return static_cast<PetscInt>(start(rank + 1) - start(rank));
}

namespace {

struct Test {
  double tolerance;
  Vec t, v;  // KSPBuildResidual's work vectors
};

// Converged where the largest miss at a marker is within the tolerance: the true residual's
// maximum norm, as the no-slip is stated per marker. Each iteration is counted in
// FluidForcingIteration's log event (bench/particulate reads the count).
PetscErrorCode converged(KSP ksp, PetscInt it, PetscReal, KSPConvergedReason* reason, void* context) {
  PetscFunctionBeginUser;
  const Test* test = static_cast<const Test*>(context);
  if (it > 0) {
    PetscCall(PetscLogEventBegin(forcing_iteration_event(), 0, 0, 0, 0));
    PetscCall(PetscLogEventEnd(forcing_iteration_event(), 0, 0, 0, 0));
  }
  Vec r = nullptr;
  PetscCall(KSPBuildResidual(ksp, test->t, test->v, &r));
  PetscReal largest = 0;
  PetscCall(VecNorm(r, NORM_INFINITY, &largest));
  *reason = largest <= test->tolerance ? KSP_CONVERGED_ATOL : KSP_CONVERGED_ITERATING;
  PetscFunctionReturn(0);
}

// The preconditioner: each body's block solved on its own. An exception must not cross
// PETSc's C frames: it becomes PETSc's error, which KSPSolve returns.
PetscErrorCode apply_blocks(PC pc, Vec x, Vec y) {
  PetscFunctionBeginUser;
  void* context = nullptr;
  PetscCall(PCShellGetContext(pc, &context));
  try {
    static_cast<const BodyBlockSolvers*>(context)->apply(x, y);
  } catch (const std::exception& e) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", e.what());
  }
  PetscFunctionReturn(0);
}

}  // namespace

ForcingSystem::ForcingSystem(const MarkerStencils& stencils, const MarkerStencils& spreading,
                             std::span<const std::size_t> first_marker, BodyBlockSolvers& blocks)
    : stencils_(stencils) {
  const MarkerSharing& sharing = stencils.sharing();
  // A value no rank holds (a marker inside another body or outside the domain) has the
  // identity's row.
  B_ = summed_rows(sharing.comm(), sharing.roots(), stencils.products(spreading));
  COSIM_PETSC(MatCreateVecs(B_, &g_, &rhs_));
  COSIM_PETSC(VecDuplicate(g_, &work_));
  COSIM_PETSC(VecDuplicate(g_, &left_));

  COSIM_PETSC(KSPCreate(sharing.comm(), &ksp_));
  COSIM_PETSC(KSPSetOptionsPrefix(ksp_, "ibm_forcing_"));
  const bool symmetric = &spreading == &stencils;
  COSIM_PETSC(KSPSetType(ksp_, symmetric ? KSPCG : KSPGMRES));
  COSIM_PETSC(KSPSetOperators(ksp_, B_, B_));
  PC pc = nullptr;
  COSIM_PETSC(KSPGetPC(ksp_, &pc));
  COSIM_PETSC(PCSetType(pc, PCSHELL));
  COSIM_PETSC(PCShellSetName(pc, "each body's block solved on its own"));
  COSIM_PETSC(PCShellSetContext(pc, &blocks));
  COSIM_PETSC(PCShellSetApply(pc, apply_blocks));
  COSIM_PETSC(KSPSetFromOptions(ksp_));
  PetscBool shell = PETSC_FALSE;
  COSIM_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCSHELL, &shell));
  if (shell) blocks.update(B_, first_marker, symmetric);
  COSIM_PETSC(KSPSetUp(ksp_));
}

ForcingSystem::~ForcingSystem() {
  KSPDestroy(&ksp_);
  MatDestroy(&B_);
  for (Vec* v : {&rhs_, &g_, &work_, &left_}) VecDestroy(v);
}

int ForcingSystem::solve(std::vector<double>& g, std::vector<double>& residual, double tolerance,
                         int max_iterations) const {
  const MarkerSharing& sharing = stencils_.sharing();
  sharing.to_roots(residual, rhs_);
  sharing.to_roots(g, g_);
  Test test{tolerance, work_, left_};
  COSIM_PETSC(KSPSetConvergenceTest(ksp_, converged, &test, nullptr));
  COSIM_PETSC(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE));
  COSIM_PETSC(KSPSetTolerances(ksp_, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, max_iterations));
  COSIM_PETSC(KSPSolve(ksp_, rhs_, g_));
  PetscInt iterations = 0;
  COSIM_PETSC(KSPGetIterationNumber(ksp_, &iterations));
  // What is left: r - B g.
  COSIM_PETSC(MatMult(B_, g_, work_));
  COSIM_PETSC(VecAYPX(work_, -1.0, rhs_));
  sharing.from_roots(g_, g);
  sharing.from_roots(work_, residual);
  return static_cast<int>(iterations);
}

}  // namespace cosim::fluid::ibm
