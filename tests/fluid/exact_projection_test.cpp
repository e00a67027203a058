// The exact projection (PressureUpdate::exact): the step's implicit viscous solve and its
// pressure solved together. One backward-Euler step far longer than the viscous time, from
// rest, is then the steady Stokes flow, which the standard projection reaches only after
// many steps: its single step carries the splitting error along the no-slip walls (the
// rotational update changes the pressure, not this step's velocity).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bench/fluid_accuracy/cases.hpp"
#include "fluid/ibm/immersed_boundary.hpp"
#include "tests/fluid/flow_checks.hpp"

namespace cosim::fluid {

using grid::Axis;
using grid::Boundary;
using grid::BoundaryConditions;
using grid::Grid;
using grid::Point;
using grid::Side;
using ibm::IbmOptions;
using navier_stokes::NavierStokes;
using navier_stokes::PressureUpdate;
using navier_stokes::TimeStepOptions;
using viscous::ViscosityModel;

namespace {

// A closed box whose lid (y = 1) slides along x and, at a generic angle, z; so slow and
// viscous (Re 1e-4) that the convection is below the tolerances.
constexpr double kNu = 1e4, kLid = 1;

struct Box {
  Grid grid{PETSC_COMM_WORLD,
            {Axis::uniform(10, 0, 1.2, false), Axis::uniform(9, 0, 1, false), Axis::uniform(8, 0, 0.9, false)}};
  BoundaryConditions bc{grid};
  Box() { bc.set(1, Side::upper, Boundary::moving_wall({kLid, 0, 0.4 * kLid})); }
};

// Fluid at rest in the box, stepped by backward Euler with steps of dt.
struct Flow {
  NavierStokes flow;
  Flow(const Box& box, double dt, PressureUpdate update)
      : flow(box.grid, box.bc, {1.0, ViscosityModel::newtonian(kNu), {0, 0, 0}},
             {.cfl = 1e9, .dt_max = dt, .dt_initial = dt, .theta = 1, .pressure_update = update}) {
    flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  }
};

TEST(ExactProjection, OneLongStepIsTheSteadyStokesFlow) {
  const Box box;
  const double h = 0.1, viscous_time = 1.0 / kNu;
  // The steady flow: standard steps of nu dt / h^2 = 1 until nothing changes.
  Flow steady(box, h * h / kNu, PressureUpdate::standard);
  testing::run_to_steady_state(steady.flow, 1e-9 * kLid / viscous_time, 200 * viscous_time, 1e-8);

  const auto one_step_error = [&](PressureUpdate update) {
    Flow one(box, 1e4 * viscous_time, update);
    EXPECT_LT(one.flow.step().max_divergence, 1e-8);
    return testing::max_difference(one.flow, steady.flow) / kLid;
  };
  const double exact = one_step_error(PressureUpdate::exact);
  const double standard = one_step_error(PressureUpdate::standard);
  // The step's own time error is 1e-4 of the flow (its u^n / dt term).
  EXPECT_LT(exact, 1e-3);
  EXPECT_GT(standard, 30 * exact);
  std::printf("largest difference from the steady flow after one step, of the lid's speed: exact %.2e, standard %.2e\n",
              exact, standard);
}

// A sphere (d/h 6, Re 0.5) driven from 1.5 radii above the floor of a cube four diameters
// wide: its drag at half a radius, where it moves a third of a cell (nu dt / h^2 4) per
// step, against steps sixteen times smaller. With the exact pressure and backward Euler
// the large step keeps the drag; the standard update and Crank-Nicolson lose a good part
// of it, as they lag the film's pressure and viscous stress a step behind the sphere
// (bench/fluid_accuracy/README.md "Sphere closing on a wall").
TEST(ExactProjection, KeepsTheDragOfASphereClosingOnAWallAtLargeSteps) {
  IbmOptions ibm;
  ibm.corrections = 20;
  const bench::WallApproachBox box{.diameters = 4, .start_gap = 1.5};
  const TimeStepOptions exact{.theta = 1, .pressure_update = PressureUpdate::exact};
  const auto run = [&](double viscous_number, const TimeStepOptions& stepping) {
    return bench::sphere_approaching_a_wall(ibm, 6, viscous_number, 0.5, {0.5}, stepping, box);
  };
  const bench::WallApproach small = run(0.25, exact);
  const double large = bench::error_against(run(4, exact), small, 0.5);
  const double standard = bench::error_against(run(4, {}), small, 0.5);
  std::printf("drag at half a radius from the wall, nu dt / h^2 4 against 0.25: exact %+.2f %%, standard %+.2f %%\n",
              100 * large, 100 * standard);
  EXPECT_LT(std::abs(large), 0.01);
  EXPECT_LT(standard, -0.05);
}

}  // namespace
}  // namespace cosim::fluid
