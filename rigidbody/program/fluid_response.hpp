// The fluid's response tensors as the bodies carry them over a window (the added-mass
// partitioned scheme, coupler/participant/robin.hpp): each body's added inertia and damping.
// The forces that come with the tensors are the coupler's Robin wrenches, which the bodies
// take as they are.
#pragma once

#include <span>
#include <vector>

#include "coupler/participant/body_rows.hpp"
#include "rigidbody/dynamics/added_inertia.hpp"

namespace cosim::rigidbody::program {

std::vector<dynamics::AddedInertia> added_inertia(std::span<const participant::ResponseRow> responses);

}  // namespace cosim::rigidbody::program
