// What the scene knows of the space a body takes: a bounding sphere and a world-axis-aligned
// bounding box, both about its position. Two solids overlap when both bounds do. That is
// exact for two spheres (a sphere is its own bounding sphere, and spheres that meet have
// boxes that meet) and conservative for other shapes, which may be found overlapping where
// only their bounds do: the box keeps a lattice of touching boxes apart, the sphere a
// rotated shape whose box is loose.
#pragma once

#include <optional>

#include "coupler/scene/scene.hpp"

namespace cosim::scene {

struct Solid {
  Vec3 centre{};
  double radius = 0.0;  // of the bounding sphere
  Vec3 half{};          // half widths of the bounding box
};

// The solid of `shape` turned by `q` at `centre`; nullopt for shapes without extent
// (planes, meshes).
std::optional<Solid> solid_of(const Shape& shape, const Quat& q, const Vec3& centre);
inline std::optional<Solid> solid_of(const Body& b) { return solid_of(b.shape, b.orientation, b.position); }

// Touching is no overlap: bounds must cut into each other by more than 1e-9 of their size.
bool overlap(const Solid& a, const Solid& b);

// Whether `body` centred anywhere in the box [lo, hi] overlaps `placed`.
bool rules_out(const Solid& placed, const Solid& body, const Vec3& lo, const Vec3& hi);

}  // namespace cosim::scene
