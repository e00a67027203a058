#include "fluid/ibm/kernel_stencil.hpp"

#include <algorithm>
#include <cmath>

namespace cosim::fluid::ibm {

using grid::Axis;
using grid::Box;
using grid::Grid;
using grid::Point;

AxisWeights axis_weights(const Axis& a, bool faces, DeltaKernel kernel, double x) {
  AxisWeights out;
  if (a.degenerate()) {
    out.size = 1;
    out.weight[0] = 1;
    out.width = a.width(0);
    return out;
  }
  if (!a.periodic() && (x <= a.lo() || x >= a.hi())) return out;
  const int n = a.cells();
  const double period = a.hi() - a.lo();
  // On a periodic axis, x wrapped into the period and the points' indices wrapped alike.
  const double wrapped = a.periodic() ? x - std::floor((x - a.lo()) / period) * period : x;
  const int cell = a.cell_at(wrapped);
  out.width = a.width(cell);
  const double radius = support_radius(kernel);
  const int reach = static_cast<int>(std::ceil(radius));
  // The nearest point at or below x: a face, or a cell centre.
  const int below = faces ? cell : (wrapped >= a.centre(cell) ? cell : cell - 1);
  double sum = 0;
  for (int i = below - reach + 1; i <= below + reach; ++i) {
    int stored = i;
    double shift = 0;
    if (a.periodic()) {
      const int turns = static_cast<int>(std::floor(static_cast<double>(i) / n));
      stored = i - turns * n;
      shift = turns * period;
    } else if (faces ? (i <= 0 || i >= n) : (i < 0 || i >= n)) {
      continue;  // a boundary face or beyond the wall: not an unknown
    }
    const double position = (faces ? a.face(stored) : a.centre(stored)) + shift;
    const double w = phi(kernel, (position - wrapped) / out.width);
    if (w <= 0) continue;
    out.index[static_cast<std::size_t>(out.size)] = stored;
    out.weight[static_cast<std::size_t>(out.size)] = w;
    ++out.size;
    sum += w;
  }
  if (!(sum > 0)) {
    out.size = 0;
    return out;
  }
  for (int k = 0; k < out.size; ++k) out.weight[static_cast<std::size_t>(k)] /= sum;
  return out;
}

bool KernelStencil::meets(const Box& box) const {
  for (int d = 0; d < 3; ++d) {
    const AxisWeights& a = axes[static_cast<std::size_t>(d)];
    bool any = false;
    for (int k = 0; k < a.size; ++k) {
      const PetscInt i = a.index[static_cast<std::size_t>(k)];
      any = any || (i >= box.lo[d] && i < box.hi[d]);
    }
    if (!any) return false;
  }
  return true;
}

KernelStencil kernel_stencil(const Grid& grid, int component, DeltaKernel kernel, const Point& x) {
  KernelStencil s;
  for (int d = 0; d < 3; ++d)
    s.axes[static_cast<std::size_t>(d)] = axis_weights(grid.axis(d), d == component, kernel, x[d]);
  return s;
}

}  // namespace cosim::fluid::ibm
