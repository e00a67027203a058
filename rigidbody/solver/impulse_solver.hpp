// Velocity-level contact solvers: projected Gauss-Seidel, projected Jacobi and sequential
// impulses. They are one iteration (see point_update.hpp) with different schedules and
// defaults; see README.md for the formulation and the choices.
#pragma once

#include "rigidbody/solver/contact_memory.hpp"
#include "rigidbody/solver/point_update.hpp"
#include "rigidbody/solver/problem.hpp"

namespace cosim::rigidbody::solver {

enum class Schedule {
  gauss_seidel,  // each point's new impulse reaches the bodies at once
  jacobi,        // all points see the velocities of the previous sweep
};

enum class Restitution {
  // Target separating speed -e u_n from the velocity before the solve, imposed on all
  // points together (Catto / Box2D). A chain of touching bodies reacts as one body.
  simultaneous,
  // Before the contact solve, impacts are resolved pairwise, one point at a time, until
  // no point approaches faster than the threshold: the impulse travels along a chain
  // (Newton's cradle). Costs extra sweeps only while something bounces.
  sequential,
};

struct ImpulseOptions {
  Schedule schedule = Schedule::gauss_seidel;
  // Jacobi only: each point's change is scaled by relaxation / (number of points on its
  // busiest dynamic body), since simultaneous updates from n points on one body add up to
  // n times the needed velocity change and would overshoot.
  double relaxation = 1.0;
  int max_iterations = 50;
  // A group has converged when no point's impulse change in a sweep makes more than
  // tolerance x V of velocity at the point (V: the group's largest normal velocity change
  // needed at the start; README.md "Stopping test").
  double tolerance = 1e-6;
  FrictionModel friction = FrictionModel::cone;
  // Baumgarte position correction: penetration beyond `slop` [m] is removed at a rate of
  // erp per step. Gaps (distance > 0) are allowed to close within the step.
  double erp = 0.2;
  double slop = 1e-4;
  double restitution_threshold = 0.1;  // [m/s]: slower impacts are inelastic (resting)
  Restitution restitution = Restitution::simultaneous;
  bool warm_start = true;

  static ImpulseOptions projected_gauss_seidel();  // cold start: the textbook LCP solve
  static ImpulseOptions projected_jacobi();
  static ImpulseOptions sequential_impulses();  // warm started Gauss-Seidel
};

// Solves each contact group separately. `memory` has one entry per contact point: last
// step's impulses on entry (used when warm starting), this step's on return.
SolveReport solve_impulses(const ContactScene& scene, std::span<CachedContact> memory, const ImpulseOptions& options);

}  // namespace cosim::rigidbody::solver
