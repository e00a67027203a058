// The response of a body's window-mean load to changes of its motion (window_response.hpp):
// a sphere's is isotropic with the Stokes damping, and the kernel, superposed over an
// arbitrary history of velocity changes, gives the load the fluid itself gives for it, so
// the load cosim-fluid predicts for the next window (body_responses.hpp) is the fluid's.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fluid/window_response.hpp"

namespace cosim::fluid {

using bodies::BodyTreatment;
using bodies::RigidBody;
using grid::Axis;
using grid::BoundaryConditions;
using grid::Grid;
using grid::Point;
using ibm::IbmOptions;
using navier_stokes::FluidProperties;
using navier_stokes::NavierStokes;
using navier_stokes::StepReport;
using navier_stokes::TimeStepOptions;
using viscous::ViscosityModel;

namespace {

constexpr double kRadius = 0.0075, kRho = 970, kMu = 0.373, kWindow = 0.005;

// Ten Cate's oil around his sphere at d/h 6, windows of 5 ms.
struct Oil {
  Grid grid{PETSC_COMM_WORLD,
            {Axis::uniform(12, 0, 0.03, false), Axis::uniform(12, 0, 0.03, false), Axis::uniform(12, 0, 0.03, false)}};
  RigidBody sphere{geometry::Sphere(kRadius), geometry::Pose({0.015, 0.015, 0.015}, Eigen::Quaterniond::Identity())};
  FluidProperties fluid{kRho, ViscosityModel::newtonian(kMu), {}};
  TimeStepOptions steps{.dt_max = kWindow, .dt_initial = kWindow};
};

TEST(WindowResponse, ASpheresIsIsotropicWithTheStokesDamping) {
  const Oil oil;
  const WindowResponse r = window_response(oil.grid, oil.sphere, oil.fluid, oil.steps, IbmOptions{}, kWindow);
  const double volume = 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3),
               stokes = 6 * std::numbers::pi * kMu * kRadius;
  const Eigen::Matrix3d a = r.added_mass.topLeftCorner<3, 3>();
  PetscPrintf(PETSC_COMM_WORLD,
              "sphere at d/h 6 in ten Cate's oil, 5 ms windows: A / (rho V) = %.4f %.4f %.4f, "
              "K_0 / (6 pi mu r) = %.3f, K_1 %.3f, K_15 %.3f\n",
              a(0, 0) / (kRho * volume), a(1, 1) / (kRho * volume), a(2, 2) / (kRho * volume),
              r.kernel[0](0, 0) / stokes, r.kernel[1](0, 0) / stokes, r.kernel[15](0, 0) / stokes);
  EXPECT_NEAR(r.added_damping(0, 0), stokes, 1e-12 * stokes);
  EXPECT_NEAR(r.added_damping(4, 4), 8 * std::numbers::pi * kMu * std::pow(kRadius, 3), 1e-18);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(a(i, i), a(0, 0), 0.02 * a(0, 0));
    EXPECT_GT(a(i, i), 0.2 * kRho * volume);  // the inertia of fluid the body moves
    for (int j = 0; j < 3; ++j) {
      if (j != i) {
        EXPECT_LT(std::abs(a(i, j)), 0.01 * a(0, 0));
      }
    }
  }
  EXPECT_EQ(r.kernel.size(), static_cast<std::size_t>(kResponseWindows));
}

// Guards against: a kernel that does not superpose, which would make the predicted load
// of the next window wrong. The sphere in fluid at rest is given velocity changes of
// different sizes and signs in successive windows (ramped within each); the fluid's own
// window-mean loads match the kernel's superposition -sum_n K_n d_(k-n) to 1 % of their
// largest.
TEST(WindowResponse, TheKernelSuperposesToTheFluidsOwnLoad) {
  const Oil oil;
  const WindowResponse r = window_response(oil.grid, oil.sphere, oil.fluid, oil.steps, IbmOptions{}, kWindow);
  const double h = 0.03 / 12, unit = 1e-3 * h / kWindow;
  const std::vector<double> changes{1.0, -0.5, 0.0, 2.0, -1.5, 0.3};
  // The fluid itself, on a periodic box like window_response's.
  const int cells = 2 * static_cast<int>(std::ceil(4 * kRadius / h));
  const Axis axis = Axis::uniform(cells, -0.5 * cells * h, 0.5 * cells * h, true);
  Grid box(PETSC_COMM_WORLD, {axis, axis, axis});
  BoundaryConditions bc(box);
  NavierStokes flow(box, bc, oil.fluid, oil.steps);
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  const std::unique_ptr<BodyTreatment> bodies = make_bodies(box, IbmOptions{});
  const Eigen::Vector3d centre = h * Eigen::Vector3d(0.137, 0.291, 0.413);
  bodies->add({oil.sphere.shape, geometry::Pose(centre, Eigen::Quaterniond::Identity())});
  double largest = 0, worst = 0, x = 0, v = 0;
  for (std::size_t k = 0; k < changes.size(); ++k) {
    const double v0 = v, x0 = x, d = changes[k] * unit, t0 = static_cast<double>(k) * kWindow;
    double mean = 0;
    flow.advance_to(
        t0 + kWindow, bodies->for_step(),
        [&](double t) {
          const double s = t - t0;
          bodies->move(0,
                       geometry::Pose(centre + Eigen::Vector3d(x0 + v0 * s + 0.5 * d * s * s / kWindow, 0, 0),
                                      Eigen::Quaterniond::Identity()),
                       {v0 + d * s / kWindow, 0, 0}, Eigen::Vector3d::Zero());
        },
        [&](const StepReport& step) { mean += bodies->loads(flow)[0].force.x() * step.dt / kWindow; });
    v = v0 + d;
    x = x0 + (v0 + 0.5 * d) * kWindow;
    double predicted = 0;
    for (std::size_t j = 0; j <= k; ++j) predicted -= r.kernel[k - j](0, 0) * changes[j] * unit;
    largest = std::max(largest, std::abs(mean));
    worst = std::max(worst, std::abs(mean - predicted));
  }
  PetscPrintf(PETSC_COMM_WORLD, "kernel superposed over six windows: off the fluid's loads by %.2e of the largest\n",
              worst / largest);
  EXPECT_LT(worst, 0.01 * largest);
}

}  // namespace
}  // namespace cosim::fluid
