#pragma once
// A body force that NavierStokes::step asks for between the explicit right-hand side and
// the implicit viscous solve: the immersed boundary's direct forcing, which needs the
// step's fully explicit velocity estimate to find the force that brings the fluid to the
// bodies' velocities, and then sees the step's final velocity to measure the bodies' loads.
#include <petscdmda.h>

#include <array>

namespace cosim::fluid {

class NavierStokes;

// This rank's owned faces of the three components, as DMDA arrays.
struct ForcingArrays {
  // u~ = u^n + dt (-convection + viscous term at u^n + body force - grad p^{n-1/2}): what the
  // step would give without the implicit viscous correction and the projection.
  std::array<PetscScalar***, 3> predicted{};
  // The right-hand side of (I - theta dt L) u* = rhs.
  std::array<PetscScalar***, 3> rhs{};
};

class BodyForcing {
 public:
  virtual ~BodyForcing() = default;
  // Adds dt f to `rhs` where the force f acts; `predicted` is the forcing's to use and
  // leave as it likes. `flow` is still at the step's start. Collective.
  virtual void force(const NavierStokes& flow, double dt, const ForcingArrays& arrays) = 0;
  // After the projection: `flow` holds the step's final velocity. Collective.
  virtual void finish_step(const NavierStokes& flow, double dt) = 0;
};

}  // namespace cosim::fluid
