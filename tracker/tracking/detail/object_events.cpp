#include "tracker/tracking/detail/algorithms.hpp"

#include "tracker/csg/events.hpp"

namespace cosim::tracker::tracking::detail {

ObjectEvent next_object_event(const Carried& carried, const Particle& p, MoveResult& result) {
  const Obstacles& obstacles = *carried.obstacles;
  const Index b = obstacles.bounding_cell(p.cell);
  ObjectEvent first;
  // A cell where an object is constant still follows the bits of its primitives (it is
  // active): a neighbour where they matter carries them over, and the crossing may be close
  // to their surfaces.
  for (const int o : obstacles.active(b)) {
    const csg::Tree& tree = obstacles.cells(o).tree(b);
    result.primitive_tests += static_cast<int>(tree.primitives().size());
    const csg::Event event = csg::next_event(tree, obstacles.object(o).permeable, carried.states[o], p.x, p.v);
    if (event.dt < first.event.dt) first = {event, o};
  }
  return first;
}

bool execute(const Carried& carried, double mass, Particle& p, const ObjectEvent& hit, Random& random,
             MoveResult& result) {
  ++result.object_events;
  const csg::Event& event = hit.event;
  csg::State& state = carried.states[hit.object];
  ObstacleTally& tally = carried.tallies[hit.object];
  if (event.reflects() && !event.into_object) {
    // The state says the particle is inside the wall and leaving it: a state gone wrong
    // (nothing enters a wall). Reflecting would keep it inside for ever; it goes out
    // through the surface and the state follows. Counted, so runs can show it never happens.
    state ^= csg::bit(event.primitive);
    ++tally.released;
    return true;
  }
  state = csg::apply(state, event);
  if (!event.boundary) return true;
  if (event.permeable) {
    ++(event.into_object ? tally.entered : tally.left);
    return true;
  }
  ++tally.hits;
  const Vec3 before = p.v;
  // The gas is outside the wall: the object's outward normal points into the domain.
  const Obstacles& obstacles = *carried.obstacles;
  const Vec3 origin = obstacles.pose(hit.object).translation();
  const BoundaryCondition& wall = obstacles.object(hit.object).wall;
  // Reflected in the frame of the moving wall. The wall stands still within a step, so a
  // particle may meet a receding surface that it could not catch: if the reflection in the
  // moving frame still heads into the standing surface, it is reflected off the surface at
  // rest instead (rare: a wall receding at a thermal speed).
  const Vec3 u = obstacles.velocity_at(hit.object, p.x);
  Vec3 relative = p.v - u;
  const bool kept = hit_wall(wall, mass, event.normal, relative, random);
  if (kept) p.v = u + relative;
  if (kept && p.v.dot(event.normal) <= 0.0) {
    p.v = before;
    hit_wall(wall, mass, event.normal, p.v, random);
  }
  if (!kept) {
    ++tally.absorbed;
    tally.exchange(p.x, origin, before, Vec3::Zero());
    result.removed = true;
    return false;
  }
  tally.exchange(p.x, origin, before, p.v);
  return true;
}

}  // namespace cosim::tracker::tracking::detail
