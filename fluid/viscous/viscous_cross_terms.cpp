#include "fluid/viscous/viscous_cross_terms.hpp"

#include "fluid/viscous/viscous_stencil.hpp"

namespace cosim::fluid::viscous {

using grid::Axis;
using grid::Grid;
using grid::Index;
using grid::LocalVelocity;
using grid::shifted;

double viscous_cross_terms(const Grid& grid, const LocalVelocity& u, const ViscosityField& nu, int c, const Index& p) {
  const Axis& own = grid.axis(c);
  if (own.degenerate()) return 0;
  const int i = static_cast<int>(p[c]);
  const double dc = own.centre(i) - own.centre(i - 1);
  double sum = 0;
  for (int d = 0; d < 3; ++d) {
    const Axis& across = grid.axis(d);
    if (across.degenerate()) continue;
    if (d == c) {
      // nu du_c/dx_c at the two cell centres beside the face.
      const Index below = shifted(p, c, -1);
      const double upper = nu.at_cell(p) * (u(c, shifted(p, c, 1)) - u(c, p)) / own.width(i);
      const double lower = nu.at_cell(below) * (u(c, p) - u(c, below)) / own.width(i - 1);
      sum += (upper - lower) / dc;
      continue;
    }
    // nu du_d/dx_c on the edges where the c-face meets the d-faces below and above.
    const auto flux = [&](PetscInt j) {
      Index face = p;
      face[d] = j;
      return nu.at_edge(c, d, p, j) * (u(d, face) - u(d, shifted(face, c, -1))) / dc;
    };
    sum += (flux(p[d] + 1) - flux(p[d])) / shear_flux_span(across, static_cast<int>(p[d]));
  }
  return sum;
}

}  // namespace cosim::fluid::viscous
