// Taylor-Green vortex, two-dimensional in a periodic box one cell thick across its plane:
// u_a = sin x_a cos x_b F(t), u_b = -cos x_a sin x_b F(t), F = exp(-2 nu t), an exact
// solution of the Navier-Stokes equations in which convection is balanced by the pressure.
// The (x, y) plane and the (y, z) plane exercise all three velocity components.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tests/fluid/flow_checks.hpp"

namespace cosim::fluid {

using grid::Axis;
using grid::BoundaryConditions;
using grid::Grid;
using grid::Point;
using navier_stokes::FluidProperties;
using navier_stokes::NavierStokes;
using navier_stokes::StepReport;
using viscous::ViscosityModel;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNu = 0.05;
constexpr double kEnd = 1.0;

struct Plane {
  int a, b;
};

Grid periodic_box(int n, Plane plane) {
  std::array<Axis, 3> axes{Axis::uniform(1, 0, 1, true), Axis::uniform(1, 0, 1, true), Axis::uniform(1, 0, 1, true)};
  axes[static_cast<std::size_t>(plane.a)] = Axis::uniform(n, 0, 2 * kPi, true);
  axes[static_cast<std::size_t>(plane.b)] = Axis::uniform(n, 0, 2 * kPi, true);
  return Grid(PETSC_COMM_WORLD, std::move(axes));
}

Point vortex(const Point& x, double t, Plane plane) {
  const double f = std::exp(-2 * kNu * t);
  const auto a = static_cast<std::size_t>(plane.a), b = static_cast<std::size_t>(plane.b);
  Point u{0, 0, 0};
  u[a] = std::sin(x[a]) * std::cos(x[b]) * f;
  u[b] = -std::cos(x[a]) * std::sin(x[b]) * f;
  return u;
}

// Runs to kEnd with a fixed step; checks the divergence after every step.
void run(NavierStokes& flow, double dt, Plane plane) {
  flow.set_velocity([plane](const Point& x) { return vortex(x, 0, plane); });
  const int steps = static_cast<int>(std::lround(kEnd / dt));
  for (int s = 0; s < steps; ++s) {
    const StepReport r = flow.step(dt);
    ASSERT_LT(r.max_divergence, 1e-8) << "step " << s;
  }
}

double velocity_error(const NavierStokes& flow, Plane plane) {
  double e = 0;
  for (int c = 0; c < 3; ++c)
    e = std::max(e, testing::max_error(flow, c, [&](const Point& x) { return vortex(x, flow.time(), plane)[c]; }));
  return e;
}

std::vector<double> orders(const std::vector<double>& errors) {
  std::vector<double> o;
  for (std::size_t i = 1; i < errors.size(); ++i) o.push_back(std::log2(errors[i - 1] / errors[i]));
  return o;
}

const FluidProperties kFluid{1.0, ViscosityModel::newtonian(kNu), {0, 0, 0}};

// Grid and step refined together (dt ~ h): both error terms are O(h^2).
TEST(TaylorGreen, SecondOrderInSpace) {
  for (Plane plane : {Plane{0, 1}, Plane{1, 2}}) {
    std::vector<double> errors;
    for (int n : {16, 32, 64}) {
      Grid grid = periodic_box(n, plane);
      BoundaryConditions bc(grid);
      NavierStokes flow(grid, bc, kFluid, {});
      run(flow, 1.6 / n, plane);
      errors.push_back(velocity_error(flow, plane));
    }
    const auto o = orders(errors);
    PetscPrintf(PETSC_COMM_WORLD,
                "Taylor-Green space, plane %c%c (n = 16, 32, 64; dt = 1.6/n): errors %.3e %.3e %.3e, orders "
                "%.2f %.2f\n",
                "xyz"[plane.a], "xyz"[plane.b], errors[0], errors[1], errors[2], o[0], o[1]);
    for (double order : o) EXPECT_GT(order, 1.8);
  }
}

// Fixed grid, against a run with a much smaller step on the same grid, so the spatial error cancels.
TEST(TaylorGreen, SecondOrderInTime) {
  const Plane plane{0, 1};
  Grid grid = periodic_box(32, plane);
  BoundaryConditions bc(grid);
  NavierStokes reference(grid, bc, kFluid, {});
  run(reference, 1.0 / 160, plane);
  std::vector<double> errors;
  for (double dt : {0.2, 0.1, 0.05}) {
    NavierStokes flow(grid, bc, kFluid, {});
    run(flow, dt, plane);
    errors.push_back(testing::max_difference(flow, reference));
  }
  const auto o = orders(errors);
  PetscPrintf(PETSC_COMM_WORLD,
              "Taylor-Green time (n = 32; dt = 0.2, 0.1, 0.05): errors %.3e %.3e %.3e, orders %.2f %.2f\n", errors[0],
              errors[1], errors[2], o[0], o[1]);
  for (double order : o) EXPECT_GT(order, 1.8);
}

// Adaptive steps: CFL-limited (the largest face velocity is cos(h/2) F(t), so dt <= 0.5 h /
// (cos(h/2) F)), never growing by more than 1.2, and the last ones shortened to land
// exactly on the end time.
TEST(TaylorGreen, AdaptiveStepsLandOnTheEndTime) {
  const Plane plane{0, 1};
  Grid grid = periodic_box(16, plane);
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, kFluid, {.cfl = 0.5, .dt_max = 0.3, .dt_initial = 0.01});
  flow.set_velocity([plane](const Point& x) { return vortex(x, 0, plane); });
  const auto reports = flow.advance_to(2.5);
  ASSERT_FALSE(reports.empty());
  EXPECT_EQ(flow.time(), 2.5);
  EXPECT_NEAR(reports.back().time, 2.5, 1e-12);
  const double h = 2 * kPi / 16;
  for (std::size_t s = 0; s < reports.size(); ++s) {
    EXPECT_LT(reports[s].max_divergence, 1e-8);
    EXPECT_LE(reports[s].dt, 0.3);
    EXPECT_LE(reports[s].dt, 0.5 * h / std::cos(h / 2) * std::exp(2 * kNu * reports[s].time) * 1.001);
    if (s > 0) {
      EXPECT_LE(reports[s].dt, 1.2 * reports[s - 1].dt + 1e-15);
    }
  }
  PetscPrintf(PETSC_COMM_WORLD, "Taylor-Green adaptive: %zu steps to t = 2.5, last dt %.4f, velocity error %.2e\n",
              reports.size(), reports.back().dt, velocity_error(flow, plane));
}

// Windows of whole numbers of dt_max take exactly that many steps, every window alike,
// although the running time carries rounding (0.1 is not exact in binary).
TEST(TaylorGreen, WindowsOfWholeStepsTakeThatManySteps) {
  const Plane plane{0, 1};
  Grid grid = periodic_box(8, plane);
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, kFluid, {.cfl = 10, .dt_max = 0.01, .dt_initial = 0.01});
  flow.set_velocity([plane](const Point& x) { return vortex(x, 0, plane); });
  for (int k = 1; k <= 20; ++k) {
    const auto reports = flow.advance_to(0.05 * k);
    ASSERT_EQ(reports.size(), 5u) << "window " << k;
    for (const StepReport& r : reports) EXPECT_NEAR(r.dt, 0.01, 1e-12) << "window " << k;
  }
}

// Galilean invariance: the vortex seen from a frame moving at -V is carried along at V,
// u(x, t) = vortex(x - V t, t) + V, and the solver follows it to second order (grid and
// step refined together; its error is mostly the discrete convection by V).
TEST(TaylorGreen, AShiftedFrameCarriesTheVortexAlong) {
  const Plane plane{0, 1};
  const Point V{0.7, -0.4, 0};
  std::vector<double> errors;
  for (int n : {32, 64}) {
    Grid grid = periodic_box(n, plane);
    BoundaryConditions bc(grid);
    NavierStokes flow(grid, bc, kFluid, {});
    flow.set_velocity([plane](const Point& x) { return vortex(x, 0, plane); });
    flow.shift_frame(V);
    for (int s = 0; s < n; ++s) ASSERT_LT(flow.step(1.0 / n).max_divergence, 1e-8);
    double error = 0;
    for (int c = 0; c < 3; ++c)
      error = std::max(error, testing::max_error(flow, c, [&](const Point& x) {
                         const double t = flow.time();
                         return vortex({x[0] - V[0] * t, x[1] - V[1] * t, x[2]}, t, plane)[c] + V[c];
                       }));
    errors.push_back(error);
  }
  const double order = orders(errors)[0];
  PetscPrintf(PETSC_COMM_WORLD,
              "Taylor-Green carried at (0.7, -0.4) to t = 1 (n = 32, 64; dt = 1/n): errors %.3e %.3e, "
              "order %.2f\n",
              errors[0], errors[1], order);
  EXPECT_LT(errors[0], 1e-2);
  EXPECT_GT(order, 1.8);
}

TEST(TaylorGreen, AChangeOfFrameNeedsAPeriodicGrid) {
  Grid grid(PETSC_COMM_WORLD,
            {Axis::uniform(4, 0, 1, true), Axis::uniform(4, 0, 1, false), Axis::uniform(1, 0, 1, true)});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, kFluid, {});
  EXPECT_THROW(flow.shift_frame({1, 0, 0}), std::logic_error);
}

}  // namespace
}  // namespace cosim::fluid
