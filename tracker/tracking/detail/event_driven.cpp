#include "tracker/tracking/detail/algorithms.hpp"

#include <algorithm>

namespace cosim::tracker::tracking::detail {

namespace {

// Consecutive events that move the particle by less than the tolerance. More than this
// and it is caught in a cycle of zero-time events: moving along a face or an edge through
// a gap of a perturbed mesh, every cell around it has a face it is outside of and moving
// out through, so each hands it on to the next.
constexpr int cycle_length = 64;

void relocate(const Domain& domain, Particle& p, const Carried& carried, MoveResult& result) {
  const Index found = domain.locator.locate(p.x);
  if (found < 0 || found == p.cell) return;
  const Index from = p.cell;
  p.cell = found;
  carried.follow(from, p, false);
  ++result.relocations;
}

// The events keep a particle that crossed into a gap or an overlap of a perturbed mesh in
// the cell it entered for as long as it moves inwards there, so it can stop outside that
// cell. Then it goes across the violated face if the neighbour contains it, else to the
// cell point location finds; in a gap no cell contains it, and it stays. True if it ends
// inside its cell to the tolerance: then is_lost, which needs a face beyond it, is false.
bool settle(const Domain& domain, Particle& p, const Carried& carried, MoveResult& result) {
  const Violation violation = outside(domain.mesh, p.cell, p.x);
  if (violation.depth <= domain.tolerance) return true;
  const mesh::Face& face = domain.mesh.faces[violation.face];
  if (face.neighbour >= 0) {
    const Vec3 there = p.x + domain.mesh.shifts[face.shift];
    if (outside(domain.mesh, face.neighbour, there).depth <= domain.tolerance) {
      const Index from = p.cell;
      p.x = there;
      p.cell = face.neighbour;
      carried.follow(from, p, face.shift != 0);
      ++result.relocations;
      return false;
    }
  }
  relocate(domain, p, carried, result);
  return false;
}

// Out of a cycle: the particle is in a gap that none of the cells around it covers. It
// jumps ahead along its path to the first of the points 4^k tolerances on that a cell
// contains (point location) and takes that cell, where it is inside, so the events resume
// with a positive time. The start and the point found are inside the domain, so the
// straight jump crosses no wall. False if no cell holds any point up to the end of the move.
bool jump_out_of_gap(const Domain& domain, Particle& p, const Carried& carried, double& remaining, MoveResult& result) {
  for (double step = domain.tolerance / p.v.norm();; step *= 4.0) {
    const double dt = std::min(step, remaining);
    const Vec3 x = p.x + dt * p.v;
    const Index found = domain.locator.locate(x);
    if (found >= 0) {
      const Index from = p.cell;
      p.x = x;
      p.cell = found;
      carried.follow(from, p, false);
      remaining -= dt;
      ++result.relocations;
      return true;
    }
    if (dt == remaining) return false;
  }
}

}  // namespace

MoveResult move_event_driven(const Domain& domain, Particle& p, double dt, Random& random, const Carried& carried) {
  // Most moves of a DSMC step end well inside the cell they start in.
  if (const Vec3 end = p.x + dt * p.v; ends_inside(domain, carried, p.cell, end)) {
    p.x = end;
    return {};
  }
  return follow_events(domain, p, dt, random, carried);
}

MoveResult follow_events(const Domain& domain, Particle& p, double dt, Random& random, const Carried& carried) {
  return follow_events(domain, p, Flight{dt, -1, 0}, random, carried, true);
}

MoveResult resume_flight(const Domain& domain, Particle& p, const Flight& flight, Random& random,
                         const Carried& carried) {
  return follow_events(domain, p, flight, random, carried, false);
}

MoveResult follow_events(const Domain& domain, Particle& p, const Flight& flight, Random& random,
                         const Carried& carried, bool first) {
  MoveResult result;
  double remaining = flight.remaining;
  Index skip = flight.entered < 0 ? -1 : domain.mesh.cell_faces[p.cell] + flight.entered;
  int streak = flight.streak;
  const Index own_cells = domain.mesh.own_cells();
  for (;; first = false) {
    if (streak > cycle_length) {
      ++result.cycles_broken;
      streak = 0;
      skip = -1;
      if (!jump_out_of_gap(domain, p, carried, remaining, result)) {
        result.stalled = true;  // the rest of the move is dropped, the cell kept
        break;
      }
    }
    // In another rank's cell: that rank goes on from here with what the loop carries.
    if (p.cell >= own_cells) {
      result.handed_over = true;
      result.rest = {remaining, skip < 0 ? -1 : static_cast<int>(skip - domain.mesh.cell_faces[p.cell]), streak};
      return result;
    }
    // The rest of most crossing moves ends well inside the cell they cross into (the caller
    // tested the start cell).
    if (const Vec3 end = p.x + remaining * p.v; !first && ends_inside(domain, carried, p.cell, end)) {
      p.x = end;
      return result;
    }
    // Bannerman, Strobl & Poeschel: the earliest dt >= 0 with f <= 0 and f' < 0; a particle
    // slightly outside a face it moves out through gets dt = 0, never a negative time. The
    // face just entered is skipped: the two sides' normals are opposite only to round-off.
    const FaceEvent face = exit_face(domain, p, skip, remaining);
    // The objects' events in the cell, merged in time; on a tie the object goes first, so a
    // wall on a face reflects before the particle could leave through it.
    const ObjectEvent object = carried.any() ? next_object_event(carried, p, result) : ObjectEvent{};
    const double event_dt = std::min(face.dt, object.event.dt);
    if (event_dt >= remaining) {
      p.x += remaining * p.v;
      // Most moves end in their cell without an event: settle would scan the faces again.
      if (skip < 0 && face.behind >= -domain.tolerance) return result;
      break;
    }
    p.x += event_dt * p.v;
    remaining -= event_dt;
    result.zero_time_events += event_dt == 0.0;
    const double moved_squared = event_dt * event_dt * p.v.squaredNorm();
    streak = moved_squared <= domain.tolerance * domain.tolerance ? streak + 1 : 0;
    if (object.event.dt <= face.dt) {
      if (!execute(carried, domain.boundaries.mass, p, object, random, result)) return result;
      if (object.event.reflects()) skip = -1;
      continue;
    }
    const Index from = p.cell;
    if (domain.implicit.linked(from, face.face)) {
      // What cross does across an interior face, from the cell index instead of the record;
      // the zero shift added as cross adds it, since x + 0 turns a -0 coordinate into +0.
      p.x += domain.mesh.shifts[0];
      p.cell = domain.implicit.neighbour(from, face.face);
      ++result.faces_crossed;
      skip = ImplicitLattice::twin(p.cell, from, face.face);
      carried.follow(from, p, false);
      continue;
    }
    switch (cross(domain, p, face.face, random, result, carried.patches)) {
      case Crossed::removed:
        return result;
      case Crossed::neighbour:
        skip = domain.mesh.faces[face.face].twin;
        carried.follow(from, p, domain.mesh.faces[face.face].shift != 0);
        break;
      case Crossed::wall:
        skip = -1;
        break;
    }
  }
  // Inside its cell a particle is not lost: the scan of is_lost is needed only otherwise.
  if (!settle(domain, p, carried, result)) result.lost = is_lost(domain, p);
  return result;
}

}  // namespace cosim::tracker::tracking::detail
