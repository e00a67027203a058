#include "rigidbody/program/scene_world.hpp"

#include <array>
#include <stdexcept>

#include "scene/error.hpp"
#include "scene/reader.hpp"

namespace cosim::program {
namespace {

using Eigen::Vector3d;

Vector3d vec(const scene::Vec3& v) { return {v[0], v[1], v[2]}; }

const scene::Participant& section(const scene::Scene& scene) {
  const auto* p = scene.participant("rigidbody");
  if (p == nullptr)
    throw scene::SceneError(scene.file.string(), 0, "participants.rigidbody", "", "missing: cosim-rigidbody reads its dt and options there");
  return *p;
}

geometry::Shape shape_of(const scene::Shape& s) {
  switch (s.type) {
    case scene::ShapeType::Sphere: return geometry::Sphere(s.radius);
    case scene::ShapeType::Ellipsoid: return geometry::Ellipsoid(vec(s.radii));
    case scene::ShapeType::Box: return geometry::Box(vec(s.half_extents));
    case scene::ShapeType::Cylinder: return geometry::Cylinder(s.radius, s.height);
    case scene::ShapeType::Capsule: return geometry::Capsule(s.radius, s.height);
    case scene::ShapeType::Plane: return geometry::HalfSpace(vec(s.normal));
    case scene::ShapeType::Mesh: return geometry::TriangleMesh::from_file(s.file);
  }
  throw std::invalid_argument("unknown shape type");
}

}  // namespace

world::Settings settings_of(const scene::Scene& scene) {
  const auto& p = section(scene);
  const auto options = scene::options_of(scene, p);
  world::Settings s;
  s.dt = p.dt;

  constexpr std::array solver_names{"sequential-impulses", "pgs", "jacobi", "dem"};
  constexpr std::array solvers{world::SolverKind::sequential_impulses, world::SolverKind::pgs,
                               world::SolverKind::jacobi, world::SolverKind::dem};
  s.solver = solvers[options.choice("solver", solver_names, 0)];
  s.iterations = options.integer("iterations", s.iterations, scene::Range::at_least(0));
  s.tolerance = options.number("tolerance", s.tolerance, scene::Range::above(0));
  s.contact_margin = options.number("contact_margin", s.contact_margin, scene::Range::at_least(0));
  constexpr std::array restitution_names{"simultaneous", "sequential"};
  constexpr std::array restitutions{solver::Restitution::simultaneous, solver::Restitution::sequential};
  s.restitution = restitutions[options.choice("restitution", restitution_names, 0)];

  s.body_forces.gravity = scene.has_effect(scene::Effect::Gravity);
  s.body_forces.g = vec(scene.gravity);
  s.body_forces.buoyancy = scene.has_effect(scene::Effect::Buoyancy);
  // Hydrostatic buoyancy needs the fluid's density, which the scene has nowhere else.
  if (s.body_forces.buoyancy) s.body_forces.fluid_density = options.number("fluid_density", scene::Range::above(0));
  s.contact = scene.has_effect(scene::Effect::Contact);
  options.finish();
  return s;
}

world::BodyDesc body_of(const scene::Body& b, bool friction) {
  world::BodyDesc d{.shape = shape_of(b.shape)};
  const auto& o = b.orientation;
  d.state.orientation = Eigen::Quaterniond(o[0], o[1], o[2], o[3]);
  d.state.position = vec(b.position);
  if (const auto* mesh = std::get_if<geometry::TriangleMesh>(&d.shape))
    d.state.position += d.state.orientation * mesh->com_shift();
  d.state.velocity = vec(b.velocity);
  d.state.angular_velocity = vec(b.angular_velocity);
  d.density = b.material.density;
  d.material = {.friction = friction ? b.material.friction : 0.0, .restitution = b.material.restitution};
  d.fixed = b.fixed;
  return d;
}

std::unique_ptr<world::World> make_world(const scene::Scene& scene) {
  auto w = std::make_unique<world::World>(settings_of(scene));
  const bool friction = scene.has_effect(scene::Effect::Friction);
  for (const auto& b : scene.bodies) w->add(body_of(b, friction));
  return w;
}

}  // namespace cosim::program
