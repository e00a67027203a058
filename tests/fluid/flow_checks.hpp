#pragma once
// Measurements shared by the fluid tests.
#include <array>
#include <functional>
#include <vector>

#include "fluid/navier_stokes/navier_stokes.hpp"

namespace cosim::fluid::testing {

// max over all faces of component c of |u_c - exact(x)|, all ranks.
double max_error(const navier_stokes::NavierStokes& flow, int c,
                 const std::function<double(const grid::Point&)>& exact);

// max over components and faces of |a - b|; both flows on the same grid.
double max_difference(const navier_stokes::NavierStokes& a, const navier_stokes::NavierStokes& b);

// Component c in natural (i fastest) order, on every rank: for comparisons across partitions.
std::vector<double> gather(const navier_stokes::NavierStokes& flow, int c);

// Velocity components gathered on every rank.
using GatheredVelocity = std::array<std::vector<double>, 3>;

// A three-dimensional flow using every kind of boundary on a 12 x 8 x 6 grid: parabolic
// inflow at x = 0, outflow at x = 2, no-slip at y = 0, a moving wall at y = 1 (y stretched
// by y_stretching, 0 for uniform), periodic in z; 20 adaptive steps from a
// divergence-free start, checking the divergence after each.
GatheredVelocity mixed_boundary_flow(MPI_Comm comm, const viscous::ViscosityModel& viscosity, double y_stretching);

// max |a - b| over all components and faces.
double max_difference(const GatheredVelocity& a, const GatheredVelocity& b);

// Runs until the velocity changes by less than tolerance * dt per step (steady state) or
// t_max is reached; returns the time reached. Checks the divergence after every step.
double run_to_steady_state(navier_stokes::NavierStokes& flow, double tolerance, double t_max, double max_divergence,
                           const bodies::StepBodies& bodies = {});

}  // namespace cosim::fluid::testing
