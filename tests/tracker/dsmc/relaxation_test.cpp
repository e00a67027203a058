// Relaxation of non-equilibrium velocity distributions in one cell to a Maxwellian, with
// momentum and energy conserved to round-off at every step.
#include "tests/tracker/dsmc/gas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

namespace cosim::tracker::dsmc {
namespace {

struct Stats {
  Vec3 momentum;     // sum of v (mass is common)
  double energy;     // sum of |v|^2
  Vec3 temperature;  // per axis, about the mean, with N - 1
  Vec3 kurtosis;     // <c^4> / <c^2>^2 per axis (3 for a Maxwellian)
};

Stats stats(const std::vector<Vec3>& v, double mass) {
  Stats s{Vec3::Zero(), 0, Vec3::Zero(), Vec3::Zero()};
  // Sums in long double, so that the check sees the collisions' round-off, not the sum's.
  long double p[3] = {0, 0, 0}, e = 0;
  for (const auto& x : v)
    for (int a = 0; a < 3; ++a) {
      p[a] += x[a];
      e += static_cast<long double>(x[a]) * x[a];
    }
  s.momentum = Vec3(static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]));
  s.energy = static_cast<double>(e);
  const double n = static_cast<double>(v.size());
  const Vec3 mean = s.momentum / n;
  Vec3 m2 = Vec3::Zero(), m4 = Vec3::Zero();
  for (const auto& x : v) {
    const Vec3 c2 = (x - mean).cwiseProduct(x - mean);
    m2 += c2;
    m4 += c2.cwiseProduct(c2);
  }
  s.temperature = mass * m2 / ((n - 1) * boltzmann);
  for (int a = 0; a < 3; ++a) s.kurtosis[a] = m4[a] / n / std::pow(m2[a] / n, 2);
  return s;
}

// Steps one cell of N simulators (dt = 0.1 mean collision times at the mean temperature)
// for `times` mean collision times; checks conservation at every step and the Maxwellian
// at the end. Returns the collision times after which (Tx - Ty) / T first fell below 1/e
// of its start (or -1).
double relax(const CollisionModel& model, std::vector<Vec3> v, double T, double times, Rng& rng) {
  const std::size_t N = v.size();
  const double n = 1e21, V = 1e-9, fnum = n * V / static_cast<double>(N);
  const double dt = 0.1 / (n * model.mean_sigma_g(T));
  const Stats start = stats(v, model.mass());
  const double scale = std::sqrt(start.energy);  // |momentum| <= sqrt(N * energy)
  const double anisotropy0 = (start.temperature.x() - start.temperature.y()) / T;
  double e_time = -1;
  CellCollisionState state{initial_sigma_g_max(model, T), 0};
  const int steps = static_cast<int>(std::lround(times / 0.1));
  double worst_energy = 0, worst_momentum = 0;
  std::int64_t collisions = 0;
  for (int k = 1; k <= steps; ++k) {
    collisions += collide_cell(v, model, state, V, fnum, dt, rng).collisions;
    const Stats s = stats(v, model.mass());
    worst_energy = std::max(worst_energy, std::abs(s.energy / start.energy - 1));
    worst_momentum = std::max(worst_momentum, (s.momentum - start.momentum).norm() / (scale * std::sqrt(N)));
    if (e_time < 0 && anisotropy0 != 0 && (s.temperature.x() - s.temperature.y()) / T < anisotropy0 / std::exp(1))
      e_time = 0.1 * k;
  }
  const Stats end = stats(v, model.mass());
  const double Nd = static_cast<double>(N);
  std::cout << "  " << collisions / (0.5 * Nd) << " collisions per particle; T/T0 = " << end.temperature.transpose() / T
            << " (+- " << std::sqrt(2 / Nd) << "), kurtosis " << end.kurtosis.transpose() << " (+- "
            << std::sqrt(24 / Nd) << "); start T/T0 " << start.temperature.transpose() / T << ", kurtosis "
            << start.kurtosis.transpose() << "; worst relative energy error " << worst_energy << ", momentum "
            << worst_momentum << '\n';
  EXPECT_LT(worst_energy, 1e-14);
  EXPECT_LT(worst_momentum, 1e-15);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(end.temperature[a] / T, 1, 5 * std::sqrt(2 / Nd)) << a;  // sample variance of N Gaussians
    EXPECT_NEAR(end.kurtosis[a], 3, 5 * std::sqrt(24 / Nd)) << a;        // sample kurtosis
  }
  return e_time;
}

// An anisotropic Maxwellian, Tx = 2 T, Ty = Tz = T / 2, drifting, in VSS argon: the axis
// temperatures equalize. The e-folding of Tx - Ty is reported in mean collision times.
TEST(Relaxation, TwoTemperatureMaxwellian) {
  const SpeciesTable table = read_species(default_species_file());
  const auto model = CollisionModel::from_species(table.at("Ar"), Model::vss);
  const double T = 300;
  Rng rng = make_rng(11);
  auto v = test::maxwellian(40000, model.mass(), Vec3(2 * T, 0.5 * T, 0.5 * T), Vec3(300, -100, 50), rng);
  const double e_time = relax(model, std::move(v), T, 10, rng);
  std::cout << "  (Tx - Ty) fell by 1/e after " << e_time << " mean collision times\n";
  EXPECT_GT(e_time, 0.3);
  EXPECT_LT(e_time, 3);
}

// All particles with one speed in random directions (each component uniform on [-c, c],
// kurtosis 9/5), hard spheres: the distribution becomes Maxwellian.
TEST(Relaxation, MonoenergeticToMaxwellian) {
  const auto model = CollisionModel::hard_sphere(6.63e-26, 4.17e-10);
  const double T = 273;
  const double c = std::sqrt(3 * boltzmann * T / model.mass());
  Rng rng = make_rng(12);
  std::vector<Vec3> v(40000);
  for (auto& x : v) {
    const double z = 2 * uniform(rng) - 1, phi = 2 * std::numbers::pi * uniform(rng);
    const double r = std::sqrt(1 - z * z);
    x = c * Vec3(r * std::cos(phi), r * std::sin(phi), z);
  }
  relax(model, std::move(v), T, 10, rng);
}

}  // namespace
}  // namespace cosim::tracker::dsmc
