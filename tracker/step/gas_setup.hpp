// What a Simulation is made from: the mesh with its walls, obstacles and inflows, the
// initial particles and, optionally, collisions or tracer mode. The program reads them from
// a scene (tracker/program/scene_tracker.hpp); the library never sees one.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/step/collide.hpp"
#include "tracker/step/seed_particles.hpp"
#include "tracker/tracers/advance.hpp"
#include "tracker/tracking/domain.hpp"
#include "tracker/tracking/inflow.hpp"
#include "tracker/tracking/obstacles.hpp"

namespace cosim::tracker::step {

// Tracer mode: the particles are tracers carried by a fluid's velocity field.
struct Tracers {
  tracers::TracerModel model;
  std::optional<tracers::VelocityField> velocity;  // none yet: a coupled run's fluid sends it
};

// How the ranks' particle loads are kept even, as SPARTA's `fix balance` does: every
// `every` steps (0: never) a re-partition by particles when the most a rank holds exceeds
// the mean by `threshold`.
struct Balance {
  int every = 10;
  double threshold = 1.2;
};

struct GasSetup {
  // On the heap: the domain and the obstacles refer to the mesh, and the whole moves. The
  // whole mesh, or (several ranks) this rank's part of a box (Mesh::partial).
  std::unique_ptr<mesh::Mesh> mesh;
  std::optional<mesh::BoxSpec> box;  // the mesh is this box's
  std::unique_ptr<const tracking::Domain> domain;
  tracking::Obstacles obstacles;
  Seeding particles;
  std::vector<tracking::Inflow> inflows;
  std::optional<Collisions> collisions;
  std::optional<Tracers> tracers;  // no collisions, no inflow
  Balance balance;                 // over several ranks
  double dt = 0.0;                 // the longest step
};

}  // namespace cosim::tracker::step
