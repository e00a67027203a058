#pragma once
// The adversarial moves of the robustness test, shared with bench/tracker_study: a start
// on a vertex, on an edge or inside a face of a random cell (on a perturbed mesh possibly
// just outside that cell, since its faces are not planar), and a direction that is
// isotropic, aimed exactly at a vertex of the cell, or along the face (towards one of its
// vertices). Unit speed; a flight of up to three cell widths.

#include "tracker/tracking/particle.hpp"

#include <vector>

namespace cosim::tracker::tracking::testing {

struct Flight {
  Particle particle;
  double dt;
};

Flight hard_move(const mesh::Mesh& mesh, Random& random);
// The same from a given face of a given cell.
Flight hard_move(const mesh::Mesh& mesh, Random& random, Index cell, Index face);
Vec3 isotropic(Random& random);
// `count` uniform points in the unit cube: Voronoi sites.
std::vector<Vec3> random_points(int count, std::uint64_t seed);

}  // namespace cosim::tracker::tracking::testing
