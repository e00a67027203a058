// The initial gas (Seeding), the same for any number of ranks: each
// random number comes from a pcg64 stream keyed by what it decides (one cell's positions and
// velocities; one range of cells' share of a count), not from one sequence that every rank
// would have to run through in full. A rank draws only its own cells' particles, and 1 and
// N ranks start from identical particles (in each cell, in the same order).
//
// per_cell: that many draws in every cell, uniform in the cell (rejection in its bounding
// box against its planes); a draw inside a wall obstacle is dropped, so a cell keeps the
// density of the free gas.
// total: exactly `total` particles, uniform over the free space, in rounds: the round's count
// is split over the cells by volume (a multinomial, as nested binomial splits of ranges of
// cell indices), each cell draws its share and drops draws inside walls, and the next round
// draws as many again as all ranks dropped. That is rejection sampling of the free space, so
// the result is exact in distribution; every rank takes part in every round (collective).
// regions (seed_regions.hpp): each region in turn, in every cell it meets, n V / weight draws
// at its number density n in the cell's volume V (the whole part, and one more with the
// probability of the fraction, as SPARTA rounds), uniform in the cell; a draw is kept when it
// lies inside the region (wholly inside: all are) and outside every wall. So the count in a
// region is n / weight times its free volume in expectation, exactly in volume, with no
// more spread than Poisson's; region i's draws in a cell come from the cell's stream of round i.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/parallel/decomposition.hpp"
#include "tracker/step/seed_regions.hpp"
#include "tracker/tracking/obstacles.hpp"

namespace cosim::tracker::step {

struct Seeding {
  int per_cell = 0;                 // particles per cell, or
  int total = 0;                    // in all, cells drawn by volume (exactly one of the two is used), or
  std::vector<SeedRegion> regions;  // gases by region (then per_cell, total, temperature and drift are not)
  double temperature = 0.0;         // K: Maxwellian velocities about the drift (0: all at the drift)
  Vec3 drift = Vec3::Zero();
  double mass = 0.0;       // kg, also what diffuse walls re-emit with
  double weight = 1.0;     // real molecules per simulator (fnum)
  std::uint64_t seed = 1;  // of every random draw of the run

  // The hottest temperature and the fastest drift the gas starts with, over its regions.
  double hottest() const {
    double t = temperature;
    for (const SeedRegion& r : regions) t = std::max(t, r.temperature);
    return t;
  }
  double fastest_drift() const {
    double v = drift.norm();
    for (const SeedRegion& r : regions) v = std::max(v, r.velocity.norm());
    return v;
  }
};

// The whole mesh's cells by volume, for `total`'s split: `below(c)` is the volume of the cells
// numbered below c (0 <= c <= cells), without holding every cell's.
struct CellVolumes {
  Index cells = 0;
  std::function<double(Index)> below;
};
// From the mesh's cells (prefix sums: every rank of a run must see the same mesh).
CellVolumes volumes_of(const mesh::Mesh& whole);
// From the box's nodes (every Kuhn tetrahedron a sixth of its hexahedron), as box_mesh numbers
// the cells: no mesh needed.
CellVolumes volumes_of(const mesh::BoxSpec& box);

// The particles of the cells `cells` gives this rank (collective over its ranks), numbered
// by `mesh`'s cells: the whole mesh or this rank's part (obstacles registered there), while
// the streams are keyed by the whole's cell numbers. Throws std::runtime_error when the
// walls leave (almost) no free space to seed `total` in.
tracking::Swarm seed_particles(const mesh::Mesh& mesh, const tracking::Obstacles& obstacles, const Seeding& seeding,
                               const parallel::Decomposition& cells, const CellVolumes& volumes);

// How many particles seed_particles() makes on any number of ranks, counted on one that
// holds the whole mesh without making them (fast where no obstacle has primitives; for the
// work a scene gives). `total` is taken as it comes: the walls' leaving no room for it is
// found by the seeding.
std::size_t seeded_count(const mesh::Mesh& whole, const tracking::Obstacles& obstacles, const Seeding& seeding);

}  // namespace cosim::tracker::step
