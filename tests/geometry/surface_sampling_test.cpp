// Points spread over a shape's surface (the fluid's immersed-boundary markers): they lie on
// the (inset) surface, their areas add up to the surface's, and they are about the asked
// spacing apart, for every kind of shape and any pose.
#include "geometry/surface_sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/geometry/fixtures.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

using testing::random_pose;
constexpr double pi = std::numbers::pi;

double total_area(const std::vector<SurfaceSample>& samples) {
  double a = 0;
  for (const SurfaceSample& s : samples) a += s.area;
  return a;
}

// Distance from each point to its nearest other point: smallest and largest over the set.
std::pair<double, double> nearest_neighbour_range(const std::vector<SurfaceSample>& samples) {
  double lo = INFINITY, hi = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    double nearest = INFINITY;
    for (std::size_t j = 0; j < samples.size(); ++j)
      if (j != i) nearest = std::min(nearest, (samples[i].point - samples[j].point).norm());
    lo = std::min(lo, nearest);
    hi = std::max(hi, nearest);
  }
  return {lo, hi};
}

struct Known {
  std::string name;
  Shape shape;
  double area;
};

std::vector<Known> known_areas() {
  const double r = 0.5, h = 0.8;
  return {{"sphere", Sphere(r), 4 * pi * r * r},
          {"box", Box({0.5, 0.3, 0.2}), 8 * (0.5 * 0.3 + 0.3 * 0.2 + 0.2 * 0.5)},
          {"cylinder", Cylinder(r, h), 2 * pi * r * h + 2 * pi * r * r},
          {"capsule", Capsule(0.3, h), 2 * pi * 0.3 * h + 4 * pi * 0.09},
          {"torus mesh", testing::make_mesh(testing::torus_mesh(0.6, 0.25, 96, 48)), 4 * pi * pi * 0.6 * 0.25}};
}

TEST(SurfaceSampling, PointsOnTheSurfaceAreasAddUpSpacingEven) {
  std::mt19937 rng(3);
  const double spacing = 0.08;
  for (const Known& k : known_areas()) {
    SCOPED_TRACE(k.name);
    const Pose pose = random_pose(rng);
    const std::vector<SurfaceSample> samples = sample_surface(k.shape, pose, spacing);
    // The torus mesh is a polyhedron slightly inside the true torus; edges lose about a
    // lattice width's strip.
    const bool edges = k.name == "box" || k.name == "cylinder" || k.name == "torus mesh";
    EXPECT_NEAR(total_area(samples), k.area, (edges ? 0.02 : 0.003) * k.area);
    EXPECT_NEAR(static_cast<double>(samples.size()), k.area / (spacing * spacing), 0.15 * k.area / (spacing * spacing));
    for (const SurfaceSample& s : samples) {
      EXPECT_NEAR(signed_distance(k.shape, pose, s.point), 0, 1e-9);
      EXPECT_NEAR(s.normal.norm(), 1, 1e-12);
      EXPECT_GT(s.area, 0.2 * spacing * spacing);
      EXPECT_LT(s.area, 3.0 * spacing * spacing);
    }
    const auto [lo, hi] = nearest_neighbour_range(samples);
    EXPECT_GT(lo, 0.5 * spacing);
    EXPECT_LT(hi, 1.3 * spacing);
  }
}

TEST(SurfaceSampling, SectionsAreCurvesInTheirPlane) {
  const double r = 0.5, spacing = 0.04;
  // A cylinder along z, as thick as a two-dimensional grid's layer, cut at its middle: a
  // circle, normals radial.
  const Pose upright({0.3, 0.2, 0.005}, Eigen::Quaterniond::Identity());
  const std::vector<SurfaceSample> circle = sample_section(Cylinder(r, 0.01), upright, 2, 0.005, spacing);
  EXPECT_NEAR(total_area(circle), 2 * pi * r, 0.003 * 2 * pi * r);
  EXPECT_NEAR(static_cast<double>(circle.size()), 2 * pi * r / spacing, 0.15 * 2 * pi * r / spacing);
  for (const SurfaceSample& s : circle) {
    EXPECT_DOUBLE_EQ(s.point.z(), 0.005);
    EXPECT_EQ(s.normal.z(), 0);
    EXPECT_NEAR((s.point - upright.position()).norm(), r, 1e-9);
    EXPECT_NEAR((s.point - upright.position()).normalized().dot(s.normal), 1, 1e-9);
  }
  // Its dense boundary points, a sixth of the spacing apart, add up to the circle too.
  EXPECT_NEAR(total_area(section_boundary(Cylinder(r, 0.01), upright, 2, 0.005, spacing)), 2 * pi * r,
              0.003 * 2 * pi * r);
  // A sphere cut off its centre: a circle of radius sqrt(r^2 - z^2).
  const double z = 0.3, radius = std::sqrt(r * r - z * z);
  EXPECT_NEAR(total_area(sample_section(Sphere(r), Pose(), 2, z, spacing)), 2 * pi * radius, 0.003 * 2 * pi * radius);
  EXPECT_TRUE(sample_section(Sphere(r), Pose(), 2, 0.6, spacing).empty());
}

TEST(SurfaceSampling, TheSameInputGivesTheSamePoints) {
  const Pose pose({0.1, 0.2, 0.3}, Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized())));
  const auto a = sample_surface(Ellipsoid({0.5, 0.3, 0.2}), pose, 0.05);
  const auto b = sample_surface(Ellipsoid({0.5, 0.3, 0.2}), pose, 0.05);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].point, b[i].point);
    EXPECT_EQ(a[i].area, b[i].area);
  }
  EXPECT_THROW(sample_surface(HalfSpace(Eigen::Vector3d::UnitZ()), pose, 0.05), std::invalid_argument);
  EXPECT_THROW(sample_surface(Sphere(1), pose, 0), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::geometry
