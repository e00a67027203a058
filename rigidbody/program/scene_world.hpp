// The scene as the rigid-body world sees it: shapes, materials and the effects that switch
// gravity, contact, friction and buoyancy on.
#pragma once

#include <memory>
#include <vector>

#include "rigidbody/world/world.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::rigidbody::program {

struct ProgramOptions {
  world::Settings settings;
  // Mesh bodies (scene indices) that collide as their convex hull: exact GJK/EPA contacts
  // instead of distance-map samples, for meshes that are convex or nearly so.
  std::vector<std::size_t> convex_hulls;
  // Faces of the scene's domain that are walls for contact (the container of a fluid, whose
  // faces cosim-fluid holds as boundaries rather than bodies): fixed half-spaces appended
  // after the scene's bodies, never exchanged with the coupler.
  std::vector<world::BodyDesc> walls;
  // C of the virtual mass C rho_f V that stabilizes explicitly coupled light bodies
  // (virtual_mass.hpp); 0: off.
  double virtual_mass = 0;
};

// Reads participants.rigidbody (dt and options) and the effects. Throws SceneError naming
// the key for a bad or unknown option, or a missing rigidbody section.
ProgramOptions program_options(const scene::Scene& scene);
world::Settings settings_of(const scene::Scene& scene);  // program_options(scene).settings

// One world body per scene body, in scene order. Mesh bodies are placed by their centre of
// mass, so their state position is the scene position plus the rotated com_shift.
world::BodyDesc body_of(const scene::Body& body, bool friction, bool convex_hull = false);

// The scene's bodies in scene order, then the walls. On the heap: a World is neither
// copyable nor movable.
std::unique_ptr<world::World> make_world(const scene::Scene& scene);
// The same with the options already read (a caller that needs them too reads them once).
std::unique_ptr<world::World> make_world(const scene::Scene& scene, const ProgramOptions& options);

}  // namespace cosim::rigidbody::program
