// Surface properties of one body, and how two of them combine at a contact.
#pragma once

#include "rigidbody/solver/problem.hpp"

namespace cosim::rigidbody::world {

struct BodyMaterial {
  double friction = 0.5;     // Coulomb coefficient
  double restitution = 0.0;  // normal restitution coefficient in [0, 1]
};

// Friction: geometric mean sqrt(mu_a mu_b), so a frictionless body (mu = 0) makes every
// contact frictionless, and equal materials keep their value (Box2D, Bullet, ODE users).
// Restitution: the maximum, so a bouncy ball bounces on any floor; the product would make
// a ball with e = 1 dead on a floor with e = 0 (Box2D's b2MixRestitution).
solver::Material combine(const BodyMaterial& a, const BodyMaterial& b);

}  // namespace cosim::rigidbody::world
