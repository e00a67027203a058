// Obstacles::set_pose: rigid motion of an object between tracking steps.
#include "tracker/tracking/obstacles.hpp"

#include "tracker/csg/events.hpp"
#include "tracker/tracking/domain.hpp"
#include "tracker/tracking/swarm.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace cosim::tracker::tracking {
namespace {

// A particle the wall overran: put just outside the surface where it met the particle, in
// the cell there, and reflected off the wall moving with velocity u (the wall's condition
// acts on the velocity relative to the wall). False if that point is in no cell or the wall
// absorbs it.
bool put_back(const Obstacles& obstacles, int o, const Domain& domain, const Vec3& at, const Vec3& n, const Vec3& u,
              Particle& p, std::span<csg::State> states, Random& random, ObstacleTally& tally) {
  const Vec3 x = at + 10.0 * domain.tolerance * n;
  const Index cell = domain.locator.locate(x);
  if (cell < 0) return false;
  p.x = x;
  p.cell = cell;
  obstacles.classify(cell, x, states);
  Vec3 relative = p.v - u;
  if (relative.dot(n) >= 0.0) return true;  // already leaving the wall faster than it comes
  ++tally.hits;
  const Vec3 before = p.v;
  if (!hit_wall(obstacles.object(o).wall, domain.boundaries.mass, n, relative, random)) return false;
  p.v = u + relative;
  tally.exchange(x, obstacles.pose(o).translation(), before, p.v);
  return true;
}

}  // namespace

void Obstacles::place(int o, const Eigen::Isometry3d& pose) { reregister(o, pose); }

bounding::CellObject Obstacles::reregister(int o, const Eigen::Isometry3d& pose) {
  const auto i = static_cast<std::size_t>(o);
  // The new registration first: if it throws (too many primitives in a cell), nothing changed.
  csg::Tree placed = objects_[i].shape;
  for (csg::Primitive& primitive : placed.primitives()) primitive.place(pose);
  bounding::CellObject moved(*bounding_, placed);
  bounding::CellObject old = std::exchange(cells_[i], std::move(moved));
  objects_[i].shape = std::move(placed);
  poses_[i] = pose;
  motions_[i] = {};
  find_active();
  return old;
}

long Obstacles::set_pose(int o, const Eigen::Isometry3d& pose, double dt, const Domain& domain, Swarm& swarm,
                         Random& random, ObstacleTally& tally) {
  if (!(dt > 0.0)) throw std::invalid_argument("obstacle '" + object(o).name + "': set_pose needs a time dt > 0");
  if (swarm.objects() != count())
    throw std::invalid_argument("set_pose: the swarm carries " + std::to_string(swarm.objects()) + " states, " +
                                std::to_string(count()) + " obstacles");
  const auto i = static_cast<std::size_t>(o);
  // A body that is sent every step but holds still (fixed, or resting) costs nothing.
  if (pose.matrix() == poses_[i].matrix()) {
    motions_[i] = {};
    return 0;
  }
  const Eigen::Isometry3d old_pose = poses_[i];
  const bounding::CellObject old = reregister(o, pose);

  // Object-frame point q seen at the old and new pose: the relative motion of a fixed
  // particle is old_pose * pose^-1 * x - x in the old world frame.
  const Eigen::Isometry3d back = old_pose * pose.inverse();
  const Eigen::Isometry3d forward = pose * old_pose.inverse();
  motions_[i] = {back, dt};
  const bool wall = !objects_[i].permeable;
  long overrun = 0;
  std::vector<bool> removed(swarm.size(), false);
  const auto remove = [&](std::size_t k) {
    removed[k] = true;
    ++tally.absorbed;
  };
  for (std::size_t k = 0; k < swarm.size(); ++k) {
    Particle p = swarm.particle(k);
    const std::span<csg::State> states = swarm.states(k);
    const Index b = bounding_cell(p.cell);
    const std::span<const int> before = old.primitives(b);
    csg::Swept swept{states[i]};
    if (!before.empty()) swept = csg::sweep(old.tree(b), states[i], p.x, back * p.x - p.x);
    states[i] = cells_[i].carry(before, swept.state, b, p.x);
    if (!wall) continue;
    if (!swept.overrun) {
      // Inside the moved wall with no entry seen: its surface came from beyond the old
      // cell's primitives (a move of more than a cell). Nowhere known to put the particle.
      if (cells_[i].tree(b).evaluate(states[i])) remove(k);
      continue;
    }
    ++overrun;
    ++tally.overrun;
    // Where the surface met the particle, now: that material point at the new pose.
    const Vec3 met = forward * (p.x + swept.at * (back * p.x - p.x));
    const Vec3 n = forward.linear() * swept.normal;
    const Vec3 u = velocity_at(o, met);
    const Vec3 v = p.v;
    if (!put_back(*this, o, domain, met, n, u, p, states, random, tally)) {
      tally.exchange(met, pose.translation(), v, Vec3::Zero());
      remove(k);
    }
    swarm.set(k, p);
  }
  swarm.remove_if([&](std::size_t k) { return removed[k]; });
  return overrun;
}

}  // namespace cosim::tracker::tracking
