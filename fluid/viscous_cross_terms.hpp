#pragma once
// The part of div(2 nu D) that the implicit operator leaves out, sum_d d/dx_d (nu du_d/dx_c).
// It is the gradient of nu div(u), zero for a divergence-free field, as long as nu is
// constant; a generalized-Newtonian fluid needs it, explicitly, with the convection.
#include "fluid/grid.hpp"
#include "fluid/local_velocity.hpp"
#include "fluid/viscosity_field.hpp"

namespace cosim::fluid {

// At face p of component c, not a boundary face of c.
double viscous_cross_terms(const Grid& grid, const LocalVelocity& u, const ViscosityField& nu, int c, const Index& p);

}  // namespace cosim::fluid
