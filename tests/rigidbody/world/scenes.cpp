#include "tests/rigidbody/world/scenes.hpp"

#include <algorithm>

#include "rigidbody/dynamics/invariants.hpp"
#include "rigidbody/narrowphase/narrowphase.hpp"

namespace cosim::rigidbody::world::test {

std::uint32_t add_ground(World& world, const BodyMaterial& material) {
  return world.add({.shape = geometry::HalfSpace(Eigen::Vector3d::UnitZ()), .material = material, .fixed = true});
}

std::uint32_t add_sphere(World& world, double radius, const Eigen::Vector3d& position, const BodyMaterial& material) {
  BodyDesc d{.shape = geometry::Sphere(radius), .material = material};
  d.state.position = position;
  return world.add(d);
}

std::uint32_t add_box(World& world, const Eigen::Vector3d& half, const Eigen::Vector3d& position,
                      const BodyMaterial& material) {
  BodyDesc d{.shape = geometry::Box(half), .material = material};
  d.state.position = position;
  return world.add(d);
}

std::vector<std::uint32_t> add_box_stack(World& world, int count, double half) {
  std::vector<std::uint32_t> boxes;
  for (int i = 0; i < count; ++i)
    boxes.push_back(add_box(world, Eigen::Vector3d::Constant(half), {0.0, 0.0, half * (2 * i + 1)}));
  return boxes;
}

double total_energy(const World& world) {
  double e = dynamics::kinetic_energy(world.states(), world.inertias());
  const Eigen::Vector3d g =
      world.settings().body_forces.gravity ? world.settings().body_forces.g : Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < world.size(); ++i) {
    const auto& body = world.inertias()[i];
    if (!body.is_fixed()) e -= g.dot(world.states()[i].position) / body.inverse_mass;
  }
  return e;
}

double overlap(const World& world, std::uint32_t i, std::uint32_t j) {
  const auto& a = world.states()[i];
  const auto& b = world.states()[j];
  contact::Manifold m;
  narrowphase::collide(world.shape(i), geometry::Pose(a.position, a.orientation), world.shape(j),
                       geometry::Pose(b.position, b.orientation), 0.0, m);
  double deepest = 0.0;
  for (int k = 0; k < m.count; ++k) deepest = std::max(deepest, -m.points[k].distance);
  return deepest;
}

}  // namespace cosim::rigidbody::world::test
