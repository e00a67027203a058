#include "rigidbody/program/fluid_response.hpp"

#include "coupler/participant/robin.hpp"

namespace cosim::rigidbody::program {

std::vector<dynamics::AddedInertia> added_inertia(std::span<const participant::ResponseRow> responses) {
  std::vector<dynamics::AddedInertia> out;
  for (const participant::ResponseRow& r : responses) {
    const participant::Carried c = participant::carried(r);
    out.push_back({c.added_mass(0, 0), c.added_mass.bottomRightCorner<3, 3>(), c.added_damping(0, 0),
                   c.added_damping.bottomRightCorner<3, 3>()});
  }
  return out;
}

}  // namespace cosim::rigidbody::program
