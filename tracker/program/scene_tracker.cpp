#include "tracker/program/scene_tracker.hpp"

#include <stdexcept>

#include "scene/error.hpp"
#include "tracker/program/scene_inflow.hpp"
#include "tracker/program/scene_mesh.hpp"
#include "tracker/program/scene_obstacles.hpp"
#include "tracker/program/scene_tracers.hpp"
#include "tracker/program/scene_walls.hpp"

namespace cosim::tracker {

TrackerScene read_tracker(const scene::Scene& scene) {
  const scene::Participant* p = scene.participant("tracker");
  if (p == nullptr) throw scene::SceneError(scene.file.string(), 0, "participants", "", "the scene has no tracker");
  const scene::Reader options = scene::options_of(scene, *p);

  TrackerScene t;
  t.dt = p->dt;
  SceneMesh mesh = read_mesh(options.map("mesh"), scene);
  t.mesh = std::make_unique<const Mesh>(std::move(mesh.mesh));
  t.box = std::move(mesh.box);
  t.particles = read_seeding(options.map("particles"));
  Boundaries boundaries = read_boundaries(options, *t.mesh, t.particles.mass);
  t.inflows = read_inflows(options, *t.mesh, boundaries, t.particles.mass, t.particles.weight);
  t.collisions = read_collisions(options, t.particles.mass);
  t.tracers = read_tracers(options, scene);
  if (t.tracers && (t.collisions || !t.inflows.empty()))
    options.fail("tracers", "tracers ride the fluid: a scene with tracers has no collisions and no inflow");
  try {
    t.domain = std::make_unique<const Domain>(*t.mesh, std::move(boundaries));
  } catch (const std::invalid_argument& e) {
    options.fail("boundaries", e.what());
  }
  SceneObstacles obstacles = read_obstacles(options, scene);
  t.obstacle_body = std::move(obstacles.body);
  if (!obstacles.objects.empty()) {
    try {
      t.obstacles = Obstacles(*t.mesh, std::move(obstacles.objects));
      for (int i = 0; i < t.obstacles.count(); ++i)
        if (const int b = t.obstacle_body[static_cast<std::size_t>(i)]; b >= 0)
          t.obstacles.place(i, initial_pose(scene.bodies[static_cast<std::size_t>(b)]));
    } catch (const std::invalid_argument& e) {
      options.fail("obstacles", e.what());
    }
    // An object whose surface meets no cell does nothing: most likely given in other units
    // or outside the domain.
    for (int i = 0; i < t.obstacles.count(); ++i)
      if (t.obstacles.cells(i).stats().max_primitives == 0)
        options.fail("obstacles", "obstacle '" + t.obstacles.object(i).name +
                                      "': its surface meets no cell of the mesh (outside the domain, or in other units?)");
  }
  t.particle_output = read_particle_output(options, scene, t.obstacles);
  t.balance = read_balance(options);
  options.finish();
  return t;
}

}  // namespace cosim::tracker
