// Where generated bodies go: on a lattice, or by random sequential addition. Centres only;
// body_generators.cpp reads the entries of `bodies:` that ask for them.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "coupler/scene/scene.hpp"
#include "coupler/scene/solid.hpp"
#include "coupler/scene/uniform.hpp"

namespace cosim::scene {

// One axis of a lattice: `count` centres from `first`, `step` apart.
struct LatticeAxis {
  int count = 1;
  double first = 0.0;
  double step = 0.0;
};

// The lattice's centres, x fastest, then y, then z, each moved by an offset drawn uniformly
// from [-jitter, jitter] per axis (x, y, z of one centre, then the next centre's).
std::vector<Vec3> lattice(const std::array<LatticeAxis, 3>& axes, const Vec3& jitter, Uniform& random);

// Random sequential addition: up to `count` copies of `body` (its solid about the origin),
// each at a centre drawn uniformly from the box `centres` and kept if it overlaps neither
// an obstacle nor a copy kept before, and if its bounding sphere has room (room.hpp) within
// the containers: `room(x)`, the distance from x to the nearest container's wall. Gives up
// once `attempts` draws in a row were refused, and then returns fewer than `count` centres.
std::vector<Vec3> random_addition(const Solid& body, const Domain& centres, std::size_t count,
                                  std::span<const Solid> obstacles, const std::function<double(const Vec3&)>& room,
                                  int attempts, Uniform& random);

}  // namespace cosim::scene
