#pragma once
// Velocity boundary conditions per domain face. Pressure conditions follow from them:
// zero normal pressure gradient where the velocity is given, zero pressure at an outflow.
#include <array>
#include <functional>

#include "fluid/grid/grid.hpp"

namespace cosim::fluid::grid {

using VelocityFunction = std::function<Point(const Point& x, double t)>;

enum class BoundaryKind {
  wall,      // given velocity, tangential only (a moving lid); zero for no-slip
  inflow,    // given velocity profile, normal component included
  outflow,   // do-nothing: zero normal derivative of the velocity, zero pressure
  periodic,  // both faces of a periodic axis
};

struct Boundary {
  BoundaryKind kind = BoundaryKind::wall;
  VelocityFunction velocity;  // wall and inflow only

  static Boundary no_slip();
  static Boundary moving_wall(Point velocity);
  static Boundary inflow(VelocityFunction profile);
  static Boundary outflow();
  static Boundary periodic();
};

enum class Side { lower = 0, upper = 1 };

class BoundaryConditions {
 public:
  // All faces are no-slip walls until set; periodic axes get periodic faces.
  explicit BoundaryConditions(const Grid& grid);
  void set(int axis, Side side, Boundary b);
  const Boundary& at(int axis, Side side) const { return faces_[index(axis, side)]; }
  // Without an outflow face the pressure is fixed only up to a constant.
  bool has_outflow() const;

  // The velocity a wall or inflow face imposes at point x (a wall's normal part is dropped).
  Point velocity(int axis, Side side, const Point& x, double t) const;

 private:
  static std::size_t index(int axis, Side side) { return static_cast<std::size_t>(2 * axis + static_cast<int>(side)); }
  const Grid& grid_;
  std::array<Boundary, 6> faces_;
};

}  // namespace cosim::fluid::grid
