// The projection without splitting error (PressureUpdate::exact).
//
// The projection u = u* - dt grad phi leaves a field that the implicit viscous step would
// have given with the pressure p + rho phi only where (I - theta dt L) and grad commute.
// Next to a no-slip wall they do not: on the first row of tangential faces the difference
// is a force of 2 theta (nu dt / h^2) grad phi, which slides the fluid along the wall by a
// few per cent of the wall-normal flow wherever the pressure changes quickly from step to
// step, as under a body closing on a wall (bench/fluid_accuracy/README.md "Sphere closing on a wall").
// Here phi solves the step's Schur complement instead,
//   dt div (I - theta dt L)^{-1} grad phi = div u*,
// and u = u* - dt (I - theta dt L)^{-1} grad phi, p += rho phi: the implicit step with the
// pressure p + rho phi, divergence-free. GMRES (options prefix `exact_pressure_`), right-
// preconditioned by the complement's inverse on a periodic grid (Cahouet & Chabard, Int. J.
// Numer. Meth. Fluids 8 (1988) 869),
//   phi = lap^{-1}(r) / dt - theta nu r,
// which is the rotational update and also the first guess; each iteration is one viscous
// solve per component and one pressure solve (the standard projection's cost per
// iteration). A standard projection then takes the divergence the Krylov tolerance leaves
// down to round-off.
#include <petscksp.h>

#include <array>
#include <stdexcept>
#include <string>

#include "fluid/grid/mac_operators.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"
#include "fluid/petsc_check.hpp"

namespace cosim::fluid::navier_stokes {

using grid::divergence;
using grid::face_gradient;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::read_ghosted;

namespace {

// What the Krylov solve's callbacks read.
struct Schur {
  NavierStokes* flow;
  double dt;
  std::array<Vec, 3> faces;  // scratch fields of the velocity DMs
};

}  // namespace

// The Krylov solve's callbacks, NavierStokes's friend. An exception must not cross PETSc's
// C frames: it becomes PETSc's error, which KSPSolve returns.
struct ExactProjection {
  static PetscErrorCode apply_schur(Mat A, Vec phi, Vec y) {
    PetscFunctionBeginUser;
    Schur* s = nullptr;
    PetscCall(MatShellGetContext(A, &s));
    try {
      s->flow->viscous_gradient(s->dt, phi, s->faces);
      s->flow->divergence_of(s->faces, y);
    } catch (const std::exception& e) {
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", e.what());
    }
    PetscFunctionReturn(0);
  }
  static PetscErrorCode apply_cahouet_chabard(PC pc, Vec r, Vec phi) {
    PetscFunctionBeginUser;
    Schur* s = nullptr;
    PetscCall(PCShellGetContext(pc, &s));
    try {
      s->flow->cahouet_chabard(s->dt, r, phi);
    } catch (const std::exception& e) {
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", e.what());
    }
    PetscFunctionReturn(0);
  }
};

namespace {

// The solve's PETSc objects and scratch vectors, released however project_exactly leaves.
struct SchurObjects {
  const Grid& grid;
  Vec b = nullptr, phi = nullptr;
  std::array<Vec, 3> faces{};
  Mat A = nullptr;
  KSP ksp = nullptr;
  explicit SchurObjects(const Grid& g) : grid(g) {
    COSIM_PETSC(DMGetGlobalVector(grid.pressure_dm(), &b));
    COSIM_PETSC(DMGetGlobalVector(grid.pressure_dm(), &phi));
    for (int c = 0; c < 3; ++c) COSIM_PETSC(DMGetGlobalVector(grid.velocity_dm(c), &faces[c]));
  }
  ~SchurObjects() {
    KSPDestroy(&ksp);
    MatDestroy(&A);
    for (int c = 0; c < 3; ++c) DMRestoreGlobalVector(grid.velocity_dm(c), &faces[c]);
    DMRestoreGlobalVector(grid.pressure_dm(), &phi);
    DMRestoreGlobalVector(grid.pressure_dm(), &b);
  }
  SchurObjects(const SchurObjects&) = delete;
  SchurObjects& operator=(const SchurObjects&) = delete;
};

}  // namespace

// out = (I - theta dt L)^{-1} (dt grad phi), zero on the boundary faces.
void NavierStokes::viscous_gradient(double dt, Vec phi, const std::array<Vec, 3>& out) {
  const double theta = controller_.options().theta;
  DM pdm = grid_.pressure_dm();
  const PetscScalar*** q = read_ghosted(pdm, phi, p_local_);
  for (int c = 0; c < 3; ++c) {
    DM dm = grid_.velocity_dm(c);
    Vec rhs = nullptr;
    COSIM_PETSC(DMGetGlobalVector(dm, &rhs));
    PetscScalar*** g = nullptr;
    COSIM_PETSC(DMDAVecGetArray(dm, rhs, &g));
    for_each_index(grid_.owned(dm), [&](const Index& p) {
      g[p[2]][p[1]][p[0]] = grid_.on_boundary(c, p) ? 0.0 : dt * face_gradient(grid_, bc_, q, c, p);
    });
    COSIM_PETSC(DMDAVecRestoreArray(dm, rhs, &g));
    COSIM_PETSC(VecZeroEntries(out[c]));
    viscous_.solve(c, theta * dt, viscosity_, nullptr, rhs, out[c]);
    COSIM_PETSC(DMRestoreGlobalVector(dm, &rhs));
  }
  COSIM_PETSC(DMDAVecRestoreArrayRead(pdm, p_local_, &q));
}

// y = div u at the cells; u's boundary faces are its own, so no ghost is read.
void NavierStokes::divergence_of(const std::array<Vec, 3>& u, Vec y) {
  local_.update(u, bc_, time_);
  DM pdm = grid_.pressure_dm();
  PetscScalar*** d = nullptr;
  COSIM_PETSC(DMDAVecGetArray(pdm, y, &d));
  for_each_index(grid_.owned(pdm), [&](const Index& m) { d[m[2]][m[1]][m[0]] = divergence(grid_, local_, m); });
  COSIM_PETSC(DMDAVecRestoreArray(pdm, y, &d));
}

// phi = lap^{-1}(r) / dt - theta nu r.
void NavierStokes::cahouet_chabard(double dt, Vec r, Vec phi) {
  pressure_solver_.solve(r, phi);
  COSIM_PETSC(VecScale(phi, 1 / dt));
  const double theta = controller_.options().theta;
  DM pdm = grid_.pressure_dm();
  PetscScalar*** out = nullptr;
  const PetscScalar*** in = nullptr;
  COSIM_PETSC(DMDAVecGetArray(pdm, phi, &out));
  COSIM_PETSC(DMDAVecGetArrayRead(pdm, r, &in));
  for_each_index(grid_.owned(pdm), [&](const Index& m) {
    out[m[2]][m[1]][m[0]] -= theta * viscosity_.at_cell(m) * in[m[2]][m[1]][m[0]];
  });
  COSIM_PETSC(DMDAVecRestoreArrayRead(pdm, r, &in));
  COSIM_PETSC(DMDAVecRestoreArray(pdm, phi, &out));
}

int NavierStokes::project_exactly(double dt, const std::array<Vec, 3>& u_star, bool update) {
  SchurObjects o(grid_);
  divergence_of(u_star, o.b);
  cahouet_chabard(dt, o.b, o.phi);  // also sets the pressure solver up for the null space
  Schur context{this, dt, o.faces};
  PetscInt n = 0, global = 0;
  COSIM_PETSC(VecGetLocalSize(o.b, &n));
  COSIM_PETSC(VecGetSize(o.b, &global));
  COSIM_PETSC(MatCreateShell(grid_.comm(), n, n, global, global, &context, &o.A));
  COSIM_PETSC(MatShellSetOperation(o.A, MATOP_MULT, reinterpret_cast<void (*)(void)>(ExactProjection::apply_schur)));
  if (MatNullSpace constants = pressure_solver_.null_space()) {
    COSIM_PETSC(MatSetNullSpace(o.A, constants));
    COSIM_PETSC(MatNullSpaceRemove(constants, o.b));
  }
  COSIM_PETSC(KSPCreate(grid_.comm(), &o.ksp));
  COSIM_PETSC(KSPSetOptionsPrefix(o.ksp, "exact_pressure_"));
  COSIM_PETSC(KSPSetType(o.ksp, KSPGMRES));
  COSIM_PETSC(KSPSetOperators(o.ksp, o.A, o.A));
  COSIM_PETSC(KSPSetPCSide(o.ksp, PC_RIGHT));
  PC pc;
  COSIM_PETSC(KSPGetPC(o.ksp, &pc));
  COSIM_PETSC(PCSetType(pc, PCSHELL));
  COSIM_PETSC(PCShellSetContext(pc, &context));
  COSIM_PETSC(PCShellSetApply(pc, ExactProjection::apply_cahouet_chabard));
  COSIM_PETSC(KSPSetTolerances(o.ksp, 1e-4, PETSC_DEFAULT, PETSC_DEFAULT, 100));
  COSIM_PETSC(KSPSetInitialGuessNonzero(o.ksp, PETSC_TRUE));
  COSIM_PETSC(KSPSetFromOptions(o.ksp));
  COSIM_PETSC(KSPSolve(o.ksp, o.b, o.phi));
  KSPConvergedReason reason;
  COSIM_PETSC(KSPGetConvergedReason(o.ksp, &reason));
  if (reason < 0)
    throw std::runtime_error("fluid: the exact pressure solve did not converge (" +
                             std::string(KSPConvergedReasons[reason]) + ")");
  PetscInt iterations = 0;
  COSIM_PETSC(KSPGetIterationNumber(o.ksp, &iterations));
  viscous_gradient(dt, o.phi, o.faces);
  for (int c = 0; c < 3; ++c) COSIM_PETSC(VecAXPY(u_star[c], -1.0, o.faces[c]));
  if (update) COSIM_PETSC(VecAXPY(p_, fluid_.density, o.phi));
  // What the tolerance left (1e-4 of div u* by default: the wall approach's drag agrees to
  // four digits with 1e-8, at 3 iterations instead of 8) a standard projection takes out.
  project_standard(dt, nullptr, u_star, update);
  return static_cast<int>(iterations) + 1;
}

}  // namespace cosim::fluid::navier_stokes
