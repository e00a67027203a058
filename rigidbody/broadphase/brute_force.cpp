#include "rigidbody/broadphase/brute_force.hpp"

#include <algorithm>

#include "rigidbody/broadphase/overlap.hpp"

namespace cosim::rigidbody::broadphase {

namespace {

bool candidates(const Object& a, const Object& b, double margin) {
  if ((a.fixed && b.fixed) || (a.infinite && b.infinite)) return false;
  if (a.infinite) return near_wall(a, b.centre, b.radius, margin);
  if (b.infinite) return near_wall(b, a.centre, a.radius, margin);
  return spheres_near(a.centre, a.radius, b.centre, b.radius, margin);
}

}  // namespace

std::vector<Pair> brute_force_pairs(std::span<const Object> objects, double margin) {
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    for (std::size_t j = i + 1; j < objects.size(); ++j) {
      if (candidates(objects[i], objects[j], margin)) {
        pairs.push_back(ordered_pair(objects[i].id, objects[j].id));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace cosim::rigidbody::broadphase
