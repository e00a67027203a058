#pragma once
// The implicit part of the viscous term, div(nu grad u_c): one stencil shared by the
// implicit matrix and the explicit half of Crank-Nicolson so both always discretise the
// same thing.
#include <array>

#include "fluid/boundary_conditions.hpp"
#include "fluid/grid.hpp"
#include "fluid/viscosity_field.hpp"

namespace cosim::fluid {

struct StencilEntry {
  Index at{};
  double weight = 0;
};

// div(nu grad u_c)(p) = sum(weight * u_c[at]) + constant; the constant carries the wall
// velocities. Entries may repeat an index on a periodic axis of two cells: add them up.
struct Stencil {
  std::array<StencilEntry, 12> entries{};  // 3 along the own axis, up to 4 per wall closure
  int size = 0;
  double constant = 0;
  void add(const Index& at, double weight) { entries[static_cast<std::size_t>(size++)] = {at, weight}; }
};

// Distance between the two flux points that the shear stress across axis d is differenced
// over at cell index i: the midpoints between neighbouring cell centres, or the wall. The
// explicit cross stresses use the same, so the two parts of div(2 nu D) cancel for a rigid
// motion. (It equals the cell width up to O(h^2) on a smoothly stretched axis.)
double shear_flux_span(const Axis& axis, int i);

// Second order on stretched axes (three-point differences exact for quadratics, and a
// one-sided quadratic closure through the boundary value next to a wall, so a parabolic
// profile is reproduced exactly). p must not be a boundary face of component c.
Stencil viscous_stencil(const Grid& grid, const BoundaryConditions& bc, const ViscosityField& nu, int c,
                        const Index& p, double t);

}  // namespace cosim::fluid
