#include "bench/fluid_accuracy/round_pipe.hpp"

#include <mpi.h>

#include <cmath>
#include <numbers>

#include "fluid/ibm/immersed_boundary.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"

namespace cosim::bench {
namespace {

constexpr double kRadius = 0.5, kNu = 1.0, kDrive = 16.0;  // u_max = G R^2 / (4 nu) = 1

double poiseuille(double r) { return r < kRadius ? kDrive * (kRadius * kRadius - r * r) / (4 * kNu) : 0.0; }

}  // namespace

PipeFlow round_pipe(int cells_across, const Eigen::Vector2d& offset, int margin, fluid::ibm::DeltaKernel kernel) {
  using fluid::grid::Axis;
  using fluid::grid::BoundaryConditions;
  using fluid::grid::for_each_index;
  using fluid::grid::Grid;
  using fluid::grid::Index;
  using fluid::grid::Point;
  using fluid::ibm::IbmOptions;
  using fluid::ibm::ImmersedBoundary;
  using fluid::navier_stokes::NavierStokes;
  using fluid::viscous::ViscosityModel;
  const double start = MPI_Wtime();
  const double h = 2 * kRadius / cells_across;
  const int n = cells_across + margin;
  const Axis across = Axis::uniform(n, -n * h / 2, n * h / 2, false);
  Grid grid(PETSC_COMM_WORLD, {across, across, Axis::uniform(6, 0, 6 * h, true)});
  BoundaryConditions bc(grid);
  const double dt = h * h / kNu;
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(kNu), {0, 0, kDrive}},
                    {.cfl = 10, .dt_max = dt, .dt_initial = dt});
  IbmOptions options;
  options.kernel = kernel;
  ImmersedBoundary bodies(grid, options);
  // Twice the period long: its caps lie beyond both ends.
  const Eigen::Vector2d axis = h * offset;
  bodies.add({geometry::Container(geometry::Cylinder(kRadius, 12 * h)),
              geometry::Pose({axis.x(), axis.y(), 3 * h}, Eigen::Quaterniond::Identity())});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  // The slowest mode decays as exp(-5.78 nu t / R^2): to 1e-6 of itself by t = 0.6.
  PipeFlow out;
  while (flow.time() < 0.6 - dt / 2) {
    flow.step(dt, bodies.for_step());
    ++out.steps;
  }
  DM dm = grid.velocity_dm(2);
  const PetscScalar*** w = nullptr;
  DMDAVecGetArrayRead(dm, flow.velocity(2), &w);
  double rate = 0;
  for_each_index(grid.owned(dm), [&](const Index& p) {
    if (p[2] != 0) return;
    const Point x = grid.position(2, p);
    const double r = std::hypot(x[0] - axis.x(), x[1] - axis.y());
    const double u = w[p[2]][p[1]][p[0]];
    if (r < kRadius) rate += u * h * h;
    if (r <= kRadius - 2 * h) out.profile_error = std::max(out.profile_error, std::abs(u - poiseuille(r)));
  });
  DMDAVecRestoreArrayRead(dm, flow.velocity(2), &w);
  MPI_Allreduce(MPI_IN_PLACE, &out.profile_error, 1, MPI_DOUBLE, MPI_MAX, grid.comm());
  MPI_Allreduce(MPI_IN_PLACE, &rate, 1, MPI_DOUBLE, MPI_SUM, grid.comm());
  out.flow_rate_error = rate / (std::numbers::pi * kDrive * std::pow(kRadius, 4) / (8 * kNu)) - 1;
  out.cells = static_cast<long>(n) * n * 6;
  out.seconds = MPI_Wtime() - start;
  return out;
}

}  // namespace cosim::bench
