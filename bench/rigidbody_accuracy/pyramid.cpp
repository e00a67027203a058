#include <cmath>

#include "bench/rigidbody_accuracy/scene.hpp"

namespace cosim::bench {

Scene build_pyramid(rigidbody::world::World& world) {
  constexpr double r = 0.05, gap = 1e-3 * r;
  constexpr int kLayers = 7;
  const rigidbody::world::BodyMaterial rough{.friction = 0.5};
  world.add({.shape = geometry::HalfSpace(Eigen::Vector3d::UnitZ()), .material = rough, .fixed = true});
  // Each layer sits in the hollows of the one below, so every sphere rests on four; the
  // gaps close during the first steps, which is where solvers add energy if they do. The
  // bottom layer is fixed: on the bare floor its edge spheres roll outwards and the pyramid
  // collapses with every solver, even with friction 1.5 (spheres have no rolling
  // resistance), and a collapse has no settled state to measure accuracy against.
  for (int layer = 0; layer < kLayers; ++layer) {
    const int n = kLayers - layer;
    const double z = r + gap + layer * (std::sqrt(2.0) * r + gap);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        rigidbody::world::BodyDesc sphere{.shape = geometry::Sphere(r), .material = rough, .fixed = layer == 0};
        sphere.state.position = {(2 * i + layer) * (r + gap), (2 * j + layer) * (r + gap), z};
        world.add(sphere);
      }
  }
  return {.name = "pyramid", .size = r, .duration = 1.0};
}

}  // namespace cosim::bench
