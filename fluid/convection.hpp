#pragma once
// The convective term of the momentum equation.
#include "fluid/grid.hpp"
#include "fluid/local_velocity.hpp"

namespace cosim::fluid {

// div(u u_c) at face p of component c, in conservative form with central (second-order,
// energy-neutral on uniform grids) interpolation. p must not be a boundary face of c.
double convection(const Grid& grid, const LocalVelocity& u, int c, const Index& p);

}  // namespace cosim::fluid
