// Virtual-mass stabilization of explicitly coupled light bodies (Schwarz, Kempe & Froehlich,
// J. Comput. Phys. 281, 2015): both sides of a body's equation of motion get the inertia
// m_v = C rho_f V of a share C of the fluid it displaces, the left implicitly and the right
// with the body's acceleration over the previous window,
//   (m + m_v) a = F_gravity,buoyancy + F_fluid + m_v a_prev,
// so a fluid force lagging by a window (its added-mass and lubrication parts react to the
// body's own acceleration) cannot feed back on itself as in plain explicit coupling, which
// diverges once the added mass exceeds the body's mass. In steady motion a = a_prev and
// nothing changes. The world keeps its masses: the same motion results from handing it the
// blend
//   F = w F_fluid + (1 - w) m (a_prev - a_body_forces),   w = m / (m + m_v),
// and likewise for torques with the body's inertia (the displaced fluid's inertia is
// rho_f / rho_body of it, so w is the same). a_prev is the acceleration the previous
// window's applied wrench and body forces gave, so m (a_prev - a_body_forces) is simply
// that wrench, F_k = w F_fluid,k + (1 - w) F_(k-1): contacts act on the body's own mass at
// once and are not replayed into later windows (a landing body would be pushed back up).
#pragma once

#include <span>
#include <vector>

#include "rigidbody/dynamics/body.hpp"
#include "rigidbody/dynamics/body_forces.hpp"

namespace cosim::rigidbody::program {

class VirtualMass {
 public:
  // coefficient C >= 0 (0: off, the fluid's wrench passes unchanged).
  VirtualMass(double coefficient, double fluid_density) : coefficient_(coefficient), fluid_density_(fluid_density) {}

  bool active() const { return coefficient_ > 0; }
  // The wrenches to apply over the next window: the fluid's `fluid` blended with the
  // wrenches applied over the previous one (before the first, those that keep a body at
  // rest: a_prev = 0). Remembers the result for the next call.
  std::vector<dynamics::WindowWrench> blend(std::span<const dynamics::BodyInertia> inertia,
                                            const dynamics::BodyForces& body_forces,
                                            std::span<const dynamics::WindowWrench> fluid);

  // [1 or NaN before the first window, per body the applied force and torque]: what blend()
  // carries from one window to the next, for a rollback or a restart.
  void save(std::vector<double>& out, std::size_t bodies) const;
  // Reads what save() wrote from the front of `in`; returns how many values it took.
  std::size_t load(std::span<const double> in, std::size_t bodies);

 private:
  double coefficient_, fluid_density_;
  std::vector<dynamics::Wrench> previous_;  // empty before the first window
};

}  // namespace cosim::rigidbody::program
