// What a World does each substep, and with which solver.
#pragma once

#include "rigidbody/dynamics/body_forces.hpp"
#include "rigidbody/solver/dem_solver.hpp"
#include "rigidbody/solver/impulse_solver.hpp"
#include "rigidbody/solver/lubrication.hpp"
#include "rigidbody/solver/soft_step.hpp"

namespace cosim::rigidbody::world {

enum class SolverKind {
  soft,                 // the soft step (settings in `soft`): the default, holds mass and size ratios
  pgs,                  // projected Gauss-Seidel, cold start
  jacobi,               // projected Jacobi
  sequential_impulses,  // warm-started Gauss-Seidel
  dem,                  // soft spring-dashpot contacts (settings in `dem`)
};

struct Settings {
  SolverKind solver = SolverKind::soft;
  int iterations = 0;  // impulse solvers' max iterations, the soft step's biased sweeps per substep; 0: the default
  double tolerance = 1e-6;  // impulse solvers' stopping test, relative; the soft step's report only (solver/README.md)
  // Simultaneous (Catto) or sequential (Newton's cradle passes momentum through).
  solver::Restitution restitution = solver::Restitution::simultaneous;
  solver::DemOptions dem{};
  solver::SoftOptions soft{};
  // The liquid film below the fluid grid's resolution, with either solver (off by default).
  solver::LubricationOptions lubrication{};
  // Pairs whose bounding spheres are this close become graph edges, and points with a gap
  // below it are speculative contacts the solver keeps from closing too fast. It should
  // exceed the distance a body travels between narrow phases (dt). 0: a tenth of the smallest bounded
  // body's bounding radius. Never below the lubrication range.
  double contact_margin = 0.0;
  double dt = 1e-3;  // [s] between narrow phases: a substep (the soft step's, split in soft.substeps)
  dynamics::BodyForces body_forces{.gravity = true};  // gravity on/off and g, buoyancy
  // Off: no broad phase, no narrow phase, no solver; bodies pass through each other.
  bool contact = true;

  solver::ImpulseOptions impulse_options() const;
  solver::SoftOptions soft_options() const;
};

}  // namespace cosim::rigidbody::world
