#include "bench/tracker_study/cluster.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <stdexcept>

namespace cosim::bench {

std::vector<Ball> sphere_cluster(int count, double diameter, double packing, unsigned seed) {
  const double r = diameter / 2.0;
  const double volume = count * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double region = std::cbrt(volume / packing * 3.0 / (4.0 * std::numbers::pi));
  const Eigen::Vector3d centre = Eigen::Vector3d::Constant(0.5);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0), size(0.95 * r, 1.05 * r);
  std::vector<Ball> balls;
  for (long tries = 0; static_cast<int>(balls.size()) < count; ++tries) {
    if (tries > 1000L * count) throw std::runtime_error("sphere_cluster: packing too dense for random addition");
    const Eigen::Vector3d offset(uniform(random), uniform(random), uniform(random));
    const double radius = size(random);
    if (offset.norm() * region + radius > region) continue;
    const Ball ball{centre + region * offset, radius};
    if (std::none_of(balls.begin(), balls.end(),
                     [&](const Ball& b) { return (b.centre - ball.centre).norm() < b.radius + ball.radius; }))
      balls.push_back(ball);
  }
  return balls;
}

namespace {

std::uint64_t morton(const Eigen::Vector3d& x) {
  std::uint64_t code = 0;
  for (int bit = 0; bit < 20; ++bit)
    for (int k = 0; k < 3; ++k) {
      const auto cell = static_cast<std::uint64_t>(std::clamp(x[k], 0.0, 1.0) * ((1 << 20) - 1));
      code |= ((cell >> bit) & 1u) << (3 * bit + k);
    }
  return code;
}

}  // namespace

std::vector<std::vector<Ball>> groups_of(std::vector<Ball> balls, int size) {
  std::sort(balls.begin(), balls.end(),
            [](const Ball& a, const Ball& b) { return morton(a.centre) < morton(b.centre); });
  std::vector<std::vector<Ball>> groups;
  for (std::size_t i = 0; i < balls.size(); i += static_cast<std::size_t>(size))
    groups.emplace_back(balls.begin() + static_cast<long>(i),
                        balls.begin() + static_cast<long>(std::min(balls.size(), i + static_cast<std::size_t>(size))));
  return groups;
}

}  // namespace cosim::bench
