// Simulation::step as named stages in the order it runs them, each timed into StageSeconds.
#include <array>
#include <stdexcept>
#include <vector>

#include "tracker/step/simulation.hpp"

namespace cosim::tracker::step {

void Simulation::step(double dt) {
  stages_.time(Stage::migrate, [&] { migrate(); });
  // In cell order, as DSMC codes keep them: a cell's particles then share its faces in cache.
  stages_.time(Stage::sort, [&] { swarm_.sort_by_cell(tracked().cell_count()); });
  if (collider_) stages_.time(Stage::collide, [&] { collisions_ += collider_->collide(swarm_, dt); });
  stages_.time(Stage::move, [&] { move(dt); });
  stages_.time(Stage::inject, [&] { inject(dt); });
  if (part_) stages_.time(Stage::hand_over, [&] { hand_over(); });
  // Where they are: a rank's sums over cells it does not own add up with the owner's.
  stages_.time(Stage::sample, [&] { sampler_.sample(swarm_); });
  ++steps_;
}

// A wall that moved since the last step may have put an overrun particle in a ghost (or, in
// tracer mode, the last step's moves crossed into other ranks' cells): they go to their
// cells' owners before the collisions need them there.
void Simulation::migrate() {
  if (!part_ || strays_) {
    const std::size_t before = swarm_.size(), left = decomposition_.migrate(swarm_, numbering());
    migrated_ += left;
    // Strays may come from a second-layer ghost, whose registration with the obstacles is
    // not the owner's: their states are evaluated anew here (a recovery or a moving wall
    // puts them away from surfaces, where that is exact).
    if (part_)
      for (std::size_t i = before - left; i < swarm_.size(); ++i)
        setup_.obstacles.classify(swarm_.cell(i), swarm_.particle(i).x, swarm_.states(i));
  }
  strays_ = false;
  if (const int every = setup_.balance.every; decomposition_.ranks().size() > 1 && every > 0 && steps_ % every == 0)
    balance();
}

void Simulation::move(double dt) {
  if (setup_.tracers)
    carry_tracers(dt);
  else
    swarm_.move_all(move_context(), dt);
}

void Simulation::carry_tracers(double dt) {
  if (!velocity_)
    throw std::runtime_error(
        "tracer mode without a velocity field: give tracers.velocity.file, or run coupled with "
        "the fluid");
  // Tracers move through the whole mesh on every rank (no handover); their wall hits are not
  // tallied per patch.
  const tracking::MoveContext step{
      .domain = *setup_.domain, .obstacles = setup_.obstacles, .random = random_, .moves = moves_, .tallies = tallies_};
  std::vector<bool> gone(swarm_.size(), false);
  for (std::size_t i = 0; i < swarm_.size(); ++i) {
    tracking::Particle p = swarm_.particle(i);
    gone[i] = !tracers::advance_tracer(step, *velocity_, setup_.tracers->model, p, swarm_.states(i), dt);
    swarm_.set(i, p);
  }
  swarm_.remove_if([&](std::size_t i) { return gone[i]; });
}

void Simulation::inject(double dt) {
  for (const tracking::Inflow& inflow : setup_.inflows)
    injected_ += static_cast<std::size_t>(inflow.inject(move_context(), dt, swarm_));
}

// The moves that entered other ranks' cells go on there, in rounds until all are done.
void Simulation::hand_over() {
  for (;;) {
    std::array<long long, 2> left{static_cast<long long>(away_.size()), away_.strays()};
    decomposition_.ranks().sum(left);
    if (left[0] == 0) {
      // Particles a recovery left in ghosts migrate at the start of the next step.
      strays_ = left[1] > 0;
      break;
    }
    migrated_ += decomposition_.hand_over(away_, numbering());
    away_.resume_all(move_context(), swarm_);
  }
  away_.forget_strays();
}

}  // namespace cosim::tracker::step
