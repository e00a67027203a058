// The 2D DFG benchmark 2D-1 (M. Schäfer, S. Turek, Notes Numer. Fluid Mech. 52, 1996, 547):
// channel 2.2 x 0.41, cylinder D = 0.1 at (0.2, 0.2), parabolic inflow with U_max = 0.3,
// nu = 1e-3, Re = U_mean D / nu = 20, steady: C_D = 5.5795, C_L = 0.010619 with
// C = 2 F / (rho U_mean^2 D) per unit length. Two-dimensional here: one periodic cell
// layer in z with the cylinder (axis z) spanning it, on a grid uniform around the cylinder
// and stretched downstream. The finer levels (20 cells per diameter takes over a minute)
// are in the accuracy study bench/fluid_accuracy.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/fluid/flow_checks.hpp"
#include "fluid/staircase/fictitious_boundary.hpp"

namespace cosim::fluid {

using grid::Axis;
using grid::Boundary;
using grid::BoundaryConditions;
using grid::Grid;
using grid::Point;
using grid::Side;
using navier_stokes::NavierStokes;
using navier_stokes::StepReport;
using staircase::FictitiousBoundary;
using viscous::ViscosityModel;

namespace {

constexpr double kLength = 2.2, kHeight = 0.41, kDiameter = 0.1, kUMax = 0.3, kThickness = 0.01;

// Cells of size h up to x = 0.6, then growing by 6 % per cell to the outflow.
Axis channel_axis(double h) {
  std::vector<double> faces{0};
  while (faces.back() < 0.6 - 1e-12) faces.push_back(faces.back() + h);
  for (double w = h * 1.06; faces.back() + w < kLength; w *= 1.06) faces.push_back(faces.back() + w);
  faces.back() = kLength;
  return Axis::from_faces(faces, false);
}

double inflow(double y) { return 4 * kUMax * y * (kHeight - y) / (kHeight * kHeight); }

struct Coefficients {
  double drag, lift, time;
  int cells;
};

Coefficients dfg_cylinder(int cells_across) {
  const double h = kHeight / cells_across;
  Grid grid(PETSC_COMM_WORLD,
            {channel_axis(h), Axis::uniform(cells_across, 0, kHeight, false), Axis::uniform(1, 0, kThickness, true)});
  BoundaryConditions bc(grid);
  bc.set(0, Side::lower, Boundary::inflow([](const Point& x, double) { return Point{inflow(x[1]), 0, 0}; }));
  bc.set(0, Side::upper, Boundary::outflow());
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(1e-3), {0, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 1e-3});
  FictitiousBoundary fbm(grid);
  const std::size_t b = fbm.add({geometry::Cylinder(kDiameter / 2, 3 * kThickness),
                                 geometry::Pose({0.2, 0.2, kThickness / 2}, Eigen::Quaterniond::Identity())});
  flow.set_velocity([](const Point& x) { return Point{inflow(x[1]), 0, 0}; });
  const double scale = 2 / (kDiameter * kThickness * (2 * kUMax / 3) * (2 * kUMax / 3));
  double drag = 0, previous = 0;
  // Steady when C_D changes by less than 1e-4 over half a time unit.
  for (double t = 0.5; t <= 12; t += 0.5) {
    for (const StepReport& r : flow.advance_to(t, fbm.for_step())) EXPECT_LT(r.max_divergence, 1e-7);
    previous = drag;
    drag = scale * fbm.loads(flow)[b].force[0];
    if (std::abs(drag - previous) < 1e-4 * drag) break;
  }
  const auto n = grid.cells();
  return {drag, scale * fbm.loads(flow)[b].force[1], flow.time(), static_cast<int>(n[0] * n[1])};
}

constexpr double kDrag = 5.5795, kLift = 0.010619;

Coefficients report(int cells_across) {
  const double start = MPI_Wtime();
  const Coefficients c = dfg_cylinder(cells_across);
  PetscPrintf(PETSC_COMM_WORLD,
              "DFG 2D-1 cylinder, D/h = %.0f (%d cells): steady at t = %.1f, C_D = %.4f (%+.2f %%), C_L = %.4f "
              "(reference %.4f, %.6f); %.1f s\n",
              kDiameter * cells_across / kHeight, c.cells, c.time, c.drag, 100 * (c.drag - kDrag) / kDrag, c.lift,
              kDrag, kLift, MPI_Wtime() - start);
  return c;
}

TEST(FbmDfgCylinder, Re20TenCellsPerDiameter) {
  const Coefficients c = report(41);
  EXPECT_NEAR(c.drag, kDrag, 0.05 * kDrag);
  EXPECT_NEAR(c.lift, kLift, 0.1 * kLift);
}

}  // namespace
}  // namespace cosim::fluid
