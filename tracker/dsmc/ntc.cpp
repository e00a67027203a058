#include "tracker/dsmc/ntc.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace cosim::tracker::dsmc {

double initial_sigma_g_max(const CollisionModel& model, double T) {
  return model.sigma_g(3 * std::sqrt(2 * boltzmann * T / (model.mass() / 2)));
}

namespace {

// The number of candidate pairs of this step, carrying the fraction.
std::int64_t candidates(std::size_t n, CellCollisionState& state, double volume, double fnum, double dt) {
  const double expected =
      0.5 * static_cast<double>(n) * static_cast<double>(n - 1) * fnum * state.sigma_g_max * dt / volume +
      state.remainder;
  const double pairs = std::floor(expected);
  state.remainder = expected - pairs;
  return static_cast<std::int64_t>(pairs);
}

// Accepts the pair with probability sigma g / (sigma g)_max, raising the maximum when
// exceeded, and scatters it.
bool try_collision(Vec3& v1, Vec3& v2, const CollisionModel& model, CellCollisionState& state, Rng& rng) {
  const double sg = model.sigma_g((v1 - v2).norm());
  if (sg > state.sigma_g_max) {
    state.sigma_g_max = sg;
  } else if (uniform(rng) * state.sigma_g_max >= sg) {
    return false;
  }
  model.scatter(v1, v2, rng);
  return true;
}

}  // namespace

CellCollisions collide_cell(std::span<Vec3> velocities, const CollisionModel& model, CellCollisionState& state,
                            double volume, double fnum, double dt, Rng& rng) {
  CellCollisions result;
  const std::size_t n = velocities.size();
  if (n < 2) return result;
  result.candidates = candidates(n, state, volume, fnum, dt);
  const auto bound = static_cast<Rng::result_type>(n);
  for (std::int64_t k = 0; k < result.candidates; ++k) {
    const auto i = static_cast<std::size_t>(rng(bound));
    auto j = static_cast<std::size_t>(rng(bound - 1));
    if (j >= i) ++j;  // uniform over the others
    result.collisions += try_collision(velocities[i], velocities[j], model, state, rng);
  }
  return result;
}

CellCollisions collide_cell_nearest(std::span<Vec3> velocities, std::span<const Vec3> positions,
                                    const CollisionModel& model, CellCollisionState& state, double volume, double fnum,
                                    double dt, Rng& rng) {
  if (positions.size() != velocities.size())
    throw std::invalid_argument("collide_cell_nearest: " + std::to_string(positions.size()) + " positions for " +
                                std::to_string(velocities.size()) + " velocities");
  CellCollisions result;
  const std::size_t n = velocities.size();
  if (n < 2) return result;
  result.candidates = candidates(n, state, volume, fnum, dt);
  thread_local std::vector<std::size_t> last;  // last partner in this call, n = none
  last.assign(n, n);
  const auto bound = static_cast<Rng::result_type>(n);
  for (std::int64_t k = 0; k < result.candidates; ++k) {
    const auto i = static_cast<std::size_t>(rng(bound));
    std::size_t j = n;
    double nearest = HUGE_VAL;
    for (std::size_t m = 0; m < n; ++m) {
      if (m == i || (m == last[i] && n > 2)) continue;
      const double d = (positions[m] - positions[i]).squaredNorm();
      if (d < nearest) {
        nearest = d;
        j = m;
      }
    }
    if (try_collision(velocities[i], velocities[j], model, state, rng)) {
      ++result.collisions;
      last[i] = j;
      last[j] = i;
    }
  }
  return result;
}

}  // namespace cosim::tracker::dsmc
