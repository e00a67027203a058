// The reference broad phase: every pair tested, O(N^2). Tests prove the grid against it.
#pragma once

#include <span>
#include <vector>

#include "rigidbody/broadphase/object.hpp"

namespace cosim::rigidbody::broadphase {

// All candidate pairs (see overlap.hpp), first < second, sorted.
std::vector<Pair> brute_force_pairs(std::span<const Object> objects, double margin);

}  // namespace cosim::rigidbody::broadphase
