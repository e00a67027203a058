#include "rigidbody/world/materials.hpp"

#include <algorithm>
#include <cmath>

namespace cosim::rigidbody::world {

solver::Material combine(const BodyMaterial& a, const BodyMaterial& b) {
  return {.friction = std::sqrt(a.friction * b.friction), .restitution = std::max(a.restitution, b.restitution)};
}

}  // namespace cosim::rigidbody::world
