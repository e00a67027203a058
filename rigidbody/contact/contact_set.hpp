// One substep's contacts, stored compactly: the points of all pairs in one array and a
// range per pair. A Manifold reserves room for twelve points; most pairs (spheres) have
// one, so in a dense granular bed this layout holds a fraction of the bytes.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "rigidbody/contact/contact.hpp"

namespace cosim::rigidbody::contact {

struct PairContacts {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  std::uint32_t first = 0;  // index of the pair's first point in ContactSet::points
  std::uint32_t count = 0;
};

struct ContactSet {
  std::vector<PairContacts> pairs;  // only pairs with at least one point
  std::vector<ContactPoint> points;

  void clear() {
    pairs.clear();
    points.clear();
  }
  // Appends the manifold's points (nothing when it has none).
  void add(const Manifold& m) {
    if (m.count == 0) return;
    pairs.push_back({m.a, m.b, static_cast<std::uint32_t>(points.size()), m.count});
    points.insert(points.end(), m.points.begin(), m.points.begin() + m.count);
  }
  std::span<const ContactPoint> points_of(const PairContacts& p) const { return {points.data() + p.first, p.count}; }

  // The largest overlap -distance, 0 when nothing overlaps.
  double deepest_penetration() const {
    double deepest = 0.0;
    for (const ContactPoint& p : points) deepest = std::max(deepest, -p.distance);
    return deepest;
  }
};

}  // namespace cosim::rigidbody::contact
