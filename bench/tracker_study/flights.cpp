#include "bench/tracker_study/flights.hpp"

namespace cosim::bench {

using namespace cosim::tracker;

std::vector<Flight> hard_moves(const tracker::mesh::Mesh& mesh, int count, tracker::tracking::Random& random) {
  std::vector<Flight> flights;
  for (int i = 0; i < count; ++i) flights.push_back(tracker::tracking::testing::hard_move(mesh, random));
  return flights;
}

std::vector<Flight> traversals(const tracker::tracking::Domain& domain, int count, double length,
                               tracker::tracking::Random& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Flight> flights;
  while (static_cast<int>(flights.size()) < count) {
    const Vec3 x(uniform(random), uniform(random), uniform(random));
    const Index cell = domain.locator.locate(x);
    if (cell >= 0) flights.push_back({{x, tracker::tracking::testing::isotropic(random), cell}, length});
  }
  return flights;
}

}  // namespace cosim::bench
