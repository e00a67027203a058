#include "bench/fluid_throughput/cavity.hpp"

#include <algorithm>
#include <ctime>

#include "fluid/body_methods.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"
#include "fluid/petsc_check.hpp"

namespace cosim::bench {
namespace {

using namespace cosim::fluid;
using fluid::bodies::BodyTreatment;
using fluid::bodies::RigidBody;
using fluid::bodies::StepBodies;
using fluid::grid::Axis;
using fluid::grid::Boundary;
using fluid::grid::BoundaryConditions;
using fluid::grid::for_each_index;
using fluid::grid::Grid;
using fluid::grid::Index;
using fluid::grid::Point;
using fluid::grid::Side;
using fluid::ibm::IbmOptions;
using fluid::navier_stokes::NavierStokes;
using fluid::navier_stokes::StepReport;
using fluid::staircase::FbmOptions;
using fluid::viscous::ViscosityModel;

// This rank's time so far in one of the library's events (FluidPressureSolve: the pressure
// KSP with its multigrid setup; FluidBodyForcing: the immersed boundary's forcing and
// loads), from PETSc's log.
double event_seconds(const char* name) {
  PetscLogEvent event;
  COSIM_PETSC(PetscLogEventGetId(name, &event));
  PetscEventPerfInfo info{};
  COSIM_PETSC(PetscLogEventGetPerfInfo(PETSC_DETERMINE, event, &info));
  return info.time;
}

double slowest(double local, MPI_Comm comm) {
  double max = 0;
  MPI_Allreduce(&local, &max, 1, MPI_DOUBLE, MPI_MAX, comm);
  return max;
}

double synchronized_time(MPI_Comm comm) {
  MPI_Barrier(comm);
  return MPI_Wtime();
}

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// u at x = 0.5 (face n/2) averaged over the two cells either side of y = 0.5, per z cell.
std::vector<double> centre_line(const NavierStokes& flow) {
  const Grid& grid = flow.grid();
  const PetscInt half = grid.cells()[0] / 2;
  std::vector<double> line(static_cast<std::size_t>(grid.cells()[2]), 0.0);
  DM dm = grid.velocity_dm(0);
  const PetscScalar*** u = nullptr;
  COSIM_PETSC(DMDAVecGetArrayRead(dm, flow.velocity(0), &u));
  for_each_index(grid.owned(dm), [&](const Index& p) {
    if (p[0] == half && (p[1] == half - 1 || p[1] == half))
      line[static_cast<std::size_t>(p[2])] += 0.5 * u[p[2]][p[1]][p[0]];
  });
  COSIM_PETSC(DMDAVecRestoreArrayRead(dm, flow.velocity(0), &u));
  MPI_Allreduce(MPI_IN_PLACE, line.data(), static_cast<int>(line.size()), MPI_DOUBLE, MPI_SUM, grid.comm());
  return line;
}

std::unique_ptr<BodyTreatment> sphere(const Grid& grid, CavityBody body) {
  if (body == CavityBody::none) return nullptr;
  auto bodies = body == CavityBody::ibm ? make_bodies(grid, IbmOptions{}) : make_bodies(grid, FbmOptions{});
  bodies->add({geometry::Sphere(0.125),
               geometry::Pose({0.5, 0.3, 0.45}, Eigen::Quaterniond::Identity()),
               {0, 0.25 * Cavity::kLidVelocity, 0}});
  return bodies;
}

}  // namespace

ThroughputRun run_cavity(const Cavity& cavity) {
  const MPI_Comm comm = PETSC_COMM_WORLD;
  ThroughputRun run;
  run.solver = cavity.body == CavityBody::none  ? "cosim_fluid"
               : cavity.body == CavityBody::ibm ? "+ibm sphere"
                                                : "+staircase";
  run.cavity = cavity;
  MPI_Comm_size(comm, &run.ranks);
  const PeakMemory memory(comm);
  const int n = cavity.n;
  Grid grid(comm, {Axis::uniform(n, 0, 1, false), Axis::uniform(n, 0, 1, false), Axis::uniform(n, 0, 1, false)});
  BoundaryConditions bc(grid);
  bc.set(2, Side::upper, Boundary::moving_wall({Cavity::kLidVelocity, 0, 0}));
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(cavity.viscosity()), {0, 0, 0}}, {});
  const std::unique_ptr<BodyTreatment> bodies = sphere(grid, cavity.body);
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  // The sphere where it is at the end of each step, and its load read after it, as a
  // coupled run does.
  const auto step = [&] {
    if (bodies) {
      const RigidBody& b = bodies->body(0);
      bodies->move(0, geometry::Pose(b.pose.position() + cavity.dt() * b.velocity, b.pose.orientation()), b.velocity,
                   b.angular_velocity);
    }
    const StepReport r = flow.step(cavity.dt(), bodies ? bodies->for_step() : StepBodies{});
    if (bodies) bodies->loads(flow);
    return r;
  };

  MPI_Barrier(comm);
  const double cpu_start = cpu_seconds();
  run.max_divergence = step().max_divergence;
  const double warm = synchronized_time(comm), cpu_warm = cpu_seconds();
  const double pressure_warm = event_seconds("FluidPressureSolve"), forcing_warm = event_seconds("FluidBodyForcing");
  long iterations = 0;
  for (int s = 1; s < cavity.steps; ++s) {
    const StepReport r = step();
    iterations += r.pressure_iterations;
    run.max_divergence = std::max(run.max_divergence, r.max_divergence);
  }
  const double end = synchronized_time(comm), cpu_end = cpu_seconds();
  run.timed_steps = cavity.steps - 1;
  run.first_step_seconds = slowest(cpu_warm - cpu_start, comm);
  run.seconds_per_step = (end - warm) / run.timed_steps;
  run.cpu_seconds_per_step = slowest(cpu_end - cpu_warm, comm) / run.timed_steps;
  run.pressure_seconds_per_step = slowest(event_seconds("FluidPressureSolve") - pressure_warm, comm) / run.timed_steps;
  run.forcing_seconds_per_step = slowest(event_seconds("FluidBodyForcing") - forcing_warm, comm) / run.timed_steps;
  run.pressure_iterations_per_step = static_cast<double>(iterations) / run.timed_steps;
  run.memory = memory.total();
  run.centre_line = centre_line(flow);
  return run;
}

}  // namespace cosim::bench
