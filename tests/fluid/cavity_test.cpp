// Lid-driven cavity at Re = 100 (two-dimensional: one periodic cell layer in z), steady
// centre-line velocities against Ghia, Ghia & Shin, J. Comput. Phys. 48 (1982) 387-411,
// Tables I and II (Re = 100 columns).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/fluid/flow_checks.hpp"

namespace cosim::fluid {

using grid::Axis;
using grid::Boundary;
using grid::BoundaryConditions;
using grid::Grid;
using grid::Point;
using grid::Side;
using navier_stokes::NavierStokes;
using viscous::ViscosityModel;

namespace {

struct Sample {
  double at;
  double value;
};

// u(0.5, y)
const std::vector<Sample> kGhiaU = {{0.9766, 0.84123},  {0.9688, 0.78871},  {0.9609, 0.73722},  {0.9531, 0.68717},
                                    {0.8516, 0.23151},  {0.7344, 0.00332},  {0.6172, -0.13641}, {0.5000, -0.20581},
                                    {0.4531, -0.21090}, {0.2813, -0.15662}, {0.1719, -0.10150}, {0.1016, -0.06434},
                                    {0.0703, -0.04775}, {0.0625, -0.04192}, {0.0547, -0.03717}};
// v(x, 0.5)
const std::vector<Sample> kGhiaV = {{0.9688, -0.05906}, {0.9609, -0.07391}, {0.9531, -0.08864}, {0.9453, -0.10313},
                                    {0.9063, -0.16914}, {0.8594, -0.22445}, {0.8047, -0.24533}, {0.5000, 0.05454},
                                    {0.2344, 0.17527},  {0.2266, 0.17507},  {0.1563, 0.16077},  {0.0938, 0.12317},
                                    {0.0781, 0.10890},  {0.0703, 0.10091},  {0.0625, 0.09233}};

// Piecewise-linear profile through the cell centres and the two wall values.
double interpolate(const Axis& axis, const std::vector<double>& inside, double lower, double upper, double x) {
  std::vector<double> xs{axis.lo()}, vs{lower};
  for (int i = 0; i < axis.cells(); ++i) {
    xs.push_back(axis.centre(i));
    vs.push_back(inside[static_cast<std::size_t>(i)]);
  }
  xs.push_back(axis.hi());
  vs.push_back(upper);
  const auto it = std::upper_bound(xs.begin(), xs.end(), x);
  const auto k = static_cast<std::size_t>(std::clamp<long>(it - xs.begin(), 1, static_cast<long>(xs.size()) - 1));
  const double w = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
  return (1 - w) * vs[k - 1] + w * vs[k];
}

TEST(LidDrivenCavity, Re100MatchesGhia) {
  const int n = 32;
  Grid grid(PETSC_COMM_WORLD,
            {Axis::stretched(n, 0, 1, 1.2, false), Axis::stretched(n, 0, 1, 1.2, false), Axis::uniform(1, 0, 1, true)});
  BoundaryConditions bc(grid);
  bc.set(1, Side::upper, Boundary::moving_wall({1, 0, 0}));
  NavierStokes flow(grid, bc, {1.0, ViscosityModel::newtonian(0.01), {0, 0, 0}},
                    {.cfl = 0.8, .dt_max = 0.1, .dt_initial = 1e-3});
  flow.set_velocity([](const Point&) { return Point{0, 0, 0}; });
  const double t = testing::run_to_steady_state(flow, 1e-5, 60, 1e-8);

  // With symmetric stretching and n even, face n/2 lies on the centre line.
  const std::vector<double> u = testing::gather(flow, 0), v = testing::gather(flow, 1);
  std::vector<double> u_line(n), v_line(n);
  for (int j = 0; j < n; ++j) u_line[static_cast<std::size_t>(j)] = u[static_cast<std::size_t>(n / 2 + (n + 1) * j)];
  for (int i = 0; i < n; ++i) v_line[static_cast<std::size_t>(i)] = v[static_cast<std::size_t>(i + n * (n / 2))];
  double u_error = 0, v_error = 0;
  for (const Sample& s : kGhiaU)
    u_error = std::max(u_error, std::abs(interpolate(grid.axis(1), u_line, 0, 1, s.at) - s.value));
  for (const Sample& s : kGhiaV)
    v_error = std::max(v_error, std::abs(interpolate(grid.axis(0), v_line, 0, 0, s.at) - s.value));
  PetscPrintf(PETSC_COMM_WORLD,
              "Cavity Re 100 (%d^2 stretched): steady at t = %.1f, max |u - Ghia| = %.4f, max |v - Ghia| = %.4f\n", n,
              t, u_error, v_error);
  EXPECT_LT(t, 60);
  EXPECT_LT(u_error, 0.02);
  EXPECT_LT(v_error, 0.02);
}

}  // namespace
}  // namespace cosim::fluid
