#include "fluid/pressure/fast_poisson.hpp"

#include <fftw3.h>
#include <petscdmda.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fluid/petsc_check.hpp"
#include "fluid/transforms/tridiagonal_lines.hpp"

namespace cosim::fluid::pressure {

using grid::Axis;
using grid::BoundaryConditions;
using grid::BoundaryKind;
using grid::Grid;
using grid::Side;
using transforms::solve_tridiagonal_lines;

namespace {

bool uniform(const Axis& a) {
  if (a.degenerate()) return true;
  const double h = a.width(0);
  for (int i = 1; i < a.cells(); ++i)
    if (std::abs(a.width(i) - h) > 1e-9 * a.max_width()) return false;
  return true;
}

// The transform that diagonalises the cell-centred 1D Laplacian of a uniform axis, its
// inverse, their combined scale and the eigenvalues -4 sin^2(theta_k / 2) / h^2, in the
// order FFTW returns the coefficients. A wall or an inflow holds the velocity, so phi has
// zero gradient there (even about the face); an outflow holds phi = 0 on the face (odd).
struct AxisTransform {
  fftw_r2r_kind forward, backward;
  double scale;
  std::vector<double> eigenvalues;
};

AxisTransform axis_transform(const Axis& axis, BoundaryKind lower, BoundaryKind upper) {
  const int n = axis.cells();
  const double h = axis.width(0);
  AxisTransform t{FFTW_R2HC, FFTW_HC2R, static_cast<double>(n), std::vector<double>(static_cast<std::size_t>(n))};
  // theta_k = pi (k + shift) / n * factor
  double shift = 0, factor = 1;
  if (axis.periodic()) {
    factor = 2;  // half-complex index k holds frequency k or n - k: the same eigenvalue
  } else {
    const bool lower_open = lower == BoundaryKind::outflow, upper_open = upper == BoundaryKind::outflow;
    t.scale = 2.0 * n;
    if (!lower_open && !upper_open) {
      t.forward = FFTW_REDFT10, t.backward = FFTW_REDFT01;
    } else if (lower_open && upper_open) {
      t.forward = FFTW_RODFT10, t.backward = FFTW_RODFT01, shift = 1;
    } else {
      t.forward = t.backward = lower_open ? FFTW_RODFT11 : FFTW_REDFT11;
      shift = 0.5;
    }
  }
  for (int k = 0; k < n; ++k) {
    const double half = 0.5 * std::numbers::pi * (k + shift) * factor / n;
    t.eigenvalues[static_cast<std::size_t>(k)] = k == 0 && shift == 0 ? 0 : -4 * std::pow(std::sin(half) / h, 2);
  }
  return t;
}

}  // namespace

bool FastPoisson::applies(const Grid& grid) { return uniform(grid.axis(0)) && uniform(grid.axis(1)); }

FastPoisson::FastPoisson(const Grid& grid, const BoundaryConditions& bc) : grid_(grid), slabs_(grid.pressure_dm()) {
  const auto n = grid.cells();
  nx_ = n[0], ny_ = n[1], nz_ = n[2];

  const AxisTransform x = axis_transform(grid.axis(0), bc.at(0, Side::lower).kind, bc.at(0, Side::upper).kind);
  const AxisTransform y = axis_transform(grid.axis(1), bc.at(1, Side::lower).kind, bc.at(1, Side::upper).kind);
  eigen_x_ = x.eigenvalues;
  eigen_y_ = y.eigenvalues;
  eigen_x_pinned_ = eigen_x_;
  eigen_x_pinned_[0] = -1;
  scale_ = 1 / (x.scale * y.scale);

  // Along z the couplings of PressureSolver's rows, divided by the cell's volume.
  const Axis& z = grid.axis(2);
  const bool open_lower = bc.at(2, Side::lower).kind == BoundaryKind::outflow;
  const bool open_upper = bc.at(2, Side::upper).kind == BoundaryKind::outflow;
  periodic_z_ = z.periodic() && !z.degenerate();
  volume_.resize(static_cast<std::size_t>(nz_));
  lower_.assign(volume_.size(), 0);
  upper_.assign(volume_.size(), 0);
  outlet_.assign(volume_.size(), 0);
  for (int k = 0; k < nz_; ++k) {
    const auto at = static_cast<std::size_t>(k);
    volume_[at] = grid.cell_volume({0, 0, k});
    if (z.degenerate()) continue;
    const double w = z.width(k);
    if (k > 0 || periodic_z_) lower_[at] = 1 / (w * (z.centre(k) - z.centre(k - 1)));
    if (k < nz_ - 1 || periodic_z_) upper_[at] = 1 / (w * (z.centre(k + 1) - z.centre(k)));
    if (k == 0 && open_lower && !z.periodic()) outlet_[at] += 1 / (w * (z.centre(0) - z.lo()));
    if (k == nz_ - 1 && open_upper && !z.periodic()) outlet_[at] += 1 / (w * (z.hi() - z.centre(k)));
  }
  work_.resize(static_cast<std::size_t>((2 * nz_ + 1) * nx_));
  singular_.resize(static_cast<std::size_t>(nz_));

  create_or_release(
      [&] {
        const int planes = static_cast<int>(slabs_.k_end() - slabs_.k_begin());
        if (planes > 0) {
          // Planned on a scratch array (FFTW_ESTIMATE leaves it alone and, unlike
          // FFTW_MEASURE, picks the same algorithm in every run, so runs repeat bit for
          // bit); executed on PETSc's arrays, whose alignment may differ.
          std::vector<double> scratch(static_cast<std::size_t>(planes * nx_ * ny_));
          const int dims[2] = {static_cast<int>(ny_), static_cast<int>(nx_)};
          const int plane = static_cast<int>(nx_ * ny_);
          const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
          const fftw_r2r_kind forward[2] = {y.forward, x.forward}, backward[2] = {y.backward, x.backward};
          forward_ = fftw_plan_many_r2r(2, dims, planes, scratch.data(), nullptr, 1, plane, scratch.data(), nullptr, 1,
                                        plane, forward, flags);
          backward_ = fftw_plan_many_r2r(2, dims, planes, scratch.data(), nullptr, 1, plane, scratch.data(), nullptr, 1,
                                         plane, backward, flags);
        }
        // Every rank learns whether any failed, so none waits in the scatters' set-up.
        int failed = planes > 0 && (!forward_ || !backward_) ? 1 : 0;
        MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, grid.comm());
        if (failed) throw std::runtime_error("fluid: FFTW could not plan the pressure transforms");
      },
      [this] { release(); });
}

FastPoisson::~FastPoisson() { release(); }

void FastPoisson::release() {
  if (forward_) fftw_destroy_plan(forward_);
  if (backward_) fftw_destroy_plan(backward_);
  forward_ = backward_ = nullptr;
}

void FastPoisson::solve(Vec b, Vec phi) {
  slabs_.run(
      b, phi, [this](double* planes, PetscInt k0, PetscInt k1) { transform(planes, k0, k1, true); },
      [this](double* data, PetscInt j0, PetscInt j1, PetscInt j_stride, PetscInt k_stride) {
        solve_lines(data, j0, j1, j_stride, k_stride);
      },
      [this](double* planes, PetscInt k0, PetscInt k1) { transform(planes, k0, k1, false); });
}

// In place on whole planes k_begin .. k_end; the forward pass first divides by the cell
// volume (A's rows carry it), the backward pass undoes the transforms' scale.
void FastPoisson::transform(double* planes, PetscInt k_begin, PetscInt k_end, bool forward) {
  if (k_end == k_begin) return;
  const PetscInt plane = nx_ * ny_;
  if (forward) {
    for (PetscInt k = k_begin; k < k_end; ++k) {
      double* p = planes + (k - k_begin) * plane;
      const double inverse = 1 / volume_[static_cast<std::size_t>(k)];
      for (PetscInt n = 0; n < plane; ++n) p[n] *= inverse;
    }
    fftw_execute_r2r(forward_, planes, planes);
  } else {
    fftw_execute_r2r(backward_, planes, planes);
    const PetscInt total = plane * (k_end - k_begin);
    for (PetscInt n = 0; n < total; ++n) planes[n] *= scale_;
  }
}

// For each mode (i, j) the z system (lower + upper + outlet - sigma) phi_k - lower phi_{k-1}
// - upper phi_{k+1} = f_k, sigma = eigen_x[i] + eigen_y[j] <= 0, by Thomas' algorithm
// across all i of a row at once; on a periodic z axis the corners are folded in by
// Sherman-Morrison. The one singular mode (sigma = 0 with no outlet along z) is fixed by
// phi_0 = 0. Element (i, j, k) sits at data[(j - j_begin) j_stride + k k_stride + i].
void FastPoisson::solve_lines(double* data, PetscInt j_begin, PetscInt j_end, PetscInt j_stride, PetscInt k_stride) {
  const PetscInt n = nz_, nx = nx_;
  const bool closed = std::all_of(outlet_.begin(), outlet_.end(), [](double o) { return o == 0; });
  const auto L = [&](PetscInt k) { return lower_[static_cast<std::size_t>(k)]; };
  const auto U = [&](PetscInt k) { return upper_[static_cast<std::size_t>(k)]; };
  const auto O = [&](PetscInt k) { return outlet_[static_cast<std::size_t>(k)]; };
  for (PetscInt j = j_begin; j < j_end; ++j) {
    double* row = data + (j - j_begin) * j_stride;
    const double sigma_y = eigen_y_[static_cast<std::size_t>(j)];
    // The singular mode, if in this row: its right-hand side kept for a solve of its own,
    // and the row's sweep run with a stand-in eigenvalue there, which divides by nothing
    // near zero (its result is overwritten).
    const bool singular = closed && sigma_y == 0 && eigen_x_[0] == 0;
    const double* sigma_x = singular ? eigen_x_pinned_.data() : eigen_x_.data();
    const auto diagonal = [&](PetscInt k, PetscInt i) { return L(k) + U(k) + O(k) - (sigma_x[i] + sigma_y); };
    if (singular)
      for (PetscInt k = 0; k < n; ++k) singular_[static_cast<std::size_t>(k)] = row[k * k_stride];
    solve_tridiagonal_lines(
        row, n, nx, k_stride, [&](PetscInt k) { return -L(k); }, [&](PetscInt k) { return -U(k); }, diagonal,
        periodic_z_, work_);
    if (singular) solve_singular_line(row, k_stride);
  }
}

// The mode sigma = 0 of a z axis without outlet: phi is fixed only up to a constant, so
// phi_0 = 0 and rows 1 .. n - 1 are solved without it (the right-hand side weighted by the
// cell widths sums to zero, so row 0 then holds too). Writes column i = 0 of the row.
void FastPoisson::solve_singular_line(double* row, PetscInt k_stride) {
  const PetscInt n = nz_;
  std::vector<double>& f = singular_;
  std::vector<double> w(static_cast<std::size_t>(n), 0);
  const auto at = [](PetscInt k) { return static_cast<std::size_t>(k); };
  for (PetscInt k = 1; k < n; ++k) {
    const double d = lower_[at(k)] + upper_[at(k)] + outlet_[at(k)];
    if (k == 1) {
      w[at(k)] = d;
      continue;
    }
    const double m = -lower_[at(k)] / w[at(k - 1)];
    w[at(k)] = d - m * -upper_[at(k - 1)];
    f[at(k)] -= m * f[at(k - 1)];
  }
  f[0] = 0;
  for (PetscInt k = n - 1; k >= 1; --k) {
    const double next = k + 1 < n ? f[at(k + 1)] : 0;
    f[at(k)] = (f[at(k)] + upper_[at(k)] * next) / w[at(k)];
  }
  for (PetscInt k = 0; k < n; ++k) row[k * k_stride] = f[at(k)];
}

}  // namespace cosim::fluid::pressure
