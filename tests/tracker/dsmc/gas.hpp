#pragma once
// Test gases in one cell.
#include "tracker/dsmc/ntc.hpp"

#include <random>
#include <vector>

namespace cosim::tracker::dsmc::test {

// N velocities of a Maxwellian at temperature T with drift `drift`, shifted and scaled so
// that the sample has exactly that mean and thermal energy (3/2) (N - 1) k T; the
// anisotropic case has temperature T_axis[a] along axis a.
inline std::vector<Vec3> maxwellian(std::size_t n, double mass, const Vec3& T_axis, const Vec3& drift, Rng& rng) {
  std::normal_distribution<double> normal;
  std::vector<Vec3> v(n);
  for (auto& x : v) x = Vec3(normal(rng), normal(rng), normal(rng));
  Vec3 mean = Vec3::Zero();
  for (const auto& x : v) mean += x;
  mean /= static_cast<double>(n);
  Vec3 square = Vec3::Zero();
  for (auto& x : v) {
    x -= mean;
    square += x.cwiseProduct(x);
  }
  for (int a = 0; a < 3; ++a) {
    const double scale = std::sqrt(boltzmann * T_axis[a] / mass * static_cast<double>(n - 1) / square[a]);
    for (auto& x : v) x[a] *= scale;
  }
  for (auto& x : v) x += drift;
  return v;
}

}  // namespace cosim::tracker::dsmc::test
