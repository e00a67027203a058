#pragma once
// The implicit part of the viscous term, div(nu grad u_c): one set of weights shared by the
// implicit matrix and the explicit half of Crank-Nicolson so both always discretise the
// same thing.
#include <array>
#include <vector>

#include "fluid/grid/boundary_conditions.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/viscous/viscosity_field.hpp"

namespace cosim::fluid::viscous {

// One axis d's part of div(nu grad u_c) at a point p: the weights of u_c at p - e_d, p and
// p + e_d, and of the boundary value u_b on the wall next to p (zero away from walls and
// at an outflow); a weight across a wall is zero.
struct ViscousWeights {
  double below = 0, centre = 0, above = 0, boundary = 0;
};

// u_c at a point and at its neighbours below and above it along x, y and z.
struct SevenPoints {
  double centre = 0;
  std::array<double, 3> below{}, above{};
};

// The three axes' weights applied to the seven points: div(nu grad u_c) without its wall
// terms. The explicit half of Crank-Nicolson and the matrix-free implicit operator share it.
inline double weighted_sum(const ViscousWeights& x, const ViscousWeights& y, const ViscousWeights& z,
                           const SevenPoints& u) {
  return (x.centre + y.centre + z.centre) * u.centre + x.below * u.below[0] + x.above * u.above[0] +
         y.below * u.below[1] + y.above * u.above[1] + z.below * u.below[2] + z.above * u.above[2];
}

// Second order on stretched axes (three-point differences exact for quadratics, and a
// one-sided quadratic closure through the boundary value next to a wall, so a parabolic
// profile is reproduced exactly). i is p's index along d, nu_below and nu_above the
// viscosities at the flux points below and above p along d. p must not be a boundary face
// of component c, and d must carry variation.
ViscousWeights viscous_axis_weights(const grid::Grid& grid, const grid::BoundaryConditions& bc, int c, int d, int i,
                                    double nu_below, double nu_above);

// The viscosities at p's flux points along d (cell centres along c, edges across).
double nu_below(const ViscosityField& nu, int c, int d, const grid::Index& p);
double nu_above(const ViscosityField& nu, int c, int d, const grid::Index& p);

// The value a wall holds u_c at next to p along d (the side p touches), at time t.
double boundary_velocity(const grid::Grid& grid, const grid::BoundaryConditions& bc, int c, int d, const grid::Index& p,
                         double t);

// A uniform viscosity's weights depend on the position along each axis only: listed once
// per component and axis, so the explicit half of Crank-Nicolson reads them per point.
class UniformViscousWeights {
 public:
  UniformViscousWeights(const grid::Grid& grid, const grid::BoundaryConditions& bc, double nu);
  const ViscousWeights& at(int c, int d, PetscInt i) const {
    return weights_[static_cast<std::size_t>(3 * c + d)][static_cast<std::size_t>(i)];
  }

 private:
  std::array<std::vector<ViscousWeights>, 9> weights_;
};

struct StencilEntry {
  grid::Index at{};
  double weight = 0;
};

// div(nu grad u_c)(p) = sum(weight * u_c[at]) + constant; the constant carries the wall
// velocities. Entries may repeat an index on a periodic axis of two cells: add them up.
struct Stencil {
  std::array<StencilEntry, 7> entries{};  // the point and its neighbours along each axis
  int size = 0;
  double constant = 0;
  void add(const grid::Index& at, double weight) { entries[static_cast<std::size_t>(size++)] = {at, weight}; }
};

// Distance between the two flux points that the shear stress across axis d is differenced
// over at cell index i: the midpoints between neighbouring cell centres, or the wall. The
// explicit cross stresses use the same, so the two parts of div(2 nu D) cancel for a rigid
// motion. (It equals the cell width up to O(h^2) on a smoothly stretched axis.)
double shear_flux_span(const grid::Axis& axis, int i);

// The axes' weights of p as a stencil over its neighbours.
Stencil viscous_stencil(const grid::Grid& grid, const grid::BoundaryConditions& bc, const ViscosityField& nu, int c,
                        const grid::Index& p, double t);

}  // namespace cosim::fluid::viscous
