#pragma once
// How the fluid holds rigid bodies on its fixed grid, as the program drives it: bodies
// placed where they are at the end of each coming step, and the hydrodynamic load on each
// after it. Two treatments: FictitiousBoundary (the staircase: faces inside a body take its
// velocity) and ImmersedBoundary (direct forcing at Lagrangian markers, smooth in the pose).
#include <Eigen/Core>
#include <span>
#include <stdexcept>
#include <vector>

#include "fluid/bodies/control_volumes.hpp"
#include "fluid/bodies/rigid_body.hpp"
#include "fluid/bodies/step_bodies.hpp"

namespace cosim::fluid::navier_stokes {
class NavierStokes;
}

namespace cosim::fluid::bodies {

struct HydrodynamicLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, on the body
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // N m, about the centre of mass
};

class BodyTreatment {
 public:
  virtual ~BodyTreatment() = default;

  virtual std::size_t add(RigidBody body) = 0;  // returns the body's index
  // Where body i is at the end of the next step, and its velocities there.
  virtual void move(std::size_t body, const geometry::Pose& pose, const Eigen::Vector3d& velocity,
                    const Eigen::Vector3d& angular_velocity) = 0;
  virtual const RigidBody& body(std::size_t i) const = 0;
  virtual std::size_t size() const = 0;

  // What every step of the flow takes from the bodies: NavierStokes::step(dt, for_step()).
  virtual StepBodies for_step() = 0;
  // Force and torque on every body from the flow's last step. Collective.
  virtual std::vector<HydrodynamicLoad> loads(const navier_stokes::NavierStokes& flow) const = 0;
  // Body i's volume fraction at this rank's owned cell centres (zero outside its patches):
  // one patch for the body and one for each periodic image of it that reaches them.
  virtual std::vector<IndicatorPatch> cell_fractions(std::size_t i) const = 0;

  // What the bodies carry from one step to the next besides the flow (this rank's part),
  // for the rollback of an implicitly coupled window; empty if nothing.
  virtual std::vector<double> state() const { return {}; }
  virtual void restore(std::span<const double> state) {
    if (!state.empty()) throw std::invalid_argument("body treatment: this one carries no state");
  }
};

}  // namespace cosim::fluid::bodies
