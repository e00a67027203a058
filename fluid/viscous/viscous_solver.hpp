#pragma once
// The implicit viscous half-step (I - s div(nu grad)) u* = rhs per velocity component,
// s = dt / 2 for Crank-Nicolson; the operator is diagonally dominant, and not symmetric
// next to walls. `-viscous_solver fft|krylov` chooses between two paths, as
// `-pressure_solver` does for the projection:
// - fft (the default where it applies: a uniform viscosity, x and y uniform, no
//   -viscous_ksp_* or -viscous_pc_* flag): FastViscous, the eigenbases of the 1D operators
//   along x and y and tridiagonal lines along z, exact to round-off at any nu dt / h^2.
//   A solve with imposed faces (the staircase) takes the Krylov path.
// - krylov, KSP options prefix `viscous_`. With a uniform viscosity the operator is
//   applied from its stencil weights (UniformViscousWeights) without a matrix: GMRES(4)
//   with Jacobi by default, whose diagonal the weights give (a preconditioner that needs
//   the matrix's entries, SOR or ILU, fails at the first solve). A generalized-Newtonian
//   viscosity varies from point to point and step to step: its operator is assembled (a
//   7-point AIJ matrix per component) and solved with GMRES + SOR by default.
#include <petscksp.h>

#include <array>
#include <memory>

#include "fluid/bodies/imposed_faces.hpp"
#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/viscous/fast_viscous.hpp"
#include "fluid/viscous/viscosity_field.hpp"
#include "fluid/viscous/viscous_stencil.hpp"

namespace cosim::fluid::viscous {

class ViscousSolver {
 public:
  // weights: a uniform viscosity's (outliving the solver), or null for a varying one.
  ViscousSolver(const grid::Grid& grid, const grid::BoundaryConditions& bc, const UniformViscousWeights* weights);
  ~ViscousSolver();
  ViscousSolver(const ViscousSolver&) = delete;
  ViscousSolver& operator=(const ViscousSolver&) = delete;

  // rhs holds, on boundary faces, the imposed value (wall/inflow) or zero (outflow, where
  // the row says u_face = u_inside), and on the `imposed` faces their values (identity
  // rows). An assembled operator is rebuilt when s, the viscosity or the imposed faces
  // change. Returns iterations (0 by the transforms).
  int solve(int c, double s, const ViscosityField& nu, const bodies::ImposedFaces* imposed, Vec rhs, Vec x);

 private:
  void create();
  void release();
  void assemble(int c, double s, const ViscosityField& nu, const bodies::ImposedFaces* imposed);
  // The stencil operator's product and diagonal (MATSHELL callbacks).
  static PetscErrorCode multiply(Mat A, Vec x, Vec y);
  static PetscErrorCode diagonal(Mat A, Vec d);

  const grid::Grid& grid_;
  const grid::BoundaryConditions& bc_;
  const UniformViscousWeights* weights_;
  std::array<KSP, 3> ksp_{};
  std::array<Mat, 3> matrix_{};  // assembled, or the stencil operator
  struct Operator {              // what the stencil operator of one component reads
    const ViscousSolver* solver = nullptr;
    int c = 0;
    double s = 0;
    const bodies::ImposedFaces* imposed = nullptr;
    Vec local = nullptr;  // x with ghosts
  };
  std::array<Operator, 3> operators_{};
  std::array<double, 3> assembled_for_{-1, -1, -1};
  std::array<int, 3> assembled_generation_{-1, -1, -1};
  std::unique_ptr<FastViscous> fast_;  // the transforms, where chosen
};

}  // namespace cosim::fluid::viscous
