// What every contact solver takes and gives back.
#pragma once

#include <span>

#include "rigidbody/contact/contact_set.hpp"
#include "rigidbody/dynamics/body.hpp"
#include "rigidbody/solver/contact_frame.hpp"

namespace cosim::rigidbody::solver {

// Combined material of one body pair (the caller mixes the two bodies' values).
struct Material {
  double friction = 0.5;     // Coulomb coefficient mu
  double restitution = 0.0;  // e: separating speed / approaching speed after an impact
};

// One step's contact problem. The solvers change `states[i].velocity` and
// `.angular_velocity` in place (positions are integrated afterwards by the caller).
struct ContactScene {
  std::span<dynamics::BodyState> states;
  std::span<const dynamics::BodyInertia> inertias;
  std::span<const Mobility> mobility;  // mobilities(states, inertias), once per step
  const contact::ContactSet& contacts;
  std::span<const Material> materials;  // one per contact pair
  double dt = 0.0;
};

struct SolveReport {
  int iterations = 0;     // largest over the contact groups: the sweeps the slowest group needed
  double residual = 0.0;  // largest over the groups; meaning depends on the solver
  bool converged = true;  // every group met the tolerance
};

}  // namespace cosim::rigidbody::solver
