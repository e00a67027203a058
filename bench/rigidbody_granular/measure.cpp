#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <ctime>
#include <numbers>

#include "bench/rigidbody_granular/result.hpp"
#include "rigidbody/broadphase/hash_grid.hpp"

namespace cosim::bench {

double max_penetration(const std::vector<Eigen::Vector3d>& centres, double radius, double half_width) {
  std::vector<rigidbody::broadphase::Object> objects;
  objects.reserve(centres.size());
  for (std::size_t i = 0; i < centres.size(); ++i)
    objects.push_back({.id = static_cast<rigidbody::broadphase::Id>(i), .centre = centres[i], .radius = radius});
  rigidbody::broadphase::HashGrid grid;
  grid.update(objects);
  std::vector<rigidbody::broadphase::Pair> pairs;
  grid.find_pairs(pairs);
  double deepest = 0.0;
  for (const auto& [a, b] : pairs) deepest = std::max(deepest, 2 * radius - (centres[a] - centres[b]).norm());
  for (const Eigen::Vector3d& c : centres) {
    const double walls = std::min({c.z(), half_width - std::abs(c.x()), half_width - std::abs(c.y())});
    deepest = std::max(deepest, radius - walls);
  }
  return deepest;
}

int kinetic_interval(int steps) { return std::max(1, steps / 100); }

void measure_pile(RunResult& r, const std::vector<Eigen::Vector3d>& centres, double radius, double half_width) {
  r.max_penetration = max_penetration(centres, radius, half_width);
  r.mean_height = 0;
  for (const auto& c : centres) r.mean_height += c.z() / static_cast<double>(centres.size());
  r.pile_height = 2 * r.mean_height;
  const double solid = static_cast<double>(centres.size()) * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  r.packing_fraction = solid / (4 * half_width * half_width * r.pile_height);
}

// Large blocks (vectors of 1e5 bodies) are mapped by mmap, which uordblks leaves out.
double heap_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return static_cast<double>(info.uordblks + info.hblkhd);
}

double cpu_time() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double peak_rss() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * static_cast<double>(usage.ru_maxrss);
}

}  // namespace cosim::bench
