// The virtual-mass blend against known answers: unchanged forces in steady motion,
// and on the model problem of explicit coupling (a fluid force lagging by one window,
// F_k = -m_a a_(k-1)) the implicit answer a = m a_g / (m + m_a) where plain explicit
// coupling diverges.
#include <gtest/gtest.h>

#include <cmath>

#include "rigidbody/program/virtual_mass.hpp"

namespace cosim::rigidbody::program {
namespace {

constexpr double kFluidDensity = 1000;

struct Body {
  dynamics::BodyInertia inertia;
  dynamics::BodyForces forces{.gravity = true, .buoyancy = true, .fluid_density = kFluidDensity};
};

Body body_of_density(double density) {
  Body b;
  const double volume = 1e-6, mass = density * volume;
  b.inertia = dynamics::BodyInertia::of(mass, Eigen::Matrix3d::Identity() * mass * 1e-4);
  b.inertia.density = density;
  return b;
}

dynamics::WindowWrench held(const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
  return {{force, torque}, {force, torque}};
}

// Steady motion: a fluid wrench that stays the same is passed on unchanged once the blend
// has caught up with it (geometrically, by (1 - w) per window).
TEST(VirtualMass, ASteadyFluidWrenchPassesUnchanged) {
  const Body b = body_of_density(800);
  VirtualMass vm(1.0, kFluidDensity);
  const Eigen::Vector3d force(0.001, -0.002, 0.004), torque(1e-7, 0, -2e-7);
  std::vector<dynamics::WindowWrench> out;
  for (int k = 0; k < 80; ++k) out = vm.blend(std::span(&b.inertia, 1), b.forces, std::vector{held(force, torque)});
  EXPECT_LT((out[0].start.force - force).norm(), 1e-12 * force.norm());
  EXPECT_LT((out[0].end.torque - torque).norm(), 1e-12 * torque.norm());
}

// Windows of the model problem; returns the accelerations.
std::vector<double> model_accelerations(double density, double added_mass_ratio, double coefficient, int windows) {
  const Body b = body_of_density(density);
  const double mass = 1 / b.inertia.inverse_mass, added = added_mass_ratio * kFluidDensity * 1e-6;
  const double g = b.forces.acceleration(b.inertia).z();
  VirtualMass vm(coefficient, kFluidDensity);
  std::vector<double> a{0.0};
  for (int k = 0; k < windows; ++k) {
    const Eigen::Vector3d fluid(0, 0, -added * a.back());
    auto wrench = std::vector{held(fluid, Eigen::Vector3d::Zero())};
    if (coefficient > 0) wrench = vm.blend(std::span(&b.inertia, 1), b.forces, wrench);
    a.push_back(g + wrench[0].start.force.z() / mass);
  }
  return a;
}

// Guards against: the virtual mass not damping the explicit coupling's added-mass
// instability (a wrong sign or weight in the blend).
TEST(VirtualMass, StabilizesTheLaggingAddedMassOfALightBody) {
  // rho_b / rho_f = 0.3 with the sphere's added mass rho_f V / 2: 1.7 times the body's.
  const double density = 300, ratio = 0.5;
  const double mass = density * 1e-6, added = ratio * kFluidDensity * 1e-6;
  const double g = body_of_density(density).forces.acceleration(body_of_density(density).inertia).z();
  const double exact = mass * g / (mass + added);
  const std::vector<double> plain = model_accelerations(density, ratio, 0, 30);
  EXPECT_GT(std::abs(plain.back()), 100 * std::abs(exact));  // |-1.67|^29
  const std::vector<double> stabilized = model_accelerations(density, ratio, 1, 30);
  EXPECT_NEAR(stabilized.back(), exact, 1e-9 * std::abs(exact));
}

TEST(VirtualMass, SavedWrenchesRepeatTheBlend) {
  const Body b = body_of_density(1200);
  VirtualMass vm(0.5, kFluidDensity), copy(0.5, kFluidDensity), fresh(0.5, kFluidDensity);
  vm.blend(std::span(&b.inertia, 1), b.forces,
           std::vector{held(Eigen::Vector3d(1e-3, -2e-3, 3e-3), Eigen::Vector3d(4e-6, 5e-6, -6e-6))});
  std::vector<double> saved;
  vm.save(saved, 1);
  EXPECT_EQ(copy.load(saved, 1), saved.size());
  const auto wrench = std::vector{held(Eigen::Vector3d(0, 0, 1e-3), Eigen::Vector3d(1e-6, 0, 0))};
  const auto a = vm.blend(std::span(&b.inertia, 1), b.forces, wrench);
  const auto c = copy.blend(std::span(&b.inertia, 1), b.forces, wrench);
  const auto f = fresh.blend(std::span(&b.inertia, 1), b.forces, wrench);
  EXPECT_EQ(a[0].start.force, c[0].start.force);
  EXPECT_EQ(a[0].start.torque, c[0].start.torque);
  EXPECT_NE(a[0].start.force, f[0].start.force);  // the loaded history matters
  EXPECT_NE(a[0].start.torque, f[0].start.torque);
  EXPECT_THROW(copy.load(std::span(saved).first(3), 1), std::runtime_error);
}

}  // namespace
}  // namespace cosim::rigidbody::program
