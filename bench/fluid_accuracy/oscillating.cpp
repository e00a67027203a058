#include "bench/fluid_accuracy/oscillating.hpp"

#include <cmath>
#include <numbers>

#include "bench/fluid_accuracy/channel.hpp"

namespace cosim::bench {

OscillatingRun oscillating_cylinder(int cells_per_diameter, double periods, const fluid::BodyOptions& method) {
  using namespace fluid;
  using fluid::bodies::HydrodynamicLoad;
  using fluid::grid::Axis;
  using fluid::grid::BoundaryConditions;
  using fluid::grid::Grid;
  using fluid::grid::Point;
  using fluid::navier_stokes::NavierStokes;
  using fluid::viscous::ViscosityModel;
  using namespace channel;
  constexpr double x0 = 1.1, y0 = 0.2, omega = 2 * std::numbers::pi * kOscillationFrequency;
  constexpr double U = omega * kOscillationAmplitude;  // the largest body velocity, 0.3927 m/s
  const double start = MPI_Wtime();
  const Axis y = across(cells_per_diameter);
  const double h = H / y.cells();
  Grid grid(PETSC_COMM_WORLD, {Axis::uniform(static_cast<int>(std::lround(L / h)), 0, L, false), y, layer()});
  BoundaryConditions bc(grid);
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(1e-3), {0, 0, 0}},
                    {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 1e-3});
  const auto bodies = make_bodies(grid, method);
  const auto body = bodies->add({geometry::Cylinder(D / 2, 3 * T),
                                 geometry::Pose({x0, y0, T / 2}, Eigen::Quaterniond::Identity()),
                                 {kOscillationAmplitude * omega, 0, 0}});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });

  OscillatingRun run;
  run.level = "D/h=" + std::to_string(cells_per_diameter);
  run.method = label(method);
  const double to_coefficient = 2 / (D * T * U * U);
  auto record = [&] {
    const HydrodynamicLoad load = bodies->loads(flow)[body];
    run.history.push_back({flow.time(), to_coefficient * load.force[0], to_coefficient * load.force[1]});
  };
  // Before each step: the force of the step just finished, then the body where it is at the
  // next step's end.
  const auto steps = flow.advance_to(periods / kOscillationFrequency, bodies->for_step(), [&](double t) {
    if (flow.time() > 0) record();
    bodies->move(
        body,
        geometry::Pose({x0 + kOscillationAmplitude * std::sin(omega * t), y0, T / 2}, Eigen::Quaterniond::Identity()),
        {kOscillationAmplitude * omega * std::cos(omega * t), 0, 0}, Eigen::Vector3d::Zero());
  });
  record();
  const auto n = grid.cells();
  run.cells = static_cast<long>(n[0] * n[1] * n[2]);
  run.steps = static_cast<int>(steps.size());
  run.seconds = MPI_Wtime() - start;
  return run;
}

}  // namespace cosim::bench
