// Kinetic plus gravitational potential energy, floor at z = 0 (g from the world's settings).
// DEM springs store energy this leaves out, so for DEM it may rise while springs relax.
#pragma once

#include "rigidbody/world/world.hpp"

namespace cosim::bench {

double kinetic_energy(const rigidbody::world::World& world);
double potential_energy(const rigidbody::world::World& world);

}  // namespace cosim::bench
