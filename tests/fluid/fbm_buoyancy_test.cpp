// Archimedes: a fixed body in fluid at rest under gravity feels the buoyancy rho g V,
// from the pressure part of the volume integral alone. Summation by parts makes the
// discrete integral of a linear pressure against the indicator of the imposed vertical
// faces exactly rho g times their volume V_z (the sum of their control volumes), acting at
// their centroid, so force and torque match that to solver tolerance; V_z approaches V
// with resolution.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/fluid/flow_checks.hpp"
#include "fluid/staircase/fictitious_boundary.hpp"

namespace cosim::fluid {

using bodies::HydrodynamicLoad;
using bodies::ImposedFace;
using grid::Axis;
using grid::BoundaryConditions;
using grid::Grid;
using grid::Point;
using navier_stokes::NavierStokes;
using staircase::FictitiousBoundary;
using viscous::ViscosityModel;

namespace {

constexpr double kDensity = 2.0, kGravity = 3.0;

void expect_buoyancy(const geometry::Shape& shape, const Eigen::Quaterniond& orientation, int subsamples) {
  Grid grid(PETSC_COMM_WORLD,
            {Axis::uniform(16, 0, 1, false), Axis::stretched(16, 0, 1, 0.6, false), Axis::uniform(16, 0, 1.2, false)});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {kDensity, ViscosityModel::newtonian(0.2), {0, 0, -kGravity}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 0.05, .theta = 1.0});
  FictitiousBoundary fbm(grid, {.subsamples = subsamples});
  const std::size_t b = fbm.add({shape, geometry::Pose({0.47, 0.52, 0.61}, orientation)});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  testing::run_to_steady_state(flow, 1e-10, 15, 1e-8, fbm.for_step());
  const HydrodynamicLoad load = fbm.loads(flow)[b];
  const double exact = kDensity * kGravity * geometry::volume(shape);
  // Volume and first moment about the centre of mass of the imposed vertical faces.
  const Axis& z = grid.axis(2);
  double sums[4] = {};
  for (const ImposedFace& f : fbm.imposed_faces().owned(2)) {
    const auto k = static_cast<int>(f.at[2]);
    const double volume = grid.axis(0).width(static_cast<int>(f.at[0])) *
                          grid.axis(1).width(static_cast<int>(f.at[1])) * (z.centre(k) - z.centre(k - 1));
    const Point x = grid.position(2, f.at);
    sums[0] += volume;
    for (std::size_t d = 0; d < 3; ++d)
      sums[d + 1] += volume * (x[d] - fbm.body(b).pose.position()[static_cast<Eigen::Index>(d)]);
  }
  MPI_Allreduce(MPI_IN_PLACE, sums, 4, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  const double grid_buoyancy = kDensity * kGravity * sums[0];
  const Eigen::Vector3d grid_torque =
      kDensity * kGravity * Eigen::Vector3d(sums[1], sums[2], sums[3]).cross(Eigen::Vector3d::UnitZ());
  PetscPrintf(PETSC_COMM_WORLD,
              "FBM buoyancy (16^3, %d^3 sub-samples), steady at t = %.1f: F = (%.2e, %.2e, %.6f), rho g V_z = %.6f, "
              "rho g V = %.6f, |T| = %.2e (V_z centroid's %.2e)\n",
              subsamples, flow.time(), load.force[0], load.force[1], load.force[2], grid_buoyancy, exact,
              load.torque.norm(), grid_torque.norm());
  EXPECT_NEAR(load.force[2], grid_buoyancy, 1e-5 * exact);
  EXPECT_NEAR(load.force[0], 0, 1e-5 * exact);
  EXPECT_NEAR(load.force[1], 0, 1e-5 * exact);
  EXPECT_LT((load.torque - grid_torque).norm(), 1e-9);
  EXPECT_NEAR(load.force[2], exact, 0.03 * exact);
}

TEST(FbmBuoyancy, SphereArchimedes) {
  expect_buoyancy(geometry::Sphere(0.2), Eigen::Quaterniond::Identity(), 1);
  expect_buoyancy(geometry::Sphere(0.2), Eigen::Quaterniond::Identity(), 4);
}

TEST(FbmBuoyancy, RotatedBoxArchimedes) {
  expect_buoyancy(geometry::Box({0.2, 0.12, 0.08}),
                  Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -1, 2).normalized())), 4);
}

}  // namespace
}  // namespace cosim::fluid
