// Advancing a set of rigid bodies over one coupling window.
#pragma once

#include <functional>
#include <span>

#include "rigidbody/dynamics/body.hpp"
#include "rigidbody/dynamics/body_forces.hpp"

namespace cosim::dynamics {

enum class Scheme {
  semi_implicit_euler,  // first order, implicit gyroscopic term; the default (semi_implicit_euler.hpp)
  leapfrog,             // second order, symplectic, conserves angular momentum (leapfrog.hpp)
};

struct IntegratorSettings {
  Scheme scheme = Scheme::semi_implicit_euler;
  double dt = 1e-3;  // target substep; the window is split into round((t1 - t0) / dt) >= 1 equal ones
  BodyForces body_forces;
};

// Called once per substep after every body's velocity update and before any position update,
// with the substep length and all states. It may change velocities (the contact solver's
// impulses); positions and orientations are then moved with what it leaves.
using VelocityHook = std::function<void(double dt, std::span<BodyState> states)>;
// Called once per substep after every position update, with the substep length and all
// states; it may change velocities only (a soft contact solver's relax pass), which the
// next substep starts from.
using PositionHook = VelocityHook;

// Moves `states` from t0 to t1. `inertia` is parallel to `states`; `external` is either
// parallel to it (the coupler's wrench per body, see WindowWrench) or empty (none).
// Fixed bodies (inverse_mass == 0) are not touched, not even by the hook's velocities;
// translation-only bodies (rotates == false) keep their orientation and angular velocity.
// Throws std::invalid_argument for mismatched spans, t1 < t0 or dt <= 0.
// How many equal substeps advance() splits a span into: round(span / dt), at least one.
long substep_count(double span, double dt);

void advance(std::span<BodyState> states, std::span<const BodyInertia> inertia,
             std::span<const WindowWrench> external, double t0, double t1,
             const IntegratorSettings& settings, const VelocityHook& hook = {},
             const PositionHook& after_positions = {});

}  // namespace cosim::dynamics
