#pragma once
// A direct solver for the projection's Poisson equation when no face is imposed (the fluid
// alone, or bodies by the immersed boundary): the operator never changes, so it is
// diagonalised once. Along x and y, which must be uniform, the discrete Laplacian of the
// cell-centred grid has known eigenvectors (cosine transforms between walls, sine
// transforms between outflows, quarter-wave transforms between one of each, real Fourier
// transforms on periodic axes: Schumann & Sweet, J. Comput. Phys. 20 (1976) 171); in each
// of their modes what is left along z, uniform or stretched, is a tridiagonal system
// (cyclic on a periodic axis), solved exactly. CaNS (Costa, Comput. Math. Appl. 76 (2018)
// 1853) solves its pressure the same way.
//
// It solves the same equations PressureSolver assembles, to round-off, with no iteration.
// On several ranks the right-hand side is redistributed into slabs of whole x-y planes
// for the transforms, then into slabs of whole z lines for the tridiagonal solves, and back
// (SlabTranspose).
#include <petscvec.h>

#include <vector>

#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/transforms/slab_transpose.hpp"

struct fftw_plan_s;  // FFTW's plan, kept out of this header

namespace cosim::fluid::pressure {

class FastPoisson {
 public:
  // Whether the grid allows it: x and y uniform (or one periodic cell).
  static bool applies(const grid::Grid& grid);

  FastPoisson(const grid::Grid& grid, const grid::BoundaryConditions& bc);
  ~FastPoisson();
  FastPoisson(const FastPoisson&) = delete;
  FastPoisson& operator=(const FastPoisson&) = delete;

  // Solves A phi = b for A the operator -V div(grad) of PressureSolver (global vectors of the
  // pressure DM). Where A is singular (no outflow), b must have zero sum; phi is then the
  // solution whose z line of the (0, 0) mode starts at zero, and the caller removes the
  // constant it wants.
  void solve(Vec b, Vec phi);

 private:
  void release();
  void transform(double* planes, PetscInt k_begin, PetscInt k_end, bool forward);
  void solve_lines(double* data, PetscInt j_begin, PetscInt j_end, PetscInt j_stride, PetscInt k_stride);
  void solve_singular_line(double* row, PetscInt k_stride);

  const grid::Grid& grid_;
  PetscInt nx_ = 0, ny_ = 0, nz_ = 0;
  transforms::SlabTranspose slabs_;
  std::vector<double> eigen_x_, eigen_y_;       // of the 1D Laplacians, <= 0
  std::vector<double> eigen_x_pinned_;          // eigen_x_ with the zero replaced: the singular row's sweep
  double scale_ = 1;                            // of a forward and backward transform together
  std::vector<double> volume_;                  // cell volume per z layer
  std::vector<double> lower_, upper_, outlet_;  // z couplings over the cell volume
  bool periodic_z_ = false;
  fftw_plan_s *forward_ = nullptr, *backward_ = nullptr;
  std::vector<double> work_;      // the sweep's modified diagonal; for cyclic lines a second solution and gamma
  std::vector<double> singular_;  // the right-hand side of the singular mode's line
};

}  // namespace cosim::fluid::pressure
