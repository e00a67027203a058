#pragma once
// The part of div(2 nu D) that the implicit operator leaves out, sum_d d/dx_d (nu du_d/dx_c).
// It is the gradient of nu div(u), zero for a divergence-free field, as long as nu is
// constant; a generalized-Newtonian fluid needs it, explicitly, with the convection.
#include "fluid/grid/grid.hpp"
#include "fluid/grid/local_velocity.hpp"
#include "fluid/viscous/viscosity_field.hpp"

namespace cosim::fluid::viscous {

// At face p of component c, not a boundary face of c.
double viscous_cross_terms(const grid::Grid& grid, const grid::LocalVelocity& u, const ViscosityField& nu, int c,
                           const grid::Index& p);

}  // namespace cosim::fluid::viscous
