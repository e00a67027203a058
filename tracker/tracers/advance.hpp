#pragma once
// Tracers carried by a fluid velocity field through the tracking mesh: massless ones move
// with the fluid, inertial ones relax to it by Stokes drag. Each substep's displacement is a
// straight segment tracked by the robust event-driven move, so tracers cross cells, meet
// walls and obstacles, and leave through open patches like any particle.

#include "tracker/tracers/velocity_field.hpp"
#include "tracker/tracking/move.hpp"

namespace cosim::tracker::tracers {

struct TracerModel {
  // 0: massless, dx/dt = u(x). > 0: dv/dt = (u(x) - v) / response_time (Stokes drag,
  // response_time = rho_p d^2 / (18 mu)), dx/dt = v.
  double response_time = 0.0;
  int substeps = 1;  // per call: each one segment through the mesh
};

// Advances a tracer by dt. Massless: the classical fourth-order Runge-Kutta step of
// dx/dt = u(x) per substep. Inertial: per substep h, with u the fluid velocity at the
// segment's midpoint estimate, v' = u + (v - u) e^(-h / tau) and the exact displacement for
// that u, h u + tau (v - u) (1 - e^(-h / tau)). A wall met on the way reflects the segment
// (its condition); the tracer then keeps the reflected velocity. On return particle.v is
// the tracer's velocity (the fluid's, for a massless one). Every segment is a move() in
// `step` (a tracer is never handed over: step.away is not used); false if the tracer left
// through an open patch or wall.
bool advance_tracer(const tracking::MoveContext& step, const VelocityField& u, const TracerModel& model,
                    tracking::Particle& tracer, std::span<csg::State> states, double dt);

}  // namespace cosim::tracker::tracers
