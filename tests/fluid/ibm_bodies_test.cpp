// The immersed boundary's bodies in the flow: volume fractions continuous in the pose, the
// inner fluid's momentum in the load, a moving and spinning body through fluid at rest
// with operators that never change, and bodies close to a wall and to each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/fluid/flow_checks.hpp"
#include "fluid/body_methods.hpp"
#include "fluid/ibm/volume_fraction.hpp"

namespace cosim::fluid {

using bodies::BodyTreatment;
using bodies::HydrodynamicLoad;
using bodies::IndicatorPatch;
using grid::Axis;
using grid::BoundaryConditions;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::Point;
using ibm::IbmOptions;
using ibm::ImmersedBoundary;
using ibm::level_set_fraction;
using navier_stokes::NavierStokes;
using staircase::FbmOptions;
using staircase::kCalibratedSurfaceOffset;
using viscous::ViscosityModel;

namespace {

constexpr double pi = std::numbers::pi;

// sum alpha dV over this rank's cells, summed over the ranks.
double grid_volume(const Grid& grid, const BodyTreatment& bodies, std::size_t b) {
  double v = 0;
  for (const IndicatorPatch& alpha : bodies.cell_fractions(b))
    for_each_index(alpha.range(), [&](const Index& m) { v += alpha(m) * grid.cell_volume(m); });
  MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_DOUBLE, MPI_SUM, grid.comm());
  return v;
}

TEST(IbmVolumeFraction, ExactForAFaceParallelPlane) {
  const std::array<double, 8> phi{-0.3, -0.3, -0.3, -0.3, 0.7, 0.7, 0.7, 0.7};
  EXPECT_DOUBLE_EQ(level_set_fraction(phi), 0.3);
  EXPECT_EQ(level_set_fraction(std::array<double, 8>{-1, -1, -1, -1, -1, -1, -1, -1}), 1.0);
  EXPECT_EQ(level_set_fraction(std::array<double, 8>{1, 1, 1, 1, 1, 1, 1, 1}), 0.0);
}

// A sphere at d/h = 8 moved through a cell in 100 steps: its grid volume is within 1 % of
// the sphere's and changes smoothly, where the staircase's point-sampled volume jumps.
TEST(IbmVolumeFraction, SphereVolumeIsContinuousInThePose) {
  const int n = 20;
  const Axis axis = Axis::uniform(n, 0, 1, false);
  Grid grid(PETSC_COMM_WORLD, {axis, axis, axis});
  const double r = 0.2, exact = 4.0 / 3 * pi * r * r * r;
  ImmersedBoundary ibm(grid);
  const Eigen::Vector3d start(0.5, 0.51, 0.53), step = Eigen::Vector3d(1.0, 0.37, 0.21) / (n * 100);
  ibm.add({geometry::Sphere(r), geometry::Pose(start, Eigen::Quaterniond::Identity())});
  double worst = 0, jump = 0, before = grid_volume(grid, ibm, 0);
  for (int k = 1; k <= 100; ++k) {
    ibm.move(0, geometry::Pose(start + k * step, Eigen::Quaterniond::Identity()), Eigen::Vector3d::Zero(),
             Eigen::Vector3d::Zero());
    const double v = grid_volume(grid, ibm, 0);
    worst = std::max(worst, std::abs(v - exact) / exact);
    jump = std::max(jump, std::abs(v - before) / exact);
    before = v;
  }
  PetscPrintf(PETSC_COMM_WORLD,
              "IBM grid volume of a sphere at d/h 8 over a cell of motion: within %.3f %%, largest "
              "change in a 1/100 cell step %.2e\n",
              100 * worst, jump);
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(jump, 2e-4);
}

// A sphere reaching across a corner of a periodic box has its whole volume on the grid,
// the parts beyond the faces wrapped round as images; across walls it is cut.
TEST(IbmVolumeFraction, ASphereAcrossPeriodicFacesWrapsRound) {
  const int n = 20;
  const double r = 0.2, exact = 4.0 / 3 * pi * r * r * r;
  const Eigen::Vector3d corner(0.011, 0.023, 0.987);
  Grid periodic(PETSC_COMM_WORLD,
                {Axis::uniform(n, 0, 1, true), Axis::uniform(n, 0, 1, true), Axis::uniform(n, 0, 1, true)});
  ImmersedBoundary wrapped(periodic);
  wrapped.add({geometry::Sphere(r), geometry::Pose(corner, Eigen::Quaterniond::Identity())});
  const double v = grid_volume(periodic, wrapped, 0);
  PetscPrintf(PETSC_COMM_WORLD, "IBM grid volume of a sphere across a periodic corner: %.6f, exact %.6f\n", v, exact);
  EXPECT_NEAR(v, exact, 0.01 * exact);
  Grid walled(PETSC_COMM_WORLD,
              {Axis::uniform(n, 0, 1, false), Axis::uniform(n, 0, 1, false), Axis::uniform(n, 0, 1, false)});
  ImmersedBoundary cut(walled);
  cut.add({geometry::Sphere(r), geometry::Pose(corner, Eigen::Quaterniond::Identity())});
  const double inside = grid_volume(walled, cut, 0);  // an eighth of it, and a little more
  EXPECT_GT(inside, 0.125 * exact);
  EXPECT_LT(inside, 0.25 * exact);
}

// On a two-dimensional grid the fractions are the section's: a cylinder as thick as the
// layer, whose end caps are nearer than its side for most points inside (the shape's own
// distance would halve the inside there).
TEST(IbmVolumeFraction, TwoDimensionalSectionOfAThinCylinder) {
  const double thickness = 0.01, r = 0.05;
  Grid grid(PETSC_COMM_WORLD,
            {Axis::uniform(40, 0, 0.4, false), Axis::uniform(40, 0, 0.4, false), Axis::uniform(1, 0, thickness, true)});
  ImmersedBoundary ibm(grid);
  ibm.add({geometry::Cylinder(r, thickness),
           geometry::Pose({0.2013, 0.1987, thickness / 2}, Eigen::Quaterniond::Identity())});
  const double section = grid_volume(grid, ibm, 0) / thickness;
  PetscPrintf(PETSC_COMM_WORLD, "IBM section of a cylinder at D/h 10 on a 2D grid: %.6f, pi r^2 = %.6f\n", section,
              pi * r * r);
  EXPECT_NEAR(section, pi * r * r, 0.01 * pi * r * r);
}

// A body carried along with its fluid: a periodic box and a uniform body force g, the
// sphere moving at g t with the fluid, so no marker has anything to correct and the load
// is the inner fluid's momentum change alone, rho g V (the pressure gradient's force on the
// body's volume), with no torque. Returns the largest relative departure from rho g V.
double accelerating_with_its_fluid(const Eigen::Vector3d& start) {
  const int n = 16;
  const Axis axis = Axis::uniform(n, 0, 1, true);
  Grid grid(PETSC_COMM_WORLD, {axis, axis, axis});
  BoundaryConditions bc(grid);
  const double g = 2, rho = 3, dt = 0.01, r = 0.25;
  NavierStokes flow(grid, bc, {rho, ViscosityModel::newtonian(0.1), {g, 0, 0}}, {.dt_max = dt, .dt_initial = dt});
  ImmersedBoundary ibm(grid);
  ibm.add({geometry::Sphere(r), geometry::Pose(start, Eigen::Quaterniond::Identity())});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  double worst = 0;
  for (int k = 1; k <= 10; ++k) {
    const double t = k * dt;
    ibm.move(0, geometry::Pose(start + Eigen::Vector3d(g * t * t / 2, 0, 0), Eigen::Quaterniond::Identity()),
             {g * t, 0, 0}, Eigen::Vector3d::Zero());
    flow.step(dt, ibm.for_step());
    const double expected = rho * g * grid_volume(grid, ibm, 0);
    const HydrodynamicLoad load = ibm.loads(flow)[0];
    worst = std::max(worst, std::abs(load.force.x() - expected) / expected);
    EXPECT_LT(std::abs(load.force.y()) + std::abs(load.force.z()), 1e-6 * expected);
    EXPECT_LT(load.torque.norm(), 1e-3 * expected * r);
  }
  return worst;
}

TEST(IbmInnerFluid, ABodyAcceleratingWithItsFluidFeelsRhoGV) {
  const double worst = accelerating_with_its_fluid({0.41, 0.52, 0.47});
  PetscPrintf(PETSC_COMM_WORLD, "IBM sphere accelerating with its fluid: load within %.2e of rho g V\n", worst);
  EXPECT_LT(worst, 5e-3);
}

// The same across the periodic y and z faces (moved by whole cells): its inner fluid is
// summed over its images, each about its own centre.
TEST(IbmInnerFluid, ABodyAcrossPeriodicFacesAcceleratingWithItsFluidFeelsRhoGV) {
  const double middle = accelerating_with_its_fluid({0.41, 0.52, 0.47});
  const double across = accelerating_with_its_fluid({0.41, 0.02, 0.97});
  PetscPrintf(PETSC_COMM_WORLD, "IBM sphere across periodic faces with its fluid: load within %.2e of rho g V\n",
              across);
  EXPECT_NEAR(across, middle, 1e-6);
}

struct MovingRun {
  double mean_drag = 0, jump = 0, torque = 0, worst_divergence = 0, worst_slip = 0;
  int assemblies = 0;
};

// An ellipsoid moving at constant velocity and spinning through fluid at rest (Re 15), as
// FbmMovingBody.ConstantVelocityThroughFluidAtRest does with the staircase.
MovingRun move_through_fluid_at_rest(const BodyOptions& method) {
  Grid grid(PETSC_COMM_WORLD,
            {Axis::uniform(24, 0, 1.2, false), Axis::uniform(20, 0, 1, false), Axis::uniform(16, 0, 0.8, false)});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(0.01), {0, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 0.005});
  const Eigen::Vector3d velocity(0.5, 0.2, 0), spin(0, 0, 3), start(0.35, 0.4, 0.4);
  const auto pose = [&](double t) {
    return geometry::Pose(start + t * velocity,
                          Eigen::Quaterniond(Eigen::AngleAxisd(t * spin.norm(), spin.normalized())));
  };
  const auto bodies = make_bodies(grid, method);
  bodies->add({geometry::Ellipsoid({0.15, 0.1, 0.12}), pose(0), velocity, spin});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  MovingRun run;
  std::vector<double> drag;
  // Whole stable steps to t >= 1: the drag depends on the step too, so a last step cut
  // short to land on t = 1 would show as a jump in the pose that is not one.
  while (flow.time() < 1.0) {
    const double dt = flow.stable_dt();
    bodies->move(0, pose(flow.time() + dt), velocity, spin);
    run.worst_divergence = std::max(run.worst_divergence, flow.step(dt, bodies->for_step()).max_divergence);
    if (const auto* ibm = dynamic_cast<const ImmersedBoundary*>(bodies.get()))
      run.worst_slip = std::max(run.worst_slip, ibm->slip());
    if (flow.time() > 0.5) drag.push_back(-bodies->loads(flow)[0].force.dot(velocity.normalized()));
  }
  for (std::size_t i = 0; i < drag.size(); ++i) {
    run.mean_drag += drag[i] / static_cast<double>(drag.size());
    if (i > 0) run.jump = std::max(run.jump, std::abs(drag[i] - drag[i - 1]));
  }
  run.torque = bodies->loads(flow)[0].torque.z();
  run.assemblies = flow.pressure_assemblies();
  PetscPrintf(PETSC_COMM_WORLD,
              "moving ellipsoid (24 x 20 x 16, Re 15), %s: max divergence %.1e, max slip %.1e, drag for t > 0.5: "
              "mean %.4f, largest change in one step %.4f; T_z %.5f; pressure operator assembled %d times\n",
              label(method).c_str(), run.worst_divergence, run.worst_slip, run.mean_drag, run.jump, run.torque,
              run.assemblies);
  return run;
}

// The immersed boundary's drag moves smoothly with the body (the staircase's jumps by 35 %
// of its mean), agrees with the staircase's mean to the two methods' errors on so coarse a
// grid (the ellipsoid is 4 to 6 cells across), and the projection's operator is the
// fluid's own, assembled once.
TEST(IbmMovingBody, ConstantVelocityThroughFluidAtRest) {
  const MovingRun ibm = move_through_fluid_at_rest(IbmOptions{});
  const MovingRun staircase = move_through_fluid_at_rest(FbmOptions{.offset = kCalibratedSurfaceOffset});
  EXPECT_LT(ibm.worst_divergence, 1e-8);
  EXPECT_LT(ibm.worst_slip, 1e-3);
  // The spinning ellipsoid's drag changes from step to step by itself: 4.3 % of its mean
  // at most with the immersed boundary, 35 % with the staircase.
  EXPECT_LT(ibm.jump, 0.1 * ibm.mean_drag);
  EXPECT_GT(staircase.jump, 3 * ibm.jump);
  EXPECT_NEAR(ibm.mean_drag, staircase.mean_drag, 0.15 * staircase.mean_drag);
  EXPECT_LT(ibm.torque, 0);
  EXPECT_EQ(ibm.assemblies, 1);
  EXPECT_GT(staircase.assemblies, 10);
}

// Guards against: kernels that overlap a wall or another body's corrupting either. Two
// spheres side by side half a cell apart settle towards the floor at 0.1 m/s until half a
// cell above it (their kernels reach the floor and each other): every step is
// divergence-free and meets the markers' velocity, the pair's forces mirror each other
// across their plane of symmetry to the grid's asymmetry, and both are pushed up. Closer
// than that the film between sphere and floor is not resolved (lubrication is the rigid
// bodies' contact model's).
TEST(IbmNearContact, TwoSpheresHalfACellApartApproachingTheFloor) {
  const int n = 24;
  const double h = 1.0 / n, r = 3 * h, gap = 0.5 * h;
  const Axis axis = Axis::uniform(n, 0, 1, false);
  Grid grid(PETSC_COMM_WORLD, {axis, axis, axis});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(0.05), {0, 0, 0}}, {.dt_max = 0.01, .dt_initial = 0.01});
  ImmersedBoundary ibm(grid);
  const Eigen::Vector3d velocity(0, 0, -0.1);
  const double x0 = 0.5 - r - gap / 2 + 0.37 * h, z0 = r + 2.5 * h;  // the pair's plane off the grid's
  const auto at = [&](double x, double t) -> Eigen::Vector3d {
    return Eigen::Vector3d(x, 0.5 + 0.21 * h, z0) + t * velocity;
  };
  ibm.add({geometry::Sphere(r), geometry::Pose(at(x0, 0), Eigen::Quaterniond::Identity()), velocity});
  ibm.add({geometry::Sphere(r), geometry::Pose(at(x0 + 2 * r + gap, 0), Eigen::Quaterniond::Identity()), velocity});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  const double end = 2.0 * h / 0.1;
  double worst_divergence = 0, worst_slip = 0, worst_mirror = 0;
  while (flow.time() < end - 1e-12) {
    const double dt = std::min(flow.stable_dt(), end - flow.time()), t = flow.time() + dt;
    ibm.move(0, geometry::Pose(at(x0, t), Eigen::Quaterniond::Identity()), velocity, Eigen::Vector3d::Zero());
    ibm.move(1, geometry::Pose(at(x0 + 2 * r + gap, t), Eigen::Quaterniond::Identity()), velocity,
             Eigen::Vector3d::Zero());
    worst_divergence = std::max(worst_divergence, flow.step(dt, ibm.for_step()).max_divergence);
    worst_slip = std::max(worst_slip, ibm.slip());
    const auto loads = ibm.loads(flow);
    const double scale = loads[0].force.norm();
    worst_mirror = std::max({worst_mirror, std::abs(loads[0].force.x() + loads[1].force.x()) / scale,
                             std::abs(loads[0].force.z() - loads[1].force.z()) / scale});
  }
  const auto loads = ibm.loads(flow);
  PetscPrintf(PETSC_COMM_WORLD,
              "two spheres half a cell apart down to half a cell above the floor: max divergence %.1e, max slip %.1e, "
              "mirror mismatch %.1e, F_z %.4f %.4f, F_x %.4f %.4f\n",
              worst_divergence, worst_slip, worst_mirror, loads[0].force.z(), loads[1].force.z(), loads[0].force.x(),
              loads[1].force.x());
  EXPECT_LT(worst_divergence, 1e-8);
  EXPECT_LT(worst_slip, 5e-3);
  EXPECT_LT(worst_mirror, 0.05);
  EXPECT_GT(loads[0].force.z(), 0);
  EXPECT_GT(loads[1].force.z(), 0);
}

}  // namespace
}  // namespace cosim::fluid
