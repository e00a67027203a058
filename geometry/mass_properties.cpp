#include "geometry/mass_properties.hpp"

#include "geometry/detail/checks.hpp"

namespace cosim::geometry {

MassProperties mass_properties(const Shape& shape, double density) {
  detail::require_positive(density, "mass properties", "density");
  const double v = volume(shape);
  return {v, density * v, density * unit_inertia(shape)};
}

}  // namespace cosim::geometry
