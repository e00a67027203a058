#pragma once
// A direct solver for the implicit viscous half-step (I - s L_c) u_c = rhs of a uniform
// (Newtonian) viscosity without imposed faces, per velocity component c: the operator is a
// sum of 1D operators along x, y and z (UniformViscousWeights lists each axis's weights by
// position alone), so with x and y diagonalised by their eigenbases (ViscousAxisBasis) what
// is left in each mode (k_x, k_y) is a tridiagonal system along z, uniform or stretched
// (cyclic on a periodic axis), solved exactly. The bases depend on the grid and the
// boundary kinds only; s enters the z lines' coefficients alone, so a new dt costs nothing
// to set up. The right-hand side is ViscousSolver's; the result the same to round-off.
//
// On several ranks each component is redistributed into x-y planes and z lines
// (SlabTranspose), as the pressure's transforms are.
#include <petscvec.h>

#include <array>
#include <memory>
#include <vector>

#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/transforms/slab_transpose.hpp"
#include "fluid/viscous/viscous_axis_basis.hpp"
#include "fluid/viscous/viscous_stencil.hpp"

namespace cosim::fluid::viscous {

class FastViscous {
 public:
  // Whether the grid allows it: x and y uniform (or one periodic cell).
  static bool applies(const grid::Grid& grid);

  FastViscous(const grid::Grid& grid, const grid::BoundaryConditions& bc, const UniformViscousWeights& weights);

  // Solves ViscousSolver's system for component c without imposed faces (global vectors of
  // the component's DMDA; boundary faces of rhs hold their value, or zero at an outflow).
  void solve(int c, double s, Vec rhs, Vec x);

 private:
  struct Component {
    std::unique_ptr<transforms::SlabTranspose> slabs;
    std::array<ViscousAxisBasis, 2> basis;                   // along x and y
    std::array<std::vector<double>, 2> eigen;                // per DMDA point, zero on boundary faces
    std::vector<double> z_below, z_centre, z_above;          // the weights along z per layer
    std::vector<char> z_boundary;                            // a boundary face's row along z
    std::vector<double> z_boundary_below, z_boundary_above;  // its couplings: -1 at an outflow
    bool cyclic = false;
  };
  void forward(const Component& m, double s, double* planes, PetscInt planes_count);
  void backward(const Component& m, double* planes, PetscInt planes_count);
  // Applies the matrix (column-major, size x size) to the unknowns along x or y, in place.
  void along_x(const ViscousAxisBasis& b, const std::vector<double>& matrix, double* planes, PetscInt rows,
               PetscInt nx);
  void along_y(const ViscousAxisBasis& b, const std::vector<double>& matrix, double* planes, PetscInt planes_count,
               PetscInt nx, PetscInt ny);
  void solve_lines(const Component& m, double s, double* data, PetscInt j_begin, PetscInt j_end, PetscInt j_stride,
                   PetscInt k_stride);

  std::array<Component, 3> components_;
  std::vector<double> saved_;    // boundary faces of the planes in hand
  std::vector<double> scratch_;  // a product's output
  std::vector<double> work_;     // the line sweeps'
};

}  // namespace cosim::fluid::viscous
