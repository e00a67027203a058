#pragma once
// The implicit viscous half-step (I - s div(nu grad)) u* = rhs per velocity component,
// s = dt / 2 for Crank-Nicolson. KSP options prefix `viscous_` (default GMRES + block
// Jacobi/ILU: the matrix is diagonally dominant and not symmetric next to walls).
#include <petscksp.h>

#include <array>

#include "fluid/boundary_conditions.hpp"
#include "fluid/grid.hpp"
#include "fluid/imposed_faces.hpp"
#include "fluid/viscosity_field.hpp"

namespace cosim::fluid {

class ViscousSolver {
 public:
  ViscousSolver(const Grid& grid, const BoundaryConditions& bc);
  ~ViscousSolver();
  ViscousSolver(const ViscousSolver&) = delete;
  ViscousSolver& operator=(const ViscousSolver&) = delete;

  // rhs holds, on boundary faces, the imposed value (wall/inflow) or zero (outflow, where
  // the row says u_face = u_inside), and on the `imposed` faces their values (identity
  // rows). Reassembles when s, a non-uniform viscosity or the imposed faces change.
  // Returns iterations.
  int solve(int c, double s, const ViscosityField& nu, const ImposedFaces* imposed, Vec rhs, Vec x);

 private:
  void create();
  void release();
  void assemble(int c, double s, const ViscosityField& nu, const ImposedFaces* imposed);

  const Grid& grid_;
  const BoundaryConditions& bc_;
  std::array<KSP, 3> ksp_{};
  std::array<Mat, 3> matrix_{};
  std::array<double, 3> assembled_for_{-1, -1, -1};
  std::array<int, 3> assembled_generation_{-1, -1, -1};
};

}  // namespace cosim::fluid
