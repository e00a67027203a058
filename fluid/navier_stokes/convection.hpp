#pragma once
// The convective term of the momentum equation.
#include "fluid/grid/grid.hpp"
#include "fluid/grid/local_velocity.hpp"

namespace cosim::fluid::navier_stokes {

// div(u u_c) at face p of component c, in conservative form with central (second-order,
// energy-neutral on uniform grids) interpolation. p must not be a boundary face of c.
double convection(const grid::Grid& grid, const grid::LocalVelocity& u, int c, const grid::Index& p);

}  // namespace cosim::fluid::navier_stokes
