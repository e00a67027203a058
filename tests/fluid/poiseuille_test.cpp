// Pressure-driven flow between plates and in a square duct, and the same parabola fed by
// an inflow profile to an outflow. On stretched grids the three-point differences and
// the quadratic wall closure reproduce a parabola exactly, so plates and channel must
// match the analytic profile to solver tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/fluid/flow_checks.hpp"

namespace cosim::fluid {

using grid::Axis;
using grid::Boundary;
using grid::BoundaryConditions;
using grid::Box;
using grid::Grid;
using grid::Point;
using grid::Side;
using navier_stokes::NavierStokes;
using viscous::ViscosityModel;

namespace {

constexpr double kMu = 1.0;
constexpr double kDrive = 8.0;  // -dp/dx / rho, so u_max = kDrive / (8 nu) = 1 between plates 0 < y < 1

double plates(double y) { return kDrive / (2 * kMu) * y * (1 - y); }

TEST(Poiseuille, PlatesOnStretchedGridExact) {
  Grid grid(PETSC_COMM_WORLD,
            {Axis::uniform(4, 0, 1, true), Axis::stretched(10, 0, 1, 1.5, false), Axis::uniform(1, 0, 1, true)});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(kMu), {kDrive, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 0.05});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  const double t = testing::run_to_steady_state(flow, 1e-10, 50, 1e-9);
  const double error = testing::max_error(flow, 0, [](const Point& x) { return plates(x[1]); });
  PetscPrintf(PETSC_COMM_WORLD, "Poiseuille plates (4 x 10 stretched): steady at t = %.2f, max |u - exact| = %.2e\n", t,
              error);
  EXPECT_LT(error, 1e-8);
  EXPECT_LT(testing::max_error(flow, 1, [](const Point&) { return 0.0; }), 1e-10);
}

TEST(Poiseuille, InflowProfileToOutflowExact) {
  Grid grid(PETSC_COMM_WORLD,
            {Axis::uniform(8, 0, 2, false), Axis::stretched(10, 0, 1, 1.5, false), Axis::uniform(1, 0, 1, true)});
  BoundaryConditions bc(grid);
  bc.set(0, Side::lower, Boundary::inflow([](const Point& x, double) { return Point{plates(x[1]), 0, 0}; }));
  bc.set(0, Side::upper, Boundary::outflow());
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(kMu), {0, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 0.05});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  // The impulsive start puts O(1/dt) divergence into u*, so the projected one is larger too.
  const double t = testing::run_to_steady_state(flow, 1e-10, 50, 1e-8);
  const double error = testing::max_error(flow, 0, [](const Point& x) { return plates(x[1]); });
  // Pressure: zero on the outflow face, falling linearly by kDrive * mu per unit length.
  const Box b = grid.owned(grid.pressure_dm());
  const PetscScalar*** p = nullptr;
  DMDAVecGetArrayRead(grid.pressure_dm(), flow.pressure(), &p);
  double p_error = 0;
  for (PetscInt j = b.lo[1]; j < b.hi[1]; ++j)
    for (PetscInt i = b.lo[0]; i < b.hi[0]; ++i)
      p_error = std::max(p_error, std::abs(p[0][j][i] - kDrive * kMu * (2 - grid.axis(0).centre(static_cast<int>(i)))));
  DMDAVecRestoreArrayRead(grid.pressure_dm(), flow.pressure(), &p);
  MPI_Allreduce(MPI_IN_PLACE, &p_error, 1, MPI_DOUBLE, MPI_MAX, grid.comm());
  PetscPrintf(PETSC_COMM_WORLD,
              "Poiseuille inflow/outflow (8 x 10): steady at t = %.2f, max |u - exact| = %.2e, max |p - "
              "exact| = %.2e\n",
              t, error, p_error);
  EXPECT_LT(error, 1e-8);
  EXPECT_LT(p_error, 1e-6);
}

// Square duct 0 < y, z < 1: u = (G/nu) sum over odd m, n of 16 sin(m pi y) sin(n pi z) / (pi^4 m n (m^2 +
// n^2)).
double duct(double y, double z) {
  constexpr double pi = std::numbers::pi;
  double sum = 0;
  for (int m = 1; m < 400; m += 2)
    for (int n = 1; n < 400; n += 2)
      sum += 16 * std::sin(m * pi * y) * std::sin(n * pi * z) / (std::pow(pi, 4) * m * n * (m * m + n * n));
  return kDrive / kMu * sum;
}

TEST(Poiseuille, SquareDuctSecondOrder) {
  double errors[2];
  const int sizes[2] = {16, 32};
  for (int level = 0; level < 2; ++level) {
    const int n = sizes[level];
    Grid grid(PETSC_COMM_WORLD,
              {Axis::uniform(1, 0, 1, true), Axis::uniform(n, 0, 1, false), Axis::uniform(n, 0, 1, false)});
    BoundaryConditions bc(grid);
    NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(kMu), {kDrive, 0, 0}},
                      {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 0.05});
    flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
    testing::run_to_steady_state(flow, 1e-9, 50, 1e-9);
    errors[level] = testing::max_error(flow, 0, [](const Point& x) { return duct(x[1], x[2]); });
  }
  const double order = std::log2(errors[0] / errors[1]);
  PetscPrintf(PETSC_COMM_WORLD,
              "Poiseuille square duct (16^2, 32^2): max errors %.3e %.3e (u_max 0.5623), order %.2f\n", errors[0],
              errors[1], order);
  // The corners carry an r^2 log r singularity (the forcing does not vanish there), which
  // keeps the max-norm order a little under 2 on coarse grids.
  EXPECT_GT(order, 1.75);
  EXPECT_LT(errors[1], 5e-4);
}

}  // namespace
}  // namespace cosim::fluid
