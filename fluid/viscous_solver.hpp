#pragma once
// The implicit viscous half-step (I - s div(nu grad)) u* = rhs per velocity component,
// s = dt / 2 for Crank-Nicolson. KSP options prefix `viscous_` (default GMRES + block
// Jacobi/ILU: the matrix is diagonally dominant and not symmetric next to walls).
#include <petscksp.h>

#include <array>

#include "fluid/boundary_conditions.hpp"
#include "fluid/grid.hpp"
#include "fluid/viscosity_field.hpp"

namespace cosim::fluid {

class ViscousSolver {
 public:
  ViscousSolver(const Grid& grid, const BoundaryConditions& bc);
  ~ViscousSolver();
  ViscousSolver(const ViscousSolver&) = delete;
  ViscousSolver& operator=(const ViscousSolver&) = delete;

  // rhs holds, on boundary faces, the imposed value (wall/inflow) or zero (outflow, where
  // the row says u_face = u_inside). Reassembles when s or a non-uniform viscosity
  // changes. Returns iterations.
  int solve(int c, double s, const ViscosityField& nu, Vec rhs, Vec x);

 private:
  void create();
  void release();
  void assemble(int c, double s, const ViscosityField& nu);

  const Grid& grid_;
  const BoundaryConditions& bc_;
  std::array<KSP, 3> ksp_{};
  std::array<Mat, 3> matrix_{};
  std::array<double, 3> assembled_for_{-1, -1, -1};
};

}  // namespace cosim::fluid
