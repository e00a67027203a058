#pragma once
// Where a marker's regularized delta reaches on the MAC grid: for one velocity component,
// per axis the grid points within the kernel's support and their weights phi(dx / h),
// h the width of the cell the marker is in. The three-dimensional weight of a point is the
// product over the axes; interpolation is sum(weight * u) and spreading puts
// F dV_marker weight / dV_face on each point, so the two are adjoint.
//
// Weights are normalised over the points that are unknowns (interior faces and cells of the
// domain; periodic axes wrap around): away from walls they sum to one already (to
// round-off, on a uniform axis); next to a wall, where part of the support lies on the
// boundary face or beyond it, a constant still interpolates exactly and a spread force
// lands whole in the fluid instead of partly on a face the boundary condition overwrites.
// On a stretched axis the moment conditions hold only approximately (the kernel sees the
// local width).
#include <array>

#include "fluid/grid/grid.hpp"
#include "fluid/ibm/delta_kernel.hpp"

namespace cosim::fluid::ibm {

struct AxisWeights {
  static constexpr int kMax = 6;  // the widest kernel's points
  int size = 0;
  std::array<PetscInt, kMax> index{};
  std::array<double, kMax> weight{};
  double width = 0;  // h of the marker's cell
};

// Along `axis` for a marker at coordinate x, at the faces (`faces`: the component's own
// axis) or the cell centres. A degenerate axis (one periodic cell) gives its one point with
// weight one. Empty (size 0) when no unknown lies within reach: x outside the domain.
AxisWeights axis_weights(const grid::Axis& axis, bool faces, DeltaKernel kernel, double x);

struct KernelStencil {
  std::array<AxisWeights, 3> axes;
  bool empty() const { return axes[0].size == 0 || axes[1].size == 0 || axes[2].size == 0; }
  // Whether any of its points lies in `box`.
  bool meets(const grid::Box& box) const;
};

KernelStencil kernel_stencil(const grid::Grid& grid, int component, DeltaKernel kernel, const grid::Point& x);

// Calls f(p, weight) for the stencil's points inside `box` (a rank's owned points).
template <typename F>
void for_each_point(const KernelStencil& s, const grid::Box& box, F&& f) {
  const auto inside = [&](int d, PetscInt i) { return i >= box.lo[d] && i < box.hi[d]; };
  for (int c = 0; c < s.axes[2].size; ++c) {
    const PetscInt k = s.axes[2].index[static_cast<std::size_t>(c)];
    if (!inside(2, k)) continue;
    for (int b = 0; b < s.axes[1].size; ++b) {
      const PetscInt j = s.axes[1].index[static_cast<std::size_t>(b)];
      if (!inside(1, j)) continue;
      const double wjk = s.axes[2].weight[static_cast<std::size_t>(c)] * s.axes[1].weight[static_cast<std::size_t>(b)];
      for (int a = 0; a < s.axes[0].size; ++a) {
        const PetscInt i = s.axes[0].index[static_cast<std::size_t>(a)];
        if (inside(0, i)) f(grid::Index{i, j, k}, wjk * s.axes[0].weight[static_cast<std::size_t>(a)]);
      }
    }
  }
}

}  // namespace cosim::fluid::ibm
