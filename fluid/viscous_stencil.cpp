#include "fluid/viscous_stencil.hpp"

#include <cmath>

namespace cosim::fluid {

namespace {

// Three-point difference of nu du/dx at a point with neighbours hm below and hp above,
// viscosities nu_m, nu_p at the flux points between, and span between those points.
void add_interior(Stencil& s, const Index& p, int d, double hm, double hp, double span, double nu_m,
                  double nu_p) {
  s.add(shifted(p, d, -1), nu_m / (hm * span));
  s.add(shifted(p, d, +1), nu_p / (hp * span));
  s.add(p, -(nu_m / hm + nu_p / hp) / span);
}

// Next to a bounded face, with the boundary value ub at distance d0 from the first cell
// centre and d1 from the second (distances measured into the domain, so both sides look
// alike). The outer flux is nu_wall times the derivative at the face of the quadratic
// through the boundary value and the two centres (zero at an outflow); the inner flux is
// the central difference, and the two are differenced over the distance between them.
void add_boundary_closure(Stencil& s, const Index& first, const Index& second, double d0, double d1,
                          double nu_inner, double nu_wall, bool dirichlet, double ub) {
  const double spacing = d1 - d0;
  const double span = 0.5 * (d0 + d1);  // shear_flux_span next to the wall
  s.add(second, nu_inner / (spacing * span));
  s.add(first, -nu_inner / (spacing * span));
  if (!dirichlet) return;
  const double aw = -(1 / d0 + 1 / d1);
  const double a0 = d1 / (d0 * spacing);
  const double a1 = -d0 / (d1 * spacing);
  s.add(first, -nu_wall * a0 / span);
  s.add(second, -nu_wall * a1 / span);
  s.constant -= nu_wall * aw * ub / span;
}

}  // namespace

double shear_flux_span(const Axis& axis, int i) {
  if (!axis.periodic() && i == 0) return 0.5 * (axis.centre(0) + axis.centre(1)) - axis.lo();
  if (!axis.periodic() && i == axis.cells() - 1)
    return axis.hi() - 0.5 * (axis.centre(i) + axis.centre(i - 1));
  return 0.5 * (axis.centre(i + 1) - axis.centre(i - 1));
}

Stencil viscous_stencil(const Grid& grid, const BoundaryConditions& bc, const ViscosityField& nu, int c,
                        const Index& p, double t) {
  Stencil s;
  for (int d = 0; d < 3; ++d) {
    const Axis& axis = grid.axis(d);
    if (axis.degenerate()) continue;
    const int i = static_cast<int>(p[d]);
    if (d == c) {
      add_interior(s, p, d, axis.width(i - 1), axis.width(i), axis.centre(i) - axis.centre(i - 1),
                   nu.at_cell(shifted(p, d, -1)), nu.at_cell(p));
      continue;
    }
    const bool lower = !axis.periodic() && i == 0;
    const bool upper = !axis.periodic() && i == axis.cells() - 1;
    if (!lower && !upper) {
      add_interior(s, p, d, axis.centre(i) - axis.centre(i - 1), axis.centre(i + 1) - axis.centre(i),
                   shear_flux_span(axis, i), nu.at_edge(c, d, p, i), nu.at_edge(c, d, p, i + 1));
      continue;
    }
    const Side side = lower ? Side::lower : Side::upper;
    const double wall = lower ? axis.lo() : axis.hi();
    const Index second = shifted(p, d, lower ? 1 : -1);
    const double d0 = std::abs(axis.centre(i) - wall);
    const double d1 = std::abs(axis.centre(static_cast<int>(second[d])) - wall);
    const double nu_inner = nu.at_edge(c, d, p, lower ? 1 : i);
    const double nu_wall = nu.at_edge(c, d, p, lower ? 0 : i + 1);
    const bool dirichlet = bc.at(d, side).kind != BoundaryKind::outflow;
    double ub = 0;
    if (dirichlet) {
      Point x = grid.position(c, p);
      x[d] = wall;
      ub = bc.velocity(d, side, x, t)[c];
    }
    add_boundary_closure(s, p, second, d0, d1, nu_inner, nu_wall, dirichlet, ub);
  }
  return s;
}

}  // namespace cosim::fluid
