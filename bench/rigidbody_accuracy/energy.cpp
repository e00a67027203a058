#include "bench/rigidbody_accuracy/energy.hpp"

#include "rigidbody/dynamics/invariants.hpp"

namespace cosim::bench {

double kinetic_energy(const rigidbody::world::World& world) {
  return rigidbody::dynamics::kinetic_energy(world.states(), world.inertias());
}

double potential_energy(const rigidbody::world::World& world) {
  const auto& forces = world.settings().body_forces;
  const Eigen::Vector3d g = forces.gravity ? forces.g : Eigen::Vector3d::Zero();
  double e = 0.0;
  for (std::size_t i = 0; i < world.size(); ++i) {
    const auto& body = world.inertias()[i];
    if (!body.is_fixed()) e -= g.dot(world.states()[i].position) / body.inverse_mass;
  }
  return e;
}

}  // namespace cosim::bench
