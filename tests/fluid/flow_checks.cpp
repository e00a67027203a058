#include "tests/fluid/flow_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace cosim::fluid::testing {

using bodies::StepBodies;
using grid::Axis;
using grid::Boundary;
using grid::BoundaryConditions;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::Point;
using grid::Side;
using navier_stokes::NavierStokes;
using navier_stokes::StepReport;
using viscous::ViscosityModel;

double max_error(const NavierStokes& flow, int c, const std::function<double(const Point&)>& exact) {
  const Grid& grid = flow.grid();
  DM dm = grid.velocity_dm(c);
  const PetscScalar*** u = nullptr;
  DMDAVecGetArrayRead(dm, flow.velocity(c), &u);
  double local = 0;
  for_each_index(grid.owned(dm), [&](const Index& p) {
    local = std::max(local, std::abs(u[p[2]][p[1]][p[0]] - exact(grid.position(c, p))));
  });
  DMDAVecRestoreArrayRead(dm, flow.velocity(c), &u);
  double global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, grid.comm());
  return global;
}

double max_difference(const NavierStokes& a, const NavierStokes& b) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) {
    Vec diff;
    VecDuplicate(a.velocity(c), &diff);
    VecWAXPY(diff, -1.0, b.velocity(c), a.velocity(c));
    PetscReal norm = 0;
    VecNorm(diff, NORM_INFINITY, &norm);
    VecDestroy(&diff);
    worst = std::max(worst, static_cast<double>(norm));
  }
  return worst;
}

std::vector<double> gather(const NavierStokes& flow, int c) {
  DM dm = flow.grid().velocity_dm(c);
  Vec natural, all;
  DMDACreateNaturalVector(dm, &natural);
  DMDAGlobalToNaturalBegin(dm, flow.velocity(c), INSERT_VALUES, natural);
  DMDAGlobalToNaturalEnd(dm, flow.velocity(c), INSERT_VALUES, natural);
  VecScatter to_all;
  VecScatterCreateToAll(natural, &to_all, &all);
  VecScatterBegin(to_all, natural, all, INSERT_VALUES, SCATTER_FORWARD);
  VecScatterEnd(to_all, natural, all, INSERT_VALUES, SCATTER_FORWARD);
  PetscInt n = 0;
  VecGetSize(all, &n);
  const PetscScalar* values = nullptr;
  VecGetArrayRead(all, &values);
  std::vector<double> out(values, values + n);
  VecRestoreArrayRead(all, &values);
  VecScatterDestroy(&to_all);
  VecDestroy(&all);
  VecDestroy(&natural);
  return out;
}

GatheredVelocity mixed_boundary_flow(MPI_Comm comm, const ViscosityModel& viscosity, double y_stretching) {
  Grid grid(comm, {Axis::uniform(12, 0, 2, false), Axis::stretched(8, 0, 1, y_stretching, false),
                   Axis::uniform(6, 0, 1, true)});
  BoundaryConditions bc(grid);
  bc.set(0, Side::lower, Boundary::inflow([](const Point& x, double) { return Point{4 * x[1] * (1 - x[1]), 0, 0.1}; }));
  bc.set(0, Side::upper, Boundary::outflow());
  bc.set(1, Side::upper, Boundary::moving_wall({0.5, 0, 0.2}));
  NavierStokes flow(grid, bc, {1.0, viscosity, {0, 0, 0}}, {.cfl = 0.5, .dt_max = 0.05, .dt_initial = 0.01});
  flow.set_velocity([](const Point& x) { return Point{4 * x[1] * (1 - x[1]), 0, 0.1 + 0.1 * std::sin(3 * x[0])}; });
  for (int s = 0; s < 20; ++s) {
    const StepReport r = flow.step();
    EXPECT_LT(r.max_divergence, 1e-7) << "step " << s;
  }
  return {gather(flow, 0), gather(flow, 1), gather(flow, 2)};
}

double max_difference(const GatheredVelocity& a, const GatheredVelocity& b) {
  double worst = 0;
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < a[c].size(); ++i) worst = std::max(worst, std::abs(a[c][i] - b[c][i]));
  return worst;
}

double run_to_steady_state(NavierStokes& flow, double tolerance, double t_max, double max_divergence,
                           const StepBodies& bodies) {
  std::array<Vec, 3> before{};
  for (int c = 0; c < 3; ++c) VecDuplicate(flow.velocity(c), &before[c]);
  while (flow.time() < t_max) {
    for (int c = 0; c < 3; ++c) VecCopy(flow.velocity(c), before[c]);
    const StepReport r = flow.step(bodies);
    EXPECT_LT(r.max_divergence, max_divergence) << "at t = " << r.time;
    double change = 0;
    for (int c = 0; c < 3; ++c) {
      VecAXPY(before[c], -1.0, flow.velocity(c));
      PetscReal norm = 0;
      VecNorm(before[c], NORM_INFINITY, &norm);
      change = std::max(change, static_cast<double>(norm));
    }
    if (change < tolerance * r.dt) break;
  }
  for (auto& v : before) VecDestroy(&v);
  return flow.time();
}

}  // namespace cosim::fluid::testing
