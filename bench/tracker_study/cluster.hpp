#pragma once
// The sphere cluster of Strobl, Bannerman & Poeschel's Table 1 (docs/references.md), at any
// size: slightly polydisperse balls packed without overlap into a spherical region at the
// centre of the unit box.

#include <Eigen/Core>

#include <vector>

namespace cosim::bench {

struct Ball {
  Eigen::Vector3d centre;
  double radius;
};

// `count` balls of mean diameter `diameter` (radii +-5 %, uniform) placed by random
// sequential addition in the sphere around (0.5, 0.5, 0.5) that they fill to `packing`.
// The paper's cluster: 790 balls of diameter 0.035, 1.77 % of the box.
std::vector<Ball> sphere_cluster(int count = 790, double diameter = 0.035, double packing = 0.3, unsigned seed = 1);

// The balls in groups of at most `size`, near ones together (sorted along a Morton curve):
// a logical state holds 64 primitives per cell, and a union splits into separate walls
// without changing where particles reflect (the first surface a particle outside all of
// them reaches is the union's).
std::vector<std::vector<Ball>> groups_of(std::vector<Ball> balls, int size);

}  // namespace cosim::bench
