#pragma once
// The algorithms behind move() and the face crossing they share.

#include "tracker/csg/events.hpp"
#include "tracker/tracking/domain.hpp"
#include "tracker/tracking/obstacles.hpp"

#include <span>

namespace cosim::tracker::tracking::detail {

enum class Crossed { neighbour, wall, removed };

struct FaceEvent {
  double dt;  // infinity: the particle leaves through no face
  Index face;
  // The least f over the faces the particle moves away from (f' >= 0), `skip` left out;
  // infinity if none. No event, and this above -tolerance: the particle ends its move
  // inside its cell to the tolerance (f only grows on these faces, and stays >= 0 on the
  // others), so the end-of-move check can be skipped.
  double behind;
};

// The face the particle leaves its cell through first: per face with f' = n.v < 0 (n
// inward), dt = f / -f' with f = n.(x - point), skipping `skip` (the face just entered).
// A plane the particle is already behind (dt < 0: round-off at an edge or a vertex, or a
// gap of a perturbed mesh) is where the algorithms differ: the event-driven rule clamps it
// to dt = 0 (`clamp_behind`), the face-intersection baselines do not see it, which is how
// they lose particles.
// Faces the particle cannot reach within `horizon` (the rest of its move) are not events.
FaceEvent first_exit(const mesh::Mesh& mesh, const Particle& particle, Index skip, bool clamp_behind, double horizon);
// An axis-aligned hexahedron's faces: face[2 a] (inward normal +e_a) in the plane x_a =
// plane[2 a], face[2 a + 1] (-e_a) in x_a = plane[2 a + 1].
struct BoxFaces {
  Index face[6];
  double plane[6];
};
// The scan of such a cell from its planes' coordinates (lattice.hpp): equal times, face and
// `behind` to first_exit's for finite x and v (a zero's sign aside).
FaceEvent box_exit(const BoxFaces& box, const Particle& particle, Index skip, bool clamp_behind, double horizon);
// With the planes read from the cell's face records.
FaceEvent lattice_exit(const mesh::Mesh& mesh, LatticeFaces cell, const Particle& particle, Index skip,
                       bool clamp_behind, double horizon);
// With the planes from the lattice's arrays (a plain cell of implicit_lattice.hpp): the same
// numbers the records hold, no record read.
FaceEvent implicit_exit(const ImplicitLattice& lattice, const Particle& particle, Index skip, bool clamp_behind,
                        double horizon);
// The one of the three the particle's cell takes.
inline FaceEvent exit_face(const Domain& domain, const Particle& particle, Index skip, double horizon) {
  if (domain.implicit.plain(particle.cell)) return implicit_exit(domain.implicit, particle, skip, true, horizon);
  if (!domain.lattice.empty())
    if (const LatticeFaces cell = domain.lattice[static_cast<std::size_t>(particle.cell)]; cell.holds())
      return lattice_exit(domain.mesh, cell, particle, skip, true, horizon);
  return first_exit(domain.mesh, particle, skip, true, horizon);
}

// The particle is on `face` of its cell: it enters the neighbour (periodic shift applied),
// or the wall changes its velocity, or it leaves through an open patch; a wall hit is added
// to its patch's tally if `patches` is not empty.
Crossed cross(const Domain& domain, Particle& particle, Index face, Random& random, MoveResult& result,
              std::span<SurfaceTally> patches = {});

// What a particle carries through the obstacles: its states, and where its hits are counted.
struct Carried {
  const Obstacles* obstacles = nullptr;  // none: a move through the mesh alone
  std::span<csg::State> states;
  std::span<ObstacleTally> tallies;
  std::span<SurfaceTally> patches;  // one per boundary condition, or none

  bool any() const { return obstacles != nullptr && !obstacles->empty(); }
  // No object has primitives in the particle's cell: no object event can happen there.
  bool none_in(Index cell) const { return !any() || obstacles->active(obstacles->bounding_cell(cell)).empty(); }
  // The particle moved from cell `from` to its current cell (x as that cell sees it).
  void follow(Index from, const Particle& p, bool shifted) const {
    if (any()) obstacles->transfer(from, p.cell, p.x, shifted, states);
  }
};

// A move (or its rest) that ends in the cell's inner box, in a cell where no object is
// active, is x + dt v and nothing else: every face plane the particle moves towards is at
// least the tolerance ahead of the end, and f is linear along the path, so the event loop
// would find no event after a scan of all the faces, and settle would find the end inside.
inline bool ends_inside(const Domain& domain, const Carried& carried, Index cell, const Vec3& end) {
  return domain.inner_boxes[static_cast<std::size_t>(cell)].contains(end) && carried.none_in(cell);
}

// Throws std::invalid_argument unless there is one state and one tally per obstacle, and
// one patch tally per boundary condition or none.
void check_carried(const Domain& domain, const Obstacles& obstacles, std::size_t states, std::size_t tallies,
                   std::size_t patches);

// The earliest event of the objects in the particle's (bounding) cell; object -1: none.
struct ObjectEvent {
  csg::Event event;
  int object = -1;
};
ObjectEvent next_object_event(const Carried& carried, const Particle& particle, MoveResult& result);
// The particle is at the event: flips the state, reflects off a wall or counts a zone
// crossing. False if an open wall absorbed the particle.
bool execute(const Carried& carried, double mass, Particle& particle, const ObjectEvent& hit, Random& random,
             MoveResult& result);

MoveResult move_event_driven(const Domain& domain, Particle& particle, double dt, Random& random,
                             const Carried& carried = {});
// The same for a move that does not end in its start cell's inner box (ends_inside false):
// the event loop.
MoveResult follow_events(const Domain& domain, Particle& particle, double dt, Random& random, const Carried& carried);
// The rest of a move another rank handed over (MoveResult::rest), in one of this rank's cells.
MoveResult resume_flight(const Domain& domain, Particle& particle, const Flight& flight, Random& random,
                         const Carried& carried);
// The event loop from `flight`; `first`: the caller tested the start cell's inner box.
MoveResult follow_events(const Domain& domain, Particle& particle, const Flight& flight, Random& random,
                         const Carried& carried, bool first);

// How the face-intersection baselines put back a particle found outside its cell.
enum class Recovery {
  first_violated_face,  // Stollmeier & Grabe, once at the end of the move
  neighbour_search,     // Haselbacher et al., after every crossing and at the end
};
MoveResult move_face_intersection(const Domain& domain, Particle& particle, double dt, Random& random,
                                  Recovery recovery);

}  // namespace cosim::tracker::tracking::detail
