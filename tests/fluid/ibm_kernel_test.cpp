// The immersed boundary's regularized delta kernels and their stencils on the MAC grid:
// the moment conditions each kernel is defined by, at every shift against the grid, and
// interpolation and spreading adjoint to round-off, next to walls and across periodic
// faces too.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fluid/ibm/delta_kernel.hpp"
#include "fluid/ibm/kernel_stencil.hpp"

namespace cosim::fluid {

using grid::Axis;
using grid::Box;
using grid::Grid;
using grid::Index;
using grid::Point;
using ibm::axis_weights;
using ibm::AxisWeights;
using ibm::DeltaKernel;
using ibm::for_each_point;
using ibm::kernel_stencil;
using ibm::KernelStencil;
using ibm::name;
using ibm::phi;
using ibm::sum_of_squares;
using ibm::support_radius;

namespace {

constexpr DeltaKernel kKernels[] = {DeltaKernel::roma3, DeltaKernel::peskin4, DeltaKernel::bao6};

struct Moments {
  double sum = 0, first = 0, second = 0, third = 0, squares = 0;
};

Moments moments(DeltaKernel kernel, double r) {
  Moments m;
  for (int j = -4; j <= 4; ++j) {
    const double x = r - j, w = phi(kernel, x);
    m.sum += w;
    m.first += x * w;
    m.second += x * x * w;
    m.third += x * x * x * w;
    m.squares += w * w;
  }
  return m;
}

TEST(DeltaKernel, MomentConditionsHoldAtEveryShift) {
  const double k6 = 59.0 / 60 - std::sqrt(29.0) / 20;
  EXPECT_DOUBLE_EQ(sum_of_squares(DeltaKernel::roma3), 0.5);
  EXPECT_DOUBLE_EQ(sum_of_squares(DeltaKernel::peskin4), 3.0 / 8);
  for (DeltaKernel kernel : kKernels)
    for (int i = 0; i <= 100; ++i) {
      const double r = i / 100.0;
      const Moments m = moments(kernel, r);
      SCOPED_TRACE(std::string(name(kernel)) + " at r = " + std::to_string(r));
      EXPECT_NEAR(m.sum, 1, 1e-14);
      EXPECT_NEAR(m.first, 0, 1e-14);
      EXPECT_NEAR(m.squares, sum_of_squares(kernel), 1e-14);
      if (kernel == DeltaKernel::bao6) {
        EXPECT_NEAR(m.second, k6, 1e-13);
        EXPECT_NEAR(m.third, 0, 1e-13);
      }
      EXPECT_GE(phi(kernel, r), 0);
      EXPECT_EQ(phi(kernel, support_radius(kernel) + r), 0);
      EXPECT_DOUBLE_EQ(phi(kernel, -r), phi(kernel, r));
    }
}

// phi is continuous (roma3), once (peskin4) or three times (bao6) continuously
// differentiable: its second difference at the breakpoints shrinks with the step like a
// smooth function's, h^2 for C^1, and the jump of a C^0 kernel's slope shows as h^1.
TEST(DeltaKernel, SmoothAtTheBreakpoints) {
  for (DeltaKernel kernel : kKernels) {
    const double radius = support_radius(kernel);
    for (double at = 0.5; at <= radius; at += 0.5) {
      const double h = 1e-4;
      const double jump = std::abs(phi(kernel, at - h) - phi(kernel, at));
      EXPECT_LT(jump, 1e-3) << name(kernel) << " at " << at;  // continuous everywhere
      if (kernel != DeltaKernel::roma3) {
        const double second = std::abs(phi(kernel, at + h) - 2 * phi(kernel, at) + phi(kernel, at - h));
        EXPECT_LT(second, 50 * h * h) << name(kernel) << " at " << at;
      }
    }
  }
}

// A field g at the points of component c and forces F_l at markers: spreading F then
// integrating against g equals interpolating g at the markers and summing F dV_l G(X_l).
double adjoint_mismatch(const Grid& grid, int c, DeltaKernel kernel, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0, 1);
  const Box all{{0, 0, 0}, {grid.axis(0).cells() + 1, grid.axis(1).cells() + 1, grid.axis(2).cells() + 1}};
  const auto g = [](const Index& p) { return std::sin(1.0 + p[0]) + std::cos(2.0 * p[1]) * (1.0 + 0.1 * p[2]); };
  double spread_side = 0, marker_side = 0, scale = 0;
  for (int l = 0; l < 20; ++l) {
    Point x;
    for (int d = 0; d < 3; ++d) {
      const Axis& a = grid.axis(d);
      // Half of the markers within two cells of a wall or a periodic face.
      const double near_end = l % 2 == 0 ? 2 * a.width(0) * unit(random) : (a.hi() - a.lo()) * unit(random);
      x[d] = a.lo() + std::max(1e-9, near_end);
    }
    const KernelStencil s = kernel_stencil(grid, c, kernel, x);
    if (s.empty()) continue;
    const double force = unit(random) - 0.5, volume = 0.5 + unit(random);
    double interpolated = 0, weights = 0;
    for_each_point(s, all, [&](const Index& p, double w) {
      interpolated += w * g(p);
      weights += w;
      spread_side += (force * volume * w / grid.face_volume(c, p)) * g(p) * grid.face_volume(c, p);
    });
    EXPECT_NEAR(weights, 1, 1e-14);
    marker_side += force * volume * interpolated;
    scale += std::abs(force * volume * interpolated);
  }
  return std::abs(spread_side - marker_side) / scale;
}

TEST(KernelStencil, InterpolationAndSpreadingAreAdjoint) {
  std::mt19937 random(7);
  // Walls in x and y (y stretched), periodic in z.
  Grid grid(PETSC_COMM_SELF,
            {Axis::uniform(12, 0, 1.2, false), Axis::stretched(10, 0, 1, 0.8, false), Axis::uniform(8, 0, 0.8, true)});
  for (DeltaKernel kernel : kKernels)
    for (int c = 0; c < 3; ++c) EXPECT_LT(adjoint_mismatch(grid, c, kernel, random), 1e-14) << name(kernel) << " " << c;
}

// Away from walls on a uniform axis the kernel's own weights (sum one, first moment zero)
// interpolate a linear field exactly; next to a wall the normalised weights still
// interpolate a constant exactly and never reach a boundary face or a ghost.
TEST(KernelStencil, LinearFieldsInsideConstantsEverywhere) {
  const Axis a = Axis::uniform(16, 0, 1.6, false);
  for (DeltaKernel kernel : kKernels)
    for (bool faces : {false, true}) {
      for (double x : {0.55, 0.613, 0.8, 1.0049}) {
        const AxisWeights w = axis_weights(a, faces, kernel, x);
        double sum = 0, linear = 0;
        for (int k = 0; k < w.size; ++k) {
          const double at = faces ? a.face(static_cast<int>(w.index[k])) : a.centre(static_cast<int>(w.index[k]));
          sum += w.weight[k];
          linear += w.weight[k] * at;
        }
        EXPECT_NEAR(sum, 1, 1e-14);
        EXPECT_NEAR(linear, x, 1e-14) << name(kernel) << " at " << x;
      }
      for (double x : {0.01, 0.07, 0.12, 1.55, 1.599}) {
        const AxisWeights w = axis_weights(a, faces, kernel, x);
        double sum = 0;
        for (int k = 0; k < w.size; ++k) {
          sum += w.weight[k];
          EXPECT_GE(w.index[k], faces ? 1 : 0);
          EXPECT_LE(w.index[k], faces ? 15 : 15);
        }
        EXPECT_GT(w.size, 0);
        EXPECT_NEAR(sum, 1, 1e-14);
      }
      EXPECT_EQ(axis_weights(a, faces, kernel, -0.01).size, 0);
    }
}

}  // namespace
}  // namespace cosim::fluid
