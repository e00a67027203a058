#include "tracker/program/scene_tracker.hpp"

#include <stdexcept>
#include <string>

#include "coupler/scene/error.hpp"
#include "tracker/mesh/box_part.hpp"
#include "tracker/parallel/bricks.hpp"
#include "tracker/program/scene_balance.hpp"
#include "tracker/program/scene_collisions.hpp"
#include "tracker/program/scene_inflow.hpp"
#include "tracker/program/scene_mesh.hpp"
#include "tracker/program/scene_obstacles.hpp"
#include "tracker/program/scene_tracers.hpp"
#include "tracker/program/scene_walls.hpp"
#include "tracker/program/seeding.hpp"

namespace cosim::tracker::program {

namespace {

// On several ranks, this rank's brick of a box and the two layers of cells around it.
std::function<mesh::Mesh(const mesh::BoxSpec&)> box_parts(const parallel::Ranks& ranks) {
  if (ranks.size() == 1) return {};
  return [ranks](const mesh::BoxSpec& spec) {
    const parallel::Bricks bricks = parallel::box_bricks(spec, ranks.size());
    const parallel::Bricks::Range& mine = bricks.brick(ranks.rank());
    // Parts differ in size (ghosts on one side or two, a periodic axis whole): a part too
    // large for its numbering fails every rank alike, not only its own.
    mesh::Mesh part;
    std::string failure;
    try {
      part = mesh::box_part(
          spec, mine.lo, mine.hi, [&](Index c) { return bricks.owner(c); }, ranks.rank());
    } catch (const std::invalid_argument& e) {
      failure = e.what();
    }
    if (ranks.sum(failure.empty() ? 0LL : 1LL) > 0)
      throw std::invalid_argument(failure.empty() ? "another rank's part of the box failed (its message names it)"
                                                  : failure);
    return part;
  };
}

// The whole mesh's, also where this rank holds only its part of a box.
double mesh_volume(const TrackerScene& t) {
  if (t.box) {
    const step::CellVolumes box = step::volumes_of(*t.box);
    return box.below(box.cells);
  }
  double v = 0;
  for (const double c : t.mesh->volume) v += c;
  return v;
}

}  // namespace

TrackerScene read_tracker(const scene::Scene& scene, parallel::Ranks ranks) {
  const scene::Participant* p = scene.participant("tracker");
  if (p == nullptr) throw scene::SceneError(scene.file.string(), 0, "participants", "", "the scene has no tracker");
  const scene::Reader options = scene::options_of(scene, *p);

  TrackerScene t;
  t.dt = p->dt;
  t.tracers = read_tracers(options, scene);
  SceneMesh mesh = read_mesh(options.map("mesh"), scene, t.tracers ? nullptr : box_parts(ranks));
  t.mesh = std::make_unique<mesh::Mesh>(std::move(mesh.mesh));
  t.box = std::move(mesh.box);
  const bool part = t.mesh->partial;
  t.particles = read_seeding(options.map("particles"), scene.folder, mesh_volume(t));
  tracking::Boundaries boundaries = read_boundaries(options, *t.mesh, t.particles.mass, ranks);
  t.inflows = read_inflows(options, *t.mesh, boundaries, t.particles.mass, t.particles.weight);
  // A part may hold none of an inflow's faces, but some rank must.
  for (std::size_t i = 0; part && i < t.inflows.size(); ++i)
    if (ranks.sum(t.inflows[i].rate() > 0.0 ? 1LL : 0LL) == 0)
      options.fail("inflow", "inflow " + std::to_string(i) + ": its patches have no boundary faces");
  t.collisions = read_collisions(options, t.particles.mass);
  if (t.tracers && (t.collisions || !t.inflows.empty()))
    options.fail("tracers", "tracers ride the fluid: a scene with tracers has no collisions and no inflow");
  try {
    t.domain = std::make_unique<const tracking::Domain>(*t.mesh, std::move(boundaries));
  } catch (const std::invalid_argument& e) {
    options.fail("boundaries", e.what());
  }
  SceneObstacles obstacles = read_obstacles(options, scene);
  t.obstacle_body = std::move(obstacles.body);
  if (!obstacles.objects.empty()) {
    std::string failure;
    try {
      t.obstacles = tracking::Obstacles(*t.mesh, std::move(obstacles.objects));
      for (int i = 0; i < t.obstacles.count(); ++i)
        if (const int b = t.obstacle_body[static_cast<std::size_t>(i)]; b >= 0)
          t.obstacles.place(i, initial_pose(scene.bodies[static_cast<std::size_t>(b)]));
    } catch (const std::invalid_argument& e) {
      failure = e.what();
    }
    // A part shows a rank only its cells' faults: every rank stops alike.
    if (const long long failed = failure.empty() ? 0 : 1; (part ? ranks.sum(failed) : failed) > 0)
      options.fail("obstacles",
                   failure.empty() ? "on another rank's part of the mesh (its message names it)" : failure);
    // An object whose surface meets no cell does nothing: most likely given in other units
    // or outside the domain.
    for (int i = 0; i < t.obstacles.count(); ++i)
      if (const long long meets = t.obstacles.cells(i).stats().max_primitives > 0 ? 1 : 0;
          (part ? ranks.sum(meets) : meets) == 0)
        options.fail("obstacles",
                     "obstacle '" + t.obstacles.object(i).name +
                         "': its surface meets no cell of the mesh (outside the domain, or in other units?)");
  }
  t.particle_output = read_particle_output(options, scene, t.obstacles);
  t.balance = read_balance(options);
  options.finish();
  return t;
}

void place_bound_obstacles(TrackerScene& setup, const std::vector<Eigen::Isometry3d>& body_poses) {
  if (body_poses.empty()) return;
  for (int i = 0; i < setup.obstacles.count(); ++i)
    if (const int b = setup.obstacle_body[static_cast<std::size_t>(i)]; b >= 0) {
      if (static_cast<std::size_t>(b) >= body_poses.size())
        throw std::runtime_error("poses for " + std::to_string(body_poses.size()) + " bodies, obstacle '" +
                                 setup.obstacles.object(i).name + "' is bound to body " + std::to_string(b));
      setup.obstacles.place(i, body_poses[static_cast<std::size_t>(b)]);
    }
}

}  // namespace cosim::tracker::program
