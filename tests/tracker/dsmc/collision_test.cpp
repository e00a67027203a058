// Collision models: cross-sections, their equilibrium averages, and the scattering law.
#include "tracker/dsmc/collision.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace cosim::tracker::dsmc {
namespace {

const double pi = std::numbers::pi;

TEST(CollisionModel, CrossSections) {
  const double m = 6.63e-26, d = 4.11e-10;
  const auto hs = CollisionModel::hard_sphere(m, d);
  EXPECT_DOUBLE_EQ(hs.cross_section(10), pi * d * d);
  EXPECT_DOUBLE_EQ(hs.cross_section(1000), pi * d * d);
  const auto vss = CollisionModel::vss(m, d, 0.81, 273.15, 1.4);
  for (const double g : {50.0, 500.0, 3000.0}) {
    const double expected =
        pi * d * d * std::pow(2 * boltzmann * 273.15 / (m / 2 * g * g), 0.81 - 0.5) / std::tgamma(2.5 - 0.81);
    EXPECT_NEAR(vss.cross_section(g) / expected, 1, 1e-13);
    EXPECT_NEAR(vss.sigma_g(g) / (expected * g), 1, 1e-13);
  }
  // omega = 1/2 is the hard sphere.
  const auto vhs_half = CollisionModel::vhs(m, d, 0.5, 273);
  EXPECT_NEAR(vhs_half.cross_section(777) / (pi * d * d), 1, 1e-14);
  EXPECT_THROW(CollisionModel::vhs(m, d, 0.4, 273), std::invalid_argument);
  EXPECT_THROW(CollisionModel::vss(m, d, 0.81, 273, 2.5), std::invalid_argument);
}

// <sigma g> over the equilibrium distribution of relative speeds (a Maxwellian with the
// reduced mass), by quadrature, against the closed form (Bird eq. 4.64 / n).
TEST(CollisionModel, MeanSigmaGMatchesQuadrature) {
  const SpeciesTable table = read_species(default_species_file());
  for (const auto& [name, s] : table.all())
    for (const Model model : {Model::hard_sphere, Model::vhs, Model::vss})
      for (const double T : {100.0, 273.0, 1000.0}) {
        const auto cm = CollisionModel::from_species(s, model);
        const double mr = s.mass / 2;
        const double beta2 = mr / (2 * boltzmann * T);
        const double gmax = 12 / std::sqrt(beta2);
        const int steps = 20000;
        const double h = gmax / steps;
        double sum = 0;
        for (int k = 1; k < steps; ++k) {  // trapezoid; the integrand vanishes at both ends
          const double g = k * h;
          sum += cm.sigma_g(g) * 4 * pi * std::pow(beta2 / pi, 1.5) * g * g * std::exp(-beta2 * g * g);
        }
        EXPECT_NEAR(sum * h / cm.mean_sigma_g(T), 1, 1e-8) << name << " T " << T;
      }
}

struct Moments {
  double mean = 0, mean_square = 0;
};

// cos chi of `samples` scatterings of relative velocities of random direction and size,
// checking that each keeps |g| and that the pair keeps momentum and energy.
Moments deflections(const CollisionModel& model, int samples, Rng& rng) {
  Moments m;
  for (int k = 0; k < samples; ++k) {
    Vec3 v1(uniform(rng) - 0.5, uniform(rng) - 0.5, uniform(rng) - 0.5);
    Vec3 v2(uniform(rng) - 0.5, uniform(rng) - 0.5, uniform(rng) - 0.5);
    v1 *= 1000;
    v2 *= 1000;
    if (k % 1000 == 0) v2 = v1 + Vec3(0, 0, k % 2000 == 0 ? 300 : -300);  // g along -z and +z
    const Vec3 g = v1 - v2;
    const Vec3 momentum = v1 + v2;
    const double energy = v1.squaredNorm() + v2.squaredNorm();
    model.scatter(v1, v2, rng);
    const Vec3 h = v1 - v2;
    EXPECT_NEAR(h.norm() / g.norm(), 1, 1e-13);
    EXPECT_LT((v1 + v2 - momentum).norm(), 1e-12 * 1000);
    EXPECT_NEAR((v1.squaredNorm() + v2.squaredNorm()) / energy, 1, 1e-13);
    const double c = g.dot(h) / g.squaredNorm();
    m.mean += c;
    m.mean_square += c * c;
  }
  m.mean /= samples;
  m.mean_square /= samples;
  return m;
}

// VSS: cos chi = 2 X - 1 with X = R^(1/alpha), R uniform on [0, 1). E[X] = alpha / (alpha + 1)
// and E[X^2] = alpha / (alpha + 2), so <cos chi> = (alpha - 1) / (alpha + 1) and
// var(cos chi) = 4 (alpha / (alpha + 2) - alpha^2 / (alpha + 1)^2).
TEST(CollisionModel, VssMeanDeflection) {
  const SpeciesTable table = read_species(default_species_file());
  Rng rng = make_rng(7);
  const int samples = 400000;
  for (const auto& [name, s] : table.all()) {
    const auto model = CollisionModel::from_species(s, Model::vss);
    const double a = s.alpha;
    const double expected = (a - 1) / (a + 1);
    const double error = std::sqrt(4 * (a / (a + 2) - a * a / ((a + 1) * (a + 1))) / samples);
    const Moments m = deflections(model, samples, rng);
    std::cout << name << " VSS alpha " << a << ": <cos chi> " << m.mean << " expected " << expected << " +- " << error
              << '\n';
    EXPECT_NEAR(m.mean, expected, 5 * error) << name;
  }
}

// HS and VHS: isotropic, <cos chi> = 0 and <cos^2 chi> = 1/3.
TEST(CollisionModel, IsotropicScattering) {
  Rng rng = make_rng(8);
  const int samples = 400000;
  for (const auto& model :
       {CollisionModel::hard_sphere(6.63e-26, 4.17e-10), CollisionModel::vhs(6.63e-26, 4.17e-10, 0.81, 273)}) {
    const Moments m = deflections(model, samples, rng);
    EXPECT_NEAR(m.mean, 0, 5 * std::sqrt(1.0 / 3 / samples));
    EXPECT_NEAR(m.mean_square, 1.0 / 3, 5 * std::sqrt(4.0 / 45 / samples));
  }
}

}  // namespace
}  // namespace cosim::tracker::dsmc
