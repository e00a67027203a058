// Independent sub-problems: contact pairs connected through shared dynamic bodies. A fixed
// body (the ground) touches everything but transmits nothing, so it links no groups.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rigidbody/contact/contact_set.hpp"
#include "rigidbody/dynamics/body.hpp"

namespace cosim::rigidbody::solver {

// Pair indices per group, each group in increasing index order, groups ordered by their
// first pair. Pairs of two fixed bodies belong to no group.
std::vector<std::vector<std::uint32_t>> contact_groups(std::span<const dynamics::BodyInertia> inertias,
                                                       std::span<const contact::PairContacts> pairs);

}  // namespace cosim::rigidbody::solver
