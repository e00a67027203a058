#include "coupler/scene/solid.hpp"

#include <algorithm>
#include <cmath>

#include "coupler/scene/extent.hpp"

namespace cosim::scene {
namespace {

// Relative, so that touching stays touching in floating point at any scale.
constexpr double touch = 1 - 1e-9;

}  // namespace

std::optional<Solid> solid_of(const Shape& shape, const Quat& q, const Vec3& centre) {
  if (!bounded(shape)) return std::nullopt;
  return Solid{centre, bounding_radius(shape), half_extent(shape, q)};
}

bool overlap(const Solid& a, const Solid& b) {
  double distance2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = a.centre[k] - b.centre[k];
    if (std::abs(d) >= (a.half[k] + b.half[k]) * touch) return false;
    distance2 += d * d;
  }
  const double reach = (a.radius + b.radius) * touch;
  return distance2 < reach * reach;
}

bool rules_out(const Solid& placed, const Solid& body, const Vec3& lo, const Vec3& hi) {
  // The box's corner farthest from `placed` overlaps last: if it does, every point does.
  double distance2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = std::max(std::abs(lo[k] - placed.centre[k]), std::abs(hi[k] - placed.centre[k]));
    if (d >= (placed.half[k] + body.half[k]) * touch) return false;
    distance2 += d * d;
  }
  const double reach = (placed.radius + body.radius) * touch;
  return distance2 < reach * reach;
}

}  // namespace cosim::scene
