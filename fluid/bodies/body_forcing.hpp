#pragma once
// A body force that NavierStokes::step asks for between the explicit right-hand side and
// the implicit viscous solve: the immersed boundary's direct forcing, which needs the
// step's fully explicit velocity estimate to find the force that brings the fluid to the
// bodies' velocities, and then sees the step's final velocity to measure the bodies' loads.
#include <petscdmda.h>

#include <array>

namespace cosim::fluid::navier_stokes {
class NavierStokes;
}

namespace cosim::fluid::bodies {

// This rank's owned faces of the three components, as DMDA arrays.
struct ForcingArrays {
  // u~ = u^n + dt (-convection + viscous term at u^n + body force - grad p^{n-1/2}): what the
  // step would give without the implicit viscous correction and the projection.
  std::array<PetscScalar***, 3> predicted{};
  // The right-hand side of (I - theta dt L) u* = rhs.
  std::array<PetscScalar***, 3> rhs{};
};

// How the step's final velocity answers impulses added to its viscous solve's right-hand
// side after the projection: the viscous solve and the projection once more, on the
// impulses' field alone, with the boundaries' values zero (the step is linear in them).
class StepResponse {
 public:
  virtual ~StepResponse() = default;
  // The right-hand side to spread into, zero; open until the next call.
  virtual const std::array<PetscScalar***, 3>& rhs() = 0;
  // The change of the velocity that rhs() causes, open for reading until the next call;
  // rhs() is zero again.
  virtual const std::array<PetscScalar***, 3>& change() = 0;
  // Adds the change that rhs() causes to the step's velocity and pressure; rhs() is zero again.
  virtual void apply() = 0;
};

class BodyForcing {
 public:
  virtual ~BodyForcing() = default;
  // Adds dt f to `rhs` where the force f acts; `predicted` is the forcing's to use and
  // leave as it likes. `flow` is still at the step's start. Collective.
  virtual void force(const navier_stokes::NavierStokes& flow, double dt, const ForcingArrays& arrays) = 0;
  // After the projection: corrects the slip the viscous solve and the projection left at
  // the bodies' surfaces in `flow`'s velocity through `response`, and takes the corrections
  // into the bodies' loads; returns how many responses it asked for. Collective.
  virtual int correct(const navier_stokes::NavierStokes& flow, double dt, StepResponse& response) = 0;
  // After the projection: `flow` holds the step's final velocity. Collective.
  virtual void finish_step(const navier_stokes::NavierStokes& flow, double dt) = 0;
};

}  // namespace cosim::fluid::bodies
