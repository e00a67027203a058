// Power-law and Carreau viscosities: the model functions, the variable-viscosity operator
// against the Newtonian one, and power-law flow between plates against its exact profile.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fluid/grid/local_velocity.hpp"
#include "fluid/viscous/viscous_cross_terms.hpp"
#include "fluid/viscous/viscous_stencil.hpp"
#include "tests/fluid/flow_checks.hpp"

namespace cosim::fluid {

using grid::Axis;
using grid::Boundary;
using grid::BoundaryConditions;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::LocalVelocity;
using grid::Point;
using grid::Side;
using navier_stokes::NavierStokes;
using viscous::Stencil;
using viscous::ViscosityField;
using viscous::ViscosityModel;
using viscous::viscous_cross_terms;
using viscous::viscous_stencil;

namespace {

TEST(ViscosityModel, LimitsAndClipping) {
  const auto carreau = ViscosityModel::carreau(2.0, 0.1, 0.5, 0.4);
  EXPECT_DOUBLE_EQ(carreau(0), 2.0);
  EXPECT_NEAR(carreau(1e9), 0.1, 1e-3);
  EXPECT_NEAR(carreau(2.0), 0.1 + 1.9 * std::pow(2.0, -0.3), 1e-12);  // lambda gamma = 1
  const auto thinning = ViscosityModel::power_law(3.0, 0.5, 0.01, 50);
  EXPECT_DOUBLE_EQ(thinning(0), 50);
  EXPECT_DOUBLE_EQ(thinning(4), 1.5);
  EXPECT_DOUBLE_EQ(ViscosityModel::power_law(3.0, 1.5, 0.01, 50)(0), 0.01);
  EXPECT_THROW(ViscosityModel::power_law(1, 0.5, 1, 0.5), std::invalid_argument);
  EXPECT_THROW(ViscosityModel::newtonian(0), std::invalid_argument);
}

// A rigid rotation has no strain, so div(2 nu D) must vanish for it whatever the
// viscosity field: the implicit stencil and the explicit cross stresses must use the same
// viscosity on the same edges, walls included.
TEST(GeneralizedNewtonian, RigidRotationFeelsNoViscousForce) {
  Grid grid(PETSC_COMM_WORLD, {Axis::stretched(8, 0, 1, 1.0, false), Axis::stretched(7, 0, 2, 0.5, false),
                               Axis::uniform(6, 0, 1, false)});
  const auto rotation = [](const Point& x) {
    const Point w{0.3, -0.5, 0.7};
    return Point{w[1] * x[2] - w[2] * x[1], w[2] * x[0] - w[0] * x[2], w[0] * x[1] - w[1] * x[0]};
  };
  const auto shear = [](const Point& x) { return Point{std::sin(3 * x[1]), x[2] * x[2], x[0] * x[1]}; };
  BoundaryConditions bc(grid);
  for (int d = 0; d < 3; ++d)
    for (Side s : {Side::lower, Side::upper})
      bc.set(d, s, Boundary::inflow([rotation](const Point& x, double) { return rotation(x); }));

  const auto sample = [&](const std::function<Point(const Point&)>& f) {
    std::array<Vec, 3> global{};
    for (int c = 0; c < 3; ++c) {
      DMCreateGlobalVector(grid.velocity_dm(c), &global[c]);
      PetscScalar*** u = nullptr;
      DMDAVecGetArray(grid.velocity_dm(c), global[c], &u);
      for_each_index(grid.owned(grid.velocity_dm(c)),
                     [&](const Index& p) { u[p[2]][p[1]][p[0]] = f(grid.position(c, p))[c]; });
      DMDAVecRestoreArray(grid.velocity_dm(c), global[c], &u);
    }
    return global;
  };
  auto sheared = sample(shear), rotating = sample(rotation);
  LocalVelocity shear_local(grid), rotation_local(grid);
  shear_local.update(sheared, bc, 0);
  rotation_local.update(rotating, bc, 0);
  ViscosityField nu(grid, ViscosityModel::power_law(1.0, 0.5, 1e-3, 1e3), 1.0);
  nu.update(shear_local);

  double worst = 0;
  for (int c = 0; c < 3; ++c)
    for_each_index(grid.owned(grid.velocity_dm(c)), [&](const Index& p) {
      if (grid.on_boundary(c, p)) return;
      const Stencil s = viscous_stencil(grid, bc, nu, c, p, 0);
      double force = s.constant + viscous_cross_terms(grid, rotation_local, nu, c, p);
      for (int e = 0; e < s.size; ++e)
        force += s.entries[static_cast<std::size_t>(e)].weight *
                 rotation_local(c, s.entries[static_cast<std::size_t>(e)].at);
      worst = std::max(worst, std::abs(force));
    });
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  for (auto* field : {&sheared, &rotating})
    for (Vec& v : *field) VecDestroy(&v);
  PetscPrintf(PETSC_COMM_WORLD, "Rigid rotation, power-law viscosity: max |div(2 nu D)| = %.2e\n", worst);
  EXPECT_LT(worst, 1e-10);
}

// A power law of index 1 is Newtonian, but takes the variable-viscosity path (edge
// averages, cross stresses, reassembly): both must give the same flow. (On a uniform grid;
// on a stretched one the cross stresses of a divergence-free field are O(h^2), not zero.)
TEST(GeneralizedNewtonian, PowerLawOfIndexOneIsNewtonian) {
  const double difference = testing::max_difference(
      testing::mixed_boundary_flow(PETSC_COMM_WORLD, ViscosityModel::newtonian(0.02), 0),
      testing::mixed_boundary_flow(PETSC_COMM_WORLD, ViscosityModel::power_law(0.02, 1.0, 1e-6, 1e6), 0));
  PetscPrintf(PETSC_COMM_WORLD, "Power law n = 1 against Newtonian (12 x 8 x 6, 20 steps): max |difference| = %.2e\n",
              difference);
  EXPECT_LT(difference, 1e-9);
}

// Between plates 0 < y < 1 driven by G: u = n/(n+1) (G/K)^(1/n) ((1/2)^(1+1/n) - |y - 1/2|^(1+1/n)).
TEST(GeneralizedNewtonian, PowerLawPlatesSecondOrder) {
  constexpr double K = 1.0, n = 0.5, G = 2.0;
  const auto exact = [](const Point& x) {
    return n / (n + 1) * std::pow(G / K, 1 / n) *
           (std::pow(0.5, 1 + 1 / n) - std::pow(std::abs(x[1] - 0.5), 1 + 1 / n));
  };
  std::vector<double> errors;
  for (int cells : {16, 32}) {
    Grid grid(PETSC_COMM_WORLD,
              {Axis::uniform(4, 0, 1, true), Axis::uniform(cells, 0, 1, false), Axis::uniform(1, 0, 1, true)});
    BoundaryConditions bc(grid);
    NavierStokes flow(grid, bc, {1.0, ViscosityModel::power_law(K, n, 1e-3, 1e3), {G, 0, 0}},
                      {.cfl = 0.5, .dt_max = 0.5, .dt_initial = 0.01, .theta = 1});
    flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
    const double t = testing::run_to_steady_state(flow, 1e-10, 100, 1e-9);
    errors.push_back(testing::max_error(flow, 0, exact));
    PetscPrintf(PETSC_COMM_WORLD, "  %d cells: steady at t = %.2f\n", cells, t);
  }
  const double order = std::log2(errors[0] / errors[1]);
  PetscPrintf(PETSC_COMM_WORLD,
              "Power law n = 0.5 plates (16, 32 cells): max errors %.3e %.3e (u_max %.4f), order %.2f\n", errors[0],
              errors[1], exact({0, 0.5, 0}), order);
  EXPECT_GT(order, 1.8);
}

}  // namespace
}  // namespace cosim::fluid
