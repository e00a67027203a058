#pragma once
// The eigenbasis of one velocity component's 1D viscous operator along a uniform x or y
// axis, with which FastViscous diagonalises that axis.
//
// The 1D operator is read off the stencil's own weights (UniformViscousWeights), so it is
// what ViscousSolver's Krylov path applies, not an idealisation of it:
// - a component normal to the axis lives on faces; on a bounded axis the first and last
//   faces are boundary rows and leave the unknowns: a wall or inflow value moves to the
//   right-hand side, an outflow's u_face = u_inside folds the neighbour's weight into the
//   first (last) unknown's diagonal. Between two walls the rows are [1 -2 1] / h^2 with
//   Dirichlet ends (the DST-I), between two outflows Neumann ends at half a cell (DCT-II);
//   an outflow below and a wall above gives cos((k + 1/2) pi (j - 1/2) / (n - 1/2)) on
//   face j of n cells, a length FFTW has no r2r kind for.
// - a component tangential to the axis lives at cell centres. Next to an outflow the row
//   is [-1 1] / h^2 (a ghost mirrored evenly: DCT-II between two outflows). Next to a wall
//   or an inflow the stencil closes with the quadratic through the wall value and two
//   centres, which gives the row [-4 4/3] / h^2, not the ghost reflection's [-3 1]: its
//   eigenvectors are sinusoids whose frequencies solve a transcendental equation, with no
//   fast transform.
// - on a periodic axis the rows are circulant and the real Fourier modes diagonalise them.
//
// Rather than a transform per case, of which the common one (a tangential component
// between walls) has none, the basis is computed numerically once per grid: the
// tridiagonal matrix is symmetrised by a diagonal similarity D (its off-diagonal pairs have
// the same sign), S = D A D^-1 = Q diag(lambda) Q^T by LAPACK, and A = B diag(lambda) F
// with F = Q^T D and B = D^-1 Q. Applied as dense products (BLAS), O(n) per point and axis;
// exact to round-off for any combination of ends. The test ViscousAxisBasis.* checks it
// against the stencil's 1D matrix and the closed forms above where they exist.
#include <petscsys.h>

#include <vector>

#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/viscous/viscous_stencil.hpp"

namespace cosim::fluid::viscous {

struct ViscousAxisBasis {
  // Unknowns along the axis: first .. first + size of the DMDA's points on it (a bounded
  // normal axis leaves out its two boundary faces).
  PetscInt first = 0, size = 0;
  // The boundary faces' rows of a bounded normal axis: whether u_face = u_inside (an
  // outflow) rather than the given value, and the weight of that face in the neighbouring
  // unknown's row (below at the lower end, above at the upper).
  bool normal_bounded = false;
  bool outflow_lower = false, outflow_upper = false;
  double weight_lower = 0, weight_upper = 0;
  std::vector<double> eigenvalues;        // of A, size
  std::vector<double> forward, backward;  // F and B, size x size, column-major
};

// The 1D matrix A (size x size, row-major) of div(nu grad u_c) along axis d, with the
// boundary faces eliminated as above: what the basis diagonalises, for tests.
std::vector<double> viscous_axis_matrix(const grid::Grid& grid, const grid::BoundaryConditions& bc,
                                        const UniformViscousWeights& weights, int c, int d);

ViscousAxisBasis viscous_axis_basis(const grid::Grid& grid, const grid::BoundaryConditions& bc,
                                    const UniformViscousWeights& weights, int c, int d);

}  // namespace cosim::fluid::viscous
