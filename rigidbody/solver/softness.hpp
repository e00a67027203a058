// A soft contact: an implicit spring-damper of natural frequency omega and damping ratio
// zeta around a reference mass m, written as a velocity constraint for a step h,
//   u_n + bias_rate * s + compliance * lambda >= 0   (s: separation, lambda: impulse),
// so a solver that holds rigid contacts holds these with the same iteration.
#pragma once

namespace cosim::rigidbody::solver {

struct Softness {
  double bias_rate = 0.0;   // [1/s]: velocity asked per metre of penetration
  double compliance = 0.0;  // [m/(s N s)]: velocity given per unit impulse
};

// Implicit Euler on m s'' = -k s - c s' with k = m omega^2, c = 2 zeta m omega over h:
// bias_rate = omega / (2 zeta + h omega), compliance = 1 / (m h omega (2 zeta + h omega)).
// At rest a force F sinks it by F / k, whatever h and zeta (Catto, "Soft Step", 2024;
// the ERP/CFM of ODE). hertz 0: rigid, no bias.
Softness make_softness(double hertz, double damping_ratio, double mass, double h);

}  // namespace cosim::rigidbody::solver
