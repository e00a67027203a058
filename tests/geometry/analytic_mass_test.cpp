// Volumes and inertia tensors of the analytic shapes against textbook closed forms, written
// in terms of the mass and the full dimensions as the tables give them.
#include <gtest/gtest.h>

#include <numbers>

#include "geometry/mass_properties.hpp"

namespace cosim::geometry {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double density = 2.5;

void expect_diagonal(const MassProperties& m, double volume, const Eigen::Vector3d& diagonal) {
  EXPECT_NEAR(m.volume, volume, 1e-14 * volume);
  EXPECT_NEAR(m.mass, density * volume, 1e-14 * density * volume);
  const Eigen::Matrix3d expected = diagonal.asDiagonal();
  EXPECT_LT((m.inertia - expected).norm(), 1e-14 * expected.norm()) << m.inertia;
}

TEST(AnalyticMass, Sphere) {
  const double r = 0.7, v = 4.0 / 3.0 * pi * r * r * r, m = density * v;
  expect_diagonal(mass_properties(Sphere(r), density), v, Eigen::Vector3d::Constant(2.0 / 5.0 * m * r * r));
}

TEST(AnalyticMass, Ellipsoid) {
  const double a = 1.2, b = 0.5, c = 0.8, v = 4.0 / 3.0 * pi * a * b * c, m = density * v;
  expect_diagonal(mass_properties(Ellipsoid({a, b, c}), density), v,
                  m / 5.0 * Eigen::Vector3d(b * b + c * c, a * a + c * c, a * a + b * b));
}

TEST(AnalyticMass, Box) {
  const double lx = 1.8, ly = 0.8, lz = 1.2, v = lx * ly * lz, m = density * v;
  expect_diagonal(mass_properties(Box({lx / 2, ly / 2, lz / 2}), density), v,
                  m / 12.0 * Eigen::Vector3d(ly * ly + lz * lz, lx * lx + lz * lz, lx * lx + ly * ly));
}

TEST(AnalyticMass, Cylinder) {
  const double r = 0.5, h = 1.6, v = pi * r * r * h, m = density * v;
  const double transverse = m * (3 * r * r + h * h) / 12.0;
  expect_diagonal(mass_properties(Cylinder(r, h), density), v, {transverse, transverse, m * r * r / 2.0});
}

// A cylinder and two hemispheres; each hemisphere's centroid sits 3r/8 from its flat face,
// its inertia about a diameter of that face is (2/5) m r^2 (half a ball's).
TEST(AnalyticMass, CapsuleIsCylinderPlusShiftedHemispheres) {
  const double r = 0.4, h = 1.0;
  const double m_cyl = density * pi * r * r * h, m_hemi = density * 2.0 / 3.0 * pi * r * r * r;
  const double d = h / 2 + 3 * r / 8;  // hemisphere centroid
  const double hemi_about_centroid = 2.0 / 5.0 * m_hemi * r * r - m_hemi * (3 * r / 8) * (3 * r / 8);
  const double transverse = m_cyl * (3 * r * r + h * h) / 12.0 + 2 * (hemi_about_centroid + m_hemi * d * d);
  const double axial = m_cyl * r * r / 2.0 + 2 * (2.0 / 5.0 * m_hemi * r * r);
  expect_diagonal(mass_properties(Capsule(r, h), density), pi * r * r * h + 4.0 / 3.0 * pi * r * r * r,
                  {transverse, transverse, axial});
}

TEST(AnalyticMass, HalfSpaceHasNoMassAndBadInputIsRejected) {
  EXPECT_THROW(mass_properties(HalfSpace({0, 0, 1}), density), std::invalid_argument);
  EXPECT_THROW(mass_properties(Sphere(1.0), 0.0), std::invalid_argument);
  EXPECT_THROW(Sphere(-1.0), std::invalid_argument);
  EXPECT_THROW(Box({1.0, 0.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(Cylinder(1.0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(HalfSpace({0, 0, 0}), std::invalid_argument);
}

TEST(ShapeKind, MatchesTheAlternativeAndHasAName) {
  const Shape shapes[] = {Sphere(1),      Ellipsoid({1, 2, 3}), Box({1, 1, 1}),
                          Cylinder(1, 1), Capsule(1, 1),        HalfSpace({0, 0, 1})};
  for (const Shape& s : shapes) EXPECT_EQ(static_cast<std::size_t>(kind(s)), s.index());
  EXPECT_EQ(name(ShapeKind::HalfSpace), "half-space");
  EXPECT_TRUE(is_convex(Shape(Box({1, 1, 1}))));
  EXPECT_FALSE(is_bounded(Shape(HalfSpace({1, 0, 0}))));
}

}  // namespace
}  // namespace cosim::geometry
