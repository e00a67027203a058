// Run under mpirun -n 2 (the cloud also under -n 4): the same flow on all ranks
// (PETSC_COMM_WORLD) and on each rank alone (PETSC_COMM_SELF) must agree to solver tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/fluid/flow_checks.hpp"
#include "fluid/body_methods.hpp"
#include "fluid/ibm/immersed_boundary.hpp"

namespace cosim::fluid {

using bodies::HydrodynamicLoad;
using grid::Axis;
using grid::BoundaryConditions;
using grid::Box;
using grid::Grid;
using grid::Point;
using ibm::IbmOptions;
using ibm::ImmersedBoundary;
using navier_stokes::NavierStokes;
using staircase::FbmOptions;
using viscous::ViscosityModel;

namespace {

void expect_same_on_one_and_two_ranks(const ViscosityModel& viscosity, const char* name) {
  PetscMPIInt size = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  ASSERT_EQ(size, 2) << "run this test with mpirun -n 2";
  const auto distributed = testing::mixed_boundary_flow(PETSC_COMM_WORLD, viscosity, 1.0);
  const auto serial = testing::mixed_boundary_flow(PETSC_COMM_SELF, viscosity, 1.0);
  const double difference = testing::max_difference(distributed, serial);
  double magnitude = 0;
  for (const auto& component : serial)
    for (double v : component) magnitude = std::max(magnitude, std::abs(v));
  PetscPrintf(PETSC_COMM_WORLD,
              "2 ranks vs 1 rank, %s (12 x 8 x 6, 20 steps): max |difference| = %.2e (max |u| = %.2f)\n", name,
              difference, magnitude);
  EXPECT_LT(difference, 1e-8);
}

TEST(TwoRanks, SameAnswerAsOneRank) { expect_same_on_one_and_two_ranks(ViscosityModel::newtonian(0.02), "Newtonian"); }

// The viscosity field is read across rank boundaries too.
TEST(TwoRanks, SameAnswerAsOneRankCarreau) {
  expect_same_on_one_and_two_ranks(ViscosityModel::carreau(0.05, 0.005, 1.0, 0.5), "Carreau");
}

// The ranks along each axis as asked, where PETSc would cut the longest axis.
TEST(TwoRanks, GridTakesTheRanksAlongEachAxisAsAsked) {
  PetscMPIInt size = 0, rank = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  ASSERT_EQ(size, 2) << "run this test with mpirun -n 2";
  const std::array<Axis, 3> axes{Axis::uniform(12, 0, 1, false), Axis::uniform(8, 0, 1, false),
                                 Axis::uniform(6, 0, 1, false)};
  const Grid decided(PETSC_COMM_WORLD, axes);
  EXPECT_EQ(decided.owned(decided.pressure_dm()).hi[0] - decided.owned(decided.pressure_dm()).lo[0], 6);
  const Grid across(PETSC_COMM_WORLD, axes, {1, 1, 2});
  for (DM dm : {across.pressure_dm(), across.cell_dm(), across.velocity_dm(0), across.velocity_dm(2)}) {
    const Box owned = across.owned(dm);
    EXPECT_EQ(owned.hi[0] - owned.lo[0], dm == across.velocity_dm(0) ? 13 : 12);
    EXPECT_EQ(owned.lo[2], rank == 0 ? 0 : 3);
  }
}

struct BodyRun {
  testing::GatheredVelocity velocity;
  HydrodynamicLoad load;
};

// A spinning box dragged through a closed 16 x 12 x 10 box of Carreau fluid for 12 steps;
// the 2-rank split cuts through it (and through the immersed boundary's kernels).
BodyRun moving_box(MPI_Comm comm, const BodyOptions& method) {
  Grid grid(comm, {Axis::uniform(16, 0, 1.6, false), Axis::uniform(12, 0, 1.2, false), Axis::uniform(10, 0, 1, false)});
  BoundaryConditions bc(grid);
  // Shear-thinning, so the force reads the viscosity field across the rank boundary too.
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::carreau(0.05, 0.005, 1.0, 0.5), {0, 0, -1}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 0.01});
  const Eigen::Vector3d velocity(0.4, 0.1, -0.1), spin(0.5, 0, 2), start(0.75, 0.6, 0.5);
  const auto bodies = make_bodies(grid, method);
  const std::size_t b = bodies->add(
      {geometry::Box({0.2, 0.15, 0.1}), geometry::Pose(start, Eigen::Quaterniond::Identity()), velocity, spin});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  for (int s = 0; s < 12; ++s) {
    const double dt = flow.stable_dt(), t = flow.time() + dt;
    bodies->move(
        b,
        geometry::Pose(start + t * velocity, Eigen::Quaterniond(Eigen::AngleAxisd(t * spin.norm(), spin.normalized()))),
        velocity, spin);
    EXPECT_LT(flow.step(dt, bodies->for_step()).max_divergence, 1e-8) << "step " << s;
  }
  return {{testing::gather(flow, 0), testing::gather(flow, 1), testing::gather(flow, 2)}, bodies->loads(flow)[b]};
}

void expect_bodies_same_on_one_and_two_ranks(const BodyOptions& method) {
  const BodyRun distributed = moving_box(PETSC_COMM_WORLD, method);
  const BodyRun serial = moving_box(PETSC_COMM_SELF, method);
  const double velocity = testing::max_difference(distributed.velocity, serial.velocity);
  const double force = (distributed.load.force - serial.load.force).norm();
  const double torque = (distributed.load.torque - serial.load.torque).norm();
  PetscPrintf(PETSC_COMM_WORLD,
              "2 ranks vs 1 rank, moving box (%s) in Carreau fluid (16 x 12 x 10, 12 steps): max |du| = %.2e, |dF| = "
              "%.2e (|F| = %.3f), |dT| = %.2e (|T| = %.4f)\n",
              label(method).c_str(), velocity, force, serial.load.force.norm(), torque, serial.load.torque.norm());
  EXPECT_LT(velocity, 1e-8);
  EXPECT_LT(force, 1e-7 * serial.load.force.norm());
  EXPECT_LT(torque, 1e-7 * serial.load.torque.norm());
}

TEST(TwoRanks, FictitiousBoundarySameAsOneRank) {
  expect_bodies_same_on_one_and_two_ranks(FbmOptions{.subsamples = 2});
}

// The markers' forcing converged tightly: its sweeps then end alike on one and two ranks.
TEST(TwoRanks, ImmersedBoundarySameAsOneRank) {
  IbmOptions ibm;
  ibm.tolerance = 1e-10;
  ibm.sweeps = 200;
  expect_bodies_same_on_one_and_two_ranks(ibm);
}

struct CloudRun {
  std::vector<HydrodynamicLoad> loads;
  std::size_t held = 0, total = 0;  // markers this rank held in the last step, and all bodies'
};

// The forcing converged tightly and the no-slip corrections after it: its iterations then
// end alike on one rank and several.
IbmOptions tight_forcing(bool spread_at_theta) {
  IbmOptions tight;
  tight.sweeps = 200;
  tight.tolerance = 1e-10;
  tight.corrections = 30;
  tight.no_slip_tolerance = 1e-9;
  tight.spread_at_theta = spread_at_theta;
  return tight;
}

// Adds spheres of radius 0.2 at `starts`, moving at `velocities` and spinning at `spin`, to
// the bodies already there, and runs 6 steps of 0.05 from rest, each sphere moved before each.
void run_spheres(NavierStokes& flow, ImmersedBoundary& bodies, const std::vector<Eigen::Vector3d>& starts,
                 const std::vector<Eigen::Vector3d>& velocities, const Eigen::Vector3d& spin) {
  const std::size_t first = bodies.size();
  for (std::size_t i = 0; i < starts.size(); ++i)
    bodies.add({geometry::Sphere(0.2), geometry::Pose(starts[i], Eigen::Quaterniond::Identity()), velocities[i], spin});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  for (int s = 0; s < 6; ++s) {
    const double t = flow.time() + 0.05;
    for (std::size_t i = 0; i < starts.size(); ++i)
      bodies.move(first + i, geometry::Pose(starts[i] + t * velocities[i], Eigen::Quaterniond::Identity()),
                  velocities[i], spin);
    EXPECT_LT(flow.step(0.05, bodies.for_step()).max_divergence, 1e-8) << "step " << s;
  }
}

// Five spheres (d/h 4.8) moving through a box periodic in x and y: on the ranks' cuts, with
// kernels across the periodic seam and inside one rank, with the no-slip corrections (a
// Krylov solve over the markers of every rank) after each of 6 steps; spreading from where
// they are at the step's end or, with `spread_at_theta`, from mid-step, where a marker may
// spread on a rank its end kernel does not touch.
CloudRun sphere_cloud(MPI_Comm comm, bool spread_at_theta) {
  const Axis across = Axis::uniform(24, 0, 2, true);
  Grid grid(comm, {across, across, Axis::uniform(12, 0, 1, false)});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(0.05), {0, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 0.05});
  ImmersedBoundary bodies(grid, tight_forcing(spread_at_theta));
  run_spheres(flow, bodies, {{1.0, 1.0, 0.5}, {1.02, 0.4, 0.45}, {0.05, 1.5, 0.5}, {1.5, 0.3, 0.55}, {0.4, 0.98, 0.5}},
              {{0.3, -0.2, 0.1}, {0, 0.4, 0}, {-0.5, 0, 0.1}, {0.1, 0.1, -0.2}, {0.2, 0.3, 0}}, {0, 0, 1});
  CloudRun out{bodies.loads(flow), bodies.held_markers(), 0};
  for (std::size_t i = 0; i < bodies.size(); ++i) out.total += bodies.markers(i).size();
  return out;
}

// A round column (a container, D/h 16, its caps beyond the box) holding three spheres moving
// through liquid at rest: one against its wall, one by the box's floor, one across the ranks'
// cuts; each of 6 steps with the no-slip corrections. The container's held solid and its
// markers are cut by the ranks too.
CloudRun column_cloud(MPI_Comm comm, bool) {
  const Axis across = Axis::uniform(20, -1, 1, false);
  Grid grid(comm, {across, across, Axis::uniform(16, 0, 1.6, false)});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(0.05), {0, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 0.05});
  ImmersedBoundary bodies(grid, tight_forcing(false));
  bodies.add({geometry::Container(geometry::Cylinder(0.8, 2.4)),
              geometry::Pose({0.03, -0.02, 0.8}, Eigen::Quaterniond::Identity())});
  run_spheres(flow, bodies, {{0.5, 0.1, 0.8}, {-0.2, 0.3, 0.25}, {0.01, -0.02, 1.0}},
              {{0.2, 0, 0.1}, {0, 0.1, -0.2}, {-0.3, 0.2, 0}}, {0, 1, 0});
  // The container's markers beyond the box's floor and top are none of its own.
  CloudRun out{bodies.loads(flow), bodies.held_markers(), 0};
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (const Eigen::Vector3d& x : bodies.markers(i)) out.total += x.z() > 0 && x.z() < 1.6 ? 1 : 0;
  return out;
}

// Each rank forces only the markers whose kernels touch its faces, and the loads are those
// of one rank.
void expect_same_as_one_rank(CloudRun (*run)(MPI_Comm, bool), bool spread_at_theta) {
  const CloudRun distributed = run(PETSC_COMM_WORLD, spread_at_theta);
  const CloudRun serial = run(PETSC_COMM_SELF, spread_at_theta);
  PetscMPIInt size = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  for (std::size_t b = 0; b < serial.loads.size(); ++b) {
    const double force = (distributed.loads[b].force - serial.loads[b].force).norm();
    const double torque = (distributed.loads[b].torque - serial.loads[b].torque).norm();
    PetscPrintf(PETSC_COMM_WORLD, "%d ranks vs 1, body %zu: |dF| = %.2e (|F| = %.4f), |dT| = %.2e (|T| = %.5f)\n", size,
                b, force, serial.loads[b].force.norm(), torque, serial.loads[b].torque.norm());
    EXPECT_LT(force, 1e-7 * serial.loads[b].force.norm()) << "body " << b;
    EXPECT_LT(torque, 1e-6 * serial.loads[b].torque.norm() + 1e-10) << "body " << b;
  }
  PetscSynchronizedPrintf(PETSC_COMM_WORLD, "  rank holds %zu of the %zu markers\n", distributed.held,
                          distributed.total);
  PetscSynchronizedFlush(PETSC_COMM_WORLD, PETSC_STDOUT);
  EXPECT_EQ(serial.held, serial.total);
  EXPECT_LT(distributed.held, serial.held);
}

TEST(TwoRanks, ImmersedBoundaryCloudSameAsOneRank) { expect_same_as_one_rank(sphere_cloud, false); }

TEST(TwoRanks, ImmersedBoundaryCloudSpreadingFromMidStepSameAsOneRank) { expect_same_as_one_rank(sphere_cloud, true); }

TEST(TwoRanks, ImmersedBoundaryCloudInARoundColumnSameAsOneRank) { expect_same_as_one_rank(column_cloud, false); }

}  // namespace
}  // namespace cosim::fluid
