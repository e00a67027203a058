#include "fluid/grid/boundary_conditions.hpp"

#include <stdexcept>
#include <string>

namespace cosim::fluid::grid {

Boundary Boundary::no_slip() { return moving_wall({0, 0, 0}); }

Boundary Boundary::moving_wall(Point velocity) {
  return {BoundaryKind::wall, [velocity](const Point&, double) { return velocity; }};
}

Boundary Boundary::inflow(VelocityFunction profile) { return {BoundaryKind::inflow, std::move(profile)}; }

Boundary Boundary::outflow() { return {BoundaryKind::outflow, {}}; }

Boundary Boundary::periodic() { return {BoundaryKind::periodic, {}}; }

BoundaryConditions::BoundaryConditions(const Grid& grid) : grid_(grid) {
  for (int d = 0; d < 3; ++d)
    for (Side s : {Side::lower, Side::upper})
      faces_[index(d, s)] = grid.axis(d).periodic() ? Boundary::periodic() : Boundary::no_slip();
}

void BoundaryConditions::set(int axis, Side side, Boundary b) {
  const std::string where = "boundary " + std::string("xyz").substr(static_cast<std::size_t>(axis), 1) +
                            (side == Side::lower ? "-lower" : "-upper");
  if ((b.kind == BoundaryKind::periodic) != grid_.axis(axis).periodic())
    throw std::invalid_argument(where + ": periodic conditions go exactly on the faces of periodic axes");
  if ((b.kind == BoundaryKind::wall || b.kind == BoundaryKind::inflow) && !b.velocity)
    throw std::invalid_argument(where + ": a wall or inflow needs a velocity");
  faces_[index(axis, side)] = std::move(b);
}

bool BoundaryConditions::has_outflow() const {
  for (const auto& f : faces_)
    if (f.kind == BoundaryKind::outflow) return true;
  return false;
}

Point BoundaryConditions::velocity(int axis, Side side, const Point& x, double t) const {
  const Boundary& b = at(axis, side);
  if (b.kind != BoundaryKind::wall && b.kind != BoundaryKind::inflow) return {0, 0, 0};
  Point u = b.velocity(x, t);
  if (b.kind == BoundaryKind::wall) u[static_cast<std::size_t>(axis)] = 0;
  return u;
}

}  // namespace cosim::fluid::grid
