// Small scene builders shared by the world tests and bench_box_stack.
#pragma once

#include <cstdint>
#include <vector>

#include "rigidbody/world/world.hpp"

namespace cosim::rigidbody::world::test {

// The fixed floor z <= 0.
std::uint32_t add_ground(World& world, const BodyMaterial& material = {});
std::uint32_t add_sphere(World& world, double radius, const Eigen::Vector3d& position,
                         const BodyMaterial& material = {});
std::uint32_t add_box(World& world, const Eigen::Vector3d& half, const Eigen::Vector3d& position,
                      const BodyMaterial& material = {});

// `count` boxes of half extent `half` stacked exactly touching on the ground, centred on
// the z axis; returns their indices, bottom first.
std::vector<std::uint32_t> add_box_stack(World& world, int count, double half);

// Kinetic plus gravitational potential energy (g from the world's settings).
double total_energy(const World& world);

// How deep bodies i and j overlap [m]: the narrow phase's deepest point, 0 when apart.
double overlap(const World& world, std::uint32_t i, std::uint32_t j);

}  // namespace cosim::rigidbody::world::test
