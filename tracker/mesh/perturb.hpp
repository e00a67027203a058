#pragma once
// Random vertex moves that make faces non-planar, for testing the tracking's robustness.

#include "tracker/mesh/mesh.hpp"

#include <cstdint>

namespace cosim::tracker::mesh {

struct Perturbation {
  double fraction = 0.05;  // largest move, as a fraction of the vertex's shortest edge
  std::uint64_t seed = 1;
};

// Moves every vertex that is not on the domain boundary or on a periodic face by a
// random vector uniform in the ball of radius fraction * (shortest edge at the vertex),
// then refits the planes. Both cells of a face share its vertices and fit the same plane
// to them, so the cells, as intersections of their half-spaces, no longer tile: small
// gaps and overlaps open along edges and at vertices. Throws std::invalid_argument
// (with the validation report) if the moves break the mesh.
Mesh perturbed(Mesh mesh, const Perturbation& perturbation);

}  // namespace cosim::tracker::mesh
