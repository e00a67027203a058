#include "fluid/viscous/viscous_axis_basis.hpp"

#include <petscblaslapack.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace cosim::fluid::viscous {

using grid::Axis;
using grid::BoundaryConditions;
using grid::BoundaryKind;
using grid::Grid;
using grid::Side;

namespace {

// The unknowns of component c along axis d and the weights' rows for them.
ViscousAxisBasis layout(const Grid& grid, const BoundaryConditions& bc, const UniformViscousWeights& weights, int c,
                        int d) {
  const Axis& axis = grid.axis(d);
  ViscousAxisBasis b;
  b.size = axis.cells();
  b.normal_bounded = d == c && !axis.periodic();
  if (!b.normal_bounded) return b;
  b.first = 1;
  b.size = axis.cells() - 1;
  b.outflow_lower = bc.at(d, Side::lower).kind == BoundaryKind::outflow;
  b.outflow_upper = bc.at(d, Side::upper).kind == BoundaryKind::outflow;
  b.weight_lower = weights.at(c, d, 1).below;
  b.weight_upper = weights.at(c, d, axis.cells() - 1).above;
  return b;
}

}  // namespace

std::vector<double> viscous_axis_matrix(const Grid& grid, const BoundaryConditions& bc,
                                        const UniformViscousWeights& weights, int c, int d) {
  const ViscousAxisBasis b = layout(grid, bc, weights, c, d);
  const PetscInt n = b.size;
  std::vector<double> a(static_cast<std::size_t>(n * n), 0.0);
  if (grid.axis(d).degenerate()) return a;
  const bool periodic = grid.axis(d).periodic();
  const auto at = [&](PetscInt r, PetscInt q) -> double& { return a[static_cast<std::size_t>(r * n + q)]; };
  for (PetscInt r = 0; r < n; ++r) {
    const ViscousWeights& w = weights.at(c, d, b.first + r);
    at(r, r) += w.centre;
    // Periodic rows wrap around (and on two points both neighbours are the same one).
    if (r > 0 || periodic) at(r, (r + n - 1) % n) += w.below;
    if (r < n - 1 || periodic) at(r, (r + 1) % n) += w.above;
  }
  if (b.normal_bounded) {
    if (b.outflow_lower) at(0, 0) += b.weight_lower;
    if (b.outflow_upper) at(n - 1, n - 1) += b.weight_upper;
  }
  return a;
}

ViscousAxisBasis viscous_axis_basis(const Grid& grid, const BoundaryConditions& bc,
                                    const UniformViscousWeights& weights, int c, int d) {
  ViscousAxisBasis b = layout(grid, bc, weights, c, d);
  const PetscInt n = b.size;
  const auto size = static_cast<std::size_t>(n);
  std::vector<double> a = viscous_axis_matrix(grid, bc, weights, c, d);
  const auto at = [&](PetscInt r, PetscInt q) { return a[static_cast<std::size_t>(r * n + q)]; };
  // D makes D A D^-1 symmetric: d_r / d_{r-1} = sqrt(A[r-1][r] / A[r][r-1]). A periodic
  // axis is uniform, its circulant already symmetric.
  std::vector<double> scale(size, 1.0);
  if (!grid.axis(d).periodic())
    for (PetscInt r = 1; r < n; ++r) {
      const double up = at(r - 1, r), down = at(r, r - 1);
      if (up * down < 0 || (up == 0) != (down == 0))
        throw std::logic_error("fluid: the 1D viscous operator along axis " + std::to_string(d) +
                               " is not symmetrisable");
      scale[static_cast<std::size_t>(r)] =
          scale[static_cast<std::size_t>(r - 1)] * (up == 0 ? 1 : std::sqrt(up / down));
    }
  std::vector<double> q(size * size);  // S, then its eigenvectors, column-major
  for (PetscInt r = 0; r < n; ++r)
    for (PetscInt k = 0; k < n; ++k)
      q[static_cast<std::size_t>(k * n + r)] =
          scale[static_cast<std::size_t>(r)] * at(r, k) / scale[static_cast<std::size_t>(k)];
  b.eigenvalues.assign(size, 0.0);
  PetscBLASInt order = static_cast<PetscBLASInt>(n), info = 0, lwork = static_cast<PetscBLASInt>(8 * n + 8);
  std::vector<double> work(static_cast<std::size_t>(lwork));
  LAPACKsyev_("V", "U", &order, q.data(), &order, b.eigenvalues.data(), work.data(), &lwork, &info);
  if (info != 0) throw std::runtime_error("fluid: LAPACK could not diagonalise the 1D viscous operator");
  b.forward.resize(size * size);
  b.backward.resize(size * size);
  for (PetscInt r = 0; r < n; ++r)
    for (PetscInt k = 0; k < n; ++k) {
      const double v = q[static_cast<std::size_t>(k * n + r)], dr = scale[static_cast<std::size_t>(r)];
      b.forward[static_cast<std::size_t>(r * n + k)] = v * dr;   // F[k][r]
      b.backward[static_cast<std::size_t>(k * n + r)] = v / dr;  // B[r][k]
    }
  return b;
}

}  // namespace cosim::fluid::viscous
