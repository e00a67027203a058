// Obstacles::set_pose: rigid motion of an object between tracking steps.
#include "tracker/tracking/obstacles.hpp"

#include "tracker/csg/events.hpp"
#include "tracker/tracking/domain.hpp"
#include "tracker/tracking/swarm.hpp"

#include <utility>

namespace cosim::tracker {
namespace {

// A particle the wall overran: put just outside the surface where it met the particle, in
// the cell there, and reflected off the wall moving with velocity u (the wall's condition
// acts on the velocity relative to the wall). False if that point is in no cell.
bool put_back(const Obstacles& obstacles, int o, const Domain& domain, const Vec3& at, const Vec3& n, const Vec3& u,
              Particle& p, std::span<csg::State> states, Random& random) {
  const Vec3 x = at + 10.0 * domain.tolerance * n;
  const Index cell = domain.locator.locate(x);
  if (cell < 0) return false;
  p.x = x;
  p.cell = cell;
  obstacles.classify(cell, x, states);
  Vec3 relative = p.v - u;
  if (relative.dot(n) < 0.0 &&
      !hit_wall(obstacles.object(o).wall, domain.boundaries.mass, n, relative, random))
    return false;  // an open wall absorbs
  p.v = u + relative;
  return true;
}

}  // namespace

long Obstacles::set_pose(int o, const Eigen::Isometry3d& pose, double dt, const Domain& domain, Swarm& swarm,
                         Random& random) {
  const auto i = static_cast<std::size_t>(o);
  const Eigen::Isometry3d old_pose = poses_[i];
  const CellObject old = std::move(cells_[i]);
  for (csg::Primitive& primitive : objects_[i].shape.primitives()) primitive.place(pose);
  cells_[i] = CellObject(*bounding_, objects_[i].shape);
  poses_[i] = pose;
  find_active();

  // Object-frame point q seen at the old and new pose: the relative motion of a fixed
  // particle is old_pose * pose^-1 * x - x in the old world frame.
  const Eigen::Isometry3d back = old_pose * pose.inverse();
  const Eigen::Isometry3d forward = pose * old_pose.inverse();
  long overrun = 0;
  std::vector<bool> removed(swarm.size(), false);
  for (std::size_t k = 0; k < swarm.size(); ++k) {
    Particle p = swarm.particle(k);
    const std::span<csg::State> states = swarm.states(k);
    const Index b = bounding_cell(p.cell);
    const std::span<const int> before = old.primitives(b);
    if (before.empty() && cells_[i].primitives(b).empty()) {
      // Constant here before and after; a wall that now fills the cell moved more than a
      // cell in one call and overran the particle with nowhere known to put it.
      if (!objects_[i].permeable && cells_[i].tree(b).evaluate(0)) {
        ++overrun;
        removed[k] = true;
      }
      continue;
    }
    csg::Swept swept{states[i]};
    if (!before.empty()) swept = csg::sweep(old.tree(b), states[i], p.x, back * p.x - p.x);
    states[i] = cells_[i].carry(before, swept.state, b, p.x);
    if (objects_[i].permeable || !swept.overrun) continue;
    ++overrun;
    // Where the surface met the particle, now: that material point at the new pose.
    const Vec3 met = forward * (p.x + swept.at * (back * p.x - p.x));
    const Vec3 n = forward.linear() * swept.normal;
    const Vec3 u = (met - back * met) / dt;
    if (!put_back(*this, o, domain, met, n, u, p, states, random)) removed[k] = true;
    swarm.set(k, p);
  }
  swarm.remove_if([&](std::size_t k) { return removed[k]; });
  return overrun;
}

}  // namespace cosim::tracker
