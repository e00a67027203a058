// The central check of the tests: the grid returns exactly the brute-force pair set.
#pragma once

#include <span>

#include "rigidbody/broadphase/hash_grid.hpp"

namespace cosim::rigidbody::broadphase::testing {

// Runs a grid with config over objects and expects: every pair first < second, no pair
// twice, no pair of two fixed objects, and the same set as brute_force_pairs. Returns the
// number of pairs, so a test can make sure its scene is not trivially empty.
std::size_t expect_brute_force_pairs(std::span<const Object> objects, const HashGridConfig& config = {});

}  // namespace cosim::rigidbody::broadphase::testing
