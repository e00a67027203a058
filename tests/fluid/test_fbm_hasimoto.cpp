// Stokes drag on a fixed sphere in a periodic box against Hasimoto's periodic-array drag,
// H. Hasimoto, J. Fluid Mech. 5 (1959) 317:
//   F = 6 pi mu a U / (1 - 1.7601 c^(1/3) + c - 1.5593 c^2),  c = (4/3) pi a^3 / L^3,
// U the mean velocity over the box (sphere included) relative to the sphere. The flow is
// driven by a uniform body force rho f on the fluid, and the run goes to the steady state
// at Re = U a / nu ~ 3e-4 (Stokes). Hasimoto's F is the force of a mean pressure gradient
// rho f over the whole cell, which includes its buoyancy-like share rho f V on the sphere;
// with a body force on the fluid instead, the volume integral measures F - rho f V.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flow_checks.hpp"
#include "fluid/fictitious_boundary.hpp"

namespace cosim::fluid {
namespace {

constexpr double kRadius = 0.2, kViscosity = 10, kDrive = 10;
constexpr int kLevels[] = {12, 16, 24};
constexpr int kSubsamples = 1;
const Eigen::Vector3d kCentre(0.5, 0.5, 0.5);
// Off the grid's symmetry planes: the centre above sits on grid nodes at every level,
// where the staircase is at its most regular and its error least typical.
const Eigen::Vector3d kGenericCentre(0.511, 0.523, 0.537);

struct DragResult {
  double force, momentum_balance, mean_velocity, seconds;
  int steps;
};

double mean_velocity(const NavierStokes& flow, int n) {
  PetscScalar sum = 0;
  VecSum(flow.velocity(0), &sum);
  return sum / (n * n * n);
}

DragResult sphere_drag(int n, const FbmOptions& options, const Eigen::Vector3d& centre) {
  const double start = MPI_Wtime();
  Grid grid(PETSC_COMM_WORLD, {Axis::uniform(n, 0, 1, true), Axis::uniform(n, 0, 1, true),
                               Axis::uniform(n, 0, 1, true)});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(kViscosity), {kDrive, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.002, .dt_initial = 0.002, .theta = 1.0});
  FictitiousBoundary fbm(grid, options);
  const std::size_t b = fbm.add({geometry::Sphere(kRadius), geometry::Pose(centre, Eigen::Quaterniond::Identity())});
  flow.impose(&fbm.imposed_faces());
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  // Steady when the mean velocity and the drag change by less than 1e-5 of themselves per step.
  double u = 0, force = 0, change = 1;
  int steps = 0;
  for (; steps < 400 && change > 1e-5; ++steps) {
    EXPECT_LT(flow.step().max_divergence, 1e-8);
    const double u_new = mean_velocity(flow, n), force_new = fbm.loads(flow)[b].force[0];
    change = std::max(std::abs(u_new - u) / u_new, std::abs(force_new - force) / force_new);
    u = u_new;
    force = force_new;
  }
  // In a steady state the drag balances the body force on the faces that are not imposed.
  double imposed = static_cast<double>(fbm.imposed_faces().owned(0).size());
  MPI_Allreduce(MPI_IN_PLACE, &imposed, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  const double balance = kDrive * (1 - imposed / (n * n * n));
  return {force, balance, u, MPI_Wtime() - start, steps};
}

// Signed relative errors at kLevels, printed as they come.
std::vector<double> hasimoto_errors(const FbmOptions& options, const Eigen::Vector3d& centre) {
  // In the unit box the volume fraction c is the sphere's volume.
  const double volume = 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
  const double k = 1 / (1 - 1.7601 * std::cbrt(volume) + volume - 1.5593 * volume * volume);
  std::vector<double> errors;
  for (int n : kLevels) {
    const DragResult r = sphere_drag(n, options, centre);
    const double hasimoto = 6 * std::numbers::pi * kViscosity * kRadius * r.mean_velocity * k;
    const double error = (r.force + kDrive * volume - hasimoto) / hasimoto;
    errors.push_back(error);
    PetscPrintf(PETSC_COMM_WORLD,
                "Hasimoto sphere a/L = %.2f, %d^3 (a/h = %.1f, %d^3 sub-samples, offset %.2f h): U = %.5f, "
                "F + rho f V = %.4f, Hasimoto %.4f: error %+.2f %%; F = %.4f against the momentum balance %.4f; "
                "%d steps, %.1f s\n",
                kRadius, n, kRadius * n, options.subsamples, options.offset, r.mean_velocity,
                r.force + kDrive * volume, hasimoto, 100 * error, r.force, r.momentum_balance, r.steps, r.seconds);
    EXPECT_NEAR(r.force, r.momentum_balance, 2e-3 * r.momentum_balance);
  }
  return errors;
}

TEST(FbmHasimoto, StokesDragConverges) {
  const std::vector<double> errors = hasimoto_errors({.subsamples = kSubsamples}, kCentre);
  // First order, with scatter from how the staircase meets the sphere: the error is that of
  // an effective radius about a quarter of a cell short (0.23 - 0.31 h up to 32^3).
  for (std::size_t l = 0; l < errors.size(); ++l) {
    EXPECT_LT(errors[l], 0);
    EXPECT_LT(-errors[l], 0.7 / (kRadius * kLevels[l]));
  }
  EXPECT_LT(-errors.back(), -0.5 * errors.front());
}

// The calibrated offset takes the quarter cell back: within a few per cent from a/h = 2.4
// on (without it: -26, -17, -9.5 % at these levels; -15 to -18 % at 16^3 over generic
// positions).
TEST(FbmHasimoto, CalibratedSurfaceOffsetRemovesTheStaircaseBias) {
  const std::vector<double> errors =
      hasimoto_errors({.subsamples = kSubsamples, .offset = kCalibratedSurfaceOffset}, kGenericCentre);
  EXPECT_LT(std::abs(errors[0]), 0.035);  // measured -2.8 %
  EXPECT_LT(std::abs(errors[1]), 0.025);  // +0.2 %
  EXPECT_LT(std::abs(errors[2]), 0.01);   // -0.4 %
}

}  // namespace
}  // namespace cosim::fluid
