#pragma once
// Bird's no-time-counter (NTC) collisions among the simulator particles of one cell.

#include "tracker/dsmc/collision.hpp"

#include <cstdint>
#include <span>

namespace cosim::tracker::dsmc {

// What a cell carries from step to step.
struct CellCollisionState {
  double sigma_g_max = 0;  // (sigma g)_max [m^3/s], raised whenever a candidate exceeds it
  double remainder = 0;    // fractional candidate pair carried to the next step, in [0, 1)
};

// A safe first (sigma g)_max for a gas at temperature T: sigma g at a relative speed of
// three times the most probable one, sqrt(2 k T / m_r); a relative speed beyond it has a
// probability of 4e-4 in equilibrium, and the cell's value then rises to it.
double initial_sigma_g_max(const CollisionModel& model, double T);

struct CellCollisions {
  std::int64_t candidates = 0;  // pairs tested
  std::int64_t collisions = 0;  // pairs collided
};

// One NTC step in a cell of volume `volume` [m^3] holding the simulator velocities
// `velocities` (each stands for `fnum` molecules): floor(0.5 N (N - 1) fnum (sigma g)_max
// dt / V + remainder) candidate pairs, each two distinct particles drawn uniformly, each
// accepted with probability sigma g / (sigma g)_max and then scattered by the model. The
// velocities are updated in place; state.sigma_g_max is raised to any larger sigma g met
// (that candidate is accepted). Pair selection is uniform in the cell.
CellCollisions collide_cell(std::span<Vec3> velocities, const CollisionModel& model, CellCollisionState& state,
                            double volume, double fnum, double dt, Rng& rng);

// The same with nearest-neighbour selection (Bird 2007, "sophisticated DSMC"): the first
// particle of a candidate pair is drawn uniformly, the second is the particle nearest to it
// in the cell (positions[k] belongs to velocities[k]), except the partner of its last
// collision in this call when the cell holds more than two particles, so that a pair does
// not collide again and again. Candidate numbers and acceptance are those of NTC, so in a
// gas whose velocities do not depend on position the rate is unchanged; the mean
// collision separation shrinks. The search is linear: O(N) per candidate, meant for the
// few tens of particles of a DSMC cell.
CellCollisions collide_cell_nearest(std::span<Vec3> velocities, std::span<const Vec3> positions,
                                    const CollisionModel& model, CellCollisionState& state, double volume, double fnum,
                                    double dt, Rng& rng);

}  // namespace cosim::tracker::dsmc
