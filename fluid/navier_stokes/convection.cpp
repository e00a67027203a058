#include "fluid/navier_stokes/convection.hpp"

namespace cosim::fluid::navier_stokes {

using grid::Axis;
using grid::Grid;
using grid::Index;
using grid::LocalVelocity;
using grid::shifted;

namespace {

// Linear interpolation weight of the upper of two cell centres at face i of an axis.
double face_weight(const Axis& a, int i) { return (a.face(i) - a.centre(i - 1)) / (a.centre(i) - a.centre(i - 1)); }

}  // namespace

double convection(const Grid& grid, const LocalVelocity& u, int c, const Index& p) {
  const Axis& own = grid.axis(c);
  const int i = static_cast<int>(p[c]);
  double sum = 0;
  // Along its own axis the momentum flux u_c u_c lives at cell centres, halfway between faces.
  if (!own.degenerate()) {
    const double upper = 0.5 * (u(c, p) + u(c, shifted(p, c, 1)));
    const double lower = 0.5 * (u(c, shifted(p, c, -1)) + u(c, p));
    sum += (upper * upper - lower * lower) / (own.centre(i) - own.centre(i - 1));
  }
  // Across axis d the flux u_d u_c lives on the edges where the c- and d-faces meet.
  const double wc = face_weight(own, i);
  for (int d = 0; d < 3; ++d) {
    const Axis& across = grid.axis(d);
    if (d == c || across.degenerate()) continue;
    const auto flux = [&](PetscInt j) {
      const Index face = shifted(p, d, j - p[d]);
      const double ud = (1 - wc) * u(d, shifted(face, c, -1)) + wc * u(d, face);
      const double wd = face_weight(across, static_cast<int>(j));
      const double uc = (1 - wd) * u(c, shifted(face, d, -1)) + wd * u(c, face);
      return ud * uc;
    };
    sum += (flux(p[d] + 1) - flux(p[d])) / across.width(static_cast<int>(p[d]));
  }
  return sum;
}

}  // namespace cosim::fluid::navier_stokes
