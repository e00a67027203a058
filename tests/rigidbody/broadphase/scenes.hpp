// Generated scenes of bounding spheres for the broad-phase tests and benchmark. Ids are a
// random permutation of 0..n-1, so nothing may rely on ids following input order.
#pragma once

#include <cstdint>
#include <vector>

#include "rigidbody/broadphase/object.hpp"

namespace cosim::rigidbody::broadphase::scenes {

struct Box {
  double lo;
  double hi;
};

// Centres uniform in box^3, radii log-uniform in [r_min, r_max].
std::vector<Object> uniform(std::size_t n, Box box, double r_min, double r_max, std::uint32_t seed);

// Centres in `clusters` Gaussian clumps of width sigma around centres uniform in box^3.
std::vector<Object> clustered(std::size_t n, std::size_t clusters, double sigma, Box box, double r_min, double r_max,
                              std::uint32_t seed);

// Equal spheres of radius 1 on a cubic lattice at solid fraction phi, each jittered by up
// to 0.1: a granular packing, every sphere with about six near neighbours.
std::vector<Object> packed(std::size_t n, double phi, std::uint32_t seed);

// Radii log-uniform in [1, ratio], centres uniform in a cube sized for solid fraction phi
// (overlaps allowed): a polydisperse bed.
std::vector<Object> polydisperse(std::size_t n, double phi, double ratio, std::uint32_t seed);

}  // namespace cosim::rigidbody::broadphase::scenes
