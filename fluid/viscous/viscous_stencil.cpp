#include "fluid/viscous/viscous_stencil.hpp"

#include <cmath>

namespace cosim::fluid::viscous {

using grid::Axis;
using grid::BoundaryConditions;
using grid::BoundaryKind;
using grid::Grid;
using grid::Index;
using grid::Point;
using grid::shifted;
using grid::Side;

namespace {

// Three-point difference of nu du/dx at a point with neighbours hm below and hp above,
// viscosities nu_m, nu_p at the flux points between, and span between those points.
ViscousWeights interior(double hm, double hp, double span, double nu_m, double nu_p) {
  return {nu_m / (hm * span), -(nu_m / hm + nu_p / hp) / span, nu_p / (hp * span), 0};
}

// Next to a bounded face, with the boundary value ub at distance d0 from the first cell
// centre and d1 from the second (distances measured into the domain, so both sides look
// alike). The outer flux is nu_wall times the derivative at the face of the quadratic
// through the boundary value and the two centres (zero at an outflow); the inner flux is
// the central difference, and the two are differenced over the distance between them.
// Returns the weights of (first, second, ub).
std::array<double, 3> boundary_closure(double d0, double d1, double nu_inner, double nu_wall, bool dirichlet) {
  const double spacing = d1 - d0;
  const double span = 0.5 * (d0 + d1);  // shear_flux_span next to the wall
  std::array<double, 3> w{-nu_inner / (spacing * span), nu_inner / (spacing * span), 0};
  if (!dirichlet) return w;
  const double aw = -(1 / d0 + 1 / d1);
  const double a0 = d1 / (d0 * spacing);
  const double a1 = -d0 / (d1 * spacing);
  w[0] -= nu_wall * a0 / span;
  w[1] -= nu_wall * a1 / span;
  w[2] = -nu_wall * aw / span;
  return w;
}

bool bounded_side(const Axis& axis, int i, Side side) {
  return !axis.periodic() && (side == Side::lower ? i == 0 : i == axis.cells() - 1);
}

}  // namespace

double shear_flux_span(const Axis& axis, int i) {
  if (!axis.periodic() && i == 0) return 0.5 * (axis.centre(0) + axis.centre(1)) - axis.lo();
  if (!axis.periodic() && i == axis.cells() - 1) return axis.hi() - 0.5 * (axis.centre(i) + axis.centre(i - 1));
  return 0.5 * (axis.centre(i + 1) - axis.centre(i - 1));
}

ViscousWeights viscous_axis_weights(const Grid& grid, const BoundaryConditions& bc, int c, int d, int i,
                                    double nu_below, double nu_above) {
  const Axis& axis = grid.axis(d);
  if (d == c)
    return interior(axis.width(i - 1), axis.width(i), axis.centre(i) - axis.centre(i - 1), nu_below, nu_above);
  const bool lower = bounded_side(axis, i, Side::lower), upper = bounded_side(axis, i, Side::upper);
  if (!lower && !upper)
    return interior(axis.centre(i) - axis.centre(i - 1), axis.centre(i + 1) - axis.centre(i), shear_flux_span(axis, i),
                    nu_below, nu_above);
  const Side side = lower ? Side::lower : Side::upper;
  const double wall = lower ? axis.lo() : axis.hi();
  const int second = lower ? 1 : i - 1;
  const double d0 = std::abs(axis.centre(i) - wall);
  const double d1 = std::abs(axis.centre(second) - wall);
  const auto w = boundary_closure(d0, d1, lower ? nu_above : nu_below, lower ? nu_below : nu_above,
                                  bc.at(d, side).kind != BoundaryKind::outflow);
  ViscousWeights out;
  out.centre = w[0];
  (lower ? out.above : out.below) = w[1];
  out.boundary = w[2];
  return out;
}

double nu_below(const ViscosityField& nu, int c, int d, const Index& p) {
  return d == c ? nu.at_cell(shifted(p, d, -1)) : nu.at_edge(c, d, p, p[d]);
}

double nu_above(const ViscosityField& nu, int c, int d, const Index& p) {
  return d == c ? nu.at_cell(p) : nu.at_edge(c, d, p, p[d] + 1);
}

double boundary_velocity(const Grid& grid, const BoundaryConditions& bc, int c, int d, const Index& p, double t) {
  const Axis& axis = grid.axis(d);
  const bool lower = bounded_side(axis, static_cast<int>(p[d]), Side::lower);
  Point x = grid.position(c, p);
  x[d] = lower ? axis.lo() : axis.hi();
  return bc.velocity(d, lower ? Side::lower : Side::upper, x, t)[c];
}

UniformViscousWeights::UniformViscousWeights(const Grid& grid, const BoundaryConditions& bc, double nu) {
  for (int c = 0; c < 3; ++c)
    for (int d = 0; d < 3; ++d) {
      const Axis& axis = grid.axis(d);
      // Along its own axis a component lives on faces: the first and last of a bounded
      // axis are boundary values with no weights of their own. An axis without variation
      // has zero weights.
      auto& list = weights_[static_cast<std::size_t>(3 * c + d)];
      const int n = axis.cells() + (d == c && !axis.periodic() ? 1 : 0);
      list.resize(static_cast<std::size_t>(n));
      if (axis.degenerate()) continue;
      for (int i = 0; i < n; ++i) {
        if (d == c && !axis.periodic() && (i == 0 || i == n - 1)) continue;
        list[static_cast<std::size_t>(i)] = viscous_axis_weights(grid, bc, c, d, i, nu, nu);
      }
    }
}

Stencil viscous_stencil(const Grid& grid, const BoundaryConditions& bc, const ViscosityField& nu, int c, const Index& p,
                        double t) {
  Stencil s;
  double centre = 0;
  for (int d = 0; d < 3; ++d) {
    if (grid.axis(d).degenerate()) continue;
    const int i = static_cast<int>(p[d]);
    const ViscousWeights w = viscous_axis_weights(grid, bc, c, d, i, nu_below(nu, c, d, p), nu_above(nu, c, d, p));
    centre += w.centre;
    if (w.below != 0) s.add(shifted(p, d, -1), w.below);
    if (w.above != 0) s.add(shifted(p, d, +1), w.above);
    if (w.boundary != 0) s.constant += w.boundary * boundary_velocity(grid, bc, c, d, p, t);
  }
  s.add(p, centre);
  return s;
}

}  // namespace cosim::fluid::viscous
