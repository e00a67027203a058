#include "fluid/viscous/fast_viscous.hpp"

#include <petscblaslapack.h>

#include <algorithm>

#include "fluid/pressure/fast_poisson.hpp"
#include "fluid/transforms/tridiagonal_lines.hpp"

namespace cosim::fluid::viscous {

using grid::Axis;
using grid::BoundaryConditions;
using grid::BoundaryKind;
using grid::Grid;
using grid::Side;
using pressure::FastPoisson;
using transforms::SlabTranspose;
using transforms::solve_tridiagonal_lines;

// The pressure's transforms' condition, so that one rule says where transforms apply. (The
// numerical bases would take a stretched x or y as well; that is left to the Krylov path.)
bool FastViscous::applies(const Grid& grid) { return FastPoisson::applies(grid); }

FastViscous::FastViscous(const Grid& grid, const BoundaryConditions& bc, const UniformViscousWeights& weights) {
  for (int c = 0; c < 3; ++c) {
    Component& m = components_[static_cast<std::size_t>(c)];
    m.slabs = std::make_unique<SlabTranspose>(grid.velocity_dm(c));
    const std::array<PetscInt, 3> points{m.slabs->nx(), m.slabs->ny(), m.slabs->nz()};
    for (int d = 0; d < 2; ++d) {
      ViscousAxisBasis& b = m.basis[static_cast<std::size_t>(d)];
      b = viscous_axis_basis(grid, bc, weights, c, d);
      auto& eigen = m.eigen[static_cast<std::size_t>(d)];
      eigen.assign(static_cast<std::size_t>(points[static_cast<std::size_t>(d)]), 0.0);
      std::copy(b.eigenvalues.begin(), b.eigenvalues.end(), eigen.begin() + b.first);
    }
    // Along z the rows as the stencil operator has them, boundary faces included.
    const Axis& z = grid.axis(2);
    const PetscInt nz = points[2];
    const auto size = static_cast<std::size_t>(nz);
    m.z_below.assign(size, 0);
    m.z_centre.assign(size, 0);
    m.z_above.assign(size, 0);
    m.z_boundary.assign(size, 0);
    m.z_boundary_below.assign(size, 0);
    m.z_boundary_above.assign(size, 0);
    m.cyclic = z.periodic() && !z.degenerate();
    for (PetscInt k = 0; k < nz; ++k) {
      const auto at = static_cast<std::size_t>(k);
      if (c == 2 && !z.periodic() && (k == 0 || k == nz - 1)) {
        const bool lower = k == 0;
        m.z_boundary[at] = 1;
        if (bc.at(2, lower ? Side::lower : Side::upper).kind == BoundaryKind::outflow)
          (lower ? m.z_boundary_above : m.z_boundary_below)[at] = -1;
        continue;
      }
      if (z.degenerate()) continue;
      const ViscousWeights& w = weights.at(c, 2, k);
      m.z_below[at] = w.below;
      m.z_centre[at] = w.centre;
      m.z_above[at] = w.above;
    }
  }
}

void FastViscous::solve(int c, double s, Vec rhs, Vec x) {
  Component& m = components_[static_cast<std::size_t>(c)];
  m.slabs->run(
      rhs, x, [&](double* planes, PetscInt k0, PetscInt k1) { forward(m, s, planes, k1 - k0); },
      [&](double* data, PetscInt j0, PetscInt j1, PetscInt j_stride, PetscInt k_stride) {
        solve_lines(m, s, data, j0, j1, j_stride, k_stride);
      },
      [&](double* planes, PetscInt k0, PetscInt k1) { backward(m, planes, k1 - k0); });
}

// The boundary faces of a bounded normal axis (x for u, y for v) leave the system: their
// values are kept aside, and s times their weight times the value moves to the first
// and last unknowns' right-hand sides (an outflow's u_face = value + u_inside puts the
// u_inside part in the 1D matrix instead). Then the transforms along x and y.
void FastViscous::forward(const Component& m, double s, double* planes, PetscInt count) {
  const PetscInt nx = m.slabs->nx(), ny = m.slabs->ny();
  const ViscousAxisBasis &bx = m.basis[0], &by = m.basis[1];
  if (count == 0) return;
  if (bx.normal_bounded) {
    saved_.resize(static_cast<std::size_t>(2 * count * ny));
    for (PetscInt r = 0; r < count * ny; ++r) {
      double* row = planes + r * nx;
      saved_[static_cast<std::size_t>(2 * r)] = row[0];
      saved_[static_cast<std::size_t>(2 * r + 1)] = row[nx - 1];
      row[1] += s * bx.weight_lower * row[0];
      row[nx - 2] += s * bx.weight_upper * row[nx - 1];
    }
  }
  if (by.normal_bounded) {
    saved_.resize(static_cast<std::size_t>(2 * count * nx));
    for (PetscInt k = 0; k < count; ++k) {
      double* p = planes + k * nx * ny;
      for (PetscInt i = 0; i < nx; ++i) {
        saved_[static_cast<std::size_t>(2 * (k * nx + i))] = p[i];
        saved_[static_cast<std::size_t>(2 * (k * nx + i) + 1)] = p[(ny - 1) * nx + i];
        p[nx + i] += s * by.weight_lower * p[i];
        p[(ny - 2) * nx + i] += s * by.weight_upper * p[(ny - 1) * nx + i];
      }
    }
  }
  along_x(bx, bx.forward, planes, count * ny, nx);
  along_y(by, by.forward, planes, count, nx, ny);
}

// Back from the modes, and the boundary faces restored from what forward() kept.
void FastViscous::backward(const Component& m, double* planes, PetscInt count) {
  const PetscInt nx = m.slabs->nx(), ny = m.slabs->ny();
  const ViscousAxisBasis &bx = m.basis[0], &by = m.basis[1];
  if (count == 0) return;
  along_y(by, by.backward, planes, count, nx, ny);
  along_x(bx, bx.backward, planes, count * ny, nx);
  if (bx.normal_bounded)
    for (PetscInt r = 0; r < count * ny; ++r) {
      double* row = planes + r * nx;
      row[0] = saved_[static_cast<std::size_t>(2 * r)] + (bx.outflow_lower ? row[1] : 0);
      row[nx - 1] = saved_[static_cast<std::size_t>(2 * r + 1)] + (bx.outflow_upper ? row[nx - 2] : 0);
    }
  if (by.normal_bounded)
    for (PetscInt k = 0; k < count; ++k) {
      double* p = planes + k * nx * ny;
      for (PetscInt i = 0; i < nx; ++i) {
        p[i] = saved_[static_cast<std::size_t>(2 * (k * nx + i))] + (by.outflow_lower ? p[nx + i] : 0);
        p[(ny - 1) * nx + i] =
            saved_[static_cast<std::size_t>(2 * (k * nx + i) + 1)] + (by.outflow_upper ? p[(ny - 2) * nx + i] : 0);
      }
    }
}

// The rows of all planes form a column-major matrix of nx x rows; its unknowns block
// (b.size x rows, leading dimension nx) is multiplied by the matrix from the left.
void FastViscous::along_x(const ViscousAxisBasis& b, const std::vector<double>& matrix, double* planes, PetscInt rows,
                          PetscInt nx) {
  if (b.size == 0) return;
  const PetscBLASInt n = static_cast<PetscBLASInt>(b.size), r = static_cast<PetscBLASInt>(rows),
                     ld = static_cast<PetscBLASInt>(nx);
  const double one = 1, zero = 0;
  scratch_.resize(static_cast<std::size_t>(b.size * rows));
  double* block = planes + b.first;
  BLASgemm_("N", "N", &n, &r, &n, &one, matrix.data(), &n, block, &ld, &zero, scratch_.data(), &n);
  for (PetscInt q = 0; q < rows; ++q) std::copy_n(scratch_.data() + q * b.size, b.size, block + q * nx);
}

// A plane is a column-major matrix nx x ny; its unknown columns (nx x b.size) are
// multiplied by the transposed matrix from the right.
void FastViscous::along_y(const ViscousAxisBasis& b, const std::vector<double>& matrix, double* planes, PetscInt count,
                          PetscInt nx, PetscInt ny) {
  if (b.size == 0) return;
  const PetscBLASInt n = static_cast<PetscBLASInt>(b.size), m = static_cast<PetscBLASInt>(nx);
  const double one = 1, zero = 0;
  scratch_.resize(static_cast<std::size_t>(nx * b.size));
  for (PetscInt k = 0; k < count; ++k) {
    double* block = planes + k * nx * ny + b.first * nx;
    BLASgemm_("N", "T", &m, &n, &n, &one, block, &m, matrix.data(), &n, &zero, scratch_.data(), &m);
    std::copy_n(scratch_.data(), nx * b.size, block);
  }
}

// For each mode (i, j) the z system as the stencil operator's rows: 1 - s (w_centre +
// lambda_x[i] + lambda_y[j]) on the diagonal, -s w_below and -s w_above off it; a boundary
// face's row is its own (1, and -1 towards the inside at an outflow) in every mode.
void FastViscous::solve_lines(const Component& m, double s, double* data, PetscInt j_begin, PetscInt j_end,
                              PetscInt j_stride, PetscInt k_stride) {
  const PetscInt nz = m.slabs->nz(), nx = m.slabs->nx();
  work_.resize(static_cast<std::size_t>((2 * nz + 1) * nx));
  const std::vector<double>& eigen_x = m.eigen[0];
  const auto at = [](PetscInt k) { return static_cast<std::size_t>(k); };
  const auto sub = [&](PetscInt k) { return m.z_boundary[at(k)] ? m.z_boundary_below[at(k)] : -s * m.z_below[at(k)]; };
  const auto super = [&](PetscInt k) {
    return m.z_boundary[at(k)] ? m.z_boundary_above[at(k)] : -s * m.z_above[at(k)];
  };
  for (PetscInt j = j_begin; j < j_end; ++j) {
    const double sigma_y = m.eigen[1][static_cast<std::size_t>(j)];
    const auto diagonal = [&](PetscInt k, PetscInt i) {
      return m.z_boundary[at(k)] ? 1.0 : 1 - s * (m.z_centre[at(k)] + eigen_x[static_cast<std::size_t>(i)] + sigma_y);
    };
    solve_tridiagonal_lines(data + (j - j_begin) * j_stride, nz, nx, k_stride, sub, super, diagonal, m.cyclic, work_);
  }
}

}  // namespace cosim::fluid::viscous
