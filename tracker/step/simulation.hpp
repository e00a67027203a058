// The gas as cosim-tracker advances it, the same standalone and coupled: the particles,
// their collisions, inflow, walls and obstacles, and what is sampled of them. One step
// (step()) is what DSMC codes do per time step, as named stages, each timed (StageSeconds):
// migrate (over several ranks, when particles may sit in ghosts; now and then
// re-partition), sort by cell, collide, move, inject, hand over the moves that entered other
// ranks' cells, sample.
//
// Over several ranks (tracker/parallel) a rank tracks on its part of the mesh (its cells and
// two layers of ghosts, mesh/part.hpp) with the obstacles registered there, and holds the
// particles in its cells: a move that enters a ghost goes on on the ghost's owner within
// the step (tracking/handover.hpp), and a particle a moving wall put in a ghost migrates
// at the start of the next. A box's part is built without the whole (no rank builds that);
// other meshes are read whole on every rank. Tracer mode keeps the
// whole mesh on every rank (a tracer's step is not handed over): its tracers migrate at the
// start of a step. The totals and per-cell results below are sums over the ranks: those
// calls are collective, every rank must make them in the same order.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "tracker/mesh/part.hpp"
#include "tracker/parallel/bricks.hpp"
#include "tracker/parallel/decomposition.hpp"
#include "tracker/step/collide.hpp"
#include "tracker/step/gas_setup.hpp"
#include "tracker/step/stages.hpp"
#include "tracker/tracking/sampling.hpp"

namespace cosim::tracker::step {

class Simulation {
 public:
  // Seeds the particles with the setup's seed around its obstacles. Collective over
  // `ranks`: each rank seeds the cells it owns, with the particles a one-rank run has there
  // (seed_particles.hpp). A setup read on several ranks may hold this rank's part of a box.
  explicit Simulation(GasSetup setup, parallel::Ranks ranks = {});

  // Its mesh is null on several ranks (moved into this rank's part): use tracked().
  const GasSetup& setup() const { return setup_; }
  // This rank's cells (the swarm's cell numbers): the whole mesh, or its part on several
  // ranks (Mesh::global_cell gives a cell's number in the whole).
  const mesh::Mesh& tracked() const { return part_ ? *part_ : *setup_.mesh; }
  const parallel::Decomposition& decomposition() const { return decomposition_; }
  // This rank's particles, numbered by tracked()'s cells: those in its cells, and the few
  // a moving wall or a recovery put in a ghost (they migrate at the start of the next step).
  const tracking::Swarm& swarm() const { return swarm_; }

  // Every random draw from here on comes from `stream` of the setup's seed (one stream per
  // rank): a coupled run reseeds at each window, so a repeated window draws the same
  // numbers and a run resumed from a checkpoint continues as it would have.
  void reseed(std::uint64_t stream);
  // Moves obstacle i to `pose` (world from its shape's frame) over the time dt, before the
  // step that covers that time (Obstacles::set_pose).
  void move_obstacle(int i, const Eigen::Isometry3d& pose, double dt);
  // One step of length dt (collective): the gas's, or in tracer mode each tracer carried
  // by the velocity field (std::runtime_error if there is none yet).
  void step(double dt);
  // Tracer mode: the fluid's velocity from here on (coupled runs: every window).
  void set_velocity(tracers::VelocityField velocity) { velocity_ = std::move(velocity); }
  // From t0 to exactly t1 in equal steps of at most the setup's dt, calling before(t, h)
  // before each step of length h that ends at t (to move obstacles there). Returns the
  // number of steps. Standalone and coupled runs step a window alike.
  int advance(double t0, double t1, const std::function<void(double t, double h)>& before = {});

  std::uint64_t steps() const { return steps_; }
  // Totals over the ranks since the start (collective).
  std::size_t particles() const;  // now
  std::size_t seeded() const;
  std::size_t injected() const;  // through inflow patches
  std::size_t migrated() const;  // sent to another rank, counted once per move between ranks
  std::int64_t collisions() const;
  // Re-partitions (the same on every rank): the particle loads drifted apart past the
  // setup's balance threshold (Balance).
  std::uint64_t rebalances() const { return rebalances_; }
  // This rank's wall time per stage of step() since the start (not restored by restore()).
  const StageSeconds& stages() const { return stages_; }
  tracking::MoveTally moves() const;
  std::vector<tracking::ObstacleTally> tallies() const;
  // Per boundary patch (Mesh::patches): what the particles gave the walls there.
  std::vector<tracking::SurfaceTally> patch_tallies() const;

  // This rank's brick, over several ranks in a box of hexahedra (not in tracer mode): its
  // per-cell results come as a block of the output's grid (take_brick()), so that no rank
  // holds every cell's. Empty otherwise (counts() and take_moments() add up on rank 0).
  std::optional<parallel::Bricks::Range> brick() const;
  struct BrickSamples {
    parallel::Bricks::Range brick;
    std::vector<double> count;                   // particles per cell now
    std::vector<tracking::CellMoments> moments;  // averaged since the last take
  };
  // This rank's cells in its brick's order (x fastest), as counts() and take_moments() give
  // every cell's: a new average begins. Collective; what its ghosts hold (particles and
  // sums a stray left there) goes to their owners first. Requires brick().
  BrickSamples take_brick();
  // Particles per cell of the whole mesh now (collective; on rank 0, empty on the others).
  std::vector<double> counts() const;
  // The per-cell moments averaged over the steps since the last call (or the start), then
  // a new average begins (collective; on rank 0, empty on the others). Over a brick(),
  // take_brick() instead (std::logic_error).
  std::vector<tracking::CellMoments> take_moments();

  // Everything a later restore() needs to continue exactly from here (with the same
  // reseed() calls): this rank's particles and states, obstacle poses, collision state per
  // cell, the sampler's sums and the rank's totals. Random generators are not in it (see
  // reseed()). A state restores on the rank, and the rank count, that wrote it
  // (simulation_state.cpp).
  std::vector<double> state() const;
  // std::runtime_error for a state that is not one of this setup's. Collective over the
  // ranks (rank 0's state holds the cells' owners for all).
  void restore(std::span<const double> state);

 private:
  // The stages of step() but sort, collide and sample (simulation_stages.cpp).
  void migrate();
  void move(double dt);
  void carry_tracers(double dt);  // tracer mode's move
  void inject(double dt);
  // The gas's moves: into this rank's tallies, handing over to the other ranks.
  tracking::MoveContext move_context() {
    return {.domain = *setup_.domain,
            .obstacles = setup_.obstacles,
            .random = random_,
            .moves = moves_,
            .tallies = tallies_,
            .patches = patch_tallies_,
            .away = &away_};
  }
  void hand_over();  // over several ranks, without tracers
  // Collective, every setup_.balance.every steps on several ranks: a new partition
  // weighted by the particles if the most a rank holds exceeds the mean by the threshold;
  // the particles, the inflow faces and the cells' collision state follow their cells.
  void balance();
  // Builds this rank's part of the mesh for the decomposition's owners, and the walls,
  // obstacles and inflows on it.
  void take_part();
  parallel::Numbering numbering() const {
    return part_ ? parallel::Numbering{part_.get(), part_cells_.get()} : parallel::Numbering{};
  }
  std::vector<double> particles_per_cell() const;  // of tracked()'s cells, this rank's particles
  // Per-cell numbers of this rank's cells (`width` a cell) added up by the whole mesh's
  // cells on rank 0, empty elsewhere (collective): only rank 0 holds an array of every cell.
  std::vector<double> at_lead(std::span<const double> mine, std::size_t width) const;

  GasSetup setup_;
  std::optional<tracers::VelocityField> velocity_;  // tracer mode
  std::uint64_t seed_;
  parallel::Decomposition decomposition_;
  tracking::Random random_;
  tracking::Swarm swarm_;
  tracking::CellSampler sampler_;
  std::optional<CellCollider> collider_;
  std::vector<tracking::ObstacleTally> tallies_;
  std::vector<tracking::SurfaceTally> patch_tallies_;
  tracking::MoveTally moves_;
  std::uint64_t steps_ = 0;
  // This rank's.
  std::size_t seeded_ = 0, injected_ = 0, migrated_ = 0;
  std::int64_t collisions_ = 0;
  std::uint64_t rebalances_ = 0;
  StageSeconds stages_;
  double balance_floor_ = 0.0;  // max/mean a re-partition could not improve, times 1.1
  // This rank's part of the mesh, at one address for good (the collider refers to it);
  // null on one rank and in tracer mode.
  std::unique_ptr<mesh::Mesh> part_;
  Index whole_cells_ = 0;
  // Of a box of tetrahedra over several ranks, rank 0's: every cell's volume (a box of
  // hexahedra gives each rank's brick its own, take_brick()).
  std::vector<double> whole_volume_;
  std::unique_ptr<mesh::PartCells> part_cells_;
  tracking::Handover away_;  // the moves of a step that entered ghosts, until they are done
  // Some rank may hold particles in its ghosts (an obstacle moved, or a recovery put them
  // there): the next step starts with a migration. The same on every rank.
  bool strays_ = false;
};

}  // namespace cosim::tracker::step
