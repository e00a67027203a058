// Soft contacts (discrete element method): overlap produces a spring-dashpot force that
// acts over the step, instead of an impulse that removes the approach at once.
#pragma once

#include <iostream>
#include <limits>

#include "rigidbody/solver/contact_memory.hpp"
#include "rigidbody/solver/problem.hpp"

namespace cosim::rigidbody::solver {

enum class NormalLaw {
  linear,  // F_n = k_n delta + c_n v
  hertz,   // F_n = k_n delta^(3/2) + c_n(delta) v: stiffness grows like sqrt(delta)
};

struct DemOptions {
  NormalLaw law = NormalLaw::linear;
  double normal_stiffness = 1e5;                  // k_n: [N/m] linear, [N/m^1.5] Hertz
  double tangential_stiffness_ratio = 2.0 / 7.0;  // k_t / k_n (ratio for a solid sphere)
  // The step must be below (2 / omega) / safety, omega = sqrt(k / m_eff): 2/omega is the
  // undamped stability limit of symplectic Euler, the safety factor resolves the contact.
  double safety = 10.0;
  std::ostream* log = &std::clog;  // where the too-large-step warning goes (none if null)
};

struct DemReport : SolveReport {
  double stable_dt = std::numeric_limits<double>::infinity();  // over current contacts
};

// Damping ratio that gives restitution e for a linear spring-dashpot contact:
// zeta = -ln e / sqrt(pi^2 + ln^2 e) (1 for e = 0: critical damping).
double damping_ratio(double restitution);

// Applies dt * contact forces to the velocities. `memory` has one entry per contact point:
// its tangential spring (Cundall-Strack) of last step on entry, this step's on return
// (zero for points that do not overlap, so a spring starts anew at each touch).
DemReport solve_dem(const ContactScene& scene, std::span<CachedContact> memory, const DemOptions& options);

}  // namespace cosim::rigidbody::solver
