// Stokes drag on a fixed sphere in a periodic box against Hasimoto's periodic-array drag
// (H. Hasimoto, J. Fluid Mech. 5 (1959) 317), with both body treatments: the immersed
// boundary (IBM) and the staircase (FBM). The case itself, its steady state and the error
// measure are in bench/fluid_accuracy/cases.hpp, whose study runs the finer grids and more
// positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bench/fluid_accuracy/cases.hpp"

namespace cosim::fluid {

using ibm::DeltaKernel;
using ibm::IbmOptions;
using staircase::FbmOptions;
using staircase::kCalibratedSurfaceOffset;

namespace {

using bench::FluidRun;

// Off the grid's symmetry planes: at the box's centre the sphere sits on grid nodes at
// every level, where the staircase is at its most regular and its error least typical.
const Eigen::Vector3d kCentre(0.5, 0.5, 0.5), kGenericCentre(0.511, 0.523, 0.537);

// At most `max_steps` steps: the staircase settles within them, the immersed boundary comes
// within about 0.3 % of its steady error (bench/fluid_accuracy/README.md, "Accuracy study").
std::vector<double> errors_at(const BodyOptions& method, const Eigen::Vector3d& centre, const std::vector<int>& levels,
                              int max_steps = 1000) {
  std::vector<double> errors;
  for (int n : levels) {
    const FluidRun r = bench::hasimoto_sphere(n, method, centre, {.max_steps = max_steps});
    PetscPrintf(PETSC_COMM_WORLD,
                "Hasimoto sphere a/L = 0.2, %d^3 (d/h = %.1f), %s: error %+.3f %%, F over its momentum "
                "balance %.5f; %d steps, %.1f s\n",
                n, 0.4 * n, r.method.c_str(), 100 * r.error(), r.check, r.steps, r.seconds);
    EXPECT_NEAR(r.check, 1, 2e-3);
    errors.push_back(r.error());
  }
  return errors;
}

TEST(FbmHasimoto, StokesDragConverges) {
  const std::vector<int> levels{12, 16, 24};
  const std::vector<double> errors = errors_at(FbmOptions{}, kCentre, levels);
  // First order, with scatter from how the staircase meets the sphere: the error is that of
  // an effective radius about a quarter of a cell short (0.23 - 0.31 h up to 32^3).
  for (std::size_t l = 0; l < errors.size(); ++l) {
    EXPECT_LT(errors[l], 0);
    EXPECT_LT(-errors[l], 0.7 / (0.2 * levels[l]));
  }
  EXPECT_LT(-errors.back(), -0.5 * errors.front());
}

// The calibrated offset takes the quarter cell back: within a few per cent from a/h = 2.4
// on (without it: -26, -17, -9.5 % at these levels; -15 to -18 % at 16^3 over generic
// positions).
TEST(FbmHasimoto, CalibratedSurfaceOffsetRemovesTheStaircaseBias) {
  const std::vector<double> errors =
      errors_at(FbmOptions{.offset = kCalibratedSurfaceOffset}, kGenericCentre, {12, 16, 24});
  EXPECT_LT(std::abs(errors[0]), 0.035);
  EXPECT_LT(std::abs(errors[1]), 0.025);
  EXPECT_LT(std::abs(errors[2]), 0.01);
}

// The immersed boundary at d/h = 8, one of the two grids its retraction was calibrated on
// (IbmOptions), at two generic positions: within 1 % and the same at both to 0.3 %.
TEST(IbmHasimoto, WithinOnePerCentAtEightCellsPerDiameter) {
  const double a = errors_at(IbmOptions{}, kGenericCentre, {20})[0];
  const double b = errors_at(IbmOptions{}, Eigen::Vector3d(0.5 + 0.72 / 20, 0.5 + 0.31 / 20, 0.5 + 0.45 / 20), {20})[0];
  EXPECT_LT(std::abs(a), 0.01);
  EXPECT_LT(std::abs(b), 0.01);
  EXPECT_LT(std::abs(a - b), 0.003);
}

// Moved by whole cells so that it reaches across all three pairs of periodic faces (a fixed
// body may), the sphere is the same discrete problem: its markers and volume fractions wrap
// round, and the drag is the one at its place in the box's middle to the solvers' tolerance.
TEST(IbmHasimoto, ASphereAcrossThePeriodicFacesDragsAsInTheMiddle) {
  const int n = 20;
  const Eigen::Vector3d across = kGenericCentre - Eigen::Vector3d::Constant(10.0 / n);
  const FluidRun middle = bench::hasimoto_sphere(n, IbmOptions{}, kGenericCentre, {.max_steps = 300});
  const FluidRun corner = bench::hasimoto_sphere(n, IbmOptions{}, across, {.max_steps = 300});
  PetscPrintf(PETSC_COMM_WORLD, "Hasimoto sphere in the middle: error %+.6f %%, across the faces: %+.6f %%\n",
              100 * middle.error(), 100 * corner.error());
  EXPECT_EQ(middle.steps, corner.steps);
  EXPECT_NEAR(middle.error(), corner.error(), 1e-6);
  EXPECT_NEAR(corner.check, 1, 2e-3);
}

bench::Smoothness through_a_cell(const BodyOptions& method) {
  const bench::Smoothness s = bench::sphere_through_a_cell(method, 20);
  PetscPrintf(PETSC_COMM_WORLD,
              "sphere moved through a cell in 20 steps (d/h 8, Re 0.05), %s: drag %.4f, off its smooth course by at "
              "most %.4f %%, largest jump %.4f %%; %d steps, %.1f s\n",
              label(method).c_str(), s.mean_drag, 100 * s.spread, 100 * s.jump, s.steps, s.seconds);
  return s;
}

// The immersed boundary's force is smooth in the pose, the staircase's jumps when a face
// switches between fluid and body (by 2.5 % here): within 0.2 % of its smooth course and no
// step above 0.05 % of it. Roma's 3-point kernel, continuous but with kinks, leaves steps
// of 0.04 % of the drag; Bao et al.'s 6-point kernel, three times continuously
// differentiable, 0.003 %.
TEST(IbmMovingBody, DragIsSmoothInThePose) {
  const bench::Smoothness roma = through_a_cell(IbmOptions{});
  EXPECT_LT(roma.spread, 0.002);
  EXPECT_LT(roma.jump, 0.0005);
  IbmOptions bao6;
  bao6.kernel = DeltaKernel::bao6;
  const bench::Smoothness bao = through_a_cell(bao6);
  EXPECT_LT(bao.spread, 0.002);
  EXPECT_LT(bao.jump, 0.0005);
  const bench::Smoothness staircase = through_a_cell(FbmOptions{.offset = kCalibratedSurfaceOffset});
  EXPECT_GT(staircase.jump, 10 * roma.jump);
}

}  // namespace
}  // namespace cosim::fluid
